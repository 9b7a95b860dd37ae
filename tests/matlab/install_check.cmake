# docs/matlab.md "Building it", as a user of an installed wrc does it: installs the build into a fresh prefix, copies
# the installed sources (share/wrc/matlab) into a folder of the user's, builds the MEX file there with the page's
# mkoctfile command, and runs the paper's equilibrium through it in Octave and through the installed `wrc run`, both
# from "/": the two must print the same numbers. -DBUILD, -DPREFIX, -DMKOCTFILE, -DOCTAVE, -DPRELOAD (may be empty).
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(user ${PREFIX}/wrc_matlab)
file(COPY ${PREFIX}/share/wrc/matlab/ DESTINATION ${user})
execute_process(COMMAND ${MKOCTFILE} --mex -I${PREFIX}/include wrc_mex.cpp -L${PREFIX}/lib -lwrc -Wl,-rpath,${PREFIX}/lib
                WORKING_DIRECTORY ${user} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mkoctfile --mex against the installed wrc failed:\n${out}\n${err}")
endif()

set(env "")
if(PRELOAD)
  set(env LD_PRELOAD=${PRELOAD} ASAN_OPTIONS=detect_leaks=0)
endif()
set(session "addpath('${user}'); \
w = wrc.profile_load('profiles/s1002.lua'); r = wrc.profile_load('profiles/60e1.lua'); \
ws = wrc.wheelset('wheel', w, 'rail', r, 'gauge', 1.435, 'cant', 0.025, 'radius', 0.45); \
e = wrc.equilibrium(ws, 'y', 3e-3, 'yaw', 0, 'Q', 200e3, 'grids', false); \
printf('Y/Q %.17g z %.17g roll %.17g pmax %.17g\\n', e.Y_Q, e.z, e.roll, e.left.patches(1).pmax);")
execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env}
                        ${OCTAVE} --no-gui --no-window-system --no-history --norc --quiet --eval "${session}"
                WORKING_DIRECTORY / RESULT_VARIABLE rc OUTPUT_VARIABLE octave_out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "octave with the installed MEX file failed (${rc}):\n${octave_out}\n${err}")
endif()

file(WRITE ${PREFIX}/equilibrium.lua [[
local ws = wrc.wheelset{wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua"),
                        gauge = 1.435, cant = 0.025, radius = 0.45}
local e = ws:equilibrium{y = 3e-3, yaw = 0, Q = 200e3, grids = false}
print(("Y/Q %.17g z %.17g roll %.17g pmax %.17g"):format(e.Y_Q, e.z, e.roll, e.left.patches[1].pmax))
]])
execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${PREFIX}/bin/wrc run ${PREFIX}/equilibrium.lua
                WORKING_DIRECTORY / RESULT_VARIABLE rc OUTPUT_VARIABLE lua_out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed wrc run failed (${rc}):\n${err}")
endif()
string(STRIP "${octave_out}" octave_out)
string(STRIP "${lua_out}" lua_out)
if(NOT octave_out STREQUAL lua_out OR octave_out STREQUAL "")
  message(FATAL_ERROR "Octave and Lua differ:\n  octave: ${octave_out}\n  lua:    ${lua_out}")
endif()
message(STATUS "the installed MEX file and wrc run agree: ${octave_out}")
