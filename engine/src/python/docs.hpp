// Help texts and the type stub of the Python module, made from the one description of every operation's options
// (api::operations()): no option is listed twice. No Python in here: the stub generator (stub_main.cpp) and the
// module (module.cpp) both use it.
#pragma once

#include "wrc/api/operations.hpp"

#include <string>
#include <vector>

namespace wrc::python {

// Where an operation appears in Python: `python` ("Wheelset.contact"), the result it returns and one line of what it
// does.
struct PythonEntry {
  std::string operation;  // api::operations() name ("contact"); "" for an entry with no options
  std::string python;     // "wheelset", "Wheelset.contact", "profile.load"
  std::string signature;  // the positional part before the options ("self", "path"; "" for none)
  std::string returns;    // "Result", "Profile", "pandas.DataFrame"
  std::string summary;    // one line
};

// Every function and method of the module that takes options.
const std::vector<PythonEntry>& python_entries();
const PythonEntry& python_entry(const std::string& python);

// The docstring of an entry: its summary, the Lua and C twins, then each option with its type, unit, default and help.
std::string docstring(const PythonEntry& entry);

// The text of wrc/__init__.pyi.
std::string stub();

}  // namespace wrc::python
