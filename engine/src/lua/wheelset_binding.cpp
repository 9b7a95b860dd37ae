// wrc.wheelset{...}: the assembled wheelset and track model, and its per-pose methods.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/profile_binding.hpp"
#include "wrc/geometry/track.hpp"

#include <memory>

namespace wrc::lua {
namespace {

const char* const kWheelsetType = "wrc.Wheelset";

struct Wheelset {
  std::shared_ptr<const Track> track;
};

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

int wheelset_new(lua_State* L) {
  const char* ctx = "wrc.wheelset";
  check_table(L, 1, ctx);
  check_keys(L, 1, ctx,
             {"wheel", "rail", "left_wheel", "right_wheel", "left_rail", "right_rail", "radius", "back_to_back",
              "tape_offset", "gauge", "gauge_depth", "cant", "E", "nu", "strategy", "grid"});
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
  auto ws = std::make_shared<Wheelset>();
  ws->track = std::make_shared<const Track>(assemble_track(wheels, rails, tp));
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
  }
  luaL_getmetatable(L, kWheelsetType);
  lua_getfield(L, -1, "methods");
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}

}  // namespace

void open_wheelset(lua_State* L) {
  if (luaL_newmetatable(L, kWheelsetType)) {
    const luaL_Reg meta[] = {{"__gc", gc_shared<Wheelset>}, {"__index", guarded<wheelset_index>}, {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    lua_setfield(L, -2, "methods");
  }
  lua_pop(L, 1);
  lua_pushcfunction(L, guarded<wheelset_new>);
  lua_setfield(L, -2, "wheelset");
}

}  // namespace wrc::lua
