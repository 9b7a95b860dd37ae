// wrc.wheelset{...}: the assembled wheelset and track model, its discretised geometry, and its per-pose methods.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/profile_binding.hpp"
#include "lua/strategy_binding.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/geometry/model.hpp"
#include "wrc/geometry/track.hpp"

#include <memory>

namespace wrc::lua {
namespace {

// The strategy used when wrc.wheelset is given none (scripts/strategies/<name>.lua; README "Strategies").
const char* const kDefaultStrategy = "accurate";

std::shared_ptr<const Profile> profile_field(lua_State* L, int idx, const char* key, const char* fallback_key,
                                             const char* ctx) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1) && fallback_key) {
    lua_pop(L, 1);
    lua_getfield(L, idx, fallback_key);
  }
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    fail("{}: '{}' (or '{}') is required: a wrc.Profile", ctx, key, fallback_key ? fallback_key : key);
  }
  auto p = check_shared<const Profile>(L, -1, kProfileType, fmt::format("{}: '{}'", ctx, key));
  lua_pop(L, 1);
  return p;
}

// Calls strategy.discretise{side=, wheel=, rail=} (strategy table at index st) and reads what it returns.
SideDiscretisation discretise_side(lua_State* L, int st, int side, const Profile& wheel, const Profile& rail,
                                   const std::string& name) {
  const std::string ctx = fmt::format("strategy '{}': discretise ({} side)", name, side_name(side));
  lua_getfield(L, st, "discretise");
  if (!lua_isfunction(L, -1)) {
    lua_pop(L, 1);
    fail("{}: the strategy table has no discretise function", ctx);
  }
  lua_createtable(L, 0, 3);
  set_string(L, "side", side_name(side));
  push_profile(L, std::make_shared<const Profile>(wheel));
  lua_setfield(L, -2, "wheel");
  push_profile(L, std::make_shared<const Profile>(rail));
  lua_setfield(L, -2, "rail");
  if (pcall_traceback(L, 1, 1) != LUA_OK) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "(error object is not a string)";
    lua_pop(L, 1);
    fail("{}: {}", ctx, msg);
  }
  const int d = lua_gettop(L);
  if (!lua_istable(L, d)) {
    lua_pop(L, 1);
    fail("{}: must return a table {{wheel =, rail =, coarse =}}", ctx);
  }
  SideDiscretisation out;
  lua_getfield(L, d, "wheel");
  out.wheel = *check_profile(L, -1, ctx + " result 'wheel'");
  lua_pop(L, 1);
  lua_getfield(L, d, "rail");
  out.rail = *check_profile(L, -1, ctx + " result 'rail'");
  lua_pop(L, 1);
  lua_getfield(L, d, "coarse");
  if (!lua_isnil(L, -1)) {
    const int c = lua_gettop(L);
    check_table(L, c, ctx + " result 'coarse'");
    check_keys(L, c, ctx + " result 'coarse'", {"every", "wheel", "wheel_step"});
    const double every = need_number(L, c, "every", ctx + " result 'coarse'");
    if (every != static_cast<int>(every) || every < 2)
      fail("{}: coarse.every must be an integer >= 2, got {}", ctx, every);
    out.coarse_every = static_cast<int>(every);
    out.coarse_wheel_step = get_number(L, c, "wheel_step", out.coarse_wheel_step, ctx + " result 'coarse'");
    lua_getfield(L, c, "wheel");
    if (!lua_isnil(L, -1)) out.coarse_wheel = *check_profile(L, -1, ctx + " result 'coarse.wheel'");
    lua_pop(L, 1);
  }
  lua_pop(L, 2);  // coarse, result
  return out;
}

int wheelset_new(lua_State* L) {
  const char* ctx = "wrc.wheelset";
  check_table(L, 1, ctx);
  check_keys(L, 1, ctx,
             {"wheel", "rail", "left_wheel", "right_wheel", "left_rail", "right_rail", "radius", "back_to_back",
              "tape_offset", "gauge", "gauge_depth", "cant", "E", "nu", "strategy", "grid", "margin", "solver",
              "tolerance", "merge_tolerance", "merge_angle"});
  TrackParams tp;
  tp.radius = get_number(L, 1, "radius", tp.radius, ctx);
  tp.back_to_back = get_number(L, 1, "back_to_back", tp.back_to_back, ctx);
  tp.tape_offset = get_number(L, 1, "tape_offset", tp.tape_offset, ctx);
  tp.gauge = get_number(L, 1, "gauge", tp.gauge, ctx);
  tp.gauge_depth = get_number(L, 1, "gauge_depth", tp.gauge_depth, ctx);
  tp.cant = get_number(L, 1, "cant", tp.cant, ctx);
  std::array<Profile, 2> wheels{*profile_field(L, 1, "left_wheel", "wheel", ctx),
                                *profile_field(L, 1, "right_wheel", "wheel", ctx)};
  std::array<Profile, 2> rails{*profile_field(L, 1, "left_rail", "rail", ctx),
                               *profile_field(L, 1, "right_rail", "rail", ctx)};
  // Normal contact: material, grid and solver options (checked by ContactModel).
  contact::Material material;
  material.E = get_number(L, 1, "E", material.E, ctx);
  material.nu = get_number(L, 1, "nu", material.nu, ctx);
  ContactOptions copt;
  copt.element = get_number(L, 1, "grid", copt.element, ctx);
  const double margin = get_number(L, 1, "margin", copt.margin, ctx);
  if (margin != static_cast<int>(margin)) fail("{}: 'margin' must be a whole number of elements, got {}", ctx, margin);
  copt.margin = static_cast<int>(margin);
  copt.normal.tolerance = get_number(L, 1, "tolerance", copt.normal.tolerance, ctx);
  copt.merge_tolerance = get_number(L, 1, "merge_tolerance", copt.merge_tolerance, ctx);
  copt.merge_angle = get_number(L, 1, "merge_angle", copt.merge_angle, ctx);
  const std::string solver = opt_string(L, 1, "solver", ctx).value_or("fast");
  if (solver != "fast" && solver != "dense") fail("{}: 'solver' must be \"fast\" or \"dense\", got \"{}\"", ctx, solver);
  copt.dense = solver == "dense";

  auto ws = std::make_shared<Wheelset>();
  ws->track = std::make_shared<const Track>(assemble_track(wheels, rails, tp));

  // Strategy: resolve, discretise both sides, build the geometry.
  lua_getfield(L, 1, "strategy");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_pushstring(L, kDefaultStrategy);
  }
  StrategyInfo info = resolve_strategy(L, -1);
  const int st = lua_gettop(L);
  std::array<SideDiscretisation, 2> sides;
  for (int s : {kLeft, kRight}) sides[s] = discretise_side(L, st, s, wheels[s], rails[s], info.name);
  attach_search_factory(info);
  ws->model = std::make_shared<const GeometryModel>(build_geometry(ws->track, sides, std::move(info)));
  ws->contact = std::make_shared<const ContactModel>(ws->model, material, copt);
  lua_pushvalue(L, st);
  ws->search = std::make_unique<LuaSearch>(L, false);  // pops the copy
  lua_pop(L, 2);                                        // strategy table, strategy value
  push_shared(L, std::move(ws), kWheelsetType);
  return 1;
}

void push_placed(lua_State* L, const std::vector<double>& y, const std::vector<double>& z, const char* kind,
                 const char* frame) {
  lua_createtable(L, 0, 4);
  push_array(L, y);
  lua_setfield(L, -2, "y");
  push_array(L, z);
  lua_setfield(L, -2, "z");
  set_string(L, "kind", kind);
  set_string(L, "frame", frame);
}

}  // namespace

int check_side_arg(lua_State* L, int idx, const char* what) {
  if (lua_type(L, idx) == LUA_TSTRING) {
    const std::string_view s = lua_tostring(L, idx);
    if (s == "left") return kLeft;
    if (s == "right") return kRight;
  }
  fail("{}: side must be \"left\" or \"right\", got {}", what,
       lua_type(L, idx) == LUA_TSTRING ? fmt::format("\"{}\"", lua_tostring(L, idx)) : std::string(luaL_typename(L, idx)));
}

// ---- the located patches (geometry only; contact_binding.cpp adds the normal-contact fields). ----

void push_segment(lua_State* L, const Segment& s) {
  lua_createtable(L, 0, 7);
  set_integer(L, "line", s.line + 1);
  set_number(L, "y", s.y);
  set_number(L, "z", s.z);
  set_number(L, "x_t", s.x_t);
  set_number(L, "x_l", s.x_l);
  lua_createtable(L, 2, 0);
  lua_pushinteger(L, s.cone_t + 1);
  lua_rawseti(L, -2, 1);
  lua_pushinteger(L, s.cone_l + 1);
  lua_rawseti(L, -2, 2);
  lua_setfield(L, -2, "cones");
}

void push_patch(lua_State* L, const LocationState& st, const Patch& p) {
  lua_createtable(L, 0, 24);
  set_string(L, "side", side_name(p.side));
  push_vec3(L, p.point);  // "point" is the centre of pressure of the normal-contact stage (DESIGN.md section 5)
  lua_setfield(L, -2, "nominal_point");
  push_vec3(L, p.normal);  // "normal" is the contact-plane normal of the normal-contact stage
  lua_setfield(L, -2, "nominal_normal");
  push_vec3(L, p.wheel_point);
  lua_setfield(L, -2, "wheel_point");
  set_integer(L, "cone", p.cone + 1);
  set_number(L, "eps", p.eps);
  set_number(L, "wheel_radius", p.wheel_radius);
  set_number(L, "depth", p.depth);
  set_integer(L, "first_line", p.first_line + 1);
  set_integer(L, "last_line", p.last_line + 1);
  set_integer(L, "longest", p.longest - p.first_segment + 1);
  const auto& segs = st.segments(p.side);
  lua_createtable(L, p.segment_count, 0);
  for (int i = 0; i < p.segment_count; ++i) {
    push_segment(L, segs[p.first_segment + i]);
    lua_rawseti(L, -2, i + 1);
  }
  lua_setfield(L, -2, "segments");
}

namespace {

void push_counters(lua_State* L, const SearchCounters& c) {
  set_integer(L, "tests", c.tests);
  set_integer(L, "coarse_tests", c.coarse_tests);
  set_integer(L, "bounds", c.bounds);
  set_integer(L, "lines_visited", c.lines);
}

// c = {left = {patches = {...}, tests = ...}, right = {...}, pose = {...}, tests = <both sides>}
void push_contact(lua_State* L, const GeometryModel&, const LocationState& st) {
  lua_createtable(L, 0, 4);
  long long tests = 0;
  for (int s : {kLeft, kRight}) {
    lua_createtable(L, 0, 6);
    const auto& patches = st.patches(s);
    lua_createtable(L, static_cast<int>(patches.size()), 0);
    for (std::size_t i = 0; i < patches.size(); ++i) {
      push_patch(L, st, patches[i]);
      lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_setfield(L, -2, "patches");
    push_counters(L, st.counters(s));
    set_integer(L, "grazes", st.grazes_dropped(s));
    tests += st.counters(s).tests;
    lua_setfield(L, -2, side_name(s));
  }
  lua_createtable(L, 0, 4);
  set_number(L, "y", st.pose().y);
  set_number(L, "z", st.pose().z);
  set_number(L, "roll", st.pose().roll);
  set_number(L, "yaw", st.pose().yaw);
  lua_setfield(L, -2, "pose");
  set_integer(L, "tests", tests);
}

// ws:locate{y=, z=, roll=, yaw=, search = "strategy" | "brute"}: the inter-penetration areas alone.
int wheelset_locate(lua_State* L) {
  const char* ctx = "wheelset:locate";
  const auto& ws = check_shared<Wheelset>(L, 1, kWheelsetType, ctx);
  check_table(L, 2, ctx);
  check_keys(L, 2, ctx, {"y", "z", "roll", "yaw", "search"});
  Pose pose;
  pose.y = get_number(L, 2, "y", 0.0, ctx);
  pose.z = get_number(L, 2, "z", 0.0, ctx);
  pose.roll = get_number(L, 2, "roll", 0.0, ctx);
  pose.yaw = get_number(L, 2, "yaw", 0.0, ctx);
  const std::string search = opt_string(L, 2, "search", ctx).value_or("strategy");
  if (search == "strategy") {
    ws->search->set_thread(L);
    locate_contact(*ws->model, pose, ws->state, *ws->search);
  } else if (search == "brute") {  // the reference: every line against every cone of the same discretisation
    NativeSearch brute({false, NativePlan::Scan::test});
    locate_contact(*ws->model, pose, ws->state, brute);
  } else {
    fail("{}: search must be \"strategy\" or \"brute\", got \"{}\"", ctx, search);
  }
  ws->located = true;
  push_contact(L, *ws->model, ws->state);
  return 1;
}

// ws:cones(side) -> {y = {...}, z = {...}, count = n}: generatrix points of the discretised wheel (wheelset frame,
// z = -radius; the first and last are the closing points on the axle). Cone k joins points k and k + 1.
int wheelset_cones(lua_State* L) {
  const auto& ws = check_shared<Wheelset>(L, 1, kWheelsetType, "wheelset:cones");
  const WheelCones& w = ws->model->side[check_side_arg(L, 2, "wheelset:cones")].wheel;
  push_placed(L, w.y, w.z, "wheel", "wheelset");
  set_integer(L, "count", w.cone_count());
  return 1;
}

// ws:lines(side) -> {y = {...}, z = {...}, count = n}: the rail lines (track frame).
int wheelset_lines(lua_State* L) {
  const auto& ws = check_shared<Wheelset>(L, 1, kWheelsetType, "wheelset:lines");
  const RailLines& r = ws->model->side[check_side_arg(L, 2, "wheelset:lines")].rail;
  push_placed(L, r.y, r.z, "rail", "track");
  set_integer(L, "count", r.count());
  return 1;
}

// ws:coarse(side) -> nil or {wheel = {y, z}, lines = {y, z}, dilation = m, every = n, cells = {{first, last}, ...}}
int wheelset_coarse(lua_State* L) {
  const auto& ws = check_shared<Wheelset>(L, 1, kWheelsetType, "wheelset:coarse");
  const SideGeometry& g = ws->model->side[check_side_arg(L, 2, "wheelset:coarse")];
  if (!g.coarse) {
    lua_pushnil(L);
    return 1;
  }
  const CoarseLevel& c = *g.coarse;
  lua_createtable(L, 0, 5);
  push_placed(L, c.wheel.y, c.wheel.z, "wheel", "wheelset");
  lua_setfield(L, -2, "wheel");
  push_placed(L, c.lines.y, c.lines.z, "rail", "track");
  lua_setfield(L, -2, "lines");
  set_number(L, "dilation", c.dilation);
  set_integer(L, "every", c.every);
  lua_createtable(L, static_cast<int>(c.cell_first.size()), 0);
  for (std::size_t i = 0; i < c.cell_first.size(); ++i) {
    lua_createtable(L, 2, 0);
    lua_pushinteger(L, c.cell_first[i] + 1);
    lua_rawseti(L, -2, 1);
    lua_pushinteger(L, c.cell_last[i] + 1);
    lua_rawseti(L, -2, 2);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "cells");
  return 1;
}

int wheelset_gc(lua_State* L) {
  auto* p = static_cast<std::shared_ptr<Wheelset>*>(lua_touserdata(L, 1));
  if (p && *p && (*p)->search) (*p)->search->release(L);
  return gc_shared<Wheelset>(L);
}

int wheelset_index(lua_State* L) {
  const auto& ws = check_shared<Wheelset>(L, 1, kWheelsetType, "wheelset");
  const Track& t = *ws->track;
  if (lua_type(L, 2) == LUA_TSTRING) {
    const std::string_view key = lua_tostring(L, 2);
    for (int s : {kLeft, kRight}) {
      const std::string side = side_name(s);
      if (key == side + "_wheel") return push_placed(L, t.wheel_y[s], t.wheel_z[s], "wheel", "wheelset"), 1;
      if (key == side + "_rail") return push_placed(L, t.rail_y[s], t.rail_z[s], "rail", "track"), 1;
    }
    if (key == "gauge_points" || key == "tape_points") {
      const auto& pts = key == "gauge_points" ? t.gauge_point : t.tape_point;
      lua_createtable(L, 0, 2);
      for (int s : {kLeft, kRight}) {
        lua_createtable(L, 0, 2);
        set_number(L, "y", pts[s].x());
        set_number(L, "z", pts[s].y());
        lua_setfield(L, -2, side_name(s));
      }
      return 1;
    }
    if (key == "rail_top") {
      lua_createtable(L, 0, 2);
      set_number(L, "left", t.rail_top[kLeft]);
      set_number(L, "right", t.rail_top[kRight]);
      return 1;
    }
    if (key == "params") {
      lua_createtable(L, 0, 6);
      set_number(L, "radius", t.params.radius);
      set_number(L, "back_to_back", t.params.back_to_back);
      set_number(L, "tape_offset", t.params.tape_offset);
      set_number(L, "gauge", t.params.gauge);
      set_number(L, "gauge_depth", t.params.gauge_depth);
      set_number(L, "cant", t.params.cant);
      return 1;
    }
    if (key == "strategy") {
      const StrategyInfo& si = ws->model->strategy;
      lua_createtable(L, 0, 4);
      set_string(L, "name", si.name);
      set_bool(L, "portable", si.portable);
      lua_createtable(L, static_cast<int>(si.components.size()), 0);
      for (std::size_t i = 0; i < si.components.size(); ++i) {
        lua_pushstring(L, si.components[i].c_str());
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      lua_setfield(L, -2, "components");
      lua_createtable(L, 0, static_cast<int>(si.options.size()));
      for (const auto& [k, v] : si.options) {
        if (const double* d = std::get_if<double>(&v)) lua_pushnumber(L, *d);
        else if (const std::string* s = std::get_if<std::string>(&v)) lua_pushstring(L, s->c_str());
        else lua_pushboolean(L, std::get<bool>(v));
        lua_setfield(L, -2, k.c_str());
      }
      lua_setfield(L, -2, "options");
      return 1;
    }
    if (key == "tests") {  // work of the last ws:locate: closed-form tests per side
      if (!ws->located) return lua_pushnil(L), 1;
      lua_createtable(L, 0, 3);
      set_integer(L, "left", ws->state.counters(kLeft).tests);
      set_integer(L, "right", ws->state.counters(kRight).tests);
      set_integer(L, "total", ws->state.counters(kLeft).tests + ws->state.counters(kRight).tests);
      return 1;
    }
  }
  luaL_getmetatable(L, kWheelsetType);
  lua_getfield(L, -1, "methods");
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}

}  // namespace

const char* const kWheelsetType = "wrc.Wheelset";

std::shared_ptr<const GeometryModel> wheelset_model(lua_State* L, int idx) {
  return check_shared<Wheelset>(L, idx, kWheelsetType, "wheelset_model")->model;
}

void open_wheelset(lua_State* L) {
  if (luaL_newmetatable(L, kWheelsetType)) {
    const luaL_Reg meta[] = {{"__gc", wheelset_gc}, {"__index", guarded<wheelset_index>}, {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    const luaL_Reg methods[] = {{"locate", guarded<wheelset_locate>},
                                {"cones", guarded<wheelset_cones>},
                                {"lines", guarded<wheelset_lines>},
                                {"coarse", guarded<wheelset_coarse>},
                                {nullptr, nullptr}};
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "methods");
  }
  lua_pop(L, 1);
  lua_pushcfunction(L, guarded<wheelset_new>);
  lua_setfield(L, -2, "wheelset");
  open_geometry(L);  // wrc.geometry: the strategies' helpers
  open_contact(L);   // ws:contact, ws:equilibrium, ws:wheel, ws:rigid, ws:sweep
}

}  // namespace wrc::lua
