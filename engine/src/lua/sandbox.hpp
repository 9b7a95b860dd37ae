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
#include "wrc/lua/definitions.hpp"
#include "wrc/profile/profile.hpp"

#include <string>

namespace wrc::lua {

// The sandbox's entry, definition_loader, and its budget, SandboxLimits, are in wrc/lua/definitions.hpp (the C API
// calls them without this binding's headers).

// wrc::load_profile(path, options) with the sandbox of `limits` as its definition loader: for a definition at `path`,
// the profile as wrc.profile.load gives it (the host's load options applied, `units` refused, orientation checked).
// Throws wrc::Error naming the file: an error of the definition with its line, a budget exceeded, a result that is
// not a wrc.Profile.
Profile load_definition(const std::string& path, const OptionTable& options, const SandboxLimits& limits = {});

}  // namespace wrc::lua
