// The Lua host: runs study scripts with the `wrc` module preloaded. This header is the only view the
// rest of the program has of Lua; lua.h is included by engine/src/lua alone.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/profile/profile.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc::lua {

// Runs a study script. `args` are the command-line words after the script: `key=value` pairs land in
// the global table `arg` as arg.key (numbers converted), other words as arg[1], arg[2], ...; arg[0] is
// the script path. Errors (missing file, syntax, runtime) are printed to stderr as `file:line: message`
// with a traceback. Returns the process exit code (0 on success).
int run_file(const std::string& path, const std::vector<std::string>& args);

// Loads a profile as wrc.profile.load(path, options) does -- a Lua definition or a file through the readers -- in a
// Lua state of its own, closed before returning (for callers without a Lua state: the C API). Throws wrc::Error.
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
