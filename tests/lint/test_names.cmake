# "lint: doctest names CTest can run": CTest registers a doctest case by its name and runs it with
# --test-case=<name>; a ';' in the name is a list separator to CMake, so the registered name is cut there and the
# filter matches no case: the test runs nothing and passes. (Commas are escaped by the discovery.) Fails naming each
# file with such a case.
file(GLOB_RECURSE sources ${ROOT}/tests/*.cpp)
set(bad "")
foreach(f ${sources})
  file(READ ${f} text)
  string(REGEX MATCHALL "TEST_CASE\\(\"[^\"\n]*;[^\"\n]*\"" cut "${text}")
  if(cut)
    string(APPEND bad "\n  ${f}: a TEST_CASE name holds ';'")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "doctest case names CTest cannot select (a ';' cuts the name):${bad}")
endif()
