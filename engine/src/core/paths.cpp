#include "wrc/core/paths.hpp"

#include "wrc/core/config.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace wrc {
namespace {

bool has_library(const fs::path& root) {
  std::error_code ec;
  return fs::is_directory(root / "scripts", ec) && fs::is_directory(root / "profiles", ec);
}

fs::path executable_dir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

Paths resolve() {
  Paths p;
  const fs::path exe_dir = executable_dir();
  fs::path root;
  std::string own_plugins;
  if (const char* home = std::getenv("WRC_HOME"); home && *home && has_library(home)) {
    root = home;
  }
  // Installed: <prefix>/bin/wrc with <prefix>/share/wrc and <prefix>/lib/wrc/plugins.
  if (!exe_dir.empty()) {
    const fs::path prefix = exe_dir.parent_path();
    if (has_library(prefix / WRC_INSTALL_DATADIR)) {
      if (root.empty()) root = prefix / WRC_INSTALL_DATADIR;
      own_plugins = (prefix / WRC_INSTALL_PLUGINDIR).string();
    }
  }
  // Build tree: the sources this binary was built from, plugins in <build>/plugins.
  if (root.empty()) root = WRC_SOURCE_DIR;
  if (own_plugins.empty()) own_plugins = WRC_BUILD_PLUGIN_DIR;

  p.root = root.string();
  p.scripts = (root / "scripts").string();
  p.profiles = (root / "profiles").string();
  p.plugin_dirs.push_back(own_plugins);
  if (const char* extra = std::getenv("WRC_PLUGIN_PATH"); extra && *extra) {
    std::string s = extra;
    std::size_t start = 0;
    while (start <= s.size()) {
      std::size_t end = s.find(':', start);
      if (end == std::string::npos) end = s.size();
      if (end > start) p.plugin_dirs.push_back(s.substr(start, end - start));
      start = end + 1;
    }
  }
  return p;
}

}  // namespace

const Paths& paths() {
  static const Paths p = resolve();
  return p;
}

}  // namespace wrc
