#include "lua/results_binding.hpp"

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

void LuaSink::grid(std::string_view key, const double* v, int nx, int ny) {
  lua_createtable(L_, ny, 0);
  for (int j = 0; j < ny; ++j) {
    lua_createtable(L_, nx, 0);
    for (int i = 0; i < nx; ++i) {
      lua_pushnumber(L_, v[static_cast<std::size_t>(nx) * j + i]);
      lua_rawseti(L_, -2, i + 1);
    }
    lua_rawseti(L_, -2, j + 1);
  }
  set(key);
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
