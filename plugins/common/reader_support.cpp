#include "reader_support.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>

namespace wrc::plugin {

std::vector<Line> split_lines(std::string_view data) {
  std::vector<Line> lines;
  int number = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const char c = data[i];
    if (c == '\0') fail_at(number, "unexpected NUL byte: this is not a text file");
    if (c == '\n' || c == '\r') {
      lines.push_back({data.substr(start, i - start), number++});
      if (c == '\r' && i + 1 < data.size() && data[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < data.size()) lines.push_back({data.substr(start), number});
  return lines;
}

std::string_view trim(std::string_view s) {
  const char* blanks = " \t\v\f";
  const auto b = s.find_first_not_of(blanks);
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(blanks);
  return s.substr(b, e - b + 1);
}

std::string_view strip_comment(std::string_view s, std::string_view comment_chars) {
  const auto p = s.find_first_of(comment_chars);
  return p == std::string_view::npos ? s : s.substr(0, p);
}

std::vector<std::string_view> split_fields(std::string_view s, char separator) {
  std::vector<std::string_view> out;
  if (separator == ' ') {
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
      if (i >= s.size()) break;
      std::size_t j = i;
      while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
      out.push_back(s.substr(i, j - i));
      i = j;
    }
    return out;
  }
  std::size_t start = 0;
  while (true) {
    const auto p = s.find(separator, start);
    out.push_back(trim(s.substr(start, p == std::string_view::npos ? std::string_view::npos : p - start)));
    if (p == std::string_view::npos) break;
    start = p + 1;
  }
  return out;
}

namespace {

// The power of ten of the leading digit of a well-formed decimal number (digits, an optional '.', an optional exponent;
// no sign): "1e400" -> 400, "0.012e-400" -> -402. from_chars leaves a number out of range unread; this says which way.
long leading_power(std::string_view s) {
  const auto e = std::min(s.find_first_of("eE"), s.size());
  long exponent = 0;
  if (e < s.size()) {
    std::string_view x = s.substr(e + 1);
    const bool negative = !x.empty() && x.front() == '-';
    if (!x.empty() && (x.front() == '-' || x.front() == '+')) x.remove_prefix(1);
    for (const char c : x) exponent = std::min(10 * exponent + (c - '0'), 1'000'000'000L);  // saturates: far out either way
    if (negative) exponent = -exponent;
  }
  const std::string_view mantissa = s.substr(0, e);
  const auto point = std::min(mantissa.find('.'), mantissa.size());
  const auto first = mantissa.find_first_of("123456789");  // exists: a zero mantissa is never out of range
  const long digit = static_cast<long>(first) - (first > point ? 1 : 0);  // its index among the digits
  return exponent + static_cast<long>(point) - 1 - digit;
}

}  // namespace

std::optional<double> parse_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || s.front() == '+') return std::nullopt;
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ptr != s.data() + s.size()) return std::nullopt;
  if (r.ec == std::errc::result_out_of_range) {
    // Beyond the doubles (|v| < 2.5e-324 or > 1.8e308): an underflow is 0 to any precision a profile has; an overflow
    // reads as +-inf, which `number` refuses as out of range.
    const bool negative = s.front() == '-';
    if (negative) s.remove_prefix(1);
    const double magnitude = leading_power(s) < 0 ? 0.0 : std::numeric_limits<double>::infinity();
    return negative ? -magnitude : magnitude;
  }
  if (r.ec != std::errc()) return std::nullopt;
  return v;
}

std::string quoted(std::string_view s) {
  std::string out = "'";
  std::size_t n = 0;
  for (char c : s) {
    if (++n > 40) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7f) out += fmt::format("\\x{:02x}", u);
    else out += c;
  }
  return out + "'";
}

namespace {

std::string with_points(std::string_view s) {
  std::string t(s);
  std::replace(t.begin(), t.end(), ',', '.');
  return t;
}

bool all_numbers(const std::vector<std::string_view>& fields) {
  return std::all_of(fields.begin(), fields.end(), [](std::string_view f) { return parse_double(f).has_value(); });
}

}  // namespace

void reject_decimal_commas(std::string_view row, int line) {
  if (row.find(',') == std::string_view::npos || all_numbers(split_fields(row, ','))) return;
  const std::string dotted = with_points(row);
  const auto fields = split_fields(dotted, dotted.find(';') != std::string::npos ? ';' : ' ');
  if (fields.size() >= 2 && all_numbers(fields))
    fail_at(line, "{} looks written with decimal commas; wrc reads numbers with a decimal point ({}): replace the "
            "decimal commas, or export the file with '.' as the decimal separator", quoted(row), quoted(dotted));
}

void refuse_text_row(std::string_view row, int line, std::string_view rows, std::string_view comment) {
  std::string fields(row);
  for (char& c : fields)
    if (c == ',' || c == ';') c = ' ';
  for (const std::string_view f : split_fields(fields, ' '))
    if (parse_double(f)) return;
  fail_at(line, "{} is a line of text among the {}, which are numbers: remove it, or make it a comment ({})", quoted(row),
          rows, comment);
}

double number(std::string_view field, int line, std::string_view what) {
  const auto v = parse_double(field);
  if (!v && field.find(',') != std::string_view::npos && parse_double(with_points(field)))
    fail_at(line, "{} must be a number, got {}: a decimal comma? wrc reads a decimal point ({})", what, quoted(field),
            quoted(with_points(field)));
  if (!v) fail_at(line, "{} must be a number, got {}", what, quoted(field));
  if (std::isinf(*v) && field.find_first_of("nN") == std::string_view::npos)  // digits, not "inf"
    fail_at(line, "{} = {} is out of range: a number's magnitude must be below {:.2g}", what, quoted(field),
            std::numeric_limits<double>::max());
  if (!std::isfinite(*v)) fail_at(line, "{} must be a finite number, got {}", what, quoted(field));
  return *v;
}

namespace {

struct Format {
  const char *name, *id, *advice;  // what the file is, the reader that reads it (null: none), how to read it
};

// A Lua chunk's first line: a comment (`-- text`, `--[[`), or a statement that a profile definition begins with
// (`local opt = ...`). A line of dashes (a rule under a table's title) is none.
bool begins_lua(std::string_view s) {
  const auto word_then = [&](std::string_view word, std::string_view next) {
    return s.substr(0, word.size()) == word && (s.size() == word.size() || next.find(s[word.size()]) != std::string_view::npos);
  };
  return word_then("--", " \t[") || word_then("local", " \t") || word_then("return", " \t{(") ||
         word_then("function", " \t");
}

// The format a file's first content line begins, or null.
const Format* format_begun_by(std::string_view s) {
  static const Format simpack{"a Simpack profile", "simpack",
                              "read it with reader = \"simpack\", or give the file the extension .prr (rail) or .prw (wheel)"};
  static const Format miniprof{"a MiniProf profile", "miniprof",
                               "read it with reader = \"miniprof\", or give the file the extension .ban (rail) or .whl (wheel)"};
  static const Format vampire{"a VAMPIRE profile", "vampire",
                              "read it with reader = \"vampire\", or give the file the extension .rai (rail) or .whe (wheel)"};
  static const Format text{"a plain text profile", "text",
                           "read it with reader = \"text\", or give the file the extension .txt, .csv or .dat"};
  // Not a file that a reader reads: a program, which wrc.profile.load runs when the name ends in .lua and no reader
  // is named (docs/guide/profiles.md, "Writing a profile definition in Lua").
  static const Format lua{"a Lua profile definition", nullptr,
                          "load it without the option reader: wrc.profile.load runs a file whose name ends in .lua as "
                          "a definition"};
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const bool one_field = s.find_first_of(" \t,;") == std::string_view::npos;
  if (s == "header.begin" || s == "spline.begin") return &simpack;
  if (u == "MINIPROF" || (one_field && s.find('=') != std::string_view::npos)) return &miniprof;
  if (u == "WHEELPROFILE" || u == "RAILPROFILE") return &vampire;
  if (begins_lua(s)) return &lua;
  const auto fields = split_fields(s, s.find(',') != std::string_view::npos ? ',' : s.find(';') != std::string_view::npos ? ';' : ' ');
  if (fields.size() >= 2 && all_numbers(fields)) return &text;
  return nullptr;
}

}  // namespace

void refuse_other_format(const std::vector<Line>& lines, std::string_view self, std::string_view self_reads) {
  for (const Line& ln : lines) {
    const std::string_view s = trim(strip_comment(ln.text, "!%#"));
    if (s.empty()) continue;
    const Format* f = format_begun_by(s);
    if (f && (!f->id || f->id != self)) fail_at(ln.number, "{} begins {}, not {}: {}", quoted(s), f->name, self_reads, f->advice);
    return;
  }
}

const std::string* Request::option(std::string_view key) const {
  for (const auto& [k, v] : options)
    if (k == key) return &v;
  return nullptr;
}

std::optional<bool> Request::flag(std::string_view key) const {
  const std::string* v = option(key);
  if (!v) return std::nullopt;
  if (*v == "true") return true;
  if (*v == "false") return false;
  fail_at(0, "option {} must be true or false, got {}", key, quoted(*v));
}

void Out::point(double y, double z, int line) {
  if (sink_->point(sink_->host, y, z, line) != 0) throw ParseError(line, "");  // the host has the reason
  ++points_;
}

void Out::reversed(int axis, const std::string& undo) {
  // The callback exists from ABI 1.1 on: a host built before it passes a smaller sink.
  const std::size_t end = offsetof(wrc_reader_sink, reversed) + sizeof(sink_->reversed);
  if (sink_->struct_size >= end && sink_->reversed) sink_->reversed(sink_->host, axis, undo.c_str());
}

namespace {

Request make_request(const wrc_reader_request* r) {
  Request q;
  q.path = r->path ? r->path : "";
  q.kind_hint = r->kind_hint;
  for (std::size_t i = 0; i < r->option_count; ++i)
    q.options.emplace_back(r->options[i].key ? r->options[i].key : "", r->options[i].value ? r->options[i].value : "");
  return q;
}

void report(const wrc_reader_sink* sink, int line, const char* message) {
  if (message && *message) sink->error(sink->host, line, message);
}

bool read_file(const std::string& path, std::string& data, std::string& why) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    why = fmt::format("cannot open the file: {}", std::strerror(errno));
    return false;
  }
  char buf[65536];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
    if (data.size() + n > kMaxFileBytes) {
      std::fclose(f);
      why = fmt::format("the file is larger than {} MB; this is not a profile", kMaxFileBytes >> 20);
      return false;
    }
    data.append(buf, n);
  }
  const bool err = std::ferror(f) != 0;
  std::fclose(f);
  if (err) {
    why = "read error";
    return false;
  }
  return true;
}

}  // namespace

namespace {

// How a number is written: the digits after its point and of its exponent (-1: none), as a program writes every
// number of a column; nullopt for a field that is no plain number.
std::optional<std::pair<int, int>> written_shape(std::string_view t) {
  if (!t.empty() && (t.front() == '-' || t.front() == '+' || t.front() == '"')) t.remove_prefix(1);
  const auto e = std::min(t.find_first_of("eE"), t.size()), point = t.find('.');
  const std::string_view mantissa = t.substr(0, e), exponent = e < t.size() ? t.substr(e + 1) : std::string_view();
  const auto digits = [](std::string_view d) { return d.find_first_not_of("0123456789") == std::string_view::npos; };
  if (point == std::string_view::npos || point >= e || !digits(mantissa.substr(0, point)) || !digits(mantissa.substr(point + 1)))
    return std::nullopt;
  const std::string_view exponent_digits = exponent.substr(!exponent.empty() && (exponent.front() == '-' || exponent.front() == '+'));
  if (e < t.size() && (exponent_digits.empty() || !digits(exponent_digits)))
    return std::pair{static_cast<int>(mantissa.size() - point - 1), -2};  // an exponent cut short
  return std::pair{static_cast<int>(mantissa.size() - point - 1), e < t.size() ? static_cast<int>(exponent.size()) : -1};
}

std::vector<std::string_view> row_fields(std::string_view s) {
  std::string_view t = trim(s);
  return split_fields(t, t.find(',') != std::string_view::npos ? ',' : t.find(';') != std::string_view::npos ? ';' : ' ');
}

// A file cut short: its last line has no line break, and it holds fewer fields than each of the rows before it, or its
// last number is written shorter than that column's on each of them (a program writes a column with one number of
// digits). Any reader would read the cut number as another value, or find a row with too few fields; the last row
// of a VAMPIRE file cut within its last number was read without a word.
void refuse_truncated(std::string_view data) {
  if (data.empty() || data.back() == '\n' || data.back() == '\r') return;
  const auto lines = split_lines(data);
  constexpr std::size_t kRows = 5;  // rows before the last that must agree
  std::vector<std::vector<std::string_view>> before;
  for (std::size_t i = lines.size() - 1; i-- > 0 && before.size() < kRows;)
    if (!trim(lines[i].text).empty()) before.push_back(row_fields(lines[i].text));
  if (before.size() < kRows) return;
  const Line& last = lines.back();
  const auto fields = row_fields(last.text);
  const std::size_t n = before.front().size();
  if (n < 2 || fields.empty() || std::any_of(before.begin(), before.end(), [&](const auto& f) { return f.size() != n; }))
    return;
  const auto shape = written_shape(before.front().back());
  if (!shape || std::any_of(before.begin(), before.end(), [&](const auto& f) { return written_shape(f.back()) != shape; }))
    return;
  if (fields.size() < n)
    fail_at(last.number, "the file ends without a line break within a row: {} holds {} of the {} fields of the rows "
            "before it; the file is cut short (truncated)", quoted(last.text), fields.size(), n);
  // Shorter: fewer digits after the point, or fewer in the exponent (or none), than a column written by a program
  // (3 digits or more after the point: a number typed by hand may well end a file with fewer).
  const auto cut = written_shape(fields.back());
  const bool shorter = !cut || cut->first < shape->first || (cut->first == shape->first && cut->second < shape->second);
  if (fields.size() == n && shape->first >= 3 && shorter)
    fail_at(last.number, "the file ends without a line break within a number: {} is written shorter than the same "
            "column on the rows before it ({}); the file is cut short (truncated)", quoted(fields.back()),
            quoted(before.front().back()));
}

}  // namespace

int run_reader_on(const ReaderSpec& spec, std::string_view data, const wrc_reader_request* request,
                  const wrc_reader_sink* sink) {
  try {
    const Request q = make_request(request);
    Out out(sink);
    if (data.substr(0, 2) == "\xff\xfe" || data.substr(0, 2) == "\xfe\xff")
      fail_at(1, "the file is UTF-16 text (it starts with a UTF-16 byte-order mark); save it as UTF-8 or ASCII");
    if (data.substr(0, 3) == "\xef\xbb\xbf") {
      data.remove_prefix(3);
      out.transform("skipped the UTF-8 byte-order mark at the start of the file");
    }
    refuse_truncated(data);
    spec.parse(data, q, out);
    return 0;
  } catch (const ParseError& e) {
    report(sink, e.line, e.what());
  } catch (const std::bad_alloc&) {
    report(sink, 0, "out of memory");
  } catch (const std::exception& e) {
    report(sink, 0, e.what());
  } catch (...) {
    report(sink, 0, "unknown internal error");
  }
  return 1;
}

int run_reader(const ReaderSpec& spec, const wrc_reader_request* request, const wrc_reader_sink* sink) {
  try {
    std::string data, why;
    if (!read_file(request->path ? request->path : "", data, why)) {
      report(sink, 0, why.c_str());
      return 1;
    }
    return run_reader_on(spec, data, request, sink);
  } catch (...) {
    report(sink, 0, "out of memory");
    return 1;
  }
}

}  // namespace wrc::plugin
