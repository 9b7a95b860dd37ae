// Lua profile definitions for callers without a Lua state (the C API): the one part of the Lua binding that
// libwrc.so links. A Lua state exists only while the loader runs a definition, one sandboxed state per definition
// (engine/src/lua/sandbox.hpp; docs/design.md section 9); loading any other file makes none.
#pragma once

#include "wrc/profile/load.hpp"
#include "wrc/profile/profile.hpp"

#include <cstddef>
#include <cstdint>

namespace wrc::lua {

// The budget of one top-level load of a definition, with everything it loads. The shipped definitions at
// kMaxProfilePoints points need at most 1e8 instructions, 48 MB and 3 M points (worn_s1002 with its S1002): the
// defaults leave ten times, five times and twice that.
struct SandboxLimits {
  std::uint64_t instructions = 1'000'000'000;   // Lua VM instructions
  std::size_t memory = std::size_t{256} << 20;  // bytes of Lua memory held at once
  double points = 6.0 * kMaxProfilePoints;      // profile points made, in all (each profile holds memory in C++)
};

// The loader of .lua definitions that wrc::load_profile calls (profile/load.hpp): each call runs one definition in
// a sandbox of its own, within `limits`.
DefinitionLoader definition_loader(const SandboxLimits& limits = {});

}  // namespace wrc::lua
