#include "wrc/core/paths.hpp"

#include "wrc/core/config.hpp"

#include <dlfcn.h>

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

// The folder of the binary holding this code: the wrc executable, or libwrc.so loaded by another program (a C
// program, Python's ctypes), whose own executable says nothing of where wrc is installed.
fs::path module_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&module_dir), &info) == 0 || !info.dli_fname) return {};
  std::error_code ec;
  const fs::path p = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path() : p.parent_path();
}

// The install prefix `dir` itself or 1 to 4 levels above it (<prefix>/bin, <prefix>/lib, <prefix>/lib/<multiarch>,
// the Python module in <prefix>/lib/pythonX.Y/site-packages/wrc, or a Python wheel's package folder that carries
// its own share/wrc and lib/wrc/plugins), or empty.
fs::path install_prefix(const fs::path& dir) {
  fs::path p = dir;
  for (int up = 0; up <= 4 && !p.empty(); ++up) {
    if (up > 0) {
      if (p == p.parent_path()) break;
      p = p.parent_path();
    }
    if (has_library(p / WRC_INSTALL_DATADIR)) return p;
  }
  return {};
}

Paths resolve() {
  Paths p;
  const fs::path exe_dir = executable_dir();
  fs::path root;
  std::string own_plugins;
  if (const char* home = std::getenv("WRC_HOME"); home && *home && has_library(home)) {
    root = home;
  }
  // Installed: <prefix>/bin/wrc or <prefix>/lib/libwrc.so with <prefix>/share/wrc and <prefix>/lib/wrc/plugins.
  for (const fs::path& dir : {exe_dir, module_dir()}) {
    if (dir.empty() || !own_plugins.empty()) continue;
    const fs::path prefix = install_prefix(dir);
    if (prefix.empty()) continue;
    if (root.empty()) root = prefix / WRC_INSTALL_DATADIR;
    own_plugins = (prefix / WRC_INSTALL_PLUGINDIR).string();
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
