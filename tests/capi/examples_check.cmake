# Installs the build into a fresh prefix, builds examples/c against it twice (CMake's find_package(wrc) and
# pkg-config's wrc.pc), runs the C program, the Python example (ctypes, standard library only) and the same
# equilibrium through the installed `wrc run`, all from "/", and requires the outputs to be identical; with the Python
# package built, its example too (installed into the prefix's site-packages, finding its profiles from there).
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(flags "")
set(env "")
if(SANITIZE)
  set(flags "-fsanitize=address,undefined")
  # Python is not built with the sanitizers: their runtimes must be loaded first, with libstdc++ (ASan intercepts
  # __cxa_throw and finds the real one only in a library loaded at start).
  foreach(lib libasan.so libubsan.so libstdc++.so)
    execute_process(COMMAND ${CC} -print-file-name=${lib} OUTPUT_VARIABLE path OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(APPEND preload ${path})
  endforeach()
  string(REPLACE ";" ":" preload "${preload}")
  set(env LD_PRELOAD=${preload} ASAN_OPTIONS=detect_leaks=0)
endif()

# 1. CMake package.
set(cbuild ${PREFIX}/build-c)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/examples/c -B ${cbuild} -DCMAKE_PREFIX_PATH=${PREFIX}
                        -DCMAKE_C_FLAGS=${flags} -DCMAKE_EXE_LINKER_FLAGS=${flags}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${cbuild} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "examples/c with find_package(wrc) failed:\n${out}\n${err}")
endif()

# 1b. The hunting wheelset (examples/mbs) with CMake's package too, run from "/" with the rigid table (a fraction of a
# second): it must find the installed profiles and print both critical speeds.
set(mbuild ${PREFIX}/build-mbs)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/examples/mbs -B ${mbuild} -DCMAKE_PREFIX_PATH=${PREFIX}
                        -DCMAKE_C_FLAGS=${flags} -DCMAKE_EXE_LINKER_FLAGS=${flags}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${mbuild} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
if(rc EQUAL 0)
  execute_process(COMMAND ${mbuild}/hunting contact=table bisections=2 WORKING_DIRECTORY / RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
if(NOT rc EQUAL 0 OR NOT out MATCHES "critical speed: linear [0-9.]+ m/s.*simulated [0-9.]+ m/s")
  message(FATAL_ERROR "examples/mbs with find_package(wrc) failed (${rc}):\n${out}\n${err}")
endif()

# 2. pkg-config.
execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${PREFIX}/lib/pkgconfig pkg-config --cflags --libs wrc
                OUTPUT_VARIABLE pc OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config does not find wrc.pc in ${PREFIX}/lib/pkgconfig")
endif()
separate_arguments(pc UNIX_COMMAND "${pc}")
separate_arguments(sflags UNIX_COMMAND "${flags}")
execute_process(COMMAND ${CC} ${sflags} ${SOURCE}/examples/c/paper_equilibrium.c ${pc} -lm -o ${PREFIX}/paper_equilibrium_pc
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "examples/c with pkg-config failed:\n${err}")
endif()

# 3. Run the C programs, the Python example and the Lua equivalent from "/".
file(WRITE ${PREFIX}/paper_equilibrium.lua [[
local ws = wrc.wheelset{wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua"),
                        gauge = 1.435, cant = 0.025, radius = 0.45}
local e = ws:equilibrium{y = 3e-3, yaw = 0, Q = 200e3, grids = false}
print(("wrc %s, equilibrium at y = 3 mm, Q = 200 kN"):format(wrc.version))
print(("Y/Q = %.6f\nz = %.6f mm\nroll = %.6f mrad"):format(e.Y_Q, e.z * 1e3, e.roll * 1e3))
for _, side in ipairs{"left", "right"} do
  for i, p in ipairs(e[side].patches) do
    print(("%s patch %d: N = %.3f kN, contact angle %.3f deg, area %.2f mm2, pmax %.1f MPa"):format(
      side, i, p.normal_force / 1e3, math.deg(p.angle), p.area * 1e6, p.pmax / 1e6))
  end
end
]])
set(runs "c-cmake" "c-pkgconfig" "python" "lua")
# The Python package, installed into the prefix's site-packages, when the build made it.
if(PACKAGE_PYTHON)
  list(APPEND runs "package")
  set(cmd_package ${CMAKE_COMMAND} -E env ${env} PYTHONPATH=${PREFIX}/${PACKAGE_SITE} ${PACKAGE_PYTHON}
      ${SOURCE}/examples/python/paper_equilibrium_package.py)
endif()
set(cmd_c-cmake ${cbuild}/paper_equilibrium)
set(cmd_c-pkgconfig ${PREFIX}/paper_equilibrium_pc)
set(cmd_python ${CMAKE_COMMAND} -E env ${env} WRC_LIBRARY=${PREFIX}/lib/libwrc.so.0 ${PYTHON}
    ${SOURCE}/examples/python/paper_equilibrium.py)
set(cmd_lua ${PREFIX}/bin/wrc run ${PREFIX}/paper_equilibrium.lua)
foreach(run ${runs})
  execute_process(COMMAND ${cmd_${run}} WORKING_DIRECTORY / RESULT_VARIABLE rc OUTPUT_VARIABLE out_${run} ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run} example failed (${rc}):\n${out_${run}}\n${err}")
  endif()
  if(NOT out_${run} MATCHES "left patch 1: N = [0-9.]+ kN")
    message(FATAL_ERROR "${run} example printed no left patch:\n${out_${run}}")
  endif()
  if(NOT out_${run} STREQUAL out_lua AND NOT run STREQUAL "lua" AND DEFINED out_lua)
    message(FATAL_ERROR "${run} differs from lua")
  endif()
endforeach()
foreach(run ${runs})
  if(NOT out_${run} STREQUAL out_lua)
    message(FATAL_ERROR "the ${run} example printed\n${out_${run}}\nthe Lua API printed\n${out_lua}")
  endif()
endforeach()
message(STATUS "C, Python and Lua agree:\n${out_lua}")

# The installed package reads the profiles of its own prefix (found from the module's folder, four levels up), not
# those of the source tree it was built from.
if(PACKAGE_PYTHON)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} PYTHONPATH=${PREFIX}/${PACKAGE_SITE} ${PACKAGE_PYTHON} -c
                          "import wrc; print(wrc.profile.load('profiles/s1002.lua').source)"
                  WORKING_DIRECTORY / RESULT_VARIABLE rc OUTPUT_VARIABLE source ERROR_VARIABLE err
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0 OR NOT source MATCHES "^${PREFIX}/share/wrc/profiles/s1002.lua$")
    message(FATAL_ERROR "the installed package read profiles/s1002.lua from '${source}', not from ${PREFIX}:\n${err}")
  endif()
endif()
