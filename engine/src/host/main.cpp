// wrc: the command-line host. Parses the command line and hands the script to the Lua host.
#include "wrc/core/config.hpp"
#include "wrc/lua/host.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

void usage(std::FILE* out) {
  std::fputs(
      "usage: wrc run STUDY.lua [key=value ...]\n"
      "       wrc --help | --version\n"
      "\n"
      "Runs a wheel-rail contact study written in Lua. The `wrc` module is preloaded as the global\n"
      "`wrc`; key=value pairs are in the global table `arg` (arg.key, numbers converted), other words\n"
      "in arg[1], arg[2], ...; require \"wrc.x.y\" loads the engine's Lua library (scripts/x/y.lua).\n"
      "\n"
      "environment: WRC_HOME (folder with scripts/ and profiles/), WRC_PLUGIN_PATH (extra plugin\n"
      "folders, ':'-separated)\n",
      out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    usage(stdout);
    return 0;
  }
  if (cmd == "--version") {
    std::printf("wrc %s\n", WRC_VERSION);
    return 0;
  }
  if (cmd == "run") {
    if (argc < 3) {
      std::fputs("wrc run: missing the study script (wrc run STUDY.lua [key=value ...])\n", stderr);
      return 2;
    }
    std::vector<std::string> args(argv + 3, argv + argc);
    return wrc::lua::run_file(argv[2], args);
  }
  std::fprintf(stderr, "wrc: unknown command '%s'\n", cmd.c_str());
  usage(stderr);
  return 2;
}
