// VAMPIRE wheel (.whe) and rail (.rai) profiles. Millimetres. The layout: line 1 `WHEELPROFILE` or `RAILPROFILE`,
// line 2 a title, line 3 `TREADDATUM <datum>` (wheel) or `GAUGEPOINT <point>` (rail), line 4 `FLANGEBACK <mm>`
// (the distance between the flange backs) or `GAUGE <mm>`, then one row per point `yl zl yr zr`: the left and the
// right profile of the pair, Y lateral in the track frame (the track centre at Y = 0, the right side at +Y), wheel Z
// the radius offset positive toward the flange tip, rail Z up. Where these facts come from: the layout of VAMPIRE
// profile files as the open-source CONTACT program reads them (github.com/eve70a/CONTACT, its read_vampire.m; wrc has
// no VAMPIRE installation to compare with), including the datum keywords: TREADDATUM EUROPEAN = the tape circle 70 mm from
// the flange back, US1 = 2 27/32 in, US2 = 3 1/16 in, CUSTOM <mm>; GAUGEPOINT EUROPEAN = 14 mm below the top of the
// head, US = 5/8 in, CUSTOM <mm>.
//
// Variants read: every datum keyword above (any letter case); fields separated by blanks or commas; `!`, `%` or `"`
// starting a comment (on any line but the title); blank lines among the rows. Rows must hold the four numbers.
//
// To the engine frame (left-side frame, y toward the field side): the option side = "left" (default) takes the
// columns yl zl, with d = -yl the lateral distance from the track centre; side = "right" takes yr zr, d = yr.
// Wheels: y = d - FLANGEBACK/2 - datum (the tape circle at y = 0), z = -Z. Rails: y = d - d_top, z = Z - Z_top, the
// origin at the highest point of the head (the file's lateral origin is the track centre, but wrc places each rail by
// its own gauge point; docs/design.md section 2); GAUGEPOINT and GAUGE are kept as metadata.
#include "reader_support.hpp"

#include <algorithm>
#include <cctype>

namespace wrc::plugin {
namespace {

const char* const kExtensions[] = {".whe", ".rai", nullptr};
const char* const kOptions[] = {"side", nullptr};
constexpr double kInch = 25.4;  // mm
constexpr std::string_view kComment = "!%\"";  // each starts a comment (not on the title line)

std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

std::string extension(const std::string& path) {
  const auto dot = path.find_last_of("./");
  if (dot == std::string::npos || path[dot] != '.') return "";
  std::string e = path.substr(dot);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Line 1 gives the kind; the extension, when it is one of the format's, must agree.
bool read_kind(const std::vector<Line>& lines, const Request& rq) {
  const Line& first = lines.front();
  const std::string s = upper(trim(first.text));
  if (s != "WHEELPROFILE" && s != "RAILPROFILE") {
    refuse_other_format(lines, "vampire", "a VAMPIRE profile");
    fail_at(first.number, "a VAMPIRE profile starts with WHEELPROFILE or RAILPROFILE, got {}", quoted(trim(first.text)));
  }
  const bool wheel = s == "WHEELPROFILE";
  const std::string ext = extension(rq.path);
  if ((ext == ".whe" && !wheel) || (ext == ".rai" && wheel))
    fail_at(first.number, "the file says {} but its extension {} is that of a {} profile", s, ext, wheel ? "rail" : "wheel");
  return wheel;
}

// A positive length in mm, at most `limit`.
double length_mm(std::string_view field, int line, std::string_view what, double limit) {
  const double v = number(field, line, what);
  if (!(v > 0) || v > limit) fail_at(line, "{} must be a length in mm in (0, {}], got {}", what, limit, quoted(field));
  return v;
}

// `KEYWORD value...` on a header line: the words after the keyword (which must be the first word).
std::vector<std::string_view> keyword_line(const Line& ln, std::string_view keyword, std::string_view expected) {
  const auto f = split_fields(trim(strip_comment(ln.text, kComment)), ' ');
  if (f.empty() || upper(f[0]) != keyword)
    fail_at(ln.number, "expected `{} {}` on line {}, got {}", keyword, expected, ln.number, quoted(trim(ln.text)));
  return {f.begin() + 1, f.end()};
}

// Line 3: TREADDATUM (wheel: flange back to tape circle, mm) or GAUGEPOINT (rail: depth below the top, mm).
double read_datum(const Line& ln, bool wheel, std::string& text) {
  const char* key = wheel ? "TREADDATUM" : "GAUGEPOINT";
  const char* choices = wheel ? "EUROPEAN | US1 | US2 | CUSTOM <mm>" : "EUROPEAN | US | CUSTOM <mm>";
  const auto f = keyword_line(ln, key, choices);
  if (f.empty()) fail_at(ln.number, "{} needs a value: {}", key, choices);
  const std::string v = upper(f[0]);
  text.assign(f[0]);
  for (std::size_t i = 1; i < f.size(); ++i) text.append(" ").append(f[i]);
  const std::size_t want = v == "CUSTOM" ? 2 : 1;
  if (f.size() != want) fail_at(ln.number, "{} {} takes {} value{}, got {}", key, v, want - 1, want == 2 ? "" : "s", quoted(trim(ln.text)));
  if (v == "CUSTOM") return length_mm(f[1], ln.number, fmt::format("{} CUSTOM", key), 500);
  if (v == "EUROPEAN") return wheel ? 70.0 : 14.0;
  if (wheel && v == "US1") return (2 + 27.0 / 32) * kInch;
  if (wheel && v == "US2") return (3 + 1.0 / 16) * kInch;
  if (!wheel && v == "US") return 5.0 / 8 * kInch;
  fail_at(ln.number, "{} {} is not a known datum; expected {}", key, quoted(f[0]), choices);
}

struct Row {
  double d, z;
  int line;
};

// The rows `yl zl yr zr` after the header; the side's lateral distance from the centre and Z.
std::vector<Row> read_rows(const std::vector<Line>& lines, bool right) {
  std::vector<Row> rows;
  for (std::size_t i = 4; i < lines.size(); ++i) {
    const Line& ln = lines[i];
    std::string s(trim(strip_comment(ln.text, kComment)));
    if (s.empty()) continue;
    refuse_text_row(s, ln.number, "rows yl zl yr zr", "after !, % or \"");
    reject_decimal_commas(s, ln.number);
    std::replace(s.begin(), s.end(), ',', ' ');
    const auto f = split_fields(s, ' ');
    if (f.size() != 4)
      fail_at(ln.number, "a row holds `yl zl yr zr` (4 numbers, mm), got {} field{}: {}", f.size(), f.size() == 1 ? "" : "s",
              quoted(trim(strip_comment(ln.text, kComment))));
    const double yl = number(f[0], ln.number, "yl"), zl = number(f[1], ln.number, "zl");
    const double yr = number(f[2], ln.number, "yr"), zr = number(f[3], ln.number, "zr");
    rows.push_back(right ? Row{yr, zr, ln.number} : Row{-yl, zl, ln.number});
  }
  return rows;
}

void parse(std::string_view data, const Request& rq, Out& out) {
  const std::string* side = rq.option("side");
  if (side && *side != "left" && *side != "right")
    fail_at(0, "option side must be \"left\" or \"right\", got {}", quoted(*side));
  const bool right = side && *side == "right";
  const auto lines = split_lines(data);
  if (lines.empty()) fail_at(0, "the file is empty");
  const bool wheel = read_kind(lines, rq);
  if (lines.size() < 4) fail_at(lines.back().number, "the file ends within the 4 header lines (kind, title, datum, spacing)");
  out.kind(wheel ? WRC_KIND_WHEEL : WRC_KIND_RAIL);
  out.metadata("title", std::string(trim(lines[1].text)));
  std::string datum_text;
  const double datum = read_datum(lines[2], wheel, datum_text);
  const auto dist = keyword_line(lines[3], wheel ? "FLANGEBACK" : "GAUGE", "<mm>");
  if (dist.size() != 1) fail_at(lines[3].number, "{} takes one length in mm, got {}", wheel ? "FLANGEBACK" : "GAUGE", quoted(trim(lines[3].text)));
  const double spacing = length_mm(dist[0], lines[3].number, wheel ? "FLANGEBACK" : "GAUGE", 5000);
  out.metadata(wheel ? "tread_datum" : "gauge_point", datum_text);
  out.metadata(wheel ? "flange_back" : "gauge", std::string(dist[0]));

  const std::vector<Row> rows = read_rows(lines, right);
  if (rows.size() < 3)
    fail_at(lines.back().number, "{} point{} read after the header; a profile needs at least 3", rows.size(), rows.size() == 1 ? "" : "s");
  const char* cols = right ? "yr zr" : "yl zl";
  if (wheel) {
    const double off = spacing / 2 + datum;
    out.transform(fmt::format("VAMPIRE wheel, {} side (columns {}): y = {}Y - {} (FLANGEBACK/2 + the {} tread datum {} mm), z = -Z",
                              right ? "right" : "left", cols, right ? "" : "-", off, datum_text, datum));
    for (const Row& r : rows) out.point(r.d - off, -r.z, r.line);
    return;
  }
  const auto top = std::max_element(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.z < b.z; });
  out.transform(fmt::format("VAMPIRE rail, {} side (columns {}): y = {}Y - {}, z = Z - ({}): the origin at the highest "
                            "point of the head (line {})", right ? "right" : "left", cols, right ? "" : "-", top->d,
                            top->z + 0.0, top->line));
  for (const Row& r : rows) out.point(r.d - top->d, r.z - top->z, r.line);
}

}  // namespace

extern const ReaderSpec vampire_reader;
const ReaderSpec vampire_reader = {"vampire", "VAMPIRE wheel/rail profile (.whe/.rai), left or right columns",
                                   kExtensions, kOptions, parse};

}  // namespace wrc::plugin
