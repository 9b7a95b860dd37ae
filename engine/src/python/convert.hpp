// Python values <-> the engine's: keyword arguments into an OptionTable (numbers, booleans, strings, sequences and
// 1-D numpy arrays, mappings, profiles; None: not given), a described result (FieldNode) into wrc.Result objects,
// lists, numpy arrays and 2-D grids. A Python value that no option can be is a TypeError naming the key.
#pragma once

#include "python/bindings.hpp"
#include "wrc/api/calls.hpp"
#include "wrc/core/field_record.hpp"
#include "wrc/core/options.hpp"

#include <pybind11/pybind11.h>

namespace wrc::python {

// The keyword arguments as an option table; `context` names the call in messages ("Wheelset.contact").
OptionTable to_options(const py::kwargs& kwargs, const std::string& context);
// One value (a mapping's entries become a table).
OptionValue to_option(py::handle value, const std::string& context, int depth = 0);
// isinstance(value, collections.abc.Mapping); an error of the ABC's check (KeyboardInterrupt) propagates.
bool is_mapping(py::handle value);
// A mapping (dict, wrc.Result, pandas.DataFrame: its columns) as a table.
OptionTable mapping_options(py::handle mapping, const std::string& context, int depth = 0);

// The request X of the call layer (wrc/api/calls.hpp) from an option table, validated: an engine error here is an
// OptionFailure (wrc.OptionError). `context` names the call ("Wheelset.contact").
template <class X>
X read_request(const OptionTable& t, const char* context) {
  return reading([&] {
    X x = api::read<X>(t, context);
    if constexpr (requires { x.validate(); }) x.validate();
    return x;
  });
}

// The same from keyword arguments.
template <class X>
X read_call(const py::kwargs& kwargs, const char* context) {
  return read_request<X>(to_options(kwargs, context), context);
}

// The result: a table becomes a wrc.Result, a list a Python list, numbers a 1-D float64 (integers int64) numpy array,
// a grid a 2-D float64 array of shape (ny, nx).
py::object to_python(const FieldNode& node);
// The same, deferred: the tree is kept and each table's fields are made when its Result is first read (what a caller
// does not read costs nothing; the values are those to_python(const FieldNode&) makes).
py::object to_python(FieldRecord&& record);
// The class of the deferred tables (_wrc._DeferredNode).
void register_deferred(py::module_& m);

}  // namespace wrc::python
