// wrc: the command-line host. Parses the command line (command_line.hpp) and hands the script to the Lua host.
#include "wrc/core/build.hpp"
#include "wrc/core/config.hpp"
#include "wrc/host/command_line.hpp"
#include "wrc/host/interrupt.hpp"
#include "wrc/lua/host.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace {

void usage(std::FILE* out) {
  std::fputs(
      "usage: wrc run STUDY.lua [key=value ...] [--shard K/N] [--merge] [--fresh] [--help]\n"
      "       wrc merge STUDY.lua [out=DIR] [key=value ...]\n"
      "       wrc --help | --version\n"
      "\n"
      "Runs a wheel-rail contact study written in Lua. The `wrc` module is preloaded as the global\n"
      "`wrc`; key=value pairs are in the global table `arg` (arg.key, numbers converted), other words\n"
      "in arg[1], arg[2], ...; require \"wrc.x.y\" loads the engine's Lua library (scripts/x/y.lua).\n"
      "\n"
      "A study that declares its options (wrc.study.new) lists them with --help and runs in parts:\n"
      "  --shard K/N   compute part K of N (inside a SLURM array job the part comes from\n"
      "                SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT; --shard wins)\n"
      "  --merge       assemble the parts of all N shards into the outputs\n"
      "  --fresh       discard the parts of an earlier run and start over (a run resumes otherwise)\n"
      "wrc merge STUDY.lua assembles them with the options the shards ran with (read from DIR/parts, where\n"
      "DIR is out=, or the study's default), if the parts came from this script (its content hash).\n"
      "Exit status: 0 done, 1 error, 2 usage, 3 done with failed cases (listed in DIR/failures.csv);\n"
      "interrupted (Ctrl-C, SIGTERM, SIGHUP): 130, 143, 129, the files being written removed.\n"
      "\n"
      "environment: WRC_HOME (folder with scripts/ and profiles/), WRC_PLUGIN_PATH (extra plugin\n"
      "folders, ':'-separated)\n",
      out);
}

}  // namespace

int main(int argc, char** argv) {
  wrc::host::remove_temporaries_when_interrupted();  // first: no thread runs yet
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
    std::printf("wrc %s (build %s, %s)\n", WRC_VERSION, wrc::build_id(), wrc::build_origin());
    return 0;
  }
  if (cmd == "run" || cmd == "merge") {
    if (argc < 3) {
      std::fprintf(stderr, "wrc %s: missing the %s\n", cmd.c_str(),
                   cmd == "run" ? "study script (wrc run STUDY.lua [key=value ...])"
                                : "study script (wrc merge STUDY.lua [out=DIR] [key=value ...])");
      return 2;
    }
    std::vector<std::string> args(argv + 3, argv + argc);
    std::error_code ec;
    if (cmd == "merge" && std::filesystem::is_directory(argv[2], ec)) return wrc::lua::refuse_folder_merge(argv[2]);
    try {
      const auto env = [](const char* name) { return std::getenv(name); };
      const wrc::host::RunFlags flags =
          cmd == "merge" ? wrc::host::take_merge_flags(args) : wrc::host::take_run_flags(args, env);
      for (const std::string& note : flags.notes) std::fprintf(stderr, "wrc: %s\n", note.c_str());
      return wrc::lua::run_file(argv[2], args, flags);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "wrc %s: %s\n", cmd.c_str(), e.what());
      return 2;
    }
  }
  std::fprintf(stderr, "wrc: unknown command '%s'\n", cmd.c_str());
  usage(stderr);
  return 2;
}
