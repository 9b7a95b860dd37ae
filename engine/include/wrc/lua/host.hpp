// The Lua host: runs study scripts with the `wrc` module preloaded. This header is the only view the
// rest of the program has of Lua; lua.h is included by engine/src/lua alone.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/host/command_line.hpp"
#include "wrc/profile/profile.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc::lua {

// Runs a study script. `args` are the command-line words after the script: `key=value` pairs land in
// the global table `arg` as arg.key (numbers converted), other words as arg[1], arg[2], ...; arg[0] is
// the script path. The flags are in the table `wrc.command` (script, shard, shards, shard_from, merge, fresh,
// help), which the study library reads. Errors (missing file, syntax, runtime) are printed to stderr as
// `file:line: message` with a traceback. Returns the process exit code: 0 on success, 1 on an error, or
// what the script left in wrc.command.status (3: a study completed with failed cases); an error object
// {exit = code} (the study library's --help) ends the script quietly with that code. A script that runs no
// study through wrc.study (wrc.command.study unset) ran whole: with --shard or --merge that is exit code 2, with a
// message.
int run_file(const std::string& path, const std::vector<std::string>& args, const host::RunFlags& flags = {});

// `wrc merge DIR`, the form before wrc named the study: runs nothing (a folder from someone else could name any
// script in its parts), says which script and options the parts in DIR came from, with that script's hash, and
// the command that merges them with it. Returns 2.
int refuse_folder_merge(const std::string& folder);

// Loads a profile as wrc.profile.load(path, options) does, without readers registered from Lua: wrc::load_profile
// (profile/load.hpp) with the sandbox as its definition loader, the warnings printed on stderr (for C++ callers
// without a Lua state: tests, benchmarks; the C API calls wrc::load_profile itself). Throws wrc::Error.
std::shared_ptr<const Profile> load_profile(const std::string& path, const OptionTable& options);

// An interpreter with the standard libraries and the `wrc` module loaded, for embedding and tests.
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Runs a chunk under a traceback handler. Returns the error message (with traceback), or nothing.
  std::optional<std::string> run(std::string_view code, const std::string& chunkname = "=(session)");

  // The underlying lua_State*, for code inside the binding layer and its tests.
  void* state() const { return state_; }

 private:
  void* state_;
};

}  // namespace wrc::lua
