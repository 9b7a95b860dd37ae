// Engine errors. Every engine failure is a wrc::Error whose message names what is wrong and where
// (file:line, key, parameter) and what was expected; the Lua binding turns it into a Lua error.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>
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

}  // namespace wrc
