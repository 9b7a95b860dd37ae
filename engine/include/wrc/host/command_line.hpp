// The command line of the wrc executable: the flags of `wrc run` and `wrc merge` (--shard, --merge, --fresh,
// --help), the shard of a SLURM array task, and the refusal of a flag or an option given twice. The Lua host
// (wrc/lua/host.hpp) runs a script with the RunFlags made here; it parses nothing itself.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace wrc::host {

// What `wrc run STUDY.lua ...` is asked besides the study's own key=value options (docs/guide/studies.md).
struct RunFlags {
  int shard = 1, shards = 1;  // compute part `shard` of `shards` (1-based)
  std::string shard_from;     // where the split came from ("--shard 2/4", "SLURM_ARRAY_TASK_ID=2 ..."), "" if none
  bool merge = false;         // --merge: assemble the shards' parts, then figures and summary
  bool fresh = false;         // --fresh: discard earlier parts and start over
  bool help = false;          // --help: list the study's options
  bool from_parts = false;    // `wrc merge STUDY.lua`: a merge with the options the shards ran with (from the parts)
  std::vector<std::string> notes;  // for the user, once, on stderr (e.g. SLURM's array variables overridden by --shard)
};

// Takes the flags --shard K/N (or --shard=K/N), --merge, --fresh and --help out of `args`. Without --shard, inside
// a SLURM array job (SLURM_ARRAY_TASK_ID set), the split comes from SLURM: shard = (ID - MIN) / STEP + 1 of
// SLURM_ARRAY_TASK_COUNT (or (MAX - MIN) / STEP + 1); --shard wins over SLURM (a note says so), and --merge
// ignores SLURM. `env` reads an environment variable (nullptr when unset). Throws wrc::Error naming a malformed
// flag, a key=value word whose key is empty or not a Lua name or whose '=' is doubled ("=3", "y-mm=3", "k==v"), a
// flag or a key=value option given twice, --merge with --shard or --fresh, or an array whose task ids do
// not number the shards (a list with gaps).
RunFlags take_run_flags(std::vector<std::string>& args, const std::function<const char*(const char*)>& env);

// The flags of `wrc merge STUDY.lua [key=value ...]`: merge and from_parts set, --help allowed; --shard, --merge and
// --fresh are errors, and so are a malformed key=value word and a key given twice.
RunFlags take_merge_flags(std::vector<std::string>& args);

}  // namespace wrc::host
