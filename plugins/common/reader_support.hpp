// Shared code of the project's reader plugins (compiled into each plugin; not part of the ABI): line
// splitting, strict number parsing, an exception-based error path that ends at the ABI boundary, and
// the descriptor/entry point built from a ReaderSpec (reader_entry.cpp).
#pragma once

#include "wrc/core/error.hpp"  // format_message: numbers in messages as the engine writes them (NaN)
#include "wrc/reader.h"

#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wrc::plugin {

// A failure at a source line; caught at the ABI boundary and handed to sink->error.
struct ParseError : std::runtime_error {
  int line;
  ParseError(int line_, const std::string& message) : std::runtime_error(message), line(line_) {}
};

template <class... Args>
[[noreturn]] void fail_at(int line, fmt::format_string<Args...> format, Args&&... args) {
  throw ParseError(line, format_message(format, std::forward<Args>(args)...));
}

struct Line {
  std::string_view text;
  int number;  // 1-based
};

// Splits on \n, \r\n or \r. Rejects a NUL byte (a binary file) with its line.
std::vector<Line> split_lines(std::string_view data);

std::string_view trim(std::string_view s);
// The part before the first of the comment characters.
std::string_view strip_comment(std::string_view s, std::string_view comment_chars);
// Fields separated by blanks (spaces, tabs), or by `separator` (with blanks around fields trimmed).
std::vector<std::string_view> split_fields(std::string_view s, char separator);

// Strict number: optional sign, digits, '.', exponent; nothing else. NaN and Inf are parsed so that
// the caller can say so; use `number` below for the checked version. A number too small for a double
// (1e-400) reads as 0 with its sign (a denormal such as 1e-310 as itself); one too large (1e400) as +-inf.
std::optional<double> parse_double(std::string_view s);
// A finite number or a ParseError naming the line, the field and what it is (not a number, out of range, NaN/Inf).
double number(std::string_view field, int line, std::string_view what);
// Printable form of a field for messages (quoted, shortened, control bytes escaped).
std::string quoted(std::string_view s);
// A ParseError when a data row looks written with decimal commas ("1,5;2,3", "1,5 2,3"): read with decimal points
// it splits (on ';' or blanks) into two or more numbers, while split on its commas it does not.
void reject_decimal_commas(std::string_view row, int line);

// A ParseError when a data row holds no number at all (a line of text among the rows), naming the rows it is among
// ("points y z") and how a comment starts in the format ("a line that starts with #"); otherwise returns, and the
// reader checks the row's fields.
void refuse_text_row(std::string_view row, int line, std::string_view rows, std::string_view comment);

// Where a file fails to begin as the reader `self` reads it: when its first line that is not blank or a comment (`!`,
// `%`, `#`) begins a file of another format the project reads (Simpack header.begin or spline.begin; MiniProf MINIPROF
// or a Key=Value line without blanks; VAMPIRE WHEELPROFILE or RAILPROFILE; plain text a row of two or more numbers),
// a ParseError at that line naming the reader to use and its extensions; when it begins a Lua profile definition
// (`-- comment`, `local`, `return`), one saying so and how to load it. Returns when it begins no other format.
void refuse_other_format(const std::vector<Line>& lines, std::string_view self, std::string_view self_reads);

// The request as the parser sees it.
struct Request {
  std::string path;
  int kind_hint = WRC_KIND_UNKNOWN;
  std::vector<std::pair<std::string, std::string>> options;
  const std::string* option(std::string_view key) const;
  // Boolean option ("true"/"false"); error naming the key otherwise.
  std::optional<bool> flag(std::string_view key) const;
};

// The sink as the parser sees it. point() throws ParseError when the host refuses a point.
class Out {
 public:
  explicit Out(const wrc_reader_sink* sink) : sink_(sink) {}
  void point(double y, double z, int line);
  void kind(int kind) { sink_->kind(sink_->host, kind); }
  void units(double metres_per_unit, const std::string& declared_by) { sink_->units(sink_->host, metres_per_unit, declared_by.c_str()); }
  void transform(const std::string& description) { sink_->transform(sink_->host, description.c_str()); }
  void metadata(const std::string& key, const std::string& value) { sink_->metadata(sink_->host, key.c_str(), value.c_str()); }
  // A file's step that reversed axis WRC_AXIS_Y or WRC_AXIS_Z, and how to undo it; nothing for a host of ABI 1.0.
  void reversed(int axis, const std::string& undo);
  std::size_t points() const { return points_; }

 private:
  const wrc_reader_sink* sink_;
  std::size_t points_ = 0;
};

// A reader: what its descriptor says and its parser (data = the whole file).
struct ReaderSpec {
  const char* id;
  const char* description;
  const char* const* extensions;  // NULL-terminated
  const char* const* options;     // NULL-terminated
  void (*parse)(std::string_view data, const Request& request, Out& out);
};

// Runs spec.parse on the file of the request; every exception ends here as sink->error. A UTF-8 byte-order mark
// at the start is skipped (and reported as a transform) before the parser sees the data; a UTF-16 one is an error.
// Returns the value of the ABI's read function.
int run_reader(const ReaderSpec& spec, const wrc_reader_request* request, const wrc_reader_sink* sink);
// The same on data already in memory (fuzz targets).
int run_reader_on(const ReaderSpec& spec, std::string_view data, const wrc_reader_request* request,
                  const wrc_reader_sink* sink);

// Files larger than this are refused (a profile is a few hundred kB at most).
inline constexpr std::size_t kMaxFileBytes = 64u << 20;

}  // namespace wrc::plugin
