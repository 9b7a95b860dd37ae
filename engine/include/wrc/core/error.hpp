// Engine errors. Every engine failure is a wrc::Error whose message names what is wrong and where
// (file:line, key, parameter) and what was expected; the Lua binding turns it into a Lua error.
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace wrc {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws wrc::Error with a fmt-formatted message.
template <class... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw Error(fmt::format(format, std::forward<Args>(args)...));
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
