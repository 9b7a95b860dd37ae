#include "wrc/profile/load.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/files.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/profile/orientation.hpp"
#include "wrc/profile/reader.hpp"
#include "wrc/profile/scatter.hpp"
#include "wrc/profile/spline.hpp"
#include "wrc/profile/units.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <system_error>
#include <utility>

namespace wrc {

namespace {

namespace fs = std::filesystem;

std::string shipped_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(paths().profiles, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) names.push_back(it->path().filename().string());
  std::sort(names.begin(), names.end());
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

}  // namespace

std::string resolve_profile_path(const std::string& name) {
  check_path_text(name, "wrc.profile.load");
  const fs::path p(name);
  std::error_code ec;
  if (p.is_relative() && !p.empty() && *p.begin() == "profiles") {
    const fs::path rest = p.lexically_relative("profiles").lexically_normal();
    const fs::path shipped = fs::path(paths().profiles) / rest;
    if (!rest.empty() && rest != "." && *rest.begin() != ".." && fs::is_regular_file(shipped, ec)) return shipped.string();
    fail("{}: not a shipped profile (a name profiles/NAME means a profile shipped with wrc, in {}: {}); a file of "
         "the working directory is named with a path: ./{}", name, paths().profiles, shipped_names(), name);
  }
  if (!fs::exists(p, ec)) {
    if (p.is_relative())
      fail("{}: no such file (relative to the working directory {})", name, fs::current_path(ec).string());
    fail("{}: no such file", name);
  }
  return name;
}

bool is_shipped_profile(const std::string& path) {
  std::error_code ec;
  const fs::path file = fs::canonical(path, ec);
  if (ec || !fs::is_regular_file(file, ec)) return false;
  const fs::path folder = fs::canonical(paths().profiles, ec);
  return !ec && file.parent_path() == folder;
}

std::string file_stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

double parse_units(const std::string& text, const std::string& context) {
  if (const double named = length_unit(text); named > 0) return named;
  double v = 0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  if (r.ec == std::errc() && r.ptr == end && std::isfinite(v) && v > 0) return v;
  fail("{}: units must be {} or a positive number of metres per file unit, got \"{}\"", context, length_unit_names(),
       text);
}

namespace {

std::string at_line(const std::string& source, int line) {
  return line > 0 ? fmt::format("{}:{}", source, line) : source;
}

double total_chord(const std::vector<double>& y, const std::vector<double>& z) {
  double L = 0;
  for (std::size_t i = 0; i + 1 < y.size(); ++i) L += std::hypot(y[i + 1] - y[i], z[i + 1] - z[i]);
  return L;
}

// The point whose removal shortens the total chord most, and by how much: a point mistyped far from its neighbours
// (a digit or a sign wrong) makes the whole chord implausible, as a wrong unit does, but the rest is plausible.
std::pair<std::size_t, double> farthest_detour(const std::vector<double>& y, const std::vector<double>& z) {
  const auto d = [&](std::size_t a, std::size_t b) { return std::hypot(y[b] - y[a], z[b] - z[a]); };
  const std::size_t n = y.size();
  std::pair<std::size_t, double> best{0, d(0, 1)};
  if (d(n - 2, n - 1) > best.second) best = {n - 1, d(n - 2, n - 1)};
  for (std::size_t i = 1; i + 1 < n; ++i)
    if (const double g = d(i - 1, i) + d(i, i + 1) - d(i - 1, i + 1); g > best.second) best = {i, g};
  return best;
}

// A total chord beyond the plausible one that a single point makes: that point, named with its line.
void refuse_detour(const std::vector<double>& y, const std::vector<double>& z, const std::vector<int>& lines,
                   const std::string& source, double chord) {
  const auto [i, detour] = farthest_detour(y, z);
  const double rest = chord - detour;
  if (!(rest >= kMinPlausibleChord && rest <= kMaxPlausibleChord)) return;
  const std::size_t a = i > 0 ? i - 1 : 1;  // the point before it (after it, for the first)
  fail("{}: the point y = {:.6g}, z = {:.6g} mm (engine frame) lies {:.6g} mm from its neighbour (y = {:.6g}, z = {:.6g} mm{}), far "
       "from the rest of the profile: the total chord is {:.6g} mm with it and a plausible {:.6g} mm without it; a "
       "mistyped point?",
       at_line(source, i < lines.size() ? lines[i] : 0), y[i] * 1e3, z[i] * 1e3, std::hypot(y[i] - y[a], z[i] - z[a]) * 1e3,
       y[a] * 1e3, z[a] * 1e3, a < lines.size() ? fmt::format(", line {}", lines[a]) : std::string(), chord * 1e3,
       rest * 1e3);
}

// The file's steps that reversed y or z (the reader's report), and the options that did.
Reversals reversals(Reversals file, const LoadOptions& o) {
  if (o.mirror_y) file.y.push_back("the option mirror_y = true: drop it if the profile was right without it");
  if (o.mirror_z) file.z.push_back("the option mirror_z = true: drop it if the profile was right without it");
  return file;
}

void apply_mirrors(std::vector<double>& y, std::vector<double>& z, const LoadOptions& o,
                   std::vector<std::string>& transforms) {
  if (o.mirror_y) {
    for (double& v : y) v = -v;
    transforms.push_back("mirror_y (option): y -> -y");
  }
  if (o.mirror_z) {
    for (double& v : z) v = -v;
    transforms.push_back("mirror_z (option): z -> -z");
  }
}

// Keeps the points inside the window; they must form one contiguous run of the profile.
void apply_crop(std::vector<double>& y, std::vector<double>& z, std::vector<int>& lines, const LoadOptions& o,
                const std::string& source, std::vector<std::string>& transforms) {
  if (!o.crop) return;
  const CropWindow& w = *o.crop;
  if (!(w.y_min < w.y_max) || !(w.z_min < w.z_max))
    fail("{}: crop window is empty (y {} .. {}, z {} .. {} m)", source, w.y_min, w.y_max, w.z_min, w.z_max);
  std::size_t first = y.size(), last = 0, runs = 0;
  bool inside_prev = false;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const bool inside = y[i] >= w.y_min && y[i] <= w.y_max && z[i] >= w.z_min && z[i] <= w.z_max;
    if (inside && !inside_prev) ++runs;
    if (inside) {
      first = std::min(first, i);
      last = i;
    }
    inside_prev = inside;
  }
  if (runs == 0) fail("{}: no point lies inside the crop window (y {} .. {}, z {} .. {} m)", source, w.y_min, w.y_max, w.z_min, w.z_max);
  if (runs > 1) {
    // Name the first point that leaves the window between two kept runs.
    std::size_t gap = first;
    while (gap <= last && y[gap] >= w.y_min && y[gap] <= w.y_max && z[gap] >= w.z_min && z[gap] <= w.z_max) ++gap;
    const int line = gap < lines.size() ? lines[gap] : 0;
    fail("{}: the crop window cuts the profile into {} separate pieces (it leaves the window at y = {:.6f}, z = {:.6f} m "
         "and comes back); choose a window that keeps one contiguous part",
         at_line(source, line), runs, y[gap], z[gap]);
  }
  const std::size_t dropped = y.size() - (last - first + 1);
  auto cut = [&](auto& v) { v = std::vector<typename std::decay_t<decltype(v)>::value_type>(v.begin() + first, v.begin() + last + 1); };
  cut(y);
  cut(z);
  if (!lines.empty()) cut(lines);
  transforms.push_back(fmt::format("crop (option): kept y {:.6g} .. {:.6g} m, z {:.6g} .. {:.6g} m ({} points dropped)",
                                   w.y_min, w.y_max, w.z_min, w.z_max, dropped));
}

void apply_shift(std::vector<double>& y, std::vector<double>& z, const LoadOptions& o,
                 std::vector<std::string>& transforms) {
  if (o.shift_y == 0 && o.shift_z == 0) return;
  for (double& v : y) v += o.shift_y;
  for (double& v : z) v += o.shift_z;
  transforms.push_back(fmt::format("shift (option): y += {:.6g} m, z += {:.6g} m", o.shift_y, o.shift_z));
}

}  // namespace

namespace {

// A smoothing length (m) of wrc.profile.load and wrc.profile.points: 0 (the interpolating spline) .. 1.
void check_smoothing_length(double smooth, std::string_view context) {
  if (!(smooth >= 0 && smooth <= 1.0))
    fail("{}: smooth = {} must be a smoothing length in metres, 0 .. 1 (0: interpolating cubic spline)", context,
         smooth);
}

// A reader option as the text the reader receives.
std::string option_text(const std::string& key, const OptionValue& v, const OptionReader& r) {
  switch (v.type) {
    case OptionValue::Type::boolean: return v.boolean ? "true" : "false";
    case OptionValue::Type::number: return number_text(v.number);  // shortest exact representation
    case OptionValue::Type::string: return v.string;
    default: fail("{}: option '{}' must be a string, number or boolean, got {}", r.context(), key, r.type_name(v));
  }
}

CropWindow read_crop(OptionReader& crop) {
  CropWindow w;
  for (const char* axis : {"y", "z"}) {
    const auto v = crop.numbers(axis, {"m", axis[0] == 'y' ? "{min, max} of y: keep the points inside" : "{min, max} of z: keep the points inside"});
    if (!v) continue;
    if (v->size() != 2 || !((*v)[0] < (*v)[1]))
      fail("{}.{} must be {{min, max}} with min < max (metres)", crop.context(), axis);
    (axis[0] == 'y' ? w.y_min : w.z_min) = (*v)[0];
    (axis[0] == 'y' ? w.y_max : w.z_max) = (*v)[1];
  }
  crop.finish();
  return w;
}

}  // namespace

const std::vector<std::string>& load_option_keys() {
  static const std::vector<std::string> keys{"mirror_y", "mirror_z", "name", "kind", "shift", "crop", "smooth",
                                             "reader", "units"};
  return keys;
}

LoadOptions read_load_options(OptionReader& r, bool geometric_only) {
  LoadOptions o;
  o.mirror_y = r.boolean("mirror_y", {"-", "y -> -y (a profile given with the other lateral direction)"}, o.mirror_y);
  o.mirror_z = r.boolean("mirror_z", {"-", "z -> -z (a profile given with the other vertical direction)"}, o.mirror_z);
  o.name = r.string("name", {"-", "the profile's name (default: the file's, or its stem)"});
  if (auto k = r.string("kind", {"-", "wheel or rail, when the file does not say (must agree when it does)"}))
    o.kind = parse_profile_kind(*k, r.context());
  if (auto shift = r.table("shift", {"m", "{y, z} added to every point, after mirrors and crop"})) {
    o.shift_y = shift->number("y", {"m", "lateral shift"}, o.shift_y);
    o.shift_z = shift->number("z", {"m", "vertical shift"}, o.shift_z);
    shift->finish();
    // Named here: past the bound on a point, the shifted points alone would be taken for a wrong unit.
    for (const auto& [axis, v] : {std::pair{"y", o.shift_y}, std::pair{"z", o.shift_z}})
      if (std::abs(v) > kMaxProfileCoordinate)
        fail("{}: shift.{} = {:g} m is out of range: it moves every point that far, and no profile lies more than {:g} m "
             "from the origin (is the shift in metres?)", r.context(), axis, v, kMaxProfileCoordinate);
  }
  if (auto crop = r.table("crop", {"m", "{y = {min, max}, z = {min, max}}: keep only the points inside"}))
    o.crop = read_crop(*crop);
  if (const OptionValue* v = r.value("smooth", "number or false",
                                     {"m", "smoothing length of the spline through the points (0: interpolating, the "
                                           "default for files; false: the polyline)"});
      v && v->type == OptionValue::Type::boolean && !v->boolean)
    o.polyline = true;  // smooth = false: keep the points as a polyline
  else
    o.smooth = r.number("smooth");
  if (o.smooth) check_smoothing_length(*o.smooth, r.context());
  if (geometric_only) {
    r.finish();
    return o;
  }
  o.reader = r.string("reader", {"-", "the reader plugin's id (default: chosen by the file's extension)"});
  if (const OptionValue* u = r.value("units", "string or number",
                                     {"-", "the file's length unit: mm (default), cm, m, in, or metres per file unit"})) {
    if (u->type != OptionValue::Type::number && u->type != OptionValue::Type::string)
      fail("{}: 'units' must be \"mm\", \"cm\", \"m\", \"in\" or a number (metres per file unit), got {}", r.context(),
           r.type_name(*u));
    o.units_text = option_text("units", *u, r);
    o.metres_per_unit = parse_units(o.units_text, r.context());
  }
  for (const auto* e : r.rest()) o.reader_options.emplace_back(e->first, option_text(e->first, e->second, r));
  return o;
}

RawProfile read_raw_profile(OptionReader& r) {
  RawProfile raw;
  auto y = r.numbers("y", false), z = r.numbers("z", false);
  if (!y || !z) fail("{}: the result has no '{}' array", r.context(), y ? "z" : "y");
  raw.y = std::move(*y);
  raw.z = std::move(*z);
  for (double l : r.numbers("lines", false).value_or(std::vector<double>{}))
    raw.lines.push_back(std::isfinite(l) && l > 0 && l < 2e9 ? static_cast<int>(l) : 0);
  if (auto k = r.string("kind")) raw.kind = parse_profile_kind(*k, r.context());
  if (const OptionValue* u = r.value("units", "string or number",
                                     {"-", "the file's length unit: mm (default), cm, m, in, or metres per file unit"})) {
    if (u->type == OptionValue::Type::number) {
      raw.metres_per_unit = u->number;
      raw.units_declared_by = fmt::format("units = {} (reader)", u->number);
    } else if (u->type == OptionValue::Type::string) {
      raw.units_declared_by = fmt::format("units = \"{}\" (reader)", u->string);
      raw.metres_per_unit = parse_units(u->string, r.context());
    } else {
      fail("{}: 'units' must be \"mm\", \"m\" or a number, got {}", r.context(), r.type_name(*u));
    }
  }
  raw.name = r.string("name").value_or("");
  raw.transforms = r.strings("transforms").value_or(std::vector<std::string>{});
  r.finish();
  return raw;
}

// A file's points without `smooth`: the interpolating cubic spline through them (docs/guide/profiles.md, "Profiles
// as smooth curves": on coarse points it follows the true curve where a polyline puts all curvature in its vertices).
// Points that no spline can pass through without folding back stay a polyline, and p.transforms says so.
Profile default_spline(Profile p) {
  try {
    return smooth_profile(p, 0.0);
  } catch (const Error& e) {
    p.transforms.push_back(fmt::format("kept as a polyline: no interpolating spline ({})", e.what()));
    return p;
  }
}

namespace {

// What looks wrong in a loaded profile but is accepted: its orientation, and points scattered as noise when it
// follows them (no smoothing length).
std::vector<std::string> load_warnings(const Profile& p, const Reversals& reversed, const LoadOptions& o) {
  std::vector<std::string> out = orientation_warnings(p, reversed);
  if (!o.smooth)
    if (auto scatter = scatter_warning(p)) out.push_back(std::move(*scatter));
  return out;
}

}  // namespace

Profile points_profile(ProfileKind kind, std::vector<double> y, std::vector<double> z, std::string name,
                       const std::string& source, std::optional<double> smooth) {
  if (smooth) check_smoothing_length(*smooth, source);
  Profile p = make_profile(kind, std::move(y), std::move(z), std::move(name), source);
  if (smooth) return smooth_profile(p, *smooth);
  if (auto scatter = scatter_warning(p, "Make it")) p.warnings.push_back(std::move(*scatter));
  return p;
}

Profile read_points_profile(OptionReader& r) {
  const auto kind_text = r.string("kind", {"", "\"wheel\" or \"rail\" (required)"});
  if (!kind_text) fail("{}: 'kind' is required (\"wheel\" or \"rail\")", r.context());
  const ProfileKind kind = parse_profile_kind(*kind_text, r.context());
  auto y = r.numbers("y", {"m", "lateral coordinates of the points (required)"}).value_or(std::vector<double>{});
  auto z = r.numbers("z", {"m", "vertical coordinates of the points (required)"}).value_or(std::vector<double>{});
  const std::string name = r.string("name", {"", "the profile's name"}).value_or(std::string(to_string(kind)));
  const OptionDoc smooth_doc{"m",
                             "smoothing length of a spline through the points (0: interpolating; none: the "
                             "polyline through them)"};
  const auto smooth = r.number("smooth", smooth_doc);
  r.finish();
  return points_profile(kind, std::move(y), std::move(z), name, r.context(), smooth);
}

Profile finish_profile(RawProfile raw, const LoadOptions& o, const std::string& source, const std::string& reader_id) {
  if (raw.y.size() != raw.z.size()) fail("{}: reader '{}' gave {} y values but {} z values", source, reader_id, raw.y.size(), raw.z.size());
  if (!raw.lines.empty() && raw.lines.size() != raw.y.size())
    fail("{}: reader '{}' gave {} line numbers for {} points", source, reader_id, raw.lines.size(), raw.y.size());
  const std::size_t n = raw.y.size();
  const int last_line = n > 0 && !raw.lines.empty() ? raw.lines.back() : 0;
  if (n == 0) fail("{}: no points (an empty file or a header without data)", source);
  if (n < 3)
    fail("{}: only {} point{} read; a profile needs at least 3", at_line(source, last_line), n, n == 1 ? "" : "s");

  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(raw.y[i]) || !std::isfinite(raw.z[i]))
      fail("{}: coordinate is not a finite number (y = {}, z = {})", at_line(source, raw.lines.empty() ? 0 : raw.lines[i]),
           raw.y[i], raw.z[i]);

  // Kind: the file's word, the option's, and they must agree.
  ProfileKind kind;
  if (raw.kind && o.kind && *raw.kind != *o.kind)
    fail("{}: the file holds a {} profile but the option kind = \"{}\"", source, to_string(*raw.kind), to_string(*o.kind));
  if (raw.kind) kind = *raw.kind;
  else if (o.kind) kind = *o.kind;
  else fail("{}: the file does not say whether it holds a wheel or a rail profile: pass kind = \"wheel\" or \"rail\"", source);

  std::vector<std::string> transforms = std::move(raw.transforms);
  // Units: the user's explicit choice, else the file's declaration, else millimetres.
  double scale = 1e-3;
  std::string unit_note;
  if (o.metres_per_unit) {
    scale = *o.metres_per_unit;
    unit_note = fmt::format("units (option units = {}): x {:.6g} to metres", o.units_text, scale);
    if (raw.metres_per_unit && std::abs(*raw.metres_per_unit - scale) > 1e-12 * scale)
      unit_note += fmt::format(", overriding the file's {} ({})", *raw.metres_per_unit, raw.units_declared_by);
  } else if (raw.metres_per_unit) {
    scale = *raw.metres_per_unit;
    unit_note = fmt::format("units (file: {}): x {:.6g} to metres", raw.units_declared_by, scale);
  } else {
    unit_note = "units: millimetres (default): x 0.001 to metres";
  }
  if (!(scale > 0) || !std::isfinite(scale)) fail("{}: the length unit must be a positive number of metres, got {}", source, scale);
  for (double& v : raw.y) v *= scale;
  for (double& v : raw.z) v *= scale;
  transforms.push_back(std::move(unit_note));

  // Extent check, before anything that depends on the scale (duplicate tolerance, crop window).
  const double chord = total_chord(raw.y, raw.z);
  if (!o.metres_per_unit && !(chord >= kMinPlausibleChord && chord <= kMaxPlausibleChord)) {
    if (chord > kMaxPlausibleChord) refuse_detour(raw.y, raw.z, raw.lines, source, chord);
    const int first_line = raw.lines.empty() ? 0 : *std::min_element(raw.lines.begin(), raw.lines.end());
    const int end_line = raw.lines.empty() ? 0 : *std::max_element(raw.lines.begin(), raw.lines.end());
    fail("{}: the profile's total chord is {:.6g} mm (points of lines {} .. {}), outside the plausible {:.0f} .. {:.0f} mm: "
         "the units are probably wrong (taken as {}); pass units = \"mm\", \"m\" or a factor to say what they are",
         at_line(source, first_line), chord * 1e3, first_line, end_line, kMinPlausibleChord * 1e3,
         kMaxPlausibleChord * 1e3, raw.metres_per_unit ? raw.units_declared_by : std::string("millimetres (default)"));
  }

  apply_mirrors(raw.y, raw.z, o, transforms);
  apply_crop(raw.y, raw.z, raw.lines, o, source, transforms);
  apply_shift(raw.y, raw.z, o, transforms);

  std::string name = o.name ? *o.name : (raw.name.empty() ? file_stem(source) : raw.name);
  Profile p = make_profile(kind, std::move(raw.y), std::move(raw.z), std::move(name), source, raw.lines);
  transforms.insert(transforms.begin(), fmt::format("read by '{}'", reader_id));
  transforms.insert(transforms.end(), p.transforms.begin(), p.transforms.end());
  p.transforms = std::move(transforms);
  p.metadata = std::move(raw.metadata);
  if (o.smooth)
    p = smooth_profile(p, *o.smooth);
  else if (!o.polyline)
    p = default_spline(std::move(p));
  p.warnings = load_warnings(p, reversals(std::move(raw.reversed), o), o);
  return p;
}

namespace {

bool has_geometric_options(const LoadOptions& o) {
  return o.mirror_y || o.mirror_z || o.crop || o.shift_y != 0 || o.shift_z != 0 || o.name || o.kind || o.smooth;
}

// A definition's profile with the host's load options applied and the orientation checked.
Profile finish_definition(Profile made, const LoadOptions& o, const std::string& path) {
  made.source = path;
  if (has_geometric_options(o)) made = transform_profile(made, o);
  made.warnings = load_warnings(made, reversals({}, o), o);
  return made;
}

}  // namespace

bool is_definition(const std::string& path, const LoadOptions& options) {
  return file_extension(path) == ".lua" && !options.reader;
}

Profile load_profile(const std::string& name, const OptionTable& options, const DefinitionLoader* definitions,
                     const ReaderRegistry* readers) {
  const char* ctx = "wrc.profile.load";
  OptionReader r(options, ctx);
  const LoadOptions o = read_load_options(r, false);
  const std::string path = resolve_profile_path(name);
  if (!is_definition(path, o)) {
    if (readers) return load_profile_file(path, o, {readers, &ReaderRegistry::plugins()});
    return load_profile_file(path, o);
  }
  if (!definitions)
    fail("{}: {}: a Lua profile definition, and this program loads no Lua (only files that a reader reads)", ctx, path);
  if (o.metres_per_unit) fail("{}: {}: 'units' does not apply to a Lua definition (it returns metres)", ctx, path);
  return finish_definition((*definitions)(path, options), o, path);
}

Profile transform_profile(const Profile& p, const LoadOptions& o) {
  if (o.kind && *o.kind != p.kind)
    fail("{}: the profile is a {} profile but the option kind = \"{}\"", p.source, to_string(p.kind), to_string(*o.kind));
  std::vector<double> y = p.y, z = p.z;
  std::vector<int> lines;
  std::vector<std::string> transforms;
  apply_mirrors(y, z, o, transforms);
  apply_crop(y, z, lines, o, p.source, transforms);
  apply_shift(y, z, o, transforms);
  if (y.size() < 3) fail("{}: only {} points left after the crop window; a profile needs at least 3", p.source, y.size());
  Profile r = make_profile(p.kind, std::move(y), std::move(z), o.name ? *o.name : p.name, p.source);
  std::vector<std::string> all = p.transforms;
  all.insert(all.end(), transforms.begin(), transforms.end());
  all.insert(all.end(), r.transforms.begin(), r.transforms.end());
  r.transforms = std::move(all);
  r.metadata = p.metadata;
  r.duplicates_dropped += p.duplicates_dropped;
  r.warnings = p.warnings;
  if (p.spline)  // the same smooth curve, mirrored and shifted as the points (a crop keeps the curve)
    r.spline = std::make_shared<const ProfileSpline>(
        mapped_spline(*p.spline, o.mirror_y ? -1.0 : 1.0, o.shift_y, o.mirror_z ? -1.0 : 1.0, o.shift_z));
  if (o.smooth) {
    r = smooth_profile(r, *o.smooth);
    std::erase_if(r.warnings, is_scatter_warning);  // the smoothing removed the scatter
  }
  return r;
}

}  // namespace wrc
