// Loading profiles (docs/design.md, section 6): the one entry point every front end calls (load_profile: path
// lookup, reader dispatch, Lua definitions through a loader the caller passes in), what a reader produces
// (RawProfile), the options every reader shares (LoadOptions) and the host's post-processing that turns raw points
// into a validated Profile: units, extent check, mirrors, crop window, shift, then make_profile.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/profile/orientation.hpp"
#include "wrc/profile/profile.hpp"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wrc {

class ReaderRegistry;  // reader.hpp

// Runs the Lua profile definition at `path` (a path to open) with `options` (all the load options) as its `...` and
// returns the profile as the definition made it, in metres; load_profile applies the load options after. The profile
// area knows no Lua: the caller that can run definitions passes one in (the Lua binding and the C API pass the sandbox
// of engine/src/lua/sandbox.hpp, which makes a Lua state only inside the call).
using DefinitionLoader = std::function<Profile(const std::string& path, const OptionTable& options)>;

// Loads a profile, the one way for every front end (wrc.profile.load, wrc_profile_load, a definition loading a
// shipped profile). Reads `options` (read_load_options, messages as "wrc.profile.load"), finds the file
// (resolve_profile_path), then:
// - a Lua definition (is_definition): runs it through `definitions` (nullptr: an error, this caller runs no Lua),
//   with `units` refused (a definition returns metres), then applies the geometric options (transform_profile) and
//   the orientation check;
// - any other file: the reader named by `reader`, else the one claiming the extension, looked up in `readers` (the
//   readers registered from Lua; may be nullptr) before the plugins (load_profile_file, reader.hpp).
// The profile's warnings are the caller's to show. Throws wrc::Error naming the file (and line).
Profile load_profile(const std::string& name, const OptionTable& options, const DefinitionLoader* definitions,
                     const ReaderRegistry* readers = nullptr);

// What a reader hands to the host: points in the engine orientation (left-side frame, z up) but still in
// the file's length unit, with their source lines and what the reader knows and did.
struct RawProfile {
  std::vector<double> y, z;                  // file units
  std::vector<int> lines;                    // source line of each point (0: none)
  std::optional<ProfileKind> kind;           // as the file says it
  std::optional<double> metres_per_unit;     // as the file declares it (nullopt: not declared)
  std::string units_declared_by;             // where the file declares it ("units.len.f = 1000 (line 33)")
  std::string name;                          // empty: the host uses the file's stem
  std::vector<std::string> transforms;       // what the reader applied, in order
  std::vector<std::pair<std::string, std::string>> metadata;
  Reversals reversed;                        // the file's steps that reversed y or z, and how to undo them
};

// Axis-aligned window (metres) of the frame after units and mirrors, before the shift.
struct CropWindow {
  double y_min = -1e300, y_max = 1e300, z_min = -1e300, z_max = 1e300;
};

// Options shared by every reader. Reader-specific options travel as strings in `reader_options`.
struct LoadOptions {
  std::optional<double> metres_per_unit;  // `units`: explicit unit (skips the extent check)
  std::string units_text;                 // how the user wrote it ("mm", "m", "0.0254"), for messages
  bool mirror_y = false;                  // y -> -y
  bool mirror_z = false;                  // z -> -z
  std::optional<CropWindow> crop;         // keep only the points inside (one contiguous run)
  double shift_y = 0, shift_z = 0;        // metres, applied last
  std::optional<ProfileKind> kind;        // when the file does not say (must agree when it does)
  std::optional<std::string> reader;      // reader id; default: chosen by the file's extension
  std::optional<std::string> name;        // overrides the profile's name
  std::optional<double> smooth;           // smoothing spline, smoothing length (m; 0: interpolating; spline.hpp)
  bool polyline = false;                  // smooth = false: a file's points stay a polyline (default: smooth = 0)
  std::vector<std::pair<std::string, std::string>> reader_options;
};

// Reads the options of wrc.profile.load and p:transform: mirror_y, mirror_z (booleans), name, kind, reader
// (strings), units ("mm", "cm", "m", "in" or a number = metres per file unit), shift = {y =, z =} (m),
// crop = {y = {min, max}, z = {min, max}} (m), smooth (m, a smoothing length >= 0). With `geometric_only` (p:transform) reader and units are not
// allowed and the reader is finished; otherwise every other key goes to the reader as text (checked by the host
// against the reader's own options when it reads).
LoadOptions read_load_options(OptionReader& options, bool geometric_only);
// The keys read_load_options reads; a Lua definition must read every other key it is given (engine/src/lua/sandbox.cpp).
const std::vector<std::string>& load_option_keys();

// True when `path` is loaded as a Lua definition: a .lua file not given to a reader (`reader = "<id>"`).
bool is_definition(const std::string& path, const LoadOptions& options);

// What a reader written in a scripting language returns: y, z (arrays, required; NaN kept for the host to report
// with its line), lines (source line per point), kind, units (a name or metres per unit), name, transforms
// (array of strings). Unknown keys are errors.
RawProfile read_raw_profile(OptionReader& result);

// Plausible total chord (sum of the chords between consecutive points) of a profile, metres. Outside this
// range the units are probably wrong (a file in metres read as millimetres, or the reverse).
inline constexpr double kMinPlausibleChord = 0.005;
inline constexpr double kMaxPlausibleChord = 0.500;

// Parses a `units` option: "mm", "cm", "m", "in", or a positive number = metres per file unit.
double parse_units(const std::string& text, const std::string& context);

// Turns raw points into a validated profile: units -> extent check (unless units were given explicitly)
// -> mirror_y -> mirror_z -> crop -> shift -> make_profile -> smooth -> the orientation check (warnings). Every
// step taken is recorded in transforms.
// `source` is the file path used in messages ("file:line: ..."); `reader_id` names the reader.
Profile finish_profile(RawProfile raw, const LoadOptions& options, const std::string& source,
                       const std::string& reader_id);

// The same geometric options (mirror_y, mirror_z, crop, shift, name, kind check, smooth) applied to a profile
// that is already in metres (a Lua definition, p:transform{...}). Returns a new validated profile; a profile's
// spline is mirrored and shifted with it.
Profile transform_profile(const Profile& p, const LoadOptions& options);

// A profile from points a program gives (wrc.profile.points, wrc_profile_from_points): make_profile of them, with
// `smooth` (m, 0 .. 1) its smoothing spline (0: interpolating); without, the polyline through them as given, whose
// scatter is warned of as a loaded file's is (p.warnings; scatter.hpp).
Profile points_profile(ProfileKind kind, std::vector<double> y, std::vector<double> z, std::string name,
                       const std::string& source, std::optional<double> smooth = std::nullopt);
// wrc.profile.points' keys (kind and y, z required; name, smooth) into points_profile; unknown keys are errors.
Profile read_points_profile(OptionReader& r);

// Where a profile name points, one rule for every caller (wrc.profile.load, wrc_profile_load, a definition loading
// another; docs/guide/profiles.md "Where profiles are found"): a relative path whose first name is `profiles`
// ("profiles/60e1.lua") is the shipped profile of that name in paths().profiles -- never a file of the working
// directory, so that a planted ./profiles/60e1.lua cannot replace the shipped rail; any other path (absolute,
// "./profiles/60e1.lua", "measured/w1.whl") is a file, relative to the working directory. Returns the path to open;
// throws wrc::Error when there is no such file (for a shipped name: listing the shipped profiles, and the ./ path of a
// file of the working directory with that name).
std::string resolve_profile_path(const std::string& name);

// True when `path` is a file directly in paths().profiles (a shipped profile), by its canonical path.
bool is_shipped_profile(const std::string& path);

// The file's stem ("MBench_S1002_v3" for ".../MBench_S1002_v3.prw").
std::string file_stem(const std::string& path);
// The extension in lower case with its dot (".prw"), or "" when there is none.
std::string file_extension(const std::string& path);

}  // namespace wrc
