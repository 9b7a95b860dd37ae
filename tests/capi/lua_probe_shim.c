/* Preloaded (LD_PRELOAD) into lua_probe: stands in front of liblua's two functions that make a Lua state, counts
 * the calls and forwards them. Every Lua state is made by one of them (luaL_newstate calls lua_newstate inside
 * liblua, where a preload cannot see it, hence both); libwrc.so calls them through the dynamic linker because it
 * links liblua as a shared library, which lua_imports.cmake checks. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <lauxlib.h>
#include <lua.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

static atomic_int states;

/* What lua_probe asks (found with dlsym: it is there only when this library is preloaded). */
__attribute__((visibility("default"))) int wrc_probe_lua_states(void) { return atomic_load(&states); }

/* liblua's definition of `name` (the next one after this library). */
static void* next(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (!f) {
    fprintf(stderr, "lua_probe_shim: no %s after the probe: %s\n", name, dlerror());
    abort();
  }
  return f;
}

__attribute__((visibility("default"))) lua_State* lua_newstate(lua_Alloc f, void* ud) {
  lua_State* (*real)(lua_Alloc, void*);
  *(void**)(&real) = next("lua_newstate");
  atomic_fetch_add(&states, 1);
  return real(f, ud);
}

__attribute__((visibility("default"))) lua_State* luaL_newstate(void) {
  lua_State* (*real)(void);
  *(void**)(&real) = next("luaL_newstate");
  atomic_fetch_add(&states, 1);
  return real();
}
