// Registration of the `wrc` module's parts. Each function adds its fields to the `wrc` table on the
// top of the stack and leaves the stack as it found it.
#pragma once

#include "lua/lua.hpp"

namespace wrc::lua {

int luaopen_wrc(lua_State* L);  // the `wrc` module (package.preload.wrc)

void open_core(lua_State* L);      // wrc.version, wrc.build_id, wrc.build_origin, wrc.paths
void open_fs(lua_State* L);        // wrc.fs (folders, atomic files, listings, hashes), wrc.closest_name, wrc.cores
void open_wheelset(lua_State* L);  // wrc.wheelset and the wrc.Wheelset metatable
void open_kinematics(lua_State* L);  // wrc.conicity, p:flange_measures, p:curvature
void open_wear(lua_State* L);        // wrc.wear: the kernels of a wear loop (damage/profile_wear.hpp)

// A fresh state with the standard libraries, package paths for scripts/ (require "wrc.x.y" loads
// scripts/x/y.lua) and the `wrc` module required into the global `wrc`. Used by the host and by the
// engine's worker threads (one state per thread).
lua_State* new_state();

// Pushes the traceback message handler used by every lua_pcall of the binding layer.
int traceback_handler(lua_State* L);

// lua_pcall with traceback_handler; on error leaves the message (with traceback) on the stack.
int pcall_traceback(lua_State* L, int nargs, int nresults);

// lua_pcall for strategy code, whose deliberate errors are messages to the user (compose.lua's checks of a strategy
// value, a strategy's checks of its options): a string raised by `error`, `assert` or an engine function checking its
// input is left on the stack as it is; a runtime error of Lua code (a bug) with its traceback.
int pcall_plain_errors(lua_State* L, int nargs, int nresults);

}  // namespace wrc::lua
