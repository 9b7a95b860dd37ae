// Sample binding code for the self-test of lua_longjmp.cmake (never compiled). Each `expect:` comment
// says what the check must report for the line below it; lua_longjmp_selftest.cmake checks the list.
#include <string>

int unmarked(lua_State* L) {
  std::string s = "x";
  // expect: luaL_error without a marker
  return luaL_error(L, "bad %s", s.c_str());
}

int family(lua_State* L) {
  // expect: luaL_checkinteger, luaL_optnumber, luaL_argerror, luaL_typeerror, lua_error (one line each)
  lua_Integer i = luaL_checkinteger(L, 1);
  double d = luaL_optnumber (L, 2, 0.0);
  if (i < 0) luaL_argerror(L, 1, "negative");
  if (d < 0) luaL_typeerror(L, 2, "number");
  return lua_error(L);
}

int reviewed(lua_State* L) {
  const char* s = luaL_checkstring(L, 1);  // longjmp-safe: no C++ objects alive
  // longjmp-safe: no C++ objects alive (marker on the comment line above the call)
  if (!*s) return luaL_error(L, "empty");
  return 0;
}

int not_calls(lua_State* L) {
  // luaL_error(L, "in a comment") is not a call, nor is the one in the string below.
  lua_pushstring(L, "luaL_error(L, \"quoted\") and lua_error(L)");
  lua_pushstring(L, "// not a comment: luaL_checkstring(L, 1)");
  const char q = '"';  /* luaL_error(L, "in a block comment") */
  /* a block comment over lines:
     luaL_error(L, "still a comment") */
  my_luaL_error(L, q);   // another function whose name ends like one
  return lua_error_count(L);
}

int stray(lua_State* L) {
  // expect: a marker on a line without a call
  lua_settop(L, 0);  // longjmp-safe: nothing here
  // expect: a comment-only marker whose next line has no call
  // longjmp-safe: no C++ objects alive
  lua_pushnil(L);
  return 1;
}
