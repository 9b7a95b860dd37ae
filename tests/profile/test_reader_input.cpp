// Every reader plugin on malformed files: each gives one error naming the file and the line, none
// crashes. The plugins are the ones built into <build>/plugins (paths().plugin_dirs[0]).
#include "wrc/core/error.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/profile/reader.hpp"
#include "approx.hpp"
#include "scratch.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>

#include <unistd.h>

using wrc::test::within_abs;
using wrc::test::within_rel;
using namespace wrc;

namespace {

const ReaderRegistry& built_plugins() {
  static ReaderRegistry r = [] {
    ReaderRegistry reg;
    reg.load_plugin_dir(paths().plugin_dirs.at(0));
    return reg;
  }();
  return r;
}

using test::tmp_path;
using test::write_tmp;

std::string error_of(const std::string& path, LoadOptions o = {}) {
  try {
    load_profile_file(path, o, {&built_plugins()});
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// `expected` must appear in the message, and the message must start with "path:line: " when line > 0.
void check_error(const std::string& name, const std::string& text, int line, const std::string& expected, LoadOptions o = {}) {
  const std::string path = write_tmp(name, text);
  const std::string msg = error_of(path, o);
  INFO(name << ": " << msg);
  const std::string prefix = line > 0 ? path + ":" + std::to_string(line) + ": " : path + ": ";
  CHECK(msg.rfind(prefix, 0) == 0);
  CHECK(msg.find(expected) != std::string::npos);
}

// A 30 mm wide arc, 31 points, "y z" in mm with `sep` between the numbers.
std::string arc_rows(const char* sep, double scale = 1.0, int n = 31) {
  std::string s;
  for (int i = 0; i < n; ++i) {
    const double y = -15.0 + 30.0 * i / (n - 1);
    s += fmt::format("{:.6f}{}{:.6f}\n", y * scale, sep, (std::sqrt(300.0 * 300.0 - y * y) - 300.0) * scale);
  }
  return s;
}

std::string simpack(const std::string& points, const std::string& units = "1000") {
  return "header.begin\n  version = 1\n  type = 0\nheader.end\nspline.begin\n  units.len.f = " + units +
         "\n  point.begin\n" + points + "  point.end\nspline.end\n";
}
constexpr int kSimpackFirstPoint = 8;  // line of the first point in simpack()

std::string miniprof(const std::string& rows, int xypoints) {
  return "Filename=x.ban\nXYPoints=" + std::to_string(xypoints) + "\nColumnDef=X,Y\n\n" + rows;
}
constexpr int kMiniprofFirstRow = 5;

// A VAMPIRE rail: the arc rows "y z" become "yl zl yr zr" (the same arc on both sides).
std::string vampire(const std::string& rows) {
  std::string s = "RAILPROFILE\narc\nGAUGEPOINT EUROPEAN\nGAUGE 1435\n";
  std::size_t start = 0;
  while (start < rows.size()) {
    const std::size_t end = rows.find('\n', start);
    const std::string row = rows.substr(start, end - start);
    const std::size_t gap = row.find_first_of(" \t;,");
    const std::string y = row.substr(0, gap), mirrored = y[0] == '-' ? y.substr(1) : "-" + y;
    s += mirrored + " " + row.substr(gap + 1) + " " + row + "\n";
    start = end + 1;
  }
  return s;
}
constexpr int kVampireFirstRow = 5;

}  // namespace

TEST_CASE("the built plugins are there") {
  const auto& r = built_plugins();
  INFO("plugin folder " << paths().plugin_dirs.at(0));
  for (const auto& why : r.rejected()) INFO(why);
  CHECK(r.find("text") != nullptr);
  CHECK(r.find("simpack") != nullptr);
  CHECK(r.find("miniprof") != nullptr);
  CHECK(r.find("vampire") != nullptr);
  CHECK(r.rejected().empty());
}

TEST_CASE("text reader: bad input") {
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  check_error("empty.txt", "", 0, "the file is empty", rail);
  check_error("blank.txt", "\n  \n# only a comment\n", 0, "no data lines: the file holds only comments and blank lines", rail);
  check_error("header_only.csv", "y_mm,z_mm\n", 1, "a header line but no data lines", rail);
  check_error("nonnumeric.txt", "0 0\n1 0.1\n2 abc\n3 0.3\n", 3, "z (column 2) must be a number, got 'abc'", rail);
  check_error("nan.txt", "0 0\n1 nan\n2 0\n", 2, "must be a finite number, got 'nan'", rail);
  check_error("inf.csv", "0,0\n1,0\n2,-inf\n", 3, "must be a finite number, got '-inf'", rail);
  check_error("single.txt", "# one point\n1.0 2.0\n", 2, "only 1 point read", rail);
  check_error("mixed.txt", "0 0\n1 0.1\n2,0.2\n", 3, "separated by commas, but the data from line 1 is separated by blanks", rail);
  check_error("mixed2.csv", "0,0\n1,0.1\n2 0.2\n", 3, "separated by blanks, but the data from line 1 is separated by commas", rail);
  check_error("fields.txt", "0 0\n1 0.1 7\n", 2, "3 fields, but the data has 2 per line", rail);
  check_error("metres.txt", arc_rows(" ", 1e-3), 1, "total chord is 0.030", rail);
  check_error("binary.txt", std::string("0 0\n1\0 2\n", 9), 2, "NUL byte", rail);
  // The same metres file with units given explicitly loads.
  LoadOptions m = rail;
  m.metres_per_unit = 1.0;
  m.units_text = "m";
  CHECK(error_of(write_tmp("metres.txt", arc_rows(" ", 1e-3)), m) == "(no error)");
  CHECK(error_of(write_tmp("good.txt", arc_rows("\t")), rail) == "(no error)");
  LoadOptions cols = rail;
  cols.reader_options = {{"columns", "3,1"}};
  check_error("columns.txt", "0 0\n1 0\n", 1, "option columns asks for column 3", cols);
}

TEST_CASE("Simpack reader: bad input") {
  check_error("empty.prr", "", 0, "the file is empty");
  check_error("comments.prr", "! nothing but a comment\n", 0, "the file holds only comments and blank lines");
  check_error("header_only.prr", "header.begin\n version = 1\n type = 0\nheader.end\n", 4, "no spline.begin");
  check_error("no_points.prr", simpack(""), 8, "no points between point.begin (line 7) and point.end");
  check_error("open.prr", "header.begin\n version = 1\n type = 0\nheader.end\nspline.begin\n point.begin\n0 0\n", 7,
              "the file ends inside point.begin (line 6)");
  check_error("nonnumeric.prr", simpack("0 0\n1 0.1\n2 x\n"), kSimpackFirstPoint + 2, "z must be a number, got 'x'");
  check_error("nan.prr", simpack("0 0\n1 NaN\n2 0\n"), kSimpackFirstPoint + 1, "must be a finite number, got 'NaN'");
  check_error("inf.prr", simpack("0 0\ninf 0\n2 0\n"), kSimpackFirstPoint + 1, "y must be a finite number, got 'inf'");
  check_error("single.prr", simpack("1 2\n"), kSimpackFirstPoint, "only 1 point read");
  check_error("mixed.prr", simpack("0 0\n1,0.1\n"), kSimpackFirstPoint + 1, "mixed separators");
  check_error("fields.prr", simpack("0 0 1 1\n"), kSimpackFirstPoint, "got 4 fields");
  check_error("metres.prr", simpack(arc_rows(" ", 1e-3)), kSimpackFirstPoint, "total chord is 0.030");
  check_error("wrong_unit.prr", simpack(arc_rows(" "), "1"), kSimpackFirstPoint, "taken as units.len.f = 1 (line 6)");
  check_error("version.prr", "header.begin\n version = 2\n type = 0\nheader.end\n", 2, "version '2' is not supported");
  check_error("type.prr", "header.begin\n version = 1\n type = 7\nheader.end\nspline.begin\n point.begin\n0 0\n point.end\nspline.end\n", 3,
              "type must be 0 (rail) or 1 (wheel)");
  check_error("twice.prr", "header.begin\n version = 1\n version = 1\nheader.end\n", 3, "key 'version' given twice (first on line 2)");
  check_error("stray.prr", "hello\n", 1, "expected header.begin or spline.begin");
  check_error("mirror.prr", "header.begin\n version = 1\n type = 0\nheader.end\nspline.begin\n mirror.y = 2\n point.begin\n" + arc_rows(" ") +
              " point.end\nspline.end\n", 6, "mirror.y must be 0 or 1");
  CHECK(error_of(write_tmp("good.prr", simpack(arc_rows("  ")))) == "(no error)");
}

TEST_CASE("Simpack reader: processing steps in their numbered order") {
  // Raw points (mm, z down): shift then rotate then bounds then mirror then inversion then units.
  const std::string keys =
      "  shift.y = 10\n  shift.z = 1\n  rotate = 0\n  bound.y.min = 5\n  bound.y.max = 45\n  bound.z.min = 1\n"
      "  bound.z.max = 0\n  mirror.y = 1\n  mirror.z = 0\n  inversion = 1\n  units.len.f = 1000\n";
  std::string pts;
  for (int i = 0; i <= 50; ++i) pts += fmt::format("{} {}\n", i - 10, 0.01 * (i - 25) * (i - 25));
  const std::string text = "header.begin\n version = 1\n type = 0\nheader.end\nspline.begin\n" + keys + " point.begin\n" + pts +
                           " point.end\nspline.end\n";
  const Profile p = load_profile_file(write_tmp("steps.prr", text), {}, {&built_plugins()});
  // Shifted y = i, kept 5..45 by the y bounds (z bounds off: min > max), mirrored: y = -i mm.
  REQUIRE(p.size() == 41);
  CHECK(p.y.front() == within_rel(-0.045, 1e-5));
  CHECK(p.y.back() == within_rel(-0.005, 1e-5));
  // z: raw 0.01 (i - 25)^2 + 1 (shift), down -> up: z = -(0.01 (i - 25)^2 + 1) mm at y = -i.
  CHECK(p.z.front() == within_rel(-(0.01 * 400 + 1) * 1e-3, 1e-5));
  CHECK(p.z[20] == within_rel(-1e-3, 1e-5));  // i = 25
}

TEST_CASE("MiniProf reader: bad input") {
  check_error("empty.ban", "", 0, "the file is empty");
  check_error("header_only.ban", "Filename=x\nXYPoints=3\nColumnDef=X,Y\n\n", 3, "a header but no points");
  check_error("count.ban", miniprof(arc_rows("\t"), 30), 2, "XYPoints = 30 but the file holds 31 points (lines 5 .. 35)");
  check_error("nonnumeric.ban", miniprof("0\t0\n1\tz\n2\t0\n", 3), kMiniprofFirstRow + 1, "Y must be a number, got 'z'");
  check_error("nan.ban", miniprof("0\t0\nnan\t0\n2\t0\n", 3), kMiniprofFirstRow + 1, "X must be a finite number, got 'nan'");
  check_error("inf.whl", miniprof("0\t0\n1\tinf\n2\t0\n", 3), kMiniprofFirstRow + 1, "Y must be a finite number, got 'inf'");
  check_error("single.ban", miniprof("1\t2\n", 1), kMiniprofFirstRow, "only 1 point read");
  check_error("mixed.ban", miniprof("0\t0\n1,0.1\n2\t0\n", 3), kMiniprofFirstRow + 1, "mixed separators");
  check_error("columns.ban", miniprof("0\t0\t1\n", 1), kMiniprofFirstRow, "3 fields, but ColumnDef declares 2 columns");
  check_error("columndef.ban", "ColumnDef=A,B\n\n0 0\n", 1, "ColumnDef must name the columns X and Y");
  check_error("header.ban", "Filename=x\nthis is not a key\n", 2, "expected a `Key=Value` header line");
  check_error("metres.ban", miniprof(arc_rows("\t", 1e-3), 31), kMiniprofFirstRow, "total chord is 0.030");
  check_error("flat.ban", miniprof("0\t0\n1\t0\n2\t0\n", 3), kMiniprofFirstRow, "cannot tell which way Y points");
  check_error("kind.xyz", miniprof(arc_rows("\t"), 31), 0, "pass kind", [] {
    LoadOptions o;
    o.reader = "miniprof";
    return o;
  }());
  LoadOptions bad_axis;
  bad_axis.reader_options = {{"y_axis", "sideways"}};
  check_error("axis.ban", miniprof(arc_rows("\t"), 31), 0, "y_axis must be \"standard\" or \"reversed\"", bad_axis);
  CHECK(error_of(write_tmp("good.ban", miniprof(arc_rows("\t"), 31))) == "(no error)");
  CHECK(error_of(write_tmp("good_nocount.ban", "MINIPROF\nColumnDef=X,A,Y\n\n" + arc_rows("\t0\t", 1.0))) ==
        "(no error)");
}

namespace {

Profile load(const std::string& name, const std::string& text, LoadOptions o = {}) {
  return load_profile_file(write_tmp(name, text), o, {&built_plugins()});
}

bool has_transform(const Profile& p, const std::string& part) {
  for (const auto& t : p.transforms)
    if (t.find(part) != std::string::npos) return true;
  return false;
}

// The arc rows written with decimal commas (",") and `sep` between the numbers.
std::string comma_rows(const char* sep) {
  std::string s = arc_rows(sep);
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] == '.') s[i] = ',';
  return s;
}

}  // namespace

TEST_CASE("every reader skips a UTF-8 byte-order mark: the same points as without it") {
  const std::string bom = "\xEF\xBB\xBF";
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  struct Case {
    const char* ext;
    std::string text;
    LoadOptions options;
  };
  const Case cases[] = {{".txt", arc_rows(" "), rail},  // headerless: the first point used to become a "header"
                        {".csv", "y_mm,z_mm\n" + arc_rows(","), rail},
                        {".prr", simpack(arc_rows(" ")), {}},
                        {".ban", miniprof(arc_rows("\t"), 31), {}},
                        {".rai", vampire(arc_rows(" ")), {}}};
  for (const Case& c : cases) {
    INFO(c.ext);
    const Profile plain = load(std::string("plain") + c.ext, c.text, c.options);
    const Profile marked = load(std::string("bom") + c.ext, bom + c.text, c.options);
    CHECK(marked.size() == plain.size());
    CHECK(marked.y == plain.y);
    CHECK(marked.z == plain.z);
    CHECK(has_transform(marked, "byte-order mark"));
    CHECK_FALSE(has_transform(plain, "byte-order mark"));
  }
  CHECK(load("bom_plain.txt", bom + arc_rows(" "), rail).size() == 31);
  check_error("utf16.txt", "\xFF\xFE" "0\0 \0" "0\0", 1, "UTF-16", rail);
}

TEST_CASE("text reader: a line taken as a header is reported in the transforms") {
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  const Profile h = load("header.csv", "y_mm,z_mm\n" + arc_rows(","), rail);
  CHECK(h.size() == 31);
  CHECK(has_transform(h, "line 1 taken as a header (its first field 'y_mm' is not a number): 'y_mm,z_mm'"));
  // A first row mangled into a non-number is a header too, and says so (a point the user may have meant).
  const Profile lost = load("lost.txt", "x" + arc_rows(" "), rail);
  CHECK(lost.size() == 30);
  CHECK(has_transform(lost, "line 1 taken as a header"));
  CHECK_FALSE(has_transform(load("noheader.txt", arc_rows(" "), rail), "header"));
}

TEST_CASE("text reader: a header reads in any unit the units option names") {
  // The 30 mm arc written in cm, in, m and mm, each under a header naming its unit in one of the forms: every file
  // gives the arc's points in metres (y_in and z [cm] were taken for the default mm: a wheel 25.4 times too small
  // built without complaint).
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  struct Case {
    const char* header;
    double per_metre;  // file units per metre, by definition of the unit
  };
  const Case cases[] = {{"y_cm,z_cm", 100}, {"y [in],z [in]", 1 / 0.0254}, {"Y(IN),Z(IN)", 1 / 0.0254},
                        {"y_m,z_m", 1}, {"y (mm),z (mm)", 1000}};
  for (const Case& c : cases) {
    INFO(std::string(c.header));
    const Profile p = load("units.csv", std::string(c.header) + "\n" + arc_rows(",", c.per_metre / 1000), rail);
    const double written = 0.5e-6 / c.per_metre + 1e-15;  // m: arc_rows writes 6 decimals of the file's unit
    REQUIRE(p.size() == 31);
    CHECK(p.y.front() == within_abs(-15e-3, written));
    CHECK(p.y.back() == within_abs(15e-3, written));
    CHECK(p.z[15] == within_abs(0.0, written));
    CHECK(p.z.front() == within_abs(std::sqrt(0.3 * 0.3 - 0.015 * 0.015) - 0.3, written));
  }
  // A header naming no unit leaves the default, millimetres; one naming two units is refused.
  CHECK(load("nounit.csv", "y_pos,z_pos\n" + arc_rows(","), rail).y.front() == within_abs(-15e-3, 1e-12));
  check_error("two_units.csv", "y_cm,z_mm\n" + arc_rows(","), 1, "different units for y ('y_cm') and z ('z_mm')", rail);
}

TEST_CASE("every reader: decimal commas are named as such") {
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  check_error("decimal_semicolon.csv", comma_rows(";"), 1, "looks written with decimal commas", rail);
  check_error("decimal_blank.txt", comma_rows(" "), 1, "looks written with decimal commas", rail);
  check_error("decimal_header.csv", "y;z\n" + comma_rows(";"), 2, "looks written with decimal commas", rail);
  check_error("decimal.prr", simpack(comma_rows(" ")), kSimpackFirstPoint, "looks written with decimal commas");
  check_error("decimal.ban", miniprof(comma_rows("\t"), 31), kMiniprofFirstRow, "looks written with decimal commas");
  check_error("decimal.rai", vampire(comma_rows(" ")), kVampireFirstRow, "looks written with decimal commas");
  // One row among decimal points, and one value of a key.
  check_error("decimal_row.prr", simpack("0 0\n1 0.1\n2 0,2\n"), kSimpackFirstPoint + 2, "'2 0,2' looks written with decimal commas");
  check_error("decimal_key.prr", simpack(arc_rows(" "), "1000,0"), 6,
              "units.len.f must be a number, got '1000,0': a decimal comma? wrc reads a decimal point ('1000.0')");
  // Commas as separators with blanks after them are no decimal commas.
  CHECK(error_of(write_tmp("comma_blank.csv", arc_rows(", ")), rail) == "(no error)");
  CHECK(error_of(write_tmp("integers.csv", "0, 0\n10, -1\n20, -4\n30, -9\n"), rail) == "(no error)");
}

TEST_CASE("every reader: a number beyond the doubles, an underflow read as 0 and an overflow out of range") {
  // The arc's middle row (the 16th) is y = 0, z = 0 (its top); the same file with that z written as an underflow
  // (below the least denormal, 4.9e-324) must give exactly the same points, in every reader.
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  const std::string rows = arc_rows(" ");
  std::size_t middle = 0;
  for (int i = 0; i < 15; ++i) middle = rows.find('\n', middle) + 1;
  const std::size_t after = rows.find('\n', middle) + 1;
  REQUIRE(rows.substr(middle, after - middle) == "0.000000 0.000000\n");
  auto with_middle = [&](const std::string& z) { return rows.substr(0, middle) + "0 " + z + "\n" + rows.substr(after); };
  struct Case {
    const char* ext;
    std::string (*file)(const std::string& rows);
    int first_row;
    LoadOptions options;
  };
  const Case cases[] = {{".txt", [](const std::string& r) { return r; }, 1, rail},
                        {".prr", [](const std::string& r) { return simpack(r); }, kSimpackFirstPoint, {}},
                        {".ban", [](const std::string& r) { return miniprof(r, 31); }, kMiniprofFirstRow, {}},
                        {".rai", [](const std::string& r) { return vampire(r); }, kVampireFirstRow, {}}};
  for (const Case& c : cases) {
    INFO(c.ext);
    const Profile zero = load(std::string("zero") + c.ext, c.file(rows), c.options);
    for (const char* tiny : {"1e-400", "-1e-400", "0.0000001e-330", "2e-324"}) {
      INFO(tiny);
      const Profile under = load(std::string("underflow") + c.ext, c.file(with_middle(tiny)), c.options);
      CHECK(under.y == zero.y);
      CHECK(under.z == zero.z);
    }
    const int line = c.first_row + 15;
    check_error(std::string("overflow") + c.ext, c.file(with_middle("1e400")), line, "= '1e400' is out of range", c.options);
    check_error(std::string("overflow_neg") + c.ext, c.file(with_middle("-2e308")), line, "= '-2e308' is out of range", c.options);
    CHECK(error_of(write_tmp(std::string("overflow") + c.ext, c.file(with_middle("1e400"))), c.options)
              .find("must be a number") == std::string::npos);
  }
  // A denormal is itself: 1e-310 mm, the text's z = 1e-313 m, not 0.
  const Profile denormal = load("denormal.txt", with_middle("1e-310"), rail);
  CHECK(denormal.z[15] > 0);
  CHECK(denormal.z[15] < 1e-312);
  // A key's value is read by the same rule.
  check_error("overflow_key.prr", simpack(rows, "1e999"), 6, "units.len.f = '1e999' is out of range");
}

TEST_CASE("text reader: comment lines of other programs (`!`, `%`) are skipped, not taken as a header") {
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  const Profile plain = load("plain_arc.txt", arc_rows(" "), rail);
  const Profile commented = load("commented_arc.txt", "! ****\n  ! a Simpack-style comment\n% a MATLAB comment\n" + arc_rows(" "), rail);
  CHECK(commented.y == plain.y);
  CHECK(commented.z == plain.z);
  CHECK_FALSE(has_transform(commented, "header"));
  check_error("only_comments.txt", "! one\n% two\n# three\n\n", 0, "no data lines: the file holds only comments", rail);
}

TEST_CASE("every reader given another format's file names the reader that reads it") {
  // One file of each format (the samples above) given to each of the other readers, by their extension.
  const std::string rows = arc_rows(" ");
  struct Format {
    const char* id;
    const char* ext;
    std::string text;
    int first_line;  // the line that begins the format (after comments)
  };
  const Format formats[] = {{"text", ".txt", rows, 1},
                            {"simpack", ".prr", "! ****\n! exported\n" + simpack(rows), 3},
                            {"miniprof", ".ban", "MINIPROF\n" + miniprof(rows, 31), 1},
                            {"vampire", ".rai", vampire(rows), 1}};
  for (const Format& file : formats)
    for (const Format& reader : formats) {
      const std::string f = file.id, r = reader.id;
      if (f == r) continue;
      INFO(file.id << " file given to the " << reader.id << " reader");
      LoadOptions o;
      o.kind = ProfileKind::rail;
      check_error(std::string(file.id) + "_as" + reader.ext, file.text, file.first_line,
                  fmt::format("read it with reader = \"{}\"", file.id), o);
    }
}

TEST_CASE("Simpack reader: a processing key that leaves no profile is named with its line") {
  const std::string keys_then = "header.begin\n version = 1\n type = 0\nheader.end\nspline.begin\n units.len.f = 1000\n";
  for (const char* shift : {"1e308", "-2e6"}) {  // mm: 1e305 m, 2 km
    INFO(shift);
    const std::string text = keys_then + " shift.y = " + shift + "\n point.begin\n" + arc_rows(" ") + " point.end\nspline.end\n";
    check_error("far_shift.prr", text, 7, fmt::format("shift.y = '{}' is out of range", shift));
    CHECK(error_of(write_tmp("far_shift.prr", text)).find("metres?") == std::string::npos);
  }
  // A shift within the bound (999 m) is a shift.
  const std::string km = keys_then + " shift.z = 999000\n point.begin\n" + arc_rows(" ") + " point.end\nspline.end\n";
  CHECK(error_of(write_tmp("km_shift.prr", km)) == "(no error)");
  // The arc's rows are 1 mm apart in y (-15 .. 15): a minimum distance of 100 mm keeps the first only; bounds
  // 0 .. 1 mm keep 2.
  check_error("sparse.prr", keys_then + " point.dist.min = 100\n point.begin\n" + arc_rows(" ") + " point.end\nspline.end\n", 7,
              "point.dist.min = '100' leaves 1 of the 31 points; a profile needs at least 3");
  check_error("narrow.prr", keys_then + " bound.y.min = 0\n bound.y.max = 1\n point.begin\n" + arc_rows(" ") +
              " point.end\nspline.end\n", 7, "2 of the 31 points lie within bound.y.min .. bound.y.max = 0 .. 1");
}

TEST_CASE("every reader given a Lua profile definition says that it is one, and how to load it") {
  // The text reader took the definition's first comment line for a header and failed on the next line's field count.
  const std::string body = "local opt = ... or {}\nreturn wrc.profile.points{kind = \"wheel\", y = {-0.07, 0, 0.06}, "
                           "z = {0.00175, 0, -0.0015}}\n";
  for (const std::string& text : {"-- a cone 1:40, 130 mm wide\n" + body, body, "--[[ a cone ]]\n" + body}) {
    for (const char* reader : {"text", "simpack", "miniprof", "vampire"}) {
      INFO(reader << " reader, the file beginning " << text.substr(0, text.find('\n')));
      LoadOptions o;
      o.reader = reader;
      o.kind = ProfileKind::wheel;
      check_error("cone.lua", text, 1, "begins a Lua profile definition", o);
      check_error("cone.lua", text, 1, "load it without the option reader", o);
    }
  }
  // A rule of dashes under a title is no Lua comment.
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  CHECK(error_of(write_tmp("ruled.txt", "----------\n" + arc_rows(" ")), rail).find("Lua") == std::string::npos);
}

TEST_CASE("MiniProf reader: rows of numbers without the MiniProf header are refused, naming the text reader") {
  // Nothing says that bare rows are X and Y, nor which way Y points: an arc with a clear top loaded as a MiniProf rail,
  // and rows of a wheel in the engine frame came out shifted by tape_x (70 mm).
  for (const char* ext : {".ban", ".whl"}) {
    INFO(ext);
    check_error(std::string("bare") + ext, arc_rows(" "), 1, "begins a plain text profile, not a MiniProf profile, which "
                "begins with its header (MINIPROF or Key=Value lines): read it with reader = \"text\"");
    check_error(std::string("bare_comma") + ext, "! exported\n" + arc_rows(","), 2, "read it with reader = \"text\"");
  }
  // Read as the message says, the rows are the points, in mm.
  LoadOptions text;
  text.reader = "text";
  text.kind = ProfileKind::rail;
  const Profile p = load("bare_as_text.ban", arc_rows(" "), text);
  REQUIRE(p.size() == 31);
  CHECK(p.y.front() == within_rel(-0.015, 1e-9));
  CHECK(p.z[15] == within_abs(0.0, 1e-12));
  // With the header, the same rows are a MiniProf rail.
  CHECK(error_of(write_tmp("with_header.ban", "ColumnDef=X,Y\n\n" + arc_rows(" "))) == "(no error)");
}

TEST_CASE("Simpack reader: a rotate that turns the profile past vertical is named with its angle and unit") {
  // The arc's tangents lie within +-atan(15 / sqrt(300^2 - 15^2)) = +-2.866 degrees of the y axis: a rotation by more
  // than 87.134 degrees turns some past vertical, and y turns back; one by less keeps y monotone.
  const double edge = std::atan(15.0 / std::sqrt(300.0 * 300.0 - 15.0 * 15.0)) * 180 / M_PI;
  REQUIRE(edge == within_abs(2.866, 1e-3));
  auto file = [](const std::string& rotate, bool degrees) {
    return "header.begin\n version = 1\n type = 0\nheader.end\nspline.begin\n units.len.f = 1000\n rotate = " + rotate +
           "\n" + (degrees ? " units.ang.f = 57.29577951308232\n" : "") + " point.begin\n" + arc_rows(" ") +
           " point.end\nspline.end\n";
  };
  // The first row past the turn, by brute force: the rows rotated in the file's frame, y = y cos a - z sin a.
  auto turn_line = [](double degrees) {
    const double a = degrees * M_PI / 180;
    int from = 0, line = 10;  // the first point's line (after units.len.f, rotate, units.ang.f, point.begin)
    double prev = 0;
    for (int i = 0; i < 31; ++i, ++line) {
      const double y = -15.0 + i, z = std::sqrt(300.0 * 300.0 - y * y) - 300.0;
      const double yr = y * std::cos(a) - z * std::sin(a);
      if (i > 0) {
        const int d = yr > prev ? 1 : -1;
        if (from != 0 && d != from) return line;
        from = d;
      }
      prev = yr;
    }
    return 0;
  };
  const int line88 = turn_line(88);
  REQUIRE(line88 > 0);
  check_error("rotate88.prr", file("88", true), 7,
              fmt::format("rotate = '88' turns the profile by 88 degrees (units.ang.f = 57.29577951308232 per radian, "
                          "line 8): its points, monotone in y before the rotation, fold back after it at line {}", line88));
  CHECK(error_of(write_tmp("rotate86.prr", file("86", true))).find("fold") == std::string::npos);
  CHECK(turn_line(86) == 0);
  // In radians without units.ang.f: 1.6 rad is 91.67 degrees.
  check_error("rotate_rad.prr", file("1.6", false), 7, "rotate = '1.6' turns the profile by 91.6732 degrees (radians: no "
              "units.ang.f)");
}

namespace {

// One file of each format around the arc's rows (a rail, mm), and the line of its first row.
struct Layout {
  const char* ext;
  std::string (*file)(const std::string& rows);
  int first_row;
};
const Layout kLayouts[] = {{".txt", [](const std::string& r) { return r; }, 1},
                           {".prr", [](const std::string& r) { return simpack(r); }, kSimpackFirstPoint},
                           {".ban", [](const std::string& r) { return "MINIPROF\nColumnDef=X,Y\n\n" + r; }, 4},
                           {".rai", [](const std::string& r) { return vampire(r); }, kVampireFirstRow}};

// The rows up to row k (1-based), and the text of row k.
std::string rows_to(const std::string& rows, int k) {
  std::size_t end = 0;
  for (int i = 0; i < k; ++i) end = rows.find('\n', end) + 1;
  return rows.substr(0, end);
}

}  // namespace

TEST_CASE("every reader: a file cut short within its last row is named as truncated, at that row") {
  // A VAMPIRE file cut within its last number was read without a word (the number cut short, the rest of the profile
  // gone); the other readers named a field count or mixed separators. The arc's numbers have 6 decimals.
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  const std::string rows = arc_rows(" ");
  for (const Layout& f : kLayouts) {
    INFO(f.ext);
    // The file ending with row 20, then cut within that row's last number ("-0.026668" -> "-0.026") or after its y.
    const std::string all = f.file(rows_to(rows, 20));
    const std::string body = all.substr(0, f.ext == std::string(".prr") ? all.rfind('\n', all.find("point.end")) + 1 : all.size());
    const std::string cut_number = body.substr(0, body.size() - 4);  // less the line break and 3 digits
    const std::string cut_row = body.substr(0, body.rfind('\n', body.size() - 2) + 1) + "4.000000";
    const int line = f.first_row + 19;
    check_error(std::string("cut_number") + f.ext, cut_number, line, "the file ends without a line break within a number", rail);
    check_error(std::string("cut_number") + f.ext, cut_number, line, "the file is cut short (truncated)", rail);
    check_error(std::string("cut_row") + f.ext, cut_row, line, "the file ends without a line break within a row", rail);
  }
  // The rows complete, without the last line break: read, the same points as with it.
  const Profile with = load("complete.txt", rows, rail);
  const Profile without = load("no_last_break.txt", rows.substr(0, rows.size() - 1), rail);
  CHECK(without.y == with.y);
  CHECK(without.z == with.z);
  // Numbers typed by hand (fewer than 3 decimals) may end a file shorter: no truncation is claimed.
  CHECK(error_of(write_tmp("typed.txt", "0 0.25\n5 0.10\n10 0.04\n15 0.01\n20 0.00\n25 0.01\n30 0.1"), rail) ==
        "(no error)");
}

TEST_CASE("every reader: a line of text among the rows is named as one, with the way to comment it") {
  // It was "mixed separators" in a CSV file and MiniProf, a field count elsewhere.
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  const std::string rows = arc_rows(","), blank_rows = arc_rows(" ");
  for (const Layout& f : kLayouts) {
    INFO(f.ext);
    const std::string& r = f.ext == std::string(".txt") || f.ext == std::string(".ban") ? rows : blank_rows;
    const std::string file = f.file(r), before = rows_to(file, f.first_row + 9);  // the file to row 10
    const std::string text = before + "this line is text\n" + file.substr(before.size());
    check_error(std::string("text_line") + f.ext, text, f.first_row + 10, "'this line is text' is a line of text among the",
                rail);
    check_error(std::string("text_line") + f.ext, text, f.first_row + 10, "make it a comment", rail);
  }
  // A row with a word after its numbers keeps its own message: the field.
  check_error("word.txt", rows_to(blank_rows, 10) + "1 2 abc\n" + blank_rows.substr(rows_to(blank_rows, 10).size()), 11,
              "3 fields, but the data has 2 per line (as on line 1): '1 2 abc'", rail);
}

TEST_CASE("a single mistyped point is named with its line: far from the rest (not a unit), or a spike") {
  LoadOptions rail;
  rail.kind = ProfileKind::rail;
  const std::string rows = arc_rows(" ");
  // Row 10 (y = -6 mm) written x100: -600 mm, 1.2 m of detour; the rest is the 30 mm arc. It was blamed on the unit.
  const double y10 = -6.0, z10 = std::sqrt(300.0 * 300.0 - 36.0) - 300.0;
  const std::string far = rows_to(rows, 9) + fmt::format("{:.6f} {:.6f}\n", 100 * y10, 100 * z10) + rows.substr(rows_to(rows, 10).size());
  check_error("far_point.txt", far, 10, "the point y = -600, z = ", rail);
  check_error("far_point.txt", far, 10, "a mistyped point?", rail);
  CHECK(error_of(write_tmp("far_point.txt", far), rail).find("units are probably wrong") == std::string::npos);
  // The same row 50 mm below the arc, between neighbours 2 mm apart: a spike (slope 25 both ways), named with how far
  // it sticks out beyond the lower neighbour (row 9, y = -7 mm; rows 9 and 11 are the arc at y = -7 and -5 mm).
  const auto written = [](double v) { return std::round(v * 1e6) / 1e6; };  // as the file holds it, 6 decimals
  const double z9 = written(std::sqrt(300.0 * 300.0 - 49.0) - 300.0), low = written(z10 - 50);
  const std::string spike = rows_to(rows, 9) + fmt::format("{:.6f} {:.6f}\n", y10, low) + rows.substr(rows_to(rows, 10).size());
  check_error("spike.txt", spike, 10, fmt::format("sticks out {:.6g} mm below its neighbours", z9 - low), rail);
  // 30 mm below (slope 15): a steep dip, not refused as a spike.
  const std::string dip = rows_to(rows, 9) + fmt::format("{:.6f} {:.6f}\n", y10, z10 - 30) + rows.substr(rows_to(rows, 10).size());
  CHECK(error_of(write_tmp("dip.txt", dip), rail).find("spike") == std::string::npos);
  // A unit still named as one, its lines in increasing order when the file reverses its points (inversion = 1).
  const std::string inverted = "header.begin\n version = 1\n type = 0\nheader.end\nspline.begin\n inversion = 1\n point.begin\n" +
                               arc_rows(" ", 1e-3) + " point.end\nspline.end\n";
  check_error("metres_inverted.prr", inverted, 8, "(points of lines 8 .. 38)");
}
