// Profile writers (write.hpp): one function per format, each the inverse of its reader plugin's conversion to the
// engine frame (the plugin's top comment states it).
#include "wrc/profile/write.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/files.hpp"
#include "wrc/profile/load.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace wrc {
namespace {

struct Format {
  const char* id;
  const char* wheel_ext;  // the extension of a wheel file ("" when the format has one for both kinds)
  const char* rail_ext;
  std::array<const char*, 2> any_ext;  // extensions for either kind
};

constexpr std::array<Format, 5> kFormats = {{{"text", "", "", {".txt", ".dat"}},
                                             {"csv", "", "", {".csv", nullptr}},
                                             {"simpack", ".prw", ".prr", {nullptr, nullptr}},
                                             {"miniprof", ".whl", ".ban", {nullptr, nullptr}},
                                             {"vampire", ".whe", ".rai", {nullptr, nullptr}}}};

std::string format_list() {
  std::string s;
  for (const Format& f : kFormats) {
    s += fmt::format("{}{} (", s.empty() ? "" : ", ", f.id);
    std::string exts;
    for (const char* e : {f.wheel_ext, f.rail_ext, f.any_ext[0], f.any_ext[1]})
      if (e && *e) exts += fmt::format("{}{}", exts.empty() ? "" : " ", e);
    s += exts + ")";
  }
  return s;
}

const Format* find_format(std::string_view id) {
  for (const Format& f : kFormats)
    if (id == f.id) return &f;
  return nullptr;
}

bool claims(const Format& f, std::string_view ext) {
  return ext == f.wheel_ext || ext == f.rail_ext || (f.any_ext[0] && ext == f.any_ext[0]) || (f.any_ext[1] && ext == f.any_ext[1]);
}

const Format* format_of_extension(std::string_view ext) {
  if (ext.empty()) return nullptr;
  for (const Format& f : kFormats)
    if (claims(f, ext)) return &f;
  return nullptr;
}

// Text for a header line or comment: control characters (a line break in a name) become blanks.
std::string one_line(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return r;
}

std::string mm(double metres) { return fmt::format("{:.{}f}", metres * 1e3, kWrittenDigits); }

std::string about(const Profile& p) {
  return one_line(fmt::format("wrc profile '{}' ({}, {} points) from {}", p.name, to_string(p.kind), p.size(), p.source));
}

// Text and CSV: the engine frame in mm, a header naming the unit (plugins/text).
std::string write_text(const Profile& p, char sep) {
  std::string s = fmt::format("# {}\n# left-side frame, y toward the field side, z up (wrc docs/design.md section 2)\n",
                              about(p));
  s += fmt::format("y_mm{}z_mm\n", sep);
  for (std::size_t i = 0; i < p.size(); ++i) s += fmt::format("{}{}{}\n", mm(p.y[i]), sep, mm(p.z[i]));
  return s;
}

// Simpack: y as in the engine, z down, units.len.f = 1000 (plugins/simpack).
std::string write_simpack(const Profile& p) {
  std::string name = one_line(p.name);
  std::replace(name.begin(), name.end(), '\'', ' ');
  std::string s = fmt::format("! {}\nheader.begin\n  version = 1\n  type = {}\nheader.end\n", about(p),
                              p.kind == ProfileKind::wheel ? 1 : 0);
  s += fmt::format("spline.begin\n  approx.smooth = 0\n  comment = '{}'\n  units.len.f = 1000  ! file units per metre: mm\n"
                   "  point.begin  ! y z, z down\n", name);
  for (std::size_t i = 0; i < p.size(); ++i) s += fmt::format("    {} {}\n", mm(p.y[i]), mm(-p.z[i]));
  return s + "  point.end\nspline.end\n";
}

// The tape circle's distance from the flange back (m), for the formats that count from the flange back.
double read_tape_offset(OptionReader& r) {
  const double tape = r.number("tape_offset", {"m", "the tape circle from the flange back"}, 0.070);
  if (!(tape > 0 && tape < 0.5)) fail("{}: tape_offset must lie in (0, 0.5) m, got {}", r.context(), tape);
  return tape;
}

// MiniProf, standard orientation: wheels X = y + tape offset, Y = -z (toward the flange tip); rails X = y, Y = z
// (plugins/miniprof).
std::string write_miniprof(const Profile& p, OptionReader& r) {
  const bool wheel = p.kind == ProfileKind::wheel;
  const double tape = wheel ? read_tape_offset(r) : 0.0;
  std::string s = fmt::format("MINIPROF\nProgramName=wrc\nComment={}\nColumnDef=X,Y\nXYPoints={}\n\n", about(p), p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    s += wheel ? fmt::format("{},{}\n", mm(p.y[i] + tape), mm(-p.z[i])) : fmt::format("{},{}\n", mm(p.y[i]), mm(p.z[i]));
  return s;
}

// The gauge side's point `depth` below the top of a rail: the first crossing walking from the highest point toward -y.
double gauge_side_y(const Profile& p, double depth, const std::string& context) {
  const std::size_t top = static_cast<std::size_t>(std::max_element(p.z.begin(), p.z.end()) - p.z.begin());
  const double level = p.z[top] - depth;
  for (std::size_t i = top; i > 0; --i)
    if (p.z[i - 1] <= level) return p.y[i - 1] + (p.y[i] - p.y[i - 1]) * (level - p.z[i - 1]) / (p.z[i] - p.z[i - 1]);
  fail("{}: the rail does not reach gauge_depth = {} m below its top on its gauge side (-y): it cannot be put in the "
       "track for a VAMPIRE file", context, depth);
}

// VAMPIRE: the pair (left mirrored, right), Y from the track centre, wheel Z toward the flange tip, rail Z up
// (plugins/vampire).
std::string write_vampire(const Profile& p, OptionReader& r) {
  const bool wheel = p.kind == ProfileKind::wheel;
  double offset;  // d = y + offset: the distance from the track centre
  const std::string title = one_line(fmt::format("{} ({}, written by wrc)", p.name, to_string(p.kind)));
  std::string s = fmt::format("{}\n{}\n", wheel ? "WHEELPROFILE" : "RAILPROFILE", title.substr(0, 80));
  if (wheel) {
    const double tape = read_tape_offset(r);
    const double back = r.number("flange_back", {"m", "the distance between the flange backs"}, 1.360);
    if (!(back > 0.3 && back < 5)) fail("{}: flange_back must lie in (0.3, 5) m, got {}", r.context(), back);
    s += tape == 0.070 ? "TREADDATUM EUROPEAN\n" : fmt::format("TREADDATUM CUSTOM {}\n", mm(tape));
    s += fmt::format("FLANGEBACK {}\n", mm(back));
    offset = back / 2 + tape;
  } else {
    const double depth = r.number("gauge_depth", {"m", "the gauge point below the top of the head"}, 0.014);
    const double gauge = r.number("gauge", {"m", "the track gauge"}, 1.435);
    if (!(depth > 0 && depth < 0.1)) fail("{}: gauge_depth must lie in (0, 0.1) m, got {}", r.context(), depth);
    if (!(gauge > 0.3 && gauge < 5)) fail("{}: gauge must lie in (0.3, 5) m, got {}", r.context(), gauge);
    s += depth == 0.014 ? "GAUGEPOINT EUROPEAN\n" : fmt::format("GAUGEPOINT CUSTOM {}\n", mm(depth));
    s += fmt::format("GAUGE {}\n", mm(gauge));
    offset = gauge / 2 - gauge_side_y(p, depth, r.context());
  }
  const double zs = wheel ? -1.0 : 1.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double d = p.y[i] + offset, z = zs * p.z[i];
    s += fmt::format("{} {} {} {}\n", mm(-d), mm(z), mm(d), mm(z));
  }
  return s;
}

}  // namespace

std::string format_profile(const Profile& p, const std::string& format, OptionReader& r) {
  if (format == "text") return write_text(p, ' ');
  if (format == "csv") return write_text(p, ',');
  if (format == "simpack") return write_simpack(p);
  if (format == "miniprof") return write_miniprof(p, r);
  if (format == "vampire") return write_vampire(p, r);
  fail("{}: unknown format '{}'; the formats are: {}", r.context(), format, format_list());
}

std::string write_profile(const Profile& p, const std::string& path, const OptionTable& options, std::string_view call) {
  const std::string context = fmt::format("{} '{}'", call, path);  // every message names the file
  OptionReader r(options, context);
  const std::string ext = file_extension(path);
  const std::optional<std::string> asked = r.string("format", {"", "text | csv | simpack | miniprof | vampire"});
  const Format* f = asked ? find_format(*asked) : format_of_extension(ext);
  if (asked && !f) fail("{}: unknown format '{}'; the formats are: {}", context, *asked, format_list());
  if (!f) fail("{}: cannot tell the format from the extension '{}'; pass format = ..., one of: {}", context, ext, format_list());
  const Format* by_ext = format_of_extension(ext);
  if (by_ext && by_ext != f)
    fail("{}: the extension {} is the {} format's, not {}'s (the file would be read back with another reader)", context, ext,
         by_ext->id, f->id);
  const bool wheel = p.kind == ProfileKind::wheel;
  if (*f->wheel_ext && by_ext && ext != (wheel ? f->wheel_ext : f->rail_ext))
    fail("{}: a {} profile is written as {}, not {} ({} is for {}s)", context, to_string(p.kind), wheel ? f->wheel_ext : f->rail_ext,
         ext, ext, wheel ? "rail" : "wheel");
  const std::string text = format_profile(p, f->id, r);
  r.finish();
  write_file_atomic(path, text);
  return f->id;
}

}  // namespace wrc
