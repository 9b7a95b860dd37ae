// Lua strategies (strategy_binding.hpp): the SearchContext userdata handed to `locate`, the Lua-driven PoseSearch,
// LuaStrategy (resolution, discretise, searches per thread) and the wrc.geometry helpers.
#include "lua/strategy_binding.hpp"

#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/profile_binding.hpp"
#include "wrc/core/conventions.hpp"

#include <cmath>
#include <string>
#include <thread>

namespace wrc::lua {

namespace {

const char* const kContextType = "wrc.SearchContext";

// The userdata holds a pointer valid only during a `locate` call.
struct ContextBox {
  SearchContext* ctx = nullptr;
};

SearchContext& check_context(lua_State* L, const char* what) {
  auto* box = static_cast<ContextBox*>(luaL_testudata(L, 1, kContextType));
  if (!box) fail("{}: call it as ctx:{}(...) on the search context given to locate", what, what);
  if (!box->ctx) fail("{}: the search context is only valid during the strategy's locate call", what);
  return *box->ctx;
}

int check_side(lua_State* L, int idx, const char* what) { return parse_side(check_string(L, idx, what), what); }

int check_index(lua_State* L, int idx, const char* what) {
  int isint = 0;
  const lua_Integer v = lua_tointegerx(L, idx, &isint);
  if (!isint) fail("{}: argument {} must be an integer index, got {}", what, idx - 1, type_name(L, idx));
  return static_cast<int>(v);
}

// ctx:name(side [, line_first, line_last, cone_first, cone_last]) with 1-based inclusive indices.
Window window_args(lua_State* L, SearchContext& c, int side, const char* what) {
  Window w = c.all(side);
  if (lua_gettop(L) >= 3) {
    if (lua_gettop(L) != 6)
      fail("{}: give all four of line_first, line_last, cone_first, cone_last (1-based), or none", what);
    w.line_first = check_index(L, 3, what) - 1;
    w.line_last = check_index(L, 4, what) - 1;
    w.cone_first = check_index(L, 5, what) - 1;
    w.cone_last = check_index(L, 6, what) - 1;
  }
  return w;
}

int ctx_test(lua_State* L) {
  SearchContext& c = check_context(L, "test");
  const int side = check_side(L, 2, "test");
  c.test(side, window_args(L, c, side, "test"));
  return 0;
}

int ctx_walk(lua_State* L) {
  SearchContext& c = check_context(L, "walk");
  const int side = check_side(L, 2, "walk");
  c.walk(side, window_args(L, c, side, "walk"));
  return 0;
}

int ctx_coarse(lua_State* L) {
  SearchContext& c = check_context(L, "coarse");
  lua_pushinteger(L, c.coarse(check_side(L, 2, "coarse")));
  return 1;
}

int ctx_test_windows(lua_State* L) {
  SearchContext& c = check_context(L, "test_windows");
  c.test_windows(check_side(L, 2, "test_windows"));
  return 0;
}

int ctx_walk_windows(lua_State* L) {
  SearchContext& c = check_context(L, "walk_windows");
  c.walk_windows(check_side(L, 2, "walk_windows"));
  return 0;
}

// ctx:windows(side) -> { {line_first, line_last, cone_first, cone_last}, ... } (1-based)
int ctx_windows(lua_State* L) {
  SearchContext& c = check_context(L, "windows");
  const auto& ws = c.windows(check_side(L, 2, "windows"));
  lua_createtable(L, static_cast<int>(ws.size()), 0);
  for (std::size_t i = 0; i < ws.size(); ++i) {
    lua_createtable(L, 4, 0);
    const int v[4] = {ws[i].line_first, ws[i].line_last, ws[i].cone_first, ws[i].cone_last};
    for (int k = 0; k < 4; ++k) {
      lua_pushinteger(L, v[k] + 1);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int ctx_lines(lua_State* L) {
  SearchContext& c = check_context(L, "lines");
  lua_pushinteger(L, c.line_count(check_side(L, 2, "lines")));
  return 1;
}

int ctx_cones(lua_State* L) {
  SearchContext& c = check_context(L, "cones");
  lua_pushinteger(L, c.cone_count(check_side(L, 2, "cones")));
  return 1;
}

int ctx_index(lua_State* L) {
  if (lua_type(L, 2) == LUA_TSTRING && std::string_view(lua_tostring(L, 2)) == "pose") {
    const Pose& p = check_context(L, "pose").pose();
    lua_createtable(L, 0, 4);
    set_number(L, "y", p.y);
    set_number(L, "z", p.z);
    set_number(L, "roll", p.roll);
    set_number(L, "yaw", p.yaw);
    return 1;
  }
  luaL_getmetatable(L, kContextType);
  lua_getfield(L, -1, "methods");
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}

void push_context_box(lua_State* L) {
  auto* box = static_cast<ContextBox*>(lua_newuserdatauv(L, sizeof(ContextBox), 0));
  new (box) ContextBox{};
  if (luaL_newmetatable(L, kContextType)) {
    const luaL_Reg meta[] = {{"__index", guarded<ctx_index>}, {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    const luaL_Reg methods[] = {{"test", guarded<ctx_test>},
                                {"walk", guarded<ctx_walk>},
                                {"coarse", guarded<ctx_coarse>},
                                {"test_windows", guarded<ctx_test_windows>},
                                {"walk_windows", guarded<ctx_walk_windows>},
                                {"windows", guarded<ctx_windows>},
                                {"lines", guarded<ctx_lines>},
                                {"cones", guarded<ctx_cones>},
                                {nullptr, nullptr}};
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "methods");
  }
  lua_setmetatable(L, -2);
}

std::string pop_message(lua_State* L) {
  std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error object is not a string";
  lua_pop(L, 1);
  return msg;
}

// Calls require("wrc.strategies.compose").resolve(<value at idx>, element) and leaves the strategy table on the
// stack; element (m): the wheelset's grid element, NaN for none (a strategy rebuilt from its options).
void call_resolve(lua_State* L, int idx, double element) {
  idx = lua_absindex(L, idx);
  lua_getglobal(L, "require");
  lua_pushstring(L, "wrc.strategies.compose");
  if (pcall_traceback(L, 1, 1) != LUA_OK) fail("wrc.wheelset: cannot load the strategy composer: {}", pop_message(L));
  lua_getfield(L, -1, "resolve");
  lua_remove(L, -2);
  lua_pushvalue(L, idx);
  if (std::isnan(element))
    lua_pushnil(L);
  else
    lua_pushnumber(L, element);
  if (pcall_plain_errors(L, 2, 1) != LUA_OK) fail("wrc.wheelset: strategy: {}", pop_message(L));
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    fail("wrc.wheelset: the strategy composer did not return a table");
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// LuaSearch

LuaSearch::LuaSearch(lua_State* L, bool owns_state) : L_(L), owns_(owns_state) {
  // Strategy table on the top.
  lua_getfield(L, -1, "locate");
  if (!lua_isfunction(L, -1)) {
    lua_pop(L, 2);
    if (owns_) lua_close(L);
    fail("strategy: the strategy table has no locate(ctx, side) function");
  }
  locate_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pop(L, 1);  // the strategy table
  push_context_box(L);
  ctx_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
}

LuaSearch::~LuaSearch() {
  if (owns_ && L_) lua_close(L_);
}

void LuaSearch::release(lua_State* L) {
  if (owns_) return;
  luaL_unref(L, LUA_REGISTRYINDEX, locate_ref_);
  luaL_unref(L, LUA_REGISTRYINDEX, ctx_ref_);
  locate_ref_ = ctx_ref_ = LUA_NOREF;
}

void LuaSearch::search(SearchContext& ctx, int side) {
  lua_State* L = L_;
  if (locate_ref_ == LUA_NOREF) fail("strategy: the search was released");
  if (!lua_checkstack(L, 8)) fail("strategy: Lua stack overflow");
  lua_rawgeti(L, LUA_REGISTRYINDEX, locate_ref_);
  lua_rawgeti(L, LUA_REGISTRYINDEX, ctx_ref_);
  auto* box = static_cast<ContextBox*>(lua_touserdata(L, -1));
  box->ctx = &ctx;
  lua_pushstring(L, side_name(side));
  const int status = pcall_plain_errors(L, 2, 0);
  box->ctx = nullptr;
  if (status != LUA_OK) {
    std::string msg = pop_message(L);
    fail("strategy '{}' (locate, {} side): {}", ctx.model().strategy.name, side_name(side), msg);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// LuaStrategy

namespace {

// What a resolved strategy table (on the top of the stack) says of itself.
StrategyInfo read_info(lua_State* L) {
  const int t = lua_gettop(L);
  const OptionTable fields = to_options(L, t, "strategy", {"discretise", "locate", "options"});
  OptionReader r(fields, "strategy");
  StrategyInfo info;
  info.name = r.string("name").value_or("(unnamed)");
  info.portable = r.boolean("portable").value_or(false);
  info.components = r.strings("components").value_or(std::vector<std::string>{});
  lua_getfield(L, t, "options");
  if (lua_istable(L, -1)) {
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
      if (lua_type(L, -2) == LUA_TSTRING) {
        const std::string key = lua_tostring(L, -2);
        switch (lua_type(L, -1)) {
          case LUA_TNUMBER: info.options[key] = lua_tonumber(L, -1); break;
          case LUA_TSTRING: info.options[key] = std::string(lua_tostring(L, -1)); break;
          case LUA_TBOOLEAN: info.options[key] = static_cast<bool>(lua_toboolean(L, -1)); break;
          default: info.portable = false;  // a value another state cannot rebuild
        }
      }
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  if (info.components.empty()) info.portable = false;
  return info;
}

// Pushes the strategy table for `info` rebuilt in L (by name and options).
void push_strategy(lua_State* L, const StrategyInfo& info) {
  if (!info.portable)
    fail("strategy '{}' is an inline Lua table: it runs only in the Lua state that built the wheelset (use a named "
         "strategy, a file in scripts/strategies/, for parallel work)",
         info.name);
  lua_createtable(L, static_cast<int>(info.components.size()), static_cast<int>(info.options.size()));
  for (std::size_t i = 0; i < info.components.size(); ++i) {
    lua_pushstring(L, info.components[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  for (const auto& [key, value] : info.options) {
    if (const double* d = std::get_if<double>(&value)) lua_pushnumber(L, *d);
    else if (const std::string* s = std::get_if<std::string>(&value)) lua_pushstring(L, s->c_str());
    else lua_pushboolean(L, std::get<bool>(value));
    lua_setfield(L, -2, key.c_str());
  }
  const int spec = lua_gettop(L);
  call_resolve(L, spec, NAN);
  lua_remove(L, spec);
}

}  // namespace

LuaStrategy::LuaStrategy(lua_State* L, int idx, double element) : L_(L) {
  call_resolve(L, idx, element);
  info_ = read_info(L);
  lua_pushvalue(L, -1);
  table_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  main_ = std::make_unique<LuaSearch>(L, false);  // pops the table
}

SideDiscretisation LuaStrategy::discretise(int side, const Profile& wheel, const Profile& rail) const {
  lua_State* L = L_;
  const std::string ctx = fmt::format("strategy '{}': discretise ({} side)", info_.name, side_name(side));
  lua_rawgeti(L, LUA_REGISTRYINDEX, table_ref_);
  lua_getfield(L, -1, "discretise");
  lua_remove(L, -2);
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
  if (pcall_plain_errors(L, 1, 1) != LUA_OK) fail("{}: {}", ctx, pop_message(L));
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    fail("{}: must return a table {{wheel =, rail =, coarse =}}", ctx);
  }
  OptionTable result;  // the fields the engine reads (a strategy may keep others of its own in d)
  for (const char* key : {"wheel", "rail", "coarse"}) {
    lua_getfield(L, -1, key);
    if (!lua_isnil(L, -1)) {
      try {
        result.set(key, to_option(L, -1, fmt::format("{} result '{}'", ctx, key)));
      } catch (...) {
        lua_pop(L, 2);
        throw;
      }
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  OptionReader r(result, ctx + " result");
  auto profile = [&](OptionReader& rd, const char* key) -> std::optional<Profile> {
    auto p = std::static_pointer_cast<const Profile>(rd.object(key, kProfileType));
    return p ? std::optional<Profile>(*p) : std::nullopt;
  };
  SideDiscretisation out;
  auto w = profile(r, "wheel");
  auto rl = profile(r, "rail");
  if (!w || !rl) fail("{}: must return a table {{wheel =, rail =, coarse =}} with both profiles", ctx);
  out.wheel = std::move(*w);
  out.rail = std::move(*rl);
  if (auto c = r.table("coarse")) {
    const auto every = c->integer("every", 2, 1 << 20);
    if (!every) fail("{}: coarse.every (an integer >= 2) is required", ctx);
    out.coarse_every = *every;
    out.coarse_wheel_step = c->number("wheel_step", out.coarse_wheel_step);
    out.coarse_wheel = profile(*c, "wheel");
    c->finish();
  }
  return out;
}

std::unique_ptr<PoseSearch> LuaStrategy::make_search() const {
  if (!info_.portable) return std::make_unique<SearchRef>(*main_);
  lua_State* L = new_state();
  try {
    push_strategy(L, info_);
  } catch (...) {
    lua_close(L);
    throw;
  }
  return std::make_unique<LuaSearch>(L, true);
}

PoseSearch& LuaStrategy::main_search(lua_State* L) {
  main_->set_thread(L);
  return *main_;
}

void LuaStrategy::release(lua_State* L) {
  main_->release(L);
  luaL_unref(L, LUA_REGISTRYINDEX, table_ref_);
  table_ref_ = LUA_NOREF;
}

std::unique_ptr<LuaSearch> make_lua_search(lua_State* L, const StrategyInfo& info) {
  push_strategy(L, info);
  return std::make_unique<LuaSearch>(L, false);
}

// ---------------------------------------------------------------------------------------------------------------
// wrc.geometry

namespace {

// wrc.geometry.constant_slope(profile, {slope_step = rad, max_step = m}) -> profile
int geometry_constant_slope(lua_State* L) {
  const char* ctx = "wrc.geometry.constant_slope";
  const auto& p = check_profile(L, 1, ctx);
  const OptionTable t = to_options(L, 2, ctx);
  OptionReader r(t, ctx);
  ConstantSlope o;
  o.slope_step = r.number("slope_step", {"rad", "turning of the tangent between kept points"}, o.slope_step);
  o.max_step = r.number("max_step", {"m", "most arc between kept points"}, o.max_step);
  r.finish();
  push_profile(L, std::make_shared<const Profile>(resample_constant_slope(*p, o.slope_step, o.max_step)));
  return 1;
}

// wrc.geometry.offset_outward(profile, distance, step) -> profile
int geometry_offset_outward(lua_State* L) {
  const char* ctx = "wrc.geometry.offset_outward";
  const auto& p = check_profile(L, 1, ctx);
  const double d = check_number(L, 2, ctx), step = check_number(L, 3, ctx);
  push_profile(L, std::make_shared<const Profile>(offset_outward(*p, d, step)));
  return 1;
}

// wrc.geometry.cell_dilation(rail_profile, every) -> metres
int geometry_cell_dilation(lua_State* L) {
  const char* ctx = "wrc.geometry.cell_dilation";
  const auto& p = check_profile(L, 1, ctx);
  const double every = check_number(L, 2, ctx);
  if (every != static_cast<int>(every) || every < 1) fail("{}: every must be an integer >= 1, got {}", ctx, every);
  lua_pushnumber(L, cell_dilation(*p, static_cast<int>(every)));
  return 1;
}

}  // namespace

void open_geometry(lua_State* L) {
  lua_newtable(L);
  const luaL_Reg funcs[] = {{"constant_slope", guarded<geometry_constant_slope>},
                            {"offset_outward", guarded<geometry_offset_outward>},
                            {"cell_dilation", guarded<geometry_cell_dilation>},
                            {nullptr, nullptr}};
  luaL_setfuncs(L, funcs, 0);
  lua_setfield(L, -2, "geometry");
}

}  // namespace wrc::lua
