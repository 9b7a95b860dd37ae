# This build's identity, written as C++ (wrc/core/build.hpp), run at every build (cmake -P):
#   build_id:     12 hex digits of a SHA-256 over the sources that make wrc's results (engine, Lua library, plugins,
#                 shipped profiles, CMake files: each file's path and content) and the compiler settings (CONFIG_FILE).
#                 The same sources built alike give the same id; any changed byte of them, another id. A study records
#                 it among its identity lines, so that it does not resume another build's parts (scripts/study).
#   build_origin: for people: "git <commit>" (the last commit that changed those sources), ", modified" when the
#                 working tree changes them; "git commit unknown" when SOURCE_DIR is not a git checkout, or git
#                 is missing (GIT empty) or fails.
# Inputs (-D): SOURCE_DIR, OUTPUT (the .cpp to write; rewritten only when it changes, so that an unchanged build
# recompiles nothing), CONFIG_FILE (the compiler settings, written at configure time), GIT (git's path, may be empty).
set(paths engine scripts plugins profiles cmake CMakeLists.txt)
set(listing "")
foreach(p IN LISTS paths)
  if(IS_DIRECTORY "${SOURCE_DIR}/${p}")
    file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${p}/*")
  elseif(EXISTS "${SOURCE_DIR}/${p}")
    set(files "${p}")
  else()
    set(files "")
  endif()
  list(SORT files)
  foreach(f IN LISTS files)
    file(SHA256 "${SOURCE_DIR}/${f}" h)
    string(APPEND listing "${f} ${h}\n")
  endforeach()
endforeach()
file(READ "${CONFIG_FILE}" config)
string(SHA256 id "${listing}${config}")
string(SUBSTRING "${id}" 0 12 id)

set(origin "git commit unknown")
if(GIT AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" log -1 --format=%h -- ${paths}
                  OUTPUT_VARIABLE commit RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT failed AND commit MATCHES "^[0-9a-f]+$")
    execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" status --porcelain -- ${paths}
                    OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
    set(origin "git ${commit}")
    if(failed OR NOT changes STREQUAL "")
      string(APPEND origin ", modified")
    endif()
  endif()
endif()

file(WRITE "${OUTPUT}.tmp" "// Written at build time by cmake/WrcBuildId.cmake: this build's identity.
#include \"wrc/core/build.hpp\"

namespace wrc {
const char* build_id() { return \"${id}\"; }
const char* build_origin() { return \"${origin}\"; }
}  // namespace wrc
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
