# A reader plugin built out of tree against an installed wrc alone, twice: with CMake (find_package(wrc) ->
# wrc::reader) and with pkg-config (--cflags wrc); neither links libwrc. Each is loaded by the installed wrc through
# WRC_PLUGIN_PATH and reads a file (plugin_check.lua).
#   cmake -DBUILD=<build> -DSOURCE=<source> -DPREFIX=<fresh prefix> -DCC=<cc> -DOBJDUMP=<objdump> -P plugin_check.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(plugin_source ${SOURCE}/tests/out_of_tree/reader_plugin)

# 1. CMake package: the prefix alone (no package registry), and the include path must be the prefix's.
set(cbuild ${PREFIX}/build-plugin)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${plugin_source} -B ${cbuild} -DCMAKE_PREFIX_PATH=${PREFIX}
                        -DCMAKE_C_COMPILER=${CC} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
                        -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${cbuild} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the reader plugin with find_package(wrc) failed:\n${out}\n${err}")
endif()
file(READ ${cbuild}/compile_commands.json commands)
if(NOT commands MATCHES "${PREFIX}/include")
  message(FATAL_ERROR "the reader plugin was not compiled with the prefix's include folder:\n${commands}")
endif()

# 2. pkg-config, --cflags only.
execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${PREFIX}/lib/pkgconfig pkg-config --cflags wrc
                OUTPUT_VARIABLE cflags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config does not find wrc.pc in ${PREFIX}/lib/pkgconfig")
endif()
separate_arguments(cflags UNIX_COMMAND "${cflags}")
file(MAKE_DIRECTORY ${PREFIX}/plugin-pc)
execute_process(COMMAND ${CC} -shared -fPIC -fvisibility=hidden ${cflags} ${plugin_source}/station_reader.c
                        -o ${PREFIX}/plugin-pc/wrc_reader_station.so
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the reader plugin with pkg-config --cflags wrc failed:\n${err}")
endif()

# 3. Each plugin needs no wrc library and reads through the installed wrc, run from "/".
foreach(dir ${cbuild}/plugins ${PREFIX}/plugin-pc)
  execute_process(COMMAND ${OBJDUMP} -p ${dir}/wrc_reader_station.so OUTPUT_VARIABLE headers RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR headers MATCHES "NEEDED +libwrc")
    message(FATAL_ERROR "${dir}/wrc_reader_station.so links libwrc (or objdump failed, ${rc}):\n${headers}")
  endif()
  file(MAKE_DIRECTORY ${PREFIX}/tmp)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env WRC_PLUGIN_PATH=${dir} ${PREFIX}/bin/wrc run
                          ${SOURCE}/tests/out_of_tree/plugin_check.lua tmp=${PREFIX}/tmp plugins=${dir}
                  WORKING_DIRECTORY / RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the installed wrc with the plugin of ${dir} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endforeach()
