// The operations of the call layer (calls.hpp) by name, each with its options as its reader describes them (an
// OptionReader in documenting mode runs X::read): for help texts, generated references and a front end that takes
// keyword arguments (Python).
#pragma once

#include "wrc/core/options.hpp"

#include <string>
#include <vector>

namespace wrc::api {

struct Operation {
  std::string name;                 // "contact"
  std::string lua, c;               // the Lua and C entries ("wheelset:contact", "wrc_contact"; "" when none)
  std::vector<OptionInfo> options;  // every key, with type, unit, help, default, choices, required
};

// Every operation, in a fixed order.
const std::vector<Operation>& operations();
// The operation called `name`; throws wrc::Error listing the names when there is none.
const Operation& operation(const std::string& name);

}  // namespace wrc::api
