#include "lua/results_binding.hpp"

#include <new>
#include <string>

namespace wrc::lua {

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

// A grid as a wrc.Grid userdata on the top of the stack.
void push_grid(lua_State* L, FieldRecord& record, const FieldNode& n) {
  auto* g = static_cast<LuaGrid*>(lua_newuserdatauv(L, sizeof(LuaGrid), 1));
  new (g) LuaGrid{record.take_values(n), n.nx, n.ny};
  if (luaL_newmetatable(L, kGridType)) {
    const luaL_Reg meta[] = {{"__index", grid_index}, {"__len", grid_len}, {"__gc", grid_gc}, {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
  }
  lua_setmetatable(L, -2);
  lua_createtable(L, n.ny, 0);
  lua_setiuservalue(L, -2, 1);
}

// The metatable registered under the table's object type on the table on the top of the stack, when there is one.
void set_object_type(lua_State* L, const FieldNode& n) {
  if (n.object_type.empty()) return;
  if (luaL_getmetatable(L, std::string(n.object_type).c_str()) == LUA_TTABLE) lua_setmetatable(L, -2);
  else lua_pop(L, 1);
}

void push_node(lua_State* L, FieldRecord& record, const FieldNode& n, int hash_size);

// The children of a table or list into the table on the top of the stack: a list's items by index, fields by key.
void fill(lua_State* L, FieldRecord& record, const FieldNode& parent) {
  const bool list = parent.kind == FieldNode::Kind::list;
  lua_Integer items = 0;
  for (const FieldNode& c : parent.children()) {
    if (list && c.kind == FieldNode::Kind::table && c.key.empty()) {
      push_node(L, record, c, 8);
      lua_rawseti(L, -2, ++items);
    } else {
      lua_pushlstring(L, c.key.data(), c.key.size());
      push_node(L, record, c, 4);
      lua_rawset(L, -3);
    }
  }
}

// The node's value on the top of the stack (a table pre-sized for hash_size fields).
void push_node(lua_State* L, FieldRecord& record, const FieldNode& n, int hash_size) {
  using K = FieldNode::Kind;
  switch (n.kind) {
    case K::number: lua_pushnumber(L, n.number); return;
    case K::integer: lua_pushinteger(L, static_cast<lua_Integer>(n.integer)); return;
    case K::boolean: lua_pushboolean(L, n.integer != 0); return;
    case K::string: lua_pushlstring(L, n.text.data(), n.text.size()); return;
    case K::numbers:
      lua_createtable(L, static_cast<int>(n.values.size()), 0);
      for (std::size_t i = 0; i < n.values.size(); ++i) {
        lua_pushnumber(L, n.values[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      return;
    case K::integers:
      lua_createtable(L, static_cast<int>(n.integers.size()), 0);
      for (std::size_t i = 0; i < n.integers.size(); ++i) {
        lua_pushinteger(L, static_cast<lua_Integer>(n.integers[i]));
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      return;
    case K::grid: push_grid(L, record, n); return;
    case K::list:
      lua_createtable(L, static_cast<int>(n.count), 0);
      fill(L, record, n);
      return;
    case K::table:
      lua_createtable(L, 0, hash_size);
      set_object_type(L, n);
      fill(L, record, n);
      return;
  }
}

}  // namespace

void push_fields(lua_State* L, FieldRecord& record) { push_node(L, record, record.root(), 8); }

const std::vector<double>* grid_values(lua_State* L, int idx, int& nx, int& ny) {
  auto* g = static_cast<LuaGrid*>(luaL_testudata(L, idx, kGridType));
  if (!g) return nullptr;
  nx = g->nx, ny = g->ny;
  return &g->values;
}

}  // namespace wrc::lua
