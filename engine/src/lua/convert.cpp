#include "lua/convert.hpp"

#include <cmath>
#include <string>

namespace wrc::lua {

void check_table(lua_State* L, int idx, std::string_view context) {
  if (!lua_istable(L, idx)) fail("{}: expected a table, got {}", context, type_name(L, idx));
}

void check_keys(lua_State* L, int idx, std::string_view context, std::initializer_list<std::string_view> known) {
  idx = lua_absindex(L, idx);
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    lua_pop(L, 1);  // value
    if (lua_type(L, -1) != LUA_TSTRING) {
      lua_pop(L, 1);
      fail("{}: unexpected non-string key in the options table", context);
    }
    std::string_view key = lua_tostring(L, -1);
    bool ok = false;
    for (auto k : known) ok = ok || k == key;
    if (!ok) {
      std::string list;
      for (auto k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      std::string bad(key);
      lua_pop(L, 1);
      fail("{}: unknown key '{}' (expected one of: {})", context, bad, list);
    }
  }
}

double check_number(lua_State* L, int idx, std::string_view context) {
  int isnum = 0;
  double v = lua_tonumberx(L, idx, &isnum);
  if (!isnum) fail("{}: argument {} must be a number, got {}", context, idx, type_name(L, idx));
  if (!std::isfinite(v)) fail("{}: argument {} must be finite, got {}", context, idx, v);
  return v;
}

std::string check_string(lua_State* L, int idx, std::string_view context) {
  if (lua_type(L, idx) != LUA_TSTRING) fail("{}: argument {} must be a string, got {}", context, idx, type_name(L, idx));
  return lua_tostring(L, idx);
}

std::optional<double> opt_number(lua_State* L, int idx, const char* key, std::string_view context) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  int isnum = 0;
  double v = lua_tonumberx(L, -1, &isnum);
  const char* tn = type_name(L, -1);
  lua_pop(L, 1);
  if (!isnum) fail("{}: '{}' must be a number, got {}", context, key, tn);
  if (!std::isfinite(v)) fail("{}: '{}' must be finite, got {}", context, key, v);
  return v;
}

double get_number(lua_State* L, int idx, const char* key, double fallback, std::string_view context) {
  return opt_number(L, idx, key, context).value_or(fallback);
}

double need_number(lua_State* L, int idx, const char* key, std::string_view context) {
  auto v = opt_number(L, idx, key, context);
  if (!v) fail("{}: '{}' is required (a number)", context, key);
  return *v;
}

std::optional<std::string> opt_string(lua_State* L, int idx, const char* key, std::string_view context) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  if (lua_type(L, -1) != LUA_TSTRING) {
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    fail("{}: '{}' must be a string, got {}", context, key, tn);
  }
  std::string s = lua_tostring(L, -1);
  lua_pop(L, 1);
  return s;
}

std::optional<bool> opt_bool(lua_State* L, int idx, const char* key, std::string_view context) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  if (!lua_isboolean(L, -1)) {
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    fail("{}: '{}' must be a boolean, got {}", context, key, tn);
  }
  bool b = lua_toboolean(L, -1);
  lua_pop(L, 1);
  return b;
}

std::vector<double> number_array(lua_State* L, int idx, const char* key, std::string_view context) {
  idx = lua_absindex(L, idx);
  std::string what = key ? fmt::format("'{}'", key) : std::string("argument");
  if (key) lua_getfield(L, idx, key);
  else lua_pushvalue(L, idx);
  if (!lua_istable(L, -1)) {
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    fail("{}: {} must be an array of numbers, got {}", context, what, tn);
  }
  const lua_Integer n = luaL_len(L, -1);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, -1, i);
    int isnum = 0;
    double v = lua_tonumberx(L, -1, &isnum);
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    if (!isnum) {
      lua_pop(L, 1);
      fail("{}: {}[{}] must be a number, got {}", context, what, i, tn);
    }
    if (!std::isfinite(v)) {
      lua_pop(L, 1);
      fail("{}: {}[{}] must be finite, got {}", context, what, i, v);
    }
    out.push_back(v);
  }
  lua_pop(L, 1);
  return out;
}

void push_vec3(lua_State* L, const Eigen::Vector3d& v) {
  lua_createtable(L, 0, 3);
  set_number(L, "x", v.x());
  set_number(L, "y", v.y());
  set_number(L, "z", v.z());
}

void push_array(lua_State* L, const double* data, std::size_t n) {
  lua_createtable(L, static_cast<int>(n), 0);
  for (std::size_t i = 0; i < n; ++i) {
    lua_pushnumber(L, data[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

void set_integer(lua_State* L, const char* key, long long v) {
  lua_pushinteger(L, static_cast<lua_Integer>(v));
  lua_setfield(L, -2, key);
}

void set_string(lua_State* L, const char* key, std::string_view v) {
  lua_pushlstring(L, v.data(), v.size());
  lua_setfield(L, -2, key);
}

void set_bool(lua_State* L, const char* key, bool v) {
  lua_pushboolean(L, v);
  lua_setfield(L, -2, key);
}

}  // namespace wrc::lua
