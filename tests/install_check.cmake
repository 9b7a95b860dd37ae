# Installs the build into a fresh prefix and runs the installed wrc from another working directory: the host must
# find its Lua library (require "wrc.strategies.topology"), the profiles and the reader plugins of the prefix.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
file(WRITE ${PREFIX}/check.lua [[
local check = require "wrc.check"
check.ok(wrc.paths.root:find(arg.prefix, 1, true) == 1, "library root inside the prefix: " .. wrc.paths.root)
check.ok(wrc.paths.plugins[1]:find(arg.prefix, 1, true) == 1, "plugin folder inside the prefix")
check.ok(type(require "wrc.strategies.topology") == "table", "strategy module from the prefix")
local ids = {}
for _, r in ipairs(wrc.profile.readers()) do ids[r.id] = true end
check.ok(ids.simpack and ids.miniprof and ids.text, "reader plugins from the prefix")
local w = wrc.profile.load("profiles/s1002.lua", {step = 1e-3})
check.ok(#w == 131, "profile definition from the prefix")
print("installed wrc ok")
]])
execute_process(COMMAND ${PREFIX}/bin/wrc run ${PREFIX}/check.lua prefix=${PREFIX} WORKING_DIRECTORY /
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "installed wrc failed (${rc}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
