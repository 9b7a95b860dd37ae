// Plain text / CSV profiles: two columns `y z` (or the columns chosen by the `columns` option), in the
// engine orientation (left-side frame, y toward the field side, z up), millimetres unless the header
// names the unit (y_mm / y_m, as wrc's own CSV tables do; z [cm], y (in): the names of `units`) or the user passes
// `units`.
// `#` starts a comment, and so does `!` or `%` as a line's first character (the comment lines other programs
// write: Simpack, MiniProf, VAMPIRE, MATLAB); one optional header line before the data; fields separated by
// commas, semicolons, or blanks (spaces/tabs), the same on every line. A first line that begins another
// format the engine reads (header.begin, MINIPROF, WHEELPROFILE, ...) is refused naming that format's reader:
// each of those lines is one field, and a header of one field never matches data of two or more.
#include "reader_support.hpp"
#include "wrc/profile/units.hpp"

#include <algorithm>

namespace wrc::plugin {
namespace {

const char* const kExtensions[] = {".txt", ".csv", ".dat", nullptr};
const char* const kOptions[] = {"columns", nullptr};

const char* separator_name(char sep) { return sep == ',' ? "commas" : sep == ';' ? "semicolons" : "blanks"; }

char detect_separator(std::string_view s) {
  if (s.find(',') != std::string_view::npos) return ',';
  if (s.find(';') != std::string_view::npos) return ';';
  return ' ';
}

// `columns = "2,3"`: 1-based columns of y and z.
std::pair<std::size_t, std::size_t> parse_columns(const Request& rq) {
  const std::string* c = rq.option("columns");
  if (!c) return {0, 1};
  const auto f = split_fields(*c, ',');
  auto col = [&](std::string_view s) -> std::size_t {
    const auto v = parse_double(s);
    if (!v || *v < 1 || *v > 1000 || *v != static_cast<double>(static_cast<int>(*v)))
      fail_at(0, "option columns must be two column numbers \"y,z\" (1-based), got {}", quoted(*c));
    return static_cast<std::size_t>(*v) - 1;
  };
  if (f.size() != 2) fail_at(0, "option columns must be two column numbers \"y,z\" (1-based), got {}", quoted(*c));
  const std::size_t cy = col(f[0]), cz = col(f[1]);
  if (cy == cz) fail_at(0, "option columns names column {} for both y and z", cy + 1);
  return {cy, cz};
}

// The line without its comment: from `#` on, or all of it when it starts with `!` or `%`.
std::string_view content(std::string_view line) {
  const std::string_view s = trim(strip_comment(line, "#"));
  return !s.empty() && (s.front() == '!' || s.front() == '%') ? std::string_view() : s;
}

// Unit named by a header field, metres per unit, or 0 when none: the field's last part after '_', or within brackets
// or parentheses ("y_mm", "z [cm]", "Y(in)"), any of the names the `units` option takes (y_in was read as mm).
double header_unit(std::string_view h) {
  std::string s(trim(h));
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string_view unit;
  if (!s.empty() && (s.back() == ']' || s.back() == ')')) {
    const std::size_t open = s.find_last_of(s.back() == ']' ? '[' : '(');
    if (open == std::string::npos) return 0;
    unit = trim(std::string_view(s).substr(open + 1, s.size() - open - 2));
  } else if (const std::size_t under = s.find_last_of('_'); under != std::string::npos) {
    unit = std::string_view(s).substr(under + 1);
  }
  return length_unit(unit);
}

void parse(std::string_view data, const Request& rq, Out& out) {
  const auto [cy, cz] = parse_columns(rq);
  const auto lines = split_lines(data);
  char sep = 0;
  int first_data_line = 0, header_line = 0;
  std::size_t fields_per_line = 0;
  std::vector<std::string_view> header;
  for (const Line& ln : lines) {
    const std::string_view s = content(ln.text);
    if (s.empty()) continue;
    reject_decimal_commas(s, ln.number);
    if (sep == 0) {
      // The first content line: a header when its first field is not a number (said in the transforms: a line
      // taken as a header is a point lost if it was meant as data).
      const char guess = detect_separator(s);
      const auto f = split_fields(s, guess);
      if (header_line == 0 && !parse_double(f[0])) {
        refuse_other_format(lines, "text", "columns of numbers");
        header_line = ln.number;
        header = f;
        out.metadata("header", std::string(s));
        out.transform(fmt::format("line {} taken as a header (its first field {} is not a number): {}", ln.number,
                                  quoted(f[0]), quoted(s)));
        continue;
      }
      sep = guess;
      first_data_line = ln.number;
      fields_per_line = f.size();
      if (fields_per_line < 2) fail_at(ln.number, "a data line needs at least 2 fields (y z), got {}", fields_per_line);
      if (std::max(cy, cz) >= fields_per_line)
        fail_at(ln.number, "option columns asks for column {}, but the data has {} columns", std::max(cy, cz) + 1, fields_per_line);
      if (!header.empty() && header.size() != fields_per_line)
        fail_at(ln.number, "{} fields, but the header (line {}) names {} columns: {}", fields_per_line, header_line, header.size(),
                quoted(s));
    } else {
      refuse_text_row(s, ln.number, "data rows", "a line that starts with #, ! or %");
      // The same separator on every line.
      const char other = detect_separator(s);
      if (other != sep)
        fail_at(ln.number, "fields separated by {}, but the data from line {} is separated by {} (mixed separators)",
                separator_name(other), first_data_line, separator_name(sep));
      if (sep == ',' && s.find(';') != std::string_view::npos)
        fail_at(ln.number, "both commas and semicolons on one line (mixed separators)");
    }
    const auto f = split_fields(s, sep);
    if (f.size() != fields_per_line)
      fail_at(ln.number, "{} fields, but the data has {} per line (as on line {}): {}", f.size(), fields_per_line, first_data_line,
              quoted(s));
    const double y = number(f[cy], ln.number, fmt::format("y (column {})", cy + 1));
    const double z = number(f[cz], ln.number, fmt::format("z (column {})", cz + 1));
    out.point(y, z, ln.number);
  }
  if (lines.empty()) fail_at(0, "the file is empty (no data lines)");
  if (header_line == 0 && sep == 0) fail_at(0, "no data lines: the file holds only comments and blank lines");
  if (sep == 0) fail_at(header_line, "a header line but no data lines after it");
  if (fields_per_line != 2 || cy != 0 || cz != 1)
    out.transform(fmt::format("columns {} and {} of {} taken as y and z", cy + 1, cz + 1, fields_per_line));
  if (!header.empty()) {
    const double uy = header_unit(header[cy]), uz = header_unit(header[cz]);
    if (uy != 0 && uy == uz)
      out.units(uy, fmt::format("header {} {} (line {})", quoted(header[cy]), quoted(header[cz]), header_line));
    else if (uy != uz)
      fail_at(header_line, "the header names different units for y ({}) and z ({})", quoted(header[cy]), quoted(header[cz]));
  }
}

}  // namespace

extern const ReaderSpec text_reader;
const ReaderSpec text_reader = {"text", "plain text / CSV: columns y z (engine orientation), mm unless told",
                                kExtensions, kOptions, parse};

}  // namespace wrc::plugin
