# doctest's Approx(x) passes when |a - x| < epsilon * (scale + max(|a|, |x|)), scale = 1 by default: an absolute
# floor of epsilon in the quantity's own unit, so for metres, radians, creepages or compliances it accepts almost
# anything, even 0. In the tests, compare with tests/approx.hpp (within_rel, within_abs) instead. A line that
# still uses Approx( must set the floor itself with .scale( on that line, or say why the default is meant with the
# marker `// approx: unit scale` (the quantity is of order 1). Comment-only lines are not checked.
#
# Usage: cmake -DDIR=<folder> [-DROOT=<paths printed relative to>] [-DEXCLUDE=<regex of paths to skip>] -P approx.cmake
# Fails (non-zero exit) listing every such line as `path:line: ...`.
if(NOT DIR OR NOT IS_DIRECTORY "${DIR}")
  message(FATAL_ERROR "approx: DIR must name a folder, got '${DIR}'")
endif()
if(NOT ROOT)
  set(ROOT "${DIR}")
endif()
get_filename_component(DIR "${DIR}" ABSOLUTE)
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

file(GLOB_RECURSE files LIST_DIRECTORIES false "${DIR}/*.cpp" "${DIR}/*.hpp" "${DIR}/*.h")
if(EXCLUDE)
  list(FILTER files EXCLUDE REGEX "${EXCLUDE}")
endif()
list(SORT files)
if(NOT files)
  message(FATAL_ERROR "approx: no C++ sources under ${DIR}")
endif()

set(bad "")
foreach(f IN LISTS files)
  file(RELATIVE_PATH rel "${ROOT}" "${f}")
  file(READ "${f}" text)
  if(NOT text MATCHES "Approx")
    continue()
  endif()
  # One list element per line (the characters CMake lists treat specially replaced; `~` keeps empty lines).
  string(REPLACE "\\" "/" text "${text}")
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "[" "<" text "${text}")
  string(REPLACE "]" ">" text "${text}")
  string(REPLACE "\n" ";~" lines "~${text}")
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    if(line MATCHES "(^|[^A-Za-z0-9_])Approx[ \t]*\\(" AND NOT line MATCHES "^~[ \t]*//"
       AND NOT line MATCHES "\\.scale[ \t]*\\(" AND NOT line MATCHES "//[ \t]*approx: unit scale")
      string(APPEND bad "\n${rel}:${n}: Approx( with no .scale( and no `// approx: unit scale` marker")
    endif()
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "doctest Approx with its default absolute floor (epsilon x 1 in the quantity's unit): use "
                      "tests/approx.hpp (within_rel, within_abs), set .scale(, or mark an order-1 quantity with "
                      "`// approx: unit scale`:${bad}")
endif()
