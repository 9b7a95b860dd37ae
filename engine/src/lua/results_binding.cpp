#include "lua/results_binding.hpp"

#include <new>

namespace wrc::lua {

LuaSink::LuaSink(lua_State* L) : L_(L) {
  lua_createtable(L, 0, 8);
  frames_.push_back({});
}

void LuaSink::set(std::string_view key) {
  lua_pushlstring(L_, key.data(), key.size());
  lua_insert(L_, -2);
  lua_rawset(L_, -3);
}

void LuaSink::number(std::string_view key, double v) {
  lua_pushnumber(L_, v);
  set(key);
}

void LuaSink::integer(std::string_view key, long long v) {
  lua_pushinteger(L_, static_cast<lua_Integer>(v));
  set(key);
}

void LuaSink::boolean(std::string_view key, bool v) {
  lua_pushboolean(L_, v);
  set(key);
}

void LuaSink::string(std::string_view key, std::string_view v) {
  lua_pushlstring(L_, v.data(), v.size());
  set(key);
}

void LuaSink::numbers(std::string_view key, const double* v, std::size_t n) {
  lua_createtable(L_, static_cast<int>(n), 0);
  for (std::size_t i = 0; i < n; ++i) {
    lua_pushnumber(L_, v[i]);
    lua_rawseti(L_, -2, static_cast<lua_Integer>(i + 1));
  }
  set(key);
}

void LuaSink::integers(std::string_view key, const long long* v, std::size_t n) {
  lua_createtable(L_, static_cast<int>(n), 0);
  for (std::size_t i = 0; i < n; ++i) {
    lua_pushinteger(L_, static_cast<lua_Integer>(v[i]));
    lua_rawseti(L_, -2, static_cast<lua_Integer>(i + 1));
  }
  set(key);
}

namespace {

// A grid of a result as userdata, its rows built as Lua tables only when read (g[j][i], #g = ny, g.nx, g.ny):
// most results' grids are never read, and building them cost more than the evaluation's own result.
const char* const kGridType = "wrc.Grid";

struct LuaGrid {
  std::vector<double> values;  // v[i + nx j]
  int nx = 0, ny = 0;
};

int grid_index(lua_State* L) {
  auto* g = static_cast<LuaGrid*>(luaL_checkudata(L, 1, kGridType));  // longjmp-safe: no C++ objects alive
  if (lua_type(L, 2) == LUA_TSTRING) {
    const std::string_view key = lua_tostring(L, 2);
    if (key == "nx" || key == "ny") return lua_pushinteger(L, key == "nx" ? g->nx : g->ny), 1;
    return lua_pushnil(L), 1;
  }
  const lua_Integer j = lua_isinteger(L, 2) ? lua_tointeger(L, 2) : 0;
  if (j < 1 || j > g->ny) return lua_pushnil(L), 1;
  lua_getiuservalue(L, 1, 1);  // the rows built so far
  if (lua_rawgeti(L, -1, j) != LUA_TNIL) return 1;
  lua_pop(L, 1);
  lua_createtable(L, g->nx, 0);
  const double* row = g->values.data() + static_cast<std::size_t>(g->nx) * (j - 1);
  for (int i = 0; i < g->nx; ++i) {
    lua_pushnumber(L, row[i]);
    lua_rawseti(L, -2, i + 1);
  }
  lua_pushvalue(L, -1);
  lua_rawseti(L, -3, j);
  return 1;
}

int grid_len(lua_State* L) {
  lua_pushinteger(L, static_cast<LuaGrid*>(luaL_checkudata(L, 1, kGridType))->ny);  // longjmp-safe: no C++ objects
  return 1;
}

int grid_gc(lua_State* L) {
  static_cast<LuaGrid*>(lua_touserdata(L, 1))->~LuaGrid();
  return 0;
}

}  // namespace

void LuaSink::grid(std::string_view key, const double* v, int nx, int ny) {
  auto* g = static_cast<LuaGrid*>(lua_newuserdatauv(L_, sizeof(LuaGrid), 1));
  new (g) LuaGrid{std::vector<double>(v, v + static_cast<std::size_t>(nx) * ny), nx, ny};
  if (luaL_newmetatable(L_, kGridType)) {
    const luaL_Reg meta[] = {{"__index", grid_index}, {"__len", grid_len}, {"__gc", grid_gc}, {nullptr, nullptr}};
    luaL_setfuncs(L_, meta, 0);
  }
  lua_setmetatable(L_, -2);
  lua_createtable(L_, ny, 0);
  lua_setiuservalue(L_, -2, 1);
  set(key);
}

const std::vector<double>* grid_values(lua_State* L, int idx, int& nx, int& ny) {
  auto* g = static_cast<LuaGrid*>(luaL_testudata(L, idx, kGridType));
  if (!g) return nullptr;
  nx = g->nx, ny = g->ny;
  return &g->values;
}

void LuaSink::object_type(std::string_view name) {
  const std::string n(name);
  if (luaL_getmetatable(L_, n.c_str()) == LUA_TTABLE) lua_setmetatable(L_, -2);
  else lua_pop(L_, 1);
}

void LuaSink::begin(std::string_view key) {
  lua_createtable(L_, 0, 4);
  frames_.push_back({std::string(key)});
}

void LuaSink::begin_list(std::string_view key, std::size_t n) {
  lua_createtable(L_, static_cast<int>(n), 0);
  frames_.push_back({std::string(key)});
}

void LuaSink::item() {
  lua_createtable(L_, 0, 8);
  frames_.push_back({{}, true});
}

void LuaSink::end() {
  const Frame f = frames_.back();
  frames_.pop_back();
  if (f.item) lua_rawseti(L_, -2, ++frames_.back().count);
  else set(f.key);
}

}  // namespace wrc::lua
