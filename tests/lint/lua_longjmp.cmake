# The longjmp rule of the Lua binding layer (engine/src/lua/guard.hpp), checked on the source text.
#
# Debian's Lua is built as C: luaL_error, the luaL_check*/luaL_opt*/luaL_arg* family, luaL_typeerror and
# lua_error longjmp out of the C function and skip the destructors of every C++ object alive in the
# frames they cross. Binding code therefore reports errors by throwing wrc::Error inside `guarded` (the
# check_* helpers of convert.hpp). A direct call is allowed only at a reviewed spot: the line, or a comment
# line just above it, carries the marker `longjmp-safe: <why>` (e.g. guard.hpp's lua_error after its catch
# block, or a function that keeps no C++ object with a destructor alive). A marker with no call on its line
# or the next one is an error too, so the markers stay where the calls are.
#
# Usage: cmake -DDIR=<folder> [-DROOT=<folder the paths are printed relative to>] -P lua_longjmp.cmake
# Fails (non-zero exit) listing every unmarked call and stray marker as `path:line: ...`.
if(NOT DIR OR NOT IS_DIRECTORY "${DIR}")
  message(FATAL_ERROR "lua_longjmp: DIR must name a folder, got '${DIR}'")
endif()
if(NOT ROOT)
  set(ROOT "${DIR}")
endif()
get_filename_component(DIR "${DIR}" ABSOLUTE)
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

file(GLOB_RECURSE files LIST_DIRECTORIES false "${DIR}/*.cpp" "${DIR}/*.hpp" "${DIR}/*.c" "${DIR}/*.h")
list(SORT files)
if(NOT files)
  message(FATAL_ERROR "lua_longjmp: no C/C++ sources under ${DIR}")
endif()

string(ASCII 1 bs)   # stands for a backslash while the text is a CMake list
set(call_re "(^|[^A-Za-z0-9_])(luaL_error|luaL_check[A-Za-z0-9_]*|luaL_opt[A-Za-z0-9_]*|luaL_arg[A-Za-z0-9_]*|luaL_typeerror|lua_error)[ \t]*\\(")
set(marker_re "//[ \t]*longjmp-safe:[ \t]*[^ \t]")
set(char_re "'(${bs}.|[^'${bs}])'")
set(string_re "\"(${bs}.|[^\"${bs}])*\"")
set(block_re "/\\*([^*]|\\*+[^*/])*\\*+/")

set(violations "")
set(reviewed "")
foreach(f IN LISTS files)
  file(RELATIVE_PATH rel "${ROOT}" "${f}")
  file(READ "${f}" text)
  # One list element per line: protect the characters CMake lists treat specially, and start every
  # element with `~` so that empty lines keep their place.
  string(REPLACE "\\" "${bs}" text "${text}")
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<" text "${text}")
  string(REPLACE "]" ">" text "${text}")
  string(REPLACE "\n" ";~" lines "~${text}")

  set(n 0)
  set(in_block FALSE)
  set(pending 0)  # line of a comment-only marker waiting for its call on the next line
  foreach(raw IN LISTS lines)
    math(EXPR n "${n} + 1")
    string(SUBSTRING "${raw}" 1 -1 raw)
    # The code of the line: without character and string literals and comments.
    set(code "${raw}")
    if(in_block)
      string(FIND "${code}" "*/" close)
      if(close EQUAL -1)
        set(code "")
      else()
        math(EXPR close "${close} + 2")
        string(SUBSTRING "${code}" ${close} -1 code)
        set(in_block FALSE)
      endif()
    endif()
    string(REGEX REPLACE "${char_re}" "' '" code "${code}")
    string(REGEX REPLACE "${string_re}" "\"\"" code "${code}")
    string(REGEX REPLACE "${block_re}" " " code "${code}")
    string(REGEX REPLACE "//.*$" "" code "${code}")
    string(FIND "${code}" "/*" open)
    if(NOT open EQUAL -1)
      string(SUBSTRING "${code}" 0 ${open} code)
      set(in_block TRUE)
    endif()
    string(STRIP "${code}" code)

    set(has_marker FALSE)
    if(raw MATCHES "${marker_re}")
      set(has_marker TRUE)
    endif()
    set(call "")
    if(code MATCHES "${call_re}")
      set(call "${CMAKE_MATCH_2}")
    endif()

    if(call)
      if(has_marker OR pending)
        list(APPEND reviewed "${rel}:${n}: ${call}")
      else()
        list(APPEND violations "${rel}:${n}: ${call} without a `longjmp-safe:` marker")
      endif()
      set(pending 0)
    else()
      if(pending)
        list(APPEND violations "${rel}:${pending}: `longjmp-safe:` marker, but line ${n} calls none of the checked functions")
        set(pending 0)
      endif()
      if(has_marker)
        if(code STREQUAL "")
          set(pending ${n})
        else()
          list(APPEND violations "${rel}:${n}: `longjmp-safe:` marker on a line that calls none of the checked functions")
        endif()
      endif()
    endif()
  endforeach()
  if(pending)
    list(APPEND violations "${rel}:${pending}: `longjmp-safe:` marker at the end of the file")
  endif()
endforeach()

list(LENGTH files nfiles)
list(LENGTH reviewed nreviewed)
string(REPLACE ";" "\n  " reviewed_text "${reviewed}")
if(violations)
  list(LENGTH violations nviolations)
  string(REPLACE ";" "\n  " violations_text "${violations}")
  message(FATAL_ERROR
    "${nviolations} unreviewed longjmp(s) in ${DIR}:\n  ${violations_text}\n"
    "luaL_error, luaL_check*, luaL_opt*, luaL_arg*, luaL_typeerror and lua_error longjmp past the destructors "
    "of the C++ objects alive in the function (see engine/src/lua/guard.hpp). Throw wrc::Error inside "
    "`guarded` instead (the check_* helpers of convert.hpp); or, where no C++ object with a destructor is "
    "alive, mark the call with `// longjmp-safe: <why>` on its line or on a comment line just above.\n"
    "Reviewed spots (${nreviewed}):\n  ${reviewed_text}")
endif()
message(STATUS "${nfiles} files, no unreviewed longjmp; ${nreviewed} reviewed spot(s):\n  ${reviewed_text}")
