// Simpack rail (.prr) and wheel (.prw) profiles. `!` starts a comment. header.begin/end holds version
// (1) and type (0 rail, 1 wheel); spline.begin/end holds the processing keys and point.begin/end the
// points `y z [weight]` with z positive DOWN. The file's processing steps are applied in their numbered
// order: 1 point.dist.min, 2 shift.y/z, 3 rotate, 4 bound.y/z.min/max (ignored when min > max),
// 5 mirror.y/z, 6 inversion, 7 units.len.f (= file units per metre). Then z -> -z (engine z up). A shift that moves
// the points beyond the host's bound on a point is refused here, naming its key and line. The steps that reverse the
// points' y or z (mirror.y, mirror.z, a rotation past a quarter turn: 180 degrees is y and z reversed) are reported to
// the host with how to undo them, so that an orientation warning names the file's key rather than an option.
#include "reader_support.hpp"
#include "wrc/profile/profile.hpp"  // kMaxProfileCoordinate, the host's bound on a point

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace wrc::plugin {
namespace {

const char* const kExtensions[] = {".prr", ".prw", nullptr};
const char* const kOptions[] = {nullptr};

struct Value {
  std::string text;
  int line = 0;
};

// Removes a `!` comment that is not inside a quoted string.
std::string_view strip_bang(std::string_view s) {
  char quote = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '!') {
      return s.substr(0, i);
    }
  }
  return s;
}

struct Section {
  std::map<std::string, Value, std::less<>> keys;
  int begin_line = 0, end_line = 0;
};

void read_key(std::string_view s, int line, Section& sec) {
  const auto eq = s.find('=');
  if (eq == std::string_view::npos) fail_at(line, "expected `key = value`, got {}", quoted(s));
  const std::string key(trim(s.substr(0, eq)));
  std::string_view value = trim(s.substr(eq + 1));
  if (key.empty()) fail_at(line, "a key is missing before '='");
  if (value.size() >= 2 && (value.front() == '\'' || value.front() == '"') && value.back() == value.front())
    value = value.substr(1, value.size() - 2);
  if (const auto it = sec.keys.find(key); it != sec.keys.end())
    fail_at(line, "key '{}' given twice (first on line {})", key, it->second.line);
  sec.keys.emplace(key, Value{std::string(value), line});
}

struct Point {
  double y, z;
  int line;
};

class Keys {
 public:
  Keys(const Section& s) : s_(s) {}
  const Value* find(std::string_view key) const {
    const auto it = s_.keys.find(key);
    return it == s_.keys.end() ? nullptr : &it->second;
  }
  double num(std::string_view key, double fallback) const {
    const Value* v = find(key);
    return v ? number(v->text, v->line, key) : fallback;
  }
  bool flag(std::string_view key) const {
    const Value* v = find(key);
    if (!v) return false;
    const double d = number(v->text, v->line, key);
    if (d != 0 && d != 1) fail_at(v->line, "{} must be 0 or 1, got {}", key, quoted(v->text));
    return d == 1;
  }
  std::string where(std::string_view key) const {
    const Value* v = find(key);
    return v ? fmt::format("{} = {} (line {})", key, v->text, v->line) : std::string(key);
  }

 private:
  const Section& s_;
};

// Header: version 1, type 0 rail / 1 wheel; checked as soon as header.end is read.
void check_header(const Section& header, Out& out) {
  const Keys hk(header);
  const Value* version = hk.find("version");
  if (!version) fail_at(header.begin_line, "the header has no version (expected version = 1)");
  if (number(version->text, version->line, "version") != 1)
    fail_at(version->line, "version {} is not supported (expected 1)", quoted(version->text));
  const Value* type = hk.find("type");
  if (!type) fail_at(header.begin_line, "the header has no type (0 = rail, 1 = wheel)");
  const double t = number(type->text, type->line, "type");
  if (t != 0 && t != 1) fail_at(type->line, "type must be 0 (rail) or 1 (wheel), got {}", quoted(type->text));
  out.kind(t == 1 ? WRC_KIND_WHEEL : WRC_KIND_RAIL);
  for (const auto& [k, v] : header.keys) out.metadata("header." + k, v.text);
}

// The sections of a file as read, before the processing.
struct File {
  Section header, spline;
  std::vector<Point> pts;
  int points_begin = 0, points_end = 0;
  bool seen_header = false, seen_points = false;
};

enum class State { top, header, spline, points, done };

// Outside a section (before or after spline.end) only header.begin and spline.begin may come.
State begin_section(std::string_view s, int line, File& f) {
  if (s == "header.begin") {
    if (f.seen_header) fail_at(line, "a second header.begin (the first is on line {})", f.header.begin_line);
    f.seen_header = true;
    f.header.begin_line = line;
    return State::header;
  }
  if (s == "spline.begin") {
    if (f.spline.begin_line) fail_at(line, "a second spline.begin (the first is on line {}); one profile per file", f.spline.begin_line);
    f.spline.begin_line = line;
    return State::spline;
  }
  fail_at(line, "expected header.begin or spline.begin, got {}", quoted(s));
}

// A line of point.begin/end: `y z [weight]` separated by blanks (the weight is checked, not used).
Point read_point(std::string_view s, int line) {
  refuse_text_row(s, line, "points between point.begin and point.end", "after !");
  reject_decimal_commas(s, line);
  if (s.find_first_of(",;") != std::string_view::npos)
    fail_at(line, "a ',' or ';' in a point line; Simpack points are separated by blanks (mixed separators)");
  const auto f = split_fields(s, ' ');
  if (f.size() < 2 || f.size() > 3) fail_at(line, "a point line holds `y z [weight]`, got {} field{}: {}", f.size(),
                                           f.size() == 1 ? "" : "s", quoted(s));
  const double y = number(f[0], line, "y");
  const double z = number(f[1], line, "z");
  if (f.size() == 3) number(f[2], line, "weight");
  return {y, z, line};
}

// A line inside header, spline or points: the section's end, a nested point.begin, a key or a point.
State read_in_section(State st, std::string_view s, int line, File& f, Out& out) {
  switch (st) {
    case State::header:
      if (s == "header.end") {
        f.header.end_line = line;
        check_header(f.header, out);
        return State::top;
      }
      read_key(s, line, f.header);
      return st;
    case State::spline:
      if (s == "spline.end") {
        f.spline.end_line = line;
        return State::done;
      }
      if (s == "point.begin") {
        if (f.seen_points) fail_at(line, "a second point.begin (the first is on line {})", f.points_begin);
        f.seen_points = true;
        f.points_begin = line;
        return State::points;
      }
      read_key(s, line, f.spline);
      return st;
    case State::points:
      if (s == "point.end") {
        f.points_end = line;
        return State::spline;
      }
      f.pts.push_back(read_point(s, line));
      return st;
    case State::top:
    case State::done:
      break;
  }
  return st;  // top and done: begin_section
}

// At the end of the file: every section closed, and points read.
void check_complete(const File& f, State st, const std::vector<Line>& lines) {
  const int last = lines.empty() ? 0 : lines.back().number;
  if (lines.empty()) fail_at(0, "the file is empty (no header.begin, no spline.begin)");
  if (!f.seen_header && !f.spline.begin_line)
    fail_at(0, "no header.begin, no spline.begin: the file holds only comments and blank lines");
  // An open section at the end: a file cut short, even exactly at a row's end, or an end marker left out.
  const char* cut = "the file is cut short (truncated), or the end marker is missing";
  if (st == State::header)
    fail_at(last, "the file ends inside header.begin (line {}): no header.end; {}", f.header.begin_line, cut);
  if (st == State::points)
    fail_at(last, "the file ends inside point.begin (line {}): no point.end; {}", f.points_begin, cut);
  if (st == State::spline)
    fail_at(last, "the file ends inside spline.begin (line {}): no spline.end; {}", f.spline.begin_line, cut);
  if (!f.seen_header) fail_at(0, "no header.begin ... header.end (it says version and type)");
  if (!f.spline.begin_line) fail_at(f.header.end_line, "no spline.begin ... spline.end after the header: no points");
  if (!f.seen_points) fail_at(f.spline.end_line, "no point.begin ... point.end in the spline section: no points");
  if (f.pts.empty()) fail_at(f.points_end, "no points between point.begin (line {}) and point.end", f.points_begin);
}

// Reads the sections line by line (a state machine); the header is checked as soon as it ends.
File read_sections(std::string_view data, Out& out) {
  const auto lines = split_lines(data);
  File f;
  State st = State::top;
  for (const Line& ln : lines) {
    const std::string_view s = trim(strip_bang(ln.text));
    if (s.empty()) continue;
    if (!f.seen_header && !f.spline.begin_line && s != "header.begin" && s != "spline.begin")
      refuse_other_format(lines, "simpack", "a Simpack profile");
    st = st == State::top || st == State::done ? begin_section(s, ln.number, f) : read_in_section(st, s, ln.number, f, out);
  }
  check_complete(f, st, lines);
  return f;
}

// 1: minimum point distance.
void drop_close_points(const Keys& sk, std::vector<Point>& pts, Out& out) {
  const double dmin = sk.num("point.dist.min", 0);
  if (dmin < 0) fail_at(sk.find("point.dist.min")->line, "point.dist.min must be >= 0");
  if (dmin > 0) {
    std::vector<Point> kept;
    for (const Point& p : pts)
      if (kept.empty() || std::hypot(p.y - kept.back().y, p.z - kept.back().z) >= dmin) kept.push_back(p);
    out.transform(fmt::format("1 {}: {} points closer than that to their predecessor dropped", sk.where("point.dist.min"),
                              pts.size() - kept.size()));
    if (kept.size() < 3)
      fail_at(sk.find("point.dist.min")->line, "point.dist.min = {} leaves {} of the {} points; a profile needs at least 3",
              quoted(sk.find("point.dist.min")->text), kept.size(), pts.size());
    pts = std::move(kept);
  }
}

// 7: units.len.f = file units per metre; without it the host's default, millimetres.
double file_unit(const Keys& sk) {
  const Value* u = sk.find("units.len.f");
  if (!u) return 1e-3;
  const double f = number(u->text, u->line, "units.len.f");
  if (!(f > 0)) fail_at(u->line, "units.len.f must be positive (file units per metre), got {}", quoted(u->text));
  return 1.0 / f;
}

// A shift that moves every point beyond the host's bound on a point is named here, with its line: the host sees only
// the shifted points, and would suspect their unit.
double shift(const Keys& sk, std::string_view key, double unit) {
  const double s = sk.num(key, 0);
  if (std::abs(s) * unit > kMaxProfileCoordinate)
    fail_at(sk.find(key)->line, "{} = {} is out of range: it moves every point {:.3g} m (at {} m per file unit), and "
            "no profile lies more than {:g} m from the origin", key, quoted(sk.find(key)->text), std::abs(s) * unit,
            unit, kMaxProfileCoordinate);
  return s;
}

// 2: shift.
void shift_points(const Keys& sk, double unit, std::vector<Point>& pts, Out& out) {
  const double sy = shift(sk, "shift.y", unit), sz = shift(sk, "shift.z", unit);
  if (sy != 0 || sz != 0) {
    for (Point& p : pts) p.y += sy, p.z += sz;
    out.transform(fmt::format("2 {}, {}: y += {}, z += {}", sk.where("shift.y"), sk.where("shift.z"), sy, sz));
  }
}

// 3: rotation about x by rotate / units.ang.f radians: (y, z) -> (y cos a - z sin a, y sin a + z cos a),
// in the file's (y, z-down) frame.
void rotate_points(const Keys& sk, std::vector<Point>& pts, Out& out) {
  const double angf = sk.num("units.ang.f", 1.0);
  if (!(angf > 0)) fail_at(sk.find("units.ang.f")->line, "units.ang.f must be positive, got {}", angf);
  const double rot = sk.num("rotate", 0) / angf;
  if (rot != 0) {
    const double c = std::cos(rot), s = std::sin(rot);
    for (Point& p : pts) {
      const double y = c * p.y - s * p.z, z = s * p.y + c * p.z;
      p.y = y, p.z = z;
    }
    out.transform(fmt::format("3 {}: points rotated by {:.9g} rad about x (file frame, z down)", sk.where("rotate"), rot));
    if (c < 0) {  // a turn past a quarter: the points' vertical direction is reversed, and their lateral one with it
      const std::string turn = fmt::format("{} in the file, a turn by {:.6g} degrees", sk.where("rotate"),
                                           rot * 180 / std::numbers::pi);
      out.reversed(WRC_AXIS_Z, turn + ", which turns the points over: set rotate = 0 if they already have z down, as "
                   "Simpack reads them");
      out.reversed(WRC_AXIS_Y, turn + ", which mirrors the points in y as it turns them over: to turn them over alone, "
                   "set rotate = 0 and mirror.z = 1");
    }
  }
}

// 4: bounds on y (on_y) or z; a pair applies only when both are given and min <= max.
void bound_points(const Keys& sk, const char* kmin, const char* kmax, bool on_y, std::vector<Point>& pts, Out& out) {
  const Value* vmin = sk.find(kmin);
  const Value* vmax = sk.find(kmax);
  if (!vmin || !vmax) return;
  const double lo = number(vmin->text, vmin->line, kmin), hi = number(vmax->text, vmax->line, kmax);
  if (lo > hi) return;  // Simpack: bounds switched off
  const std::size_t before = pts.size();
  pts.erase(std::remove_if(pts.begin(), pts.end(), [&](const Point& p) { const double v = on_y ? p.y : p.z; return v < lo || v > hi; }),
            pts.end());
  out.transform(fmt::format("4 {}, {}: {} points outside dropped", sk.where(kmin), sk.where(kmax), before - pts.size()));
  if (pts.size() < 3)
    fail_at(vmin->line, "{} of the {} points lie within {} .. {} = {} .. {}; a profile needs at least 3", pts.size(), before,
            kmin, kmax, lo, hi);
}

// 5: mirror, 6: inversion of the point order.
void mirror_points(const Keys& sk, std::vector<Point>& pts, Out& out) {
  if (sk.flag("mirror.y")) {
    for (Point& p : pts) p.y = -p.y;
    out.transform(fmt::format("5 {}: y -> -y", sk.where("mirror.y")));
    out.reversed(WRC_AXIS_Y, fmt::format("{} in the file: set mirror.y = 0 if the points' y already points to the field "
                                         "side", sk.where("mirror.y")));
  }
  if (sk.flag("mirror.z")) {
    for (Point& p : pts) p.z = -p.z;
    out.transform(fmt::format("5 {}: z -> -z", sk.where("mirror.z")));
    out.reversed(WRC_AXIS_Z, fmt::format("{} in the file: set mirror.z = 0 if the points already have z down, as "
                                         "Simpack reads them", sk.where("mirror.z")));
  }
  if (sk.flag("inversion")) {
    std::reverse(pts.begin(), pts.end());
    out.transform(fmt::format("6 {}: point order reversed", sk.where("inversion")));
  }
}

// 7: the file's unit, declared to the host when the file gives it.
void set_units(const Keys& sk, double unit, Out& out) {
  if (const Value* u = sk.find("units.len.f")) out.units(unit, fmt::format("units.len.f = {} (line {})", u->text, u->line));
}

// Where the points' y turns back (the index of the first point past the turn, 0 if none; `from`: y's direction
// before it), steps shorter than `tol` ignored: the host's test for a profile that folds back, in the file's unit.
std::size_t y_turn(const std::vector<Point>& pts, double tol, int& from) {
  from = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double dy = pts[i + 1].y - pts[i].y;
    if (std::abs(dy) <= tol) continue;
    const int d = dy > 0 ? 1 : -1;
    if (from != 0 && d != from) return i + 1;
    from = d;
  }
  return 0;
}

// Points monotone in y before the rotation (3) that fold back after the processing: the rotation turned them past
// vertical (the other steps drop, shift, mirror or reverse points, which keeps them monotone). Named here with the
// angle and its unit, where the host would see only the folded points (rotate in degrees without units.ang.f turns
// the profile 57 times too far).
void check_rotation(const Keys& sk, bool monotone_before, double unit, const std::vector<Point>& pts) {
  int from = 0;
  const std::size_t turn = y_turn(pts, kDuplicateTolerance / unit, from);
  if (!monotone_before || turn == 0) return;
  const Value* r = sk.find("rotate");
  const Value* f = sk.find("units.ang.f");
  const double rad = sk.num("rotate", 0) / sk.num("units.ang.f", 1.0);
  fail_at(r->line,
          "rotate = {} turns the profile by {:.6g} degrees ({}): its points, monotone in y before the rotation, fold "
          "back after it at line {} (y turns from {} to {}), and a profile must be monotone in y; is the angle in that "
          "unit?",
          quoted(r->text), rad * 180 / std::numbers::pi,
          f ? fmt::format("units.ang.f = {} per radian, line {}", f->text, f->line) : std::string("radians: no units.ang.f"),
          pts[turn].line, from > 0 ? "increasing" : "decreasing", from > 0 ? "decreasing" : "increasing");
}

// The spline section's keys become metadata; its processing steps are applied in their numbered order.
void process(const Section& spline, std::vector<Point>& pts, Out& out) {
  const Keys sk(spline);
  for (const auto& [k, v] : spline.keys) out.metadata(k, v.text);
  if (const Value* sm = sk.find("approx.smooth"); sm && number(sm->text, sm->line, "approx.smooth") != 0)
    out.transform(fmt::format("{}: smoothing not applied (the points are used as given)", sk.where("approx.smooth")));
  const double unit = file_unit(sk);
  drop_close_points(sk, pts, out);
  shift_points(sk, unit, pts, out);
  int from = 0;
  const bool monotone_before = y_turn(pts, kDuplicateTolerance / unit, from) == 0;
  rotate_points(sk, pts, out);
  bound_points(sk, "bound.y.min", "bound.y.max", true, pts, out);
  bound_points(sk, "bound.z.min", "bound.z.max", false, pts, out);
  mirror_points(sk, pts, out);
  if (sk.num("rotate", 0) != 0) check_rotation(sk, monotone_before, unit, pts);
  set_units(sk, unit, out);
}

void parse(std::string_view data, const Request&, Out& out) {
  File f = read_sections(data, out);
  process(f.spline, f.pts, out);
  out.transform("Simpack z points down: z -> -z (engine z up)");
  for (const Point& p : f.pts) out.point(p.y, -p.z, p.line);
}

}  // namespace

extern const ReaderSpec simpack_reader;
const ReaderSpec simpack_reader = {"simpack", "Simpack rail/wheel profile (.prr/.prw), file processing keys applied",
                                   kExtensions, kOptions, parse};

}  // namespace wrc::plugin
