// MiniProf rail (.ban) and wheel (.whl) profiles: an optional `MINIPROF` first line, `Key=Value` header
// lines (ColumnDef, XYPoints, ...; every key is kept as metadata; a file that begins with rows of numbers is refused,
// naming the text reader), then the points after the first empty
// line, one row per point with the columns of ColumnDef (X, Y first usually); a leading `"` marks a point
// (kept); `!` or `%` starts a comment. Millimetres.
//
// Orientation. X is lateral. Wheels: X = 0 at the flange back, increasing toward the field side, so
// y = X - tape_x (tape circle at X = 70 mm unless the option says otherwise). Rails: y = X (rails are
// usually measured with the track centre on the +X side: pass mirror_y = true for the engine's left
// rail). Y is vertical, and files differ: the format's standard is Y toward the head top (rails) or
// toward the flange tip (wheels), but e.g. MBench_UIC60_v3.ban has Y increasing downward. The reader
// therefore looks at the shape: the head top (flange tip) is the interior extreme of Y, the profile's
// two ends lie away from it. It reports which way it found Y pointing; the option y_axis =
// "standard" | "reversed" overrides the detection. Engine z: rail z = Y (standard) or -Y (reversed);
// wheel z = -Y (standard: Y = radius offset toward the flange tip) or Y (reversed). A file whose columns are swapped
// (the height in the X column) is refused as such before the detection, which would find no extreme in its Y; one
// with fewer rows than XYPoints as cut short.
#include "reader_support.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::plugin {
namespace {

const char* const kExtensions[] = {".ban", ".whl", nullptr};
const char* const kOptions[] = {"y_axis", "tape_x", nullptr};

struct Row {
  double x, y;
  int line;
};

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

char detect_separator(std::string_view s) {
  if (s.find(',') != std::string_view::npos) return ',';
  if (s.find(';') != std::string_view::npos) return ';';
  return ' ';
}
const char* separator_name(char sep) { return sep == ',' ? "commas" : sep == ';' ? "semicolons" : "blanks"; }

int kind_of(const Request& rq) {
  const std::string& p = rq.path;
  const auto dot = p.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : lower(std::string_view(p).substr(dot));
  if (ext == ".whl") return WRC_KIND_WHEEL;
  if (ext == ".ban") return WRC_KIND_RAIL;
  return rq.kind_hint;
}

// The reader's options: tape_x (wheels only) and y_axis, which overrides the orientation detection.
struct Options {
  double tape_x = 70.0;
  int forced_axis = 0;  // +1 standard, -1 reversed, 0 detect
};

Options read_options(const Request& rq, bool wheel) {
  Options o;
  if (const std::string* t = rq.option("tape_x")) {
    if (!wheel) fail_at(0, "option tape_x applies to wheels (.whl) only");
    o.tape_x = number(*t, 0, "option tape_x");
  }
  if (const std::string* a = rq.option("y_axis")) {
    if (*a == "standard") o.forced_axis = 1;
    else if (*a == "reversed") o.forced_axis = -1;
    else fail_at(0, "option y_axis must be \"standard\" or \"reversed\", got {}", quoted(*a));
  }
  return o;
}

// What the header says about the points.
struct Header {
  std::size_t col_x = 0, col_y = 1, ncols = 2;
  long long declared = -1;  // XYPoints, -1: not given
  int declared_line = 0, last_header_line = 0;
  bool column_def = false;
  int column_def_line = 0;
  std::string column_def_text;
};

// The keys that shape the reading of the points: ColumnDef and XYPoints.
void read_header_key(const std::string& key, std::string_view value, int line, Header& h) {
  if (key == "ColumnDef") {
    const auto names = split_fields(value, ',');
    h.ncols = names.size();
    bool hx = false, hy = false;
    for (std::size_t c = 0; c < names.size(); ++c) {
      const std::string n = lower(names[c]);
      if (n == "x") h.col_x = c, hx = true;
      if (n == "y") h.col_y = c, hy = true;
    }
    if (!hx || !hy) fail_at(line, "ColumnDef must name the columns X and Y, got {}", quoted(value));
    h.column_def = true;
    h.column_def_line = line;
    h.column_def_text = std::string(value);
  } else if (key == "XYPoints") {
    const auto v = parse_double(value);
    if (!v || *v < 0 || *v != std::floor(*v) || *v > 1e8)
      fail_at(line, "XYPoints must be a whole number of points, got {}", quoted(value));
    h.declared = static_cast<long long>(*v);
    h.declared_line = line;
  }
}

// A line without '=' that starts (after an optional mark `"`) with a number: a point row.
bool is_point_row(std::string_view s) {
  std::string_view row = s;
  if (!row.empty() && row.front() == '"') row.remove_prefix(1);
  row = trim(row);
  const auto fields = split_fields(row, detect_separator(row));
  return !fields.empty() && parse_double(fields[0]);
}

// The header, up to the first empty line or the first point row; every key becomes metadata. Advances i to
// the first line after the header.
Header read_header(const std::vector<Line>& lines, std::size_t& i, Out& out) {
  Header h;
  for (; i < lines.size(); ++i) {
    const Line& ln = lines[i];
    const std::string_view s = trim(ln.text);
    if (s.empty()) {
      ++i;  // the first empty line ends the header
      break;
    }
    if (i == 0 && lower(s) == "miniprof") continue;
    const auto eq = s.find('=');
    if (eq == std::string_view::npos) {
      if (is_point_row(s)) break;  // no empty line before the data: a numeric row ends the header too
      fail_at(ln.number, "expected a `Key=Value` header line, got {}", quoted(s));
    }
    const std::string key(trim(s.substr(0, eq)));
    const std::string_view value = trim(s.substr(eq + 1));
    h.last_header_line = ln.number;
    out.metadata(key, std::string(value));
    read_header_key(key, value, ln.number, h);
  }
  return h;
}

// The point rows from line i on, in the columns of the header; one separator for all rows.
std::vector<Row> read_rows(const std::vector<Line>& lines, std::size_t i, const Header& h, int& marked) {
  std::vector<Row> rows;
  char sep = 0;
  int first_row_line = 0;
  for (; i < lines.size(); ++i) {
    const Line& ln = lines[i];
    std::string_view s = trim(strip_comment(ln.text, "!%"));
    if (!s.empty() && s.front() == '"') {
      s = trim(s.substr(1));
      ++marked;
    }
    if (s.empty()) continue;
    if (s.find('=') != std::string_view::npos)
      fail_at(ln.number, "a `Key=Value` line after the points began (line {})", first_row_line ? first_row_line : ln.number);
    refuse_text_row(s, ln.number, "point rows", "a line that starts with ! or %");
    reject_decimal_commas(s, ln.number);
    const char here = detect_separator(s);
    if (sep == 0) sep = here, first_row_line = ln.number;
    else if (here != sep)
      fail_at(ln.number, "fields separated by {}, but the rows from line {} are separated by {} (mixed separators)",
              separator_name(here), first_row_line, separator_name(sep));
    const auto f = split_fields(s, sep);
    if (f.size() != h.ncols)
      fail_at(ln.number, "{} fields, but {} declares {} columns: {}", f.size(), h.column_def ? "ColumnDef" : "the default X,Y", h.ncols,
              quoted(s));
    rows.push_back({number(f[h.col_x], ln.number, "X"), number(f[h.col_y], ln.number, "Y"), ln.number});
  }
  return rows;
}

// How far a column's values turn back between the profile's ends: the larger overshoot of an interior extreme beyond
// the ends' range (0 when the ends are the column's extremes, as for the lateral X), and the row of that extreme.
std::pair<double, std::size_t> turn_back(const std::vector<Row>& rows, double Row::*v) {
  const double lo = std::min(rows.front().*v, rows.back().*v), hi = std::max(rows.front().*v, rows.back().*v);
  std::pair<double, std::size_t> worst{0.0, 0};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double beyond = std::max(rows[i].*v - hi, lo - rows[i].*v);
    if (beyond > worst.first) worst = {beyond, i};
  }
  return worst;
}

double span(const std::vector<Row>& rows, double Row::*v) {
  const auto less = [&](const Row& p, const Row& q) { return p.*v < q.*v; };
  const auto [a, b] = std::minmax_element(rows.begin(), rows.end(), less);
  return (*b).*v - (*a).*v;
}

// The ColumnDef line with the names X and Y exchanged.
std::string exchanged(const Header& h) {
  auto names = split_fields(h.column_def_text, ',');
  std::swap(names[h.col_x], names[h.col_y]);
  std::string line = "ColumnDef=";
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (c > 0) line += ',';
    line += names[c];
  }
  return line;
}

// X and Y swapped (the vertical in the X column): X then turns back between the ends as a head's or a flange's height
// does, while Y runs from end to end as a lateral coordinate does, and spans the wider range (a rail head is about 70
// mm wide and 15-40 mm tall as measured, a wheel 130 mm wide with a 25-40 mm flange). Neither happens in a profile
// read the right way: its X would fold back by a fifth of its width.
void refuse_swapped(const std::vector<Row>& rows, const Header& h) {
  const double sx = span(rows, &Row::x), sy = span(rows, &Row::y);
  const auto [x_turn, at] = turn_back(rows, &Row::x);
  const double y_turn = turn_back(rows, &Row::y).first;
  if (!(sy > 1.5 * sx && x_turn > 0.2 * sx && y_turn < 0.05 * sy)) return;
  const std::string columns =
      fmt::format("column {} as X (lateral) and column {} as Y (vertical)", h.col_x + 1, h.col_y + 1);
  const std::string declared = h.column_def ? fmt::format("ColumnDef={} takes {}", h.column_def_text, columns)
                                            : fmt::format("without a ColumnDef line, the reader takes {}", columns);
  fail_at(h.column_def ? h.column_def_line : rows.front().line,
          "the columns look swapped: {}, but X spans {:.1f} mm and turns back between the ends ({:.1f} mm beyond them "
          "at line {}), as a height does, while Y runs from end to end over {:.1f} mm, as a lateral coordinate does (a "
          "rail head is about 70 mm wide, a wheel 130 mm); swap the two columns, or name them in the header as they "
          "are ({})", declared, sx, x_turn, rows[at].line, sy,
          h.column_def ? exchanged(h) : std::string("ColumnDef=Y,X"));
}

// Which way Y points (+1 standard, -1 reversed) and why.
struct Orientation {
  int axis;
  std::string why;
};

// The option if given; else the head top (flange tip) is the interior extreme of Y.
Orientation orientation(const std::vector<Row>& rows, bool wheel, int forced_axis) {
  if (forced_axis != 0) return {forced_axis, fmt::format("option y_axis = {}", forced_axis > 0 ? "standard" : "reversed")};
  const auto [ymin_it, ymax_it] = std::minmax_element(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.y < b.y; });
  const double ymin = ymin_it->y, ymax = ymax_it->y, e1 = rows.front().y, e2 = rows.back().y;
  const double up = ymax - std::max(e1, e2), down = std::min(e1, e2) - ymin, extent = ymax - ymin;
  const char* extreme = wheel ? "flange tip" : "head top";
  if (up > 4 * down && up > 0.05 * extent)
    return {1, fmt::format("detected: the {} is the largest Y = {:.4f}, the ends lie at Y = {:.4f} and {:.4f}", extreme, ymax, e1, e2)};
  if (down > 4 * up && down > 0.05 * extent)
    return {-1, fmt::format("detected: the {} is the smallest Y = {:.4f}, the ends lie at Y = {:.4f} and {:.4f}", extreme, ymin, e1, e2)};
  fail_at(rows.front().line,
          "cannot tell which way Y points: no clear {} between the ends (Y {:.4f} .. {:.4f}, ends {:.4f} and {:.4f}); "
          "pass y_axis = \"standard\" or \"reversed\"",
          extreme, ymin, ymax, e1, e2);
}

void parse(std::string_view data, const Request& rq, Out& out) {
  const int kind = kind_of(rq);
  if (kind == WRC_KIND_UNKNOWN)
    fail_at(0, "a MiniProf file without the extension .ban (rail) or .whl (wheel): pass kind = \"wheel\" or \"rail\"");
  out.kind(kind);
  const bool wheel = kind == WRC_KIND_WHEEL;
  const Options opt = read_options(rq, wheel);

  const auto lines = split_lines(data);
  // Rows of numbers from the first line on are no MiniProf file: without the header, nothing says that the columns
  // are X and Y, nor which way Y points (a profile in the engine frame would be read shifted by tape_x).
  refuse_other_format(lines, "miniprof", "a MiniProf profile, which begins with its header (MINIPROF or Key=Value lines)");
  std::size_t i = 0;
  const Header h = read_header(lines, i, out);
  if (lines.empty()) fail_at(0, "the file is empty");
  if (!h.column_def) out.transform("no ColumnDef: columns taken as X, Y");

  int marked = 0;
  const std::vector<Row> rows = read_rows(lines, i, h, marked);
  if (rows.empty()) fail_at(h.last_header_line, "a header but no points after it");
  if (h.declared >= 0 && static_cast<long long>(rows.size()) < h.declared)
    fail_at(h.declared_line, "XYPoints = {} but the file holds {} points (lines {} .. {}): the file is cut short "
            "(truncated) after line {}, or XYPoints is wrong", h.declared, rows.size(), rows.front().line,
            rows.back().line, rows.back().line);
  if (h.declared >= 0 && static_cast<long long>(rows.size()) > h.declared)
    fail_at(h.declared_line, "XYPoints = {} but the file holds {} points (lines {} .. {}): XYPoints is wrong, or rows "
            "were added", h.declared, rows.size(), rows.front().line, rows.back().line);
  if (marked) out.metadata("marked_points", std::to_string(marked));
  if (rows.size() < 3)
    fail_at(rows.back().line, "only {} point{} read; a profile needs at least 3", rows.size(), rows.size() == 1 ? "" : "s");

  refuse_swapped(rows, h);
  const auto [axis, why] = orientation(rows, wheel, opt.forced_axis);
  // Rails: standard Y is up (z = Y). Wheels: standard Y is the radius offset toward the flange tip (z = -Y).
  const double zsign = (wheel ? -1.0 : 1.0) * axis;
  if (wheel)
    out.transform(fmt::format("MiniProf wheel, Y {} ({}): z = {}Y; y = X - {} (tape circle {} from the flange back)",
                              axis > 0 ? "toward the flange tip (standard)" : "away from the flange tip (reversed)", why,
                              zsign > 0 ? "" : "-", opt.tape_x, opt.tape_x));
  else
    out.transform(fmt::format("MiniProf rail, Y points {} ({}): z = {}Y; y = X", axis > 0 ? "up (standard)" : "down (reversed)",
                              why, zsign > 0 ? "" : "-"));
  for (const Row& r : rows) out.point(wheel ? r.x - opt.tape_x : r.x, zsign * r.y, r.line);
}

}  // namespace

extern const ReaderSpec miniprof_reader;
const ReaderSpec miniprof_reader = {"miniprof", "MiniProf rail/wheel profile (.ban/.whl), vertical orientation detected or given",
                                    kExtensions, kOptions, parse};

}  // namespace wrc::plugin
