#include "python/docs.hpp"

#include "wrc/api/batch.hpp"
#include "wrc/core/error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace wrc::python {

const std::vector<PythonEntry>& python_entries() {
  static const std::vector<PythonEntry> all = {
      {"profile_load", "profile.load", "path", "Profile", "Loads a profile: a Lua definition or a file of any reader."},
      {"wheelset", "wheelset", "", "Wheelset",
       "Builds a wheelset from its profiles (wheel=, rail=, or left_wheel=, right_wheel=, left_rail=, right_rail=)."},
      {"conicity", "conicity", "table", "Result",
       "EN 15302 equivalent conicity of a rolling-radius difference table (y, dr, flange: in `table` or as keywords)."},
      {"flange_measures", "Profile.flange_measures", "self", "Result", "EN 15313 flange measures Sh, Sd, qR of a wheel."},
      {"contact", "Wheelset.contact", "self", "Result",
       "The contact at a prescribed pose (y, z, roll, yaw), frictionless or rolling."},
      {"wheel", "Wheelset.wheel", "self", "Result", "One wheel with its vertical force Fz prescribed."},
      {"equilibrium", "Wheelset.equilibrium", "self", "Result",
       "The elastic equilibrium of the free wheelset under the load Q at (y, yaw): z and roll solved."},
      {"rigid", "Wheelset.rigid", "self", "Result", "The rigid contact at (y, yaw): contact points, rolling radii."},
      {"sweep", "Wheelset.sweep", "self", "Result",
       "Equilibria over y (and yaw) on all cores; .table is a pandas DataFrame of the rows. Ctrl-C stops it between "
       "cases (KeyboardInterrupt, nothing returned)."},
      {"geometry_table", "Wheelset.geometry_table", "self", "pandas.DataFrame",
       "The rigid contact over a range of y, as a pandas DataFrame (units in the column names)."},
      {"wheelset_conicity", "Wheelset.conicity", "self", "Result",
       "EN 15302 equivalent conicity of the wheelset, from its own rolling-radius difference table."},
      {"trajectory", "Wheelset.trajectory", "self", "Trajectory",
       "A trajectory: contact calls that start from the previous step (online use)."},
      {"trajectory_contact", "Trajectory.contact", "self", "Result", "One step at a prescribed pose."},
      {"trajectory_wheel", "Trajectory.wheel", "self", "Result", "One step of a wheel with Fz prescribed."},
  };
  return all;
}

const PythonEntry& python_entry(const std::string& python) {
  for (const PythonEntry& e : python_entries())
    if (e.python == python) return e;
  fail("no Python entry '{}'", python);
}

namespace {

// The Python type of an option of the given OptionInfo type.
std::string python_type(const OptionInfo& o) {
  if (o.type == "number") return "float";
  if (o.type == "integer") return "int";
  if (o.type == "boolean") return "bool";
  if (o.type == "string") return "str";
  if (o.type == "choice") {
    std::string s = "Literal[";
    for (std::size_t i = 0; i < o.choices.size(); ++i) s += (i ? ", \"" : "\"") + o.choices[i] + "\"";
    return s + "]";
  }
  if (o.type == "numbers") return "float | Sequence[float]";
  if (o.type == "strings") return "Sequence[str]";
  if (o.type == "list") return "Sequence[float] | Mapping[str, float]";  // a list or {from =, to =, step =}
  if (o.type == "table") return "Mapping[str, Any]";
  if (o.type == "wrc.Profile") return "Profile";
  return "Any";
}

// The keywords a function takes besides its operation's options (the front end's own arguments).
std::string extra_keywords(const PythonEntry& e) {
  if (e.python == "wheelset")
    return "wheel: Profile | None = ..., rail: Profile | None = ..., left_wheel: Profile | None = ..., "
           "right_wheel: Profile | None = ..., left_rail: Profile | None = ..., right_rail: Profile | None = ..., "
           "strategy: str | Sequence[str] = ..., strategy_options: Mapping[str, Any] | None = ..., ";
  return "";
}

// A wheelset method that takes arrays for its number keys (a batch call, python/wrc/batch.py).
bool batches(const PythonEntry& e) {
  const auto& ops = api::batch_operations();
  return e.python.starts_with("Wheelset.") && std::find(ops.begin(), ops.end(), e.operation) != ops.end();
}

std::string positional(const PythonEntry& e) {
  if (e.signature == "path") return "path: str | os.PathLike[str], ";
  if (e.signature == "table") return "table: Mapping[str, Any] | pandas.DataFrame | None = None, ";
  if (e.signature == "self") return "self, ";
  return "";
}

}  // namespace

std::string docstring(const PythonEntry& e) {
  const api::Operation& op = api::operation(e.operation);
  std::string s = fmt::format("{}\n\nThe Lua call {}", e.summary, op.lua);
  if (!op.c.empty()) s += fmt::format(" and the C function {}", op.c);
  s += " take the same keys.\n\nOptions (keyword arguments; SI units; None or absent: the default):\n";
  for (const OptionInfo& o : op.options) {
    s += fmt::format("  {} : {}", o.key, o.type == "choice" ? python_type(o) : o.type);
    if (!o.unit.empty() && o.unit != "-") s += fmt::format(" [{}]", o.unit);
    if (o.required) s += ", required";
    else if (!o.fallback.empty()) s += fmt::format(", default {}", o.fallback);
    s += fmt::format("\n      {}\n", o.help);
  }
  if (batches(e))
    s += "\nBatch call: any option of type number may be a list or a numpy array; the arrays broadcast together "
         "(numpy's rules) and every element is solved, on worker threads (threads=, default 0: all cores), equal to "
         "the same call made alone. Returns a wrc.Batch: the fields as arrays over the batch's shape, .items, "
         ".errors (docs/python.md, section Batch calls).\n";
  return s;
}

std::string stub() {
  std::string s =
      "# Generated by the build from the engine's description of every option (api::operations()): do not edit.\n"
      "import os\n"
      "from typing import Any, Literal, Mapping, Sequence\n\n"
      "import numpy\n"
      "import numpy.typing\n"
      "import pandas\n\n"
      "from wrc._errors import Error as Error, NotConverged as NotConverged, OptionError as OptionError, "
      "ProfileError as ProfileError, ProfileWarning as ProfileWarning, ResolutionWarning as ResolutionWarning\n"
      "from wrc._results import Result as Result\n"
      "from wrc.batch import Batch as Batch\n\n"
      "__version__: str\n\n";
  auto function = [](const PythonEntry& e, const char* indent) {
    const bool module_method = e.python.starts_with("profile.");  // a method of the stub's _ProfileModule
    std::string f = fmt::format("{}def {}({}{}*, {}", indent, e.python.substr(e.python.rfind('.') + 1),
                                module_method ? "self, " : "", positional(e), extra_keywords(e));
    for (const OptionInfo& o : api::operation(e.operation).options) {
      if (o.key.find('.') != std::string::npos) continue;  // a nested table's key: in its table
      const bool array = batches(e) && o.type == "number";  // a batch's column
      f += fmt::format("{}: {}{}, ", o.key, array ? "float | numpy.typing.ArrayLike" : python_type(o),
                       o.required ? "" : " = ...");
    }
    if (batches(e)) f += "threads: int = ..., ";
    if (f.ends_with(", ")) f.resize(f.size() - 2);
    if (f.ends_with("*")) f.resize(f.size() - (f.ends_with(", *") ? 3 : 1));
    return f + fmt::format(") -> {}{}: ...\n", e.returns, batches(e) ? " | Batch" : "");
  };
  auto entries_of = [&](const std::string& owner, const char* indent) {
    std::string out;
    for (const PythonEntry& e : python_entries()) {
      const std::size_t dot = e.python.rfind('.');
      if ((dot == std::string::npos ? "" : e.python.substr(0, dot)) == owner) out += function(e, indent);
    }
    return out;
  };
  s += "class Profile:\n"
       "    name: str\n    kind: str\n    source: str\n    duplicates_dropped: int\n"
       "    transforms: list[str]\n    warnings: list[str]\n    smooth: float | None\n    metadata: dict[str, str]\n"
       "    y: numpy.ndarray\n    z: numpy.ndarray\n"
       "    def points(self) -> tuple[numpy.ndarray, numpy.ndarray]: ...\n"
       "    def arc_length(self) -> float: ...\n"
       "    def bounds(self) -> dict[str, float]: ...\n"
       "    def curvature(self, y: float) -> tuple[float, float | None]: ...\n"
       "    def transform(self, **options: Any) -> Profile: ...\n"
       "    def write(self, path: str | os.PathLike[str], **options: Any) -> str: ...\n"
       "    def close(self) -> None: ...\n"
       "    def __enter__(self) -> Profile: ...\n    def __exit__(self, *exc: Any) -> None: ...\n"
       "    def __len__(self) -> int: ...\n";
  s += entries_of("Profile", "    ") + "\n";
  s += "class Trajectory:\n"
       "    def reset(self) -> None: ...\n    def close(self) -> None: ...\n"
       "    def __enter__(self) -> Trajectory: ...\n    def __exit__(self, *exc: Any) -> None: ...\n";
  s += entries_of("Trajectory", "    ") + "\n";
  s += "class Wheelset:\n"
       "    params: Result\n"
       "    left_wheel: Result\n    right_wheel: Result\n    left_rail: Result\n    right_rail: Result\n"
       "    gauge_points: Result\n    tape_points: Result\n    rail_top: Result\n"
       "    def close(self) -> None: ...\n"
       "    def __enter__(self) -> Wheelset: ...\n    def __exit__(self, *exc: Any) -> None: ...\n";
  s += entries_of("Wheelset", "    ") + "\n";
  s += "class _ProfileModule:\n"
       "    max_points: int\n"
       "    def points(self, *, kind: Literal[\"wheel\", \"rail\"], y: Sequence[float], z: Sequence[float], "
       "name: str = ..., smooth: float = ...) -> Profile: ...\n";
  s += entries_of("profile", "    ") + "\nprofile: _ProfileModule\n\n";
  s += entries_of("", "");
  s += "def operations() -> list[dict[str, Any]]: ...\n";
  s += "def batch_keys(operation: str) -> list[str]: ...\n";
  return s;
}

}  // namespace wrc::python
