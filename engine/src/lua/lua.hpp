// The one include of the Lua C API for the binding layer (Debian's liblua5.4-dev is built as C: lua_error
// is a longjmp, so no C++ object may be alive in a frame it unwinds; see guard.hpp).
#pragma once

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}
