// Writing a profile in the formats the reader plugins read (docs/guide/profiles.md "Writing profiles"), so that a worn,
// resampled or transformed profile goes back to the tools a user has. Each writer is the inverse of its reader
// (plugins/<format>): the file, read back with the default options (and `kind` for text), gives the same points
// within the written precision (kWrittenDigits decimals of a millimetre); a VAMPIRE rail comes back with its highest
// point as the origin (the format locates a rail in the track, not its origin).
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/profile/profile.hpp"

#include <string>
#include <string_view>

namespace wrc {

// Decimals of the millimetre values written (1e-6 mm = 1 nm).
inline constexpr int kWrittenDigits = 6;

// The file's text, as write_profile writes it. `format` is one of "text", "csv", "simpack", "miniprof", "vampire";
// `options` are the format's own (the keys of write_profile but format). Throws wrc::Error naming `context`.
std::string format_profile(const Profile& profile, const std::string& format, OptionReader& options);

// Writes `profile` to `path` whole or not at all (AtomicFile: a failure leaves no file, or the old one). Options:
// format ("text" | "csv" | "simpack" | "miniprof" | "vampire"; default: from the extension, .txt .dat | .csv |
// .prw .prr | .whl .ban | .whe .rai); tape_offset (m, 0.070: miniprof and vampire wheels, the tape circle from the flange
// back); flange_back (m, 1.360: vampire wheels, the flange backs' distance); gauge (m, 1.435) and gauge_depth (m, 0.014:
// vampire rails, where the rail is put in the track frame). A known extension must be the format's and, for the formats
// with a wheel and a rail extension, the profile's kind. Returns the format written. Throws wrc::Error naming `call`
// and the path (an unknown format or extension lists the known ones).
std::string write_profile(const Profile& profile, const std::string& path, const OptionTable& options,
                          std::string_view call);

}  // namespace wrc
