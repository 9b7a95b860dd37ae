// Engine errors. Every engine failure is a wrc::Error whose message names what is wrong and where
// (file:line, key, parameter) and what was expected; the Lua binding turns it into a Lua error.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace wrc {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Numbers in messages. fmt writes a NaN as "nan", or "-nan" when its sign bit is set (Lua's 0/0 is), which reads as
// a stray word or a negative; a message writes it "NaN" (infinities stay "inf" and "-inf", as Lua, Python and C write
// them). A number wrapped in MessageNumber is formatted so, with the format specification of a double otherwise.
struct MessageNumber {
  double value;
};

}  // namespace wrc

template <>
struct fmt::formatter<wrc::MessageNumber> : fmt::formatter<double> {
  template <class Context>
  auto format(wrc::MessageNumber n, Context& ctx) const {
    if (std::isnan(n.value)) return fmt::format_to(ctx.out(), "NaN");
    return fmt::formatter<double>::format(n.value, ctx);
  }
};

namespace wrc {

// The arguments of a message: floating-point ones wrapped in MessageNumber, the others as given.
template <class T>
decltype(auto) message_argument(const T& v) {
  if constexpr (std::is_floating_point_v<T>) return MessageNumber{static_cast<double>(v)};
  else return (v);
}

// A message formatted with its numbers as above (the format checked at compile time against the arguments).
template <class... Args>
std::string format_message(fmt::format_string<Args...> format, Args&&... args) {
  return [&](const auto&... shown) { return fmt::vformat(fmt::string_view(format), fmt::make_format_args(shown...)); }(
      message_argument(args)...);
}

// A number as text the user reads (an option value passed on as text, a message built in parts): "{}" with NaN
// written "NaN".
inline std::string number_text(double v) { return format_message("{}", v); }

// Throws wrc::Error with a message formatted by format_message().
template <class... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw Error(format_message(format, std::forward<Args>(args)...));
}

// Positions in messages. The front ends count from 1 (Lua, MATLAB) or from 0 (Python, C), so "y[2]" means a
// different element to each; a message names an element by its ordinal instead, which reads the same from all of
// them: value_at(1, "'y'") is "the 2nd value of 'y'". `index` counts from 0, as the engine's arrays do.
inline std::string ordinal(std::size_t n) {  // 1 -> "1st", 2 -> "2nd", 12 -> "12th", 23 -> "23rd"
  const std::size_t tens = n % 100, units = n % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : units == 1                ? "st"
                       : units == 2                ? "nd"
                       : units == 3                ? "rd"
                                                   : "th";
  return fmt::format("{}{}", n, suffix);
}
inline std::string value_at(std::size_t index, std::string_view of) {
  return fmt::format("the {} value of {}", ordinal(index + 1), of);
}

}  // namespace wrc
