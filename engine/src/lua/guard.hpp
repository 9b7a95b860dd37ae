// Exception -> Lua error conversion for every C++ function called from Lua.
//
// lua_error longjmps out of the C function. Called while C++ objects are alive, it would skip their
// destructors. `guarded<F>` runs F inside try/catch: when F throws, its frame is unwound by the C++
// exception (destructors run), the message is copied into a Lua string inside the catch block, and
// lua_error is called only after the catch block has ended (the exception object is destroyed too).
//
// Rule for binding code: inside F use the `check_*` helpers of convert.hpp, which throw wrc::Error,
// never luaL_check*/luaL_error, which longjmp past F's locals. The test "lint: longjmp-safe Lua bindings"
// (tests/lint) enforces it: under engine/src/lua, a call of luaL_error, luaL_check*, luaL_opt*, luaL_arg*,
// luaL_typeerror or lua_error is an error unless the line (or a comment line just above it) carries the
// marker comment "longjmp-safe: <why>", written after checking that no C++ object with a destructor is alive.
#pragma once

#include "lua/lua.hpp"

#include <exception>

namespace wrc::lua {

template <int (*F)(lua_State*)>
int guarded(lua_State* L) {
  bool failed = false;
  try {
    return F(L);
  } catch (const std::exception& e) {
    luaL_where(L, 1);  // "script.lua:12: " of the Lua line that made the call
    lua_pushstring(L, e.what());
    lua_concat(L, 2);
    failed = true;
  } catch (...) {
    luaL_where(L, 1);
    lua_pushliteral(L, "unknown C++ exception");
    lua_concat(L, 2);
    failed = true;
  }
  if (failed) return lua_error(L);  // longjmp-safe: after the catch block, no C++ objects alive
  return 0;
}

}  // namespace wrc::lua
