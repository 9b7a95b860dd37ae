// Reading Lua values into C++ and back, for the binding layer. Every `check_*`/`opt_*` helper throws
// wrc::Error naming the function, key and what was expected (never luaL_error; see guard.hpp).
#pragma once

#include "lua/lua.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/options.hpp"

#include <Eigen/Core>

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc::lua {

// "number", "string", ... of the value at idx.
inline const char* type_name(lua_State* L, int idx) { return luaL_typename(L, idx); }

// Table argument at stack index idx (context names the function for the message).
void check_table(lua_State* L, int idx, std::string_view context);

double check_number(lua_State* L, int idx, std::string_view context);  // finite number at a stack index
std::string check_string(lua_State* L, int idx, std::string_view context);

// The Lua value at idx as an engine option value: numbers, booleans, strings, arrays (keys 1..n), tables with
// string keys, wrc.Profile userdata (objects of type "wrc.Profile"). Anything else (a function, a mixed table) is
// an error naming `context` and the key. to_options reads a table argument, leaving out the keys in `skip`
// (values the binding handles itself, e.g. a strategy given as a table of functions).
OptionValue to_option(lua_State* L, int idx, std::string_view context);
OptionValue to_option_at(lua_State* L, int idx, std::string_view context, int depth);
OptionTable to_options(lua_State* L, int idx, std::string_view context,
                       std::initializer_list<std::string_view> skip = {});
// The same for a required table argument (nil is an error).
OptionTable table_options(lua_State* L, int idx, std::string_view context,
                          std::initializer_list<std::string_view> skip = {});

// Pushes an option value as the Lua value to_option would read back (a profile object as a wrc.Profile).
void push_option(lua_State* L, const OptionValue& v);

// Pushes {x=, y=, z=}.
void push_vec3(lua_State* L, const Eigen::Vector3d& v);
// Pushes a Lua array of numbers.
void push_array(lua_State* L, const double* data, std::size_t n);
inline void push_array(lua_State* L, const std::vector<double>& v) { push_array(L, v.data(), v.size()); }
// t[key] = number for the table on top of the stack.
void set_number(lua_State* L, const char* key, double v);
void set_integer(lua_State* L, const char* key, long long v);
void set_string(lua_State* L, const char* key, std::string_view v);
void set_bool(lua_State* L, const char* key, bool v);

// Userdata boxing a std::shared_ptr<T> with metatable `tname` (e.g. "wrc.Profile"); __gc releases it.
template <class T>
void push_shared(lua_State* L, std::shared_ptr<T> p, const char* tname) {
  void* mem = lua_newuserdatauv(L, sizeof(std::shared_ptr<T>), 0);
  new (mem) std::shared_ptr<T>(std::move(p));
  luaL_setmetatable(L, tname);
}

// __gc: releases the object and leaves an empty pointer, so that a second call (a script calling the metamethod
// itself) releases nothing twice.
template <class T>
int gc_shared(lua_State* L) {
  auto* p = static_cast<std::shared_ptr<T>*>(lua_touserdata(L, 1));
  if (p) {
    p->~shared_ptr<T>();
    new (p) std::shared_ptr<T>();
  }
  return 0;
}

// The shared_ptr in the userdata at idx, or an error naming the expected type.
template <class T>
const std::shared_ptr<T>& check_shared(lua_State* L, int idx, const char* tname, std::string_view context) {
  auto* p = static_cast<std::shared_ptr<T>*>(luaL_testudata(L, idx, tname));
  if (!p || !*p) fail("{}: argument {} must be a {}, got {}", context, idx, tname, type_name(L, idx));
  return *p;
}

}  // namespace wrc::lua
