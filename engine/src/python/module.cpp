// The compiled part of the Python package wrc (python/wrc/__init__.py imports it as wrc._wrc).
#include "python/bindings.hpp"
#include "python/convert.hpp"
#include "python/docs.hpp"
#include "wrc/core/config.hpp"

#include <pybind11/stl.h>

namespace wrc::python {
namespace {

// api::operations() as a list of dicts: name, lua, c, options (key, type, unit, help, default, required, choices).
py::list operations_list() {
  py::list out;
  for (const api::Operation& op : api::operations()) {
    py::list options;
    for (const OptionInfo& o : op.options) {
      py::dict d;
      d["key"] = o.key;
      d["type"] = o.type;
      d["unit"] = o.unit;
      d["help"] = o.help;
      d["default"] = o.fallback;
      d["required"] = o.required;
      d["choices"] = o.choices;
      options.append(d);
    }
    py::dict d;
    d["name"] = op.name;
    d["lua"] = op.lua;
    d["c"] = op.c;
    d["options"] = options;
    out.append(d);
  }
  return out;
}

py::list entries_list() {
  py::list out;
  for (const PythonEntry& e : python_entries()) out.append(py::make_tuple(e.operation, e.python));
  return out;
}

}  // namespace
}  // namespace wrc::python

PYBIND11_MODULE(_wrc, m) {
  namespace py = pybind11;
  using namespace wrc::python;
  m.doc() = "wrc: wheel-rail contact (the compiled module; import wrc)";
  register_errors(m);
  register_deferred(m);
  register_profile(m);
  register_wheelset(m);
  register_batch(m);
  register_track(m);
  m.attr("__version__") = WRC_VERSION;
  m.def("operations", operations_list,
        "Every operation of the engine with its options (key, type, unit, help, default, required, choices).");
  m.def("_entries", entries_list, "(operation, Python name) of every function that takes options");
  m.def("_stub", wrc::python::stub, "The text of the type stub wrc/__init__.pyi");
}
