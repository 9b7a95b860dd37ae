// The Lua host: runs study scripts with the `wrc` module preloaded. This header is the only view the
// rest of the program has of Lua; lua.h is included by engine/src/lua alone.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/profile/profile.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc::lua {

// What `wrc run STUDY.lua ...` is asked besides the study's own key=value options (docs/guide/studies.md).
struct RunFlags {
  int shard = 1, shards = 1;  // compute part `shard` of `shards` (1-based)
  std::string shard_from;     // where the split came from ("--shard 2/4", "SLURM_ARRAY_TASK_ID=2 ..."), "" if none
  bool merge = false;         // --merge: assemble the shards' parts, then figures and summary
  bool fresh = false;         // --fresh: discard earlier parts and start over
  bool help = false;          // --help: list the study's options
  bool from_parts = false;    // `wrc merge STUDY.lua`: a merge with the options the shards ran with (from the parts)
  std::vector<std::string> notes;  // said once on stderr (e.g. SLURM's array variables overridden by --shard)
};

// Takes the flags --shard K/N (or --shard=K/N), --merge, --fresh and --help out of `args`. Without --shard, inside
// a SLURM array job (SLURM_ARRAY_TASK_ID set), the split comes from SLURM: shard = (ID - MIN) / STEP + 1 of
// SLURM_ARRAY_TASK_COUNT (or (MAX - MIN) / STEP + 1); --shard wins over SLURM (a note says so), and --merge
// ignores SLURM. `env` reads an environment variable (nullptr when unset). Throws wrc::Error naming a malformed
// flag, a flag or a key=value option given twice, --merge with --shard or --fresh, or an array whose task ids do
// not number the shards (a list with gaps).
RunFlags take_run_flags(std::vector<std::string>& args, const std::function<const char*(const char*)>& env);

// The flags of `wrc merge STUDY.lua [key=value ...]`: merge and from_parts set, --help allowed; --shard, --merge and
// --fresh are errors, and so is a key given twice.
RunFlags take_merge_flags(std::vector<std::string>& args);

// Runs a study script. `args` are the command-line words after the script: `key=value` pairs land in
// the global table `arg` as arg.key (numbers converted), other words as arg[1], arg[2], ...; arg[0] is
// the script path. The flags are in the table `wrc.command` (script, shard, shards, shard_from, merge, fresh,
// help), which the study library reads. Errors (missing file, syntax, runtime) are printed to stderr as
// `file:line: message` with a traceback. Returns the process exit code: 0 on success, 1 on an error, or
// what the script left in wrc.command.status (3: a study completed with failed cases); an error object
// {exit = code} (the study library's --help) ends the script quietly with that code. A script that runs no
// study through wrc.study (wrc.command.study unset) ran whole: with --shard or --merge that is exit code 2, with a
// message.
int run_file(const std::string& path, const std::vector<std::string>& args, const RunFlags& flags = {});

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
