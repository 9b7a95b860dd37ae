# Self-test of approx.cmake on data/approx_sample.cpp: it must fail and report exactly the two unscaled, unmarked
# Approx lines of that file. Update the list below when data/approx_sample.cpp changes.
set(expected 5 8)
execute_process(COMMAND ${CMAKE_COMMAND} -DDIR=${CMAKE_CURRENT_LIST_DIR}/data -P ${CMAKE_CURRENT_LIST_DIR}/approx.cmake
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "approx.cmake passed on data/approx_sample.cpp, which breaks the rule:\n${all}")
endif()
string(REGEX MATCHALL "approx_sample\\.cpp:[0-9]+:" found "${all}")
set(lines "")
foreach(f IN LISTS found)
  string(REGEX MATCH "([0-9]+):$" _ "${f}")
  list(APPEND lines ${CMAKE_MATCH_1})
endforeach()
if(NOT lines STREQUAL expected)
  message(FATAL_ERROR "approx.cmake on data/approx_sample.cpp reported lines '${lines}' (expected '${expected}'):\n${all}")
endif()
message(STATUS "the check reports lines ${lines} of data/approx_sample.cpp")
