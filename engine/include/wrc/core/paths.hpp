// Where wrc finds its Lua library (scripts/), profile definitions (profiles/) and reader plugins,
// both from the build tree and from an install prefix.
#pragma once

#include <string>
#include <vector>

namespace wrc {

struct Paths {
  std::string root;                       // folder holding scripts/ and profiles/
  std::string scripts;                    // root/scripts
  std::string profiles;                   // root/profiles
  std::vector<std::string> plugin_dirs;   // own plugin folder first, then WRC_PLUGIN_PATH entries
};

// Resolves the paths once per process. Order: $WRC_HOME (a root with scripts/ and profiles/),
// then the install prefix above the running executable (<prefix>/bin/wrc -> <prefix>/share/wrc) or above the
// library holding the engine (<prefix>/lib/libwrc.so, for C and Python callers), then the source tree this binary
// was built from.
const Paths& paths();

}  // namespace wrc
