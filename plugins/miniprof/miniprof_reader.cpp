// MiniProf rail (.ban) and wheel (.whl) profiles: an optional `MINIPROF` first line, `Key=Value` header
// lines (ColumnDef, XYPoints, ...; every key is kept as metadata), then the points after the first empty
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
// wheel z = -Y (standard: Y = radius offset toward the flange tip) or Y (reversed).
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

void parse(std::string_view data, const Request& rq, Out& out) {
  const int kind = kind_of(rq);
  if (kind == WRC_KIND_UNKNOWN)
    fail_at(0, "a MiniProf file without the extension .ban (rail) or .whl (wheel): pass kind = \"wheel\" or \"rail\"");
  out.kind(kind);
  const bool wheel = kind == WRC_KIND_WHEEL;

  double tape_x = 70.0;
  if (const std::string* t = rq.option("tape_x")) {
    if (!wheel) fail_at(0, "option tape_x applies to wheels (.whl) only");
    tape_x = number(*t, 0, "option tape_x");
  }
  int forced_axis = 0;  // +1 standard, -1 reversed
  if (const std::string* a = rq.option("y_axis")) {
    if (*a == "standard") forced_axis = 1;
    else if (*a == "reversed") forced_axis = -1;
    else fail_at(0, "option y_axis must be \"standard\" or \"reversed\", got {}", quoted(*a));
  }

  const auto lines = split_lines(data);
  std::size_t i = 0;
  // Header.
  std::size_t col_x = 0, col_y = 1, ncols = 2;
  long long declared = -1;
  int declared_line = 0, last_header_line = 0;
  bool column_def = false;
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
      // No empty line before the data: a numeric row ends the header too.
      std::string_view row = s;
      if (!row.empty() && row.front() == '"') row.remove_prefix(1);
      row = trim(row);
      const auto fields = split_fields(row, detect_separator(row));
      if (!fields.empty() && parse_double(fields[0])) break;
      fail_at(ln.number, "expected a `Key=Value` header line, got {}", quoted(s));
    }
    const std::string key(trim(s.substr(0, eq)));
    const std::string_view value = trim(s.substr(eq + 1));
    last_header_line = ln.number;
    out.metadata(key, std::string(value));
    if (key == "ColumnDef") {
      const auto names = split_fields(value, ',');
      ncols = names.size();
      bool hx = false, hy = false;
      for (std::size_t c = 0; c < names.size(); ++c) {
        const std::string n = lower(names[c]);
        if (n == "x") col_x = c, hx = true;
        if (n == "y") col_y = c, hy = true;
      }
      if (!hx || !hy) fail_at(ln.number, "ColumnDef must name the columns X and Y, got {}", quoted(value));
      column_def = true;
    } else if (key == "XYPoints") {
      const auto v = parse_double(value);
      if (!v || *v < 0 || *v != std::floor(*v) || *v > 1e8)
        fail_at(ln.number, "XYPoints must be a whole number of points, got {}", quoted(value));
      declared = static_cast<long long>(*v);
      declared_line = ln.number;
    }
  }
  if (lines.empty()) fail_at(0, "the file is empty");
  if (!column_def) out.transform("no ColumnDef: columns taken as X, Y");

  // Points.
  std::vector<Row> rows;
  char sep = 0;
  int first_row_line = 0, marked = 0;
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
    const char here = detect_separator(s);
    if (sep == 0) sep = here, first_row_line = ln.number;
    else if (here != sep)
      fail_at(ln.number, "fields separated by {}, but the rows from line {} are separated by {} (mixed separators)",
              separator_name(here), first_row_line, separator_name(sep));
    const auto f = split_fields(s, sep);
    if (f.size() != ncols)
      fail_at(ln.number, "{} fields, but {} declares {} columns", f.size(), column_def ? "ColumnDef" : "the default X,Y", ncols);
    rows.push_back({number(f[col_x], ln.number, "X"), number(f[col_y], ln.number, "Y"), ln.number});
  }
  if (rows.empty()) fail_at(last_header_line, "a header but no points after it");
  if (declared >= 0 && static_cast<long long>(rows.size()) != declared)
    fail_at(declared_line, "XYPoints = {} but the file holds {} points (lines {} .. {})", declared, rows.size(),
            rows.front().line, rows.back().line);
  if (marked) out.metadata("marked_points", std::to_string(marked));
  if (rows.size() < 3)
    fail_at(rows.back().line, "only {} point{} read; a profile needs at least 3", rows.size(), rows.size() == 1 ? "" : "s");

  // Which way does Y point? The head top (flange tip) is the interior extreme.
  const auto [ymin_it, ymax_it] = std::minmax_element(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.y < b.y; });
  const double ymin = ymin_it->y, ymax = ymax_it->y, e1 = rows.front().y, e2 = rows.back().y;
  const double up = ymax - std::max(e1, e2), down = std::min(e1, e2) - ymin, extent = ymax - ymin;
  const char* extreme = wheel ? "flange tip" : "head top";
  int axis = forced_axis;
  std::string why;
  if (axis == 0) {
    if (up > 4 * down && up > 0.05 * extent) {
      axis = 1;
      why = fmt::format("detected: the {} is the largest Y = {:.4f}, the ends lie at Y = {:.4f} and {:.4f}", extreme, ymax, e1, e2);
    } else if (down > 4 * up && down > 0.05 * extent) {
      axis = -1;
      why = fmt::format("detected: the {} is the smallest Y = {:.4f}, the ends lie at Y = {:.4f} and {:.4f}", extreme, ymin, e1, e2);
    } else {
      fail_at(rows.front().line,
              "cannot tell which way Y points: no clear {} between the ends (Y {:.4f} .. {:.4f}, ends {:.4f} and {:.4f}); "
              "pass y_axis = \"standard\" or \"reversed\"",
              extreme, ymin, ymax, e1, e2);
    }
  } else {
    why = fmt::format("option y_axis = {}", axis > 0 ? "standard" : "reversed");
  }
  // Rails: standard Y is up (z = Y). Wheels: standard Y is the radius offset toward the flange tip (z = -Y).
  const double zsign = (wheel ? -1.0 : 1.0) * axis;
  if (wheel)
    out.transform(fmt::format("MiniProf wheel, Y {} ({}): z = {}Y; y = X - {} (tape circle {} from the flange back)",
                              axis > 0 ? "toward the flange tip (standard)" : "away from the flange tip (reversed)", why,
                              zsign > 0 ? "" : "-", tape_x, tape_x));
  else
    out.transform(fmt::format("MiniProf rail, Y points {} ({}): z = {}Y; y = X", axis > 0 ? "up (standard)" : "down (reversed)",
                              why, zsign > 0 ? "" : "-"));
  for (const Row& r : rows) out.point(wheel ? r.x - tape_x : r.x, zsign * r.y, r.line);
}

}  // namespace

extern const ReaderSpec miniprof_reader;
const ReaderSpec miniprof_reader = {"miniprof", "MiniProf rail/wheel profile (.ban/.whl), vertical orientation detected or given",
                                    kExtensions, kOptions, parse};

}  // namespace wrc::plugin
