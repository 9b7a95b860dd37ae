# Self-test of lua_longjmp.cmake on data/bindings.cpp: it must fail and report exactly the unmarked calls
# and stray markers of that file (by line), and accept its two marked calls. Update the lists below when
# data/bindings.cpp changes.
set(expected_violations 8 13 14 15 16 17 40 42)
set(expected_reviewed 21 23)

execute_process(COMMAND ${CMAKE_COMMAND} -DDIR=${CMAKE_CURRENT_LIST_DIR}/data -P ${CMAKE_CURRENT_LIST_DIR}/lua_longjmp.cmake
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "lua_longjmp.cmake passed on data/bindings.cpp, which breaks the rule:\n${all}")
endif()

string(REGEX MATCHALL "bindings\\.cpp:[0-9]+: [^\n]*" found "${all}")
set(violations "")
set(reviewed "")
foreach(f IN LISTS found)
  string(REGEX MATCH "^bindings\\.cpp:([0-9]+): (.*)$" _ "${f}")
  set(line ${CMAKE_MATCH_1})
  set(what "${CMAKE_MATCH_2}")
  if(what MATCHES "marker")
    list(APPEND violations ${line})
  else()
    list(APPEND reviewed ${line})
  endif()
endforeach()
if(NOT violations STREQUAL expected_violations OR NOT reviewed STREQUAL expected_reviewed)
  message(FATAL_ERROR "lua_longjmp.cmake on data/bindings.cpp reported violations on lines '${violations}' "
                      "(expected '${expected_violations}') and reviewed spots on lines '${reviewed}' "
                      "(expected '${expected_reviewed}'):\n${all}")
endif()
message(STATUS "the check reports lines ${violations} and accepts lines ${reviewed} of data/bindings.cpp")
