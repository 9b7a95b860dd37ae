// Profile definitions are data, not code (docs/design.md section 9): a Lua definition, wherever it comes from (a
// study, the C API, a folder of wheels), runs in a Lua state of its own that cannot reach the system, within a
// budget of instructions, memory and profile points shared with the definitions it loads.
//
// What a definition sees: `...` (its options), the base functions that compute (assert, error, ipairs, pairs, next,
// select, type, tostring, tonumber, pcall, xpcall, rawequal, rawget, rawset, rawlen, getmetatable, setmetatable,
// load of text chunks only), math, string (without string.dump), table, and wrc.profile.points,
// wrc.profile.max_points and wrc.profile.load -- the last for the shipped profiles only ("profiles/NAME"). Not there:
// os, io, package, require, dofile, loadfile, debug, collectgarbage, print, coroutine, binary chunks; naming one of
// them is an error that says so.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/profile.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace wrc::lua {

// The budget of one wrc.profile.load of a definition, with everything it loads. The shipped definitions at
// kMaxProfilePoints points need at most 1e8 instructions, 48 MB and 3 M points (worn_s1002 with its S1002): the
// defaults leave ten times, five times and twice that.
struct SandboxLimits {
  std::uint64_t instructions = 1'000'000'000;   // Lua VM instructions
  std::size_t memory = std::size_t{256} << 20;  // bytes of Lua memory held at once
  double points = 6.0 * kMaxProfilePoints;      // profile points made, in all (each profile holds memory in C++)
};

// True when `path` is loaded as a Lua definition: a .lua file not given to a reader (`reader = "<id>"`).
bool is_definition(const std::string& path, const LoadOptions& options);

// Runs the definition at `path` (a path to open: resolve_profile_path's) in a sandbox with `options` as its `...`,
// then applies the load options that are the host's (mirror_y, mirror_z, crop, shift, name, kind, smooth; `units` is
// refused: a definition returns metres) and the orientation check (warnings). Throws wrc::Error naming the file: an
// error of the definition with its line, a budget exceeded, a result that is not a wrc.Profile.
Profile load_definition(const std::string& path, const OptionTable& options, const SandboxLimits& limits = {});

}  // namespace wrc::lua
