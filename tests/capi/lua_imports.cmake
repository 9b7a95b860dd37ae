# libwrc.so takes Lua from a shared liblua, so that lua_probe's preloaded counter sees every Lua state it makes, and
# links of the Lua binding only the sandbox of profile definitions: it imports lua_newstate, and none of the functions
# that make an unsandboxed state or open the system's libraries.
#   cmake -DNM=<nm> -DLIBRARY=<libwrc.so> -P lua_imports.cmake
execute_process(COMMAND ${NM} -D --undefined-only ${LIBRARY} OUTPUT_VARIABLE imports RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} -D ${LIBRARY} failed (${rc})")
endif()
if(NOT imports MATCHES " lua_newstate(@|\n)")
  message(FATAL_ERROR "${LIBRARY} does not import lua_newstate from a shared liblua (Lua linked in statically?): a "
                      "preloaded probe cannot see the Lua states it makes, so lua_probe proves nothing")
endif()
foreach(f luaL_newstate luaL_openlibs luaopen_io luaopen_os luaopen_package luaopen_debug luaopen_coroutine)
  if(imports MATCHES " ${f}(@|\n)")
    message(FATAL_ERROR "${LIBRARY} imports ${f}: it links more of the Lua binding than the sandbox of profile "
                        "definitions (lua/sandbox, lua/profile_type, lua/convert)")
  endif()
endforeach()
message(STATUS "${LIBRARY}: Lua from a shared liblua, the definition sandbox's functions only")
