#include "python/convert.hpp"

#include <pybind11/numpy.h>

#include <fmt/format.h>

#include <memory>

namespace wrc::python {

namespace {

[[noreturn]] void type_error(const std::string& context, py::handle value, const char* expected) {
  throw py::type_error(fmt::format("{}: {}, got {}", context, expected,
                                   py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
}

const py::object& abc(const char* name) {
  static py::object mapping = py::module_::import("collections.abc").attr("Mapping");
  static py::object sequence = py::module_::import("collections.abc").attr("Sequence");
  static py::object real = py::module_::import("numbers").attr("Real");
  return std::string_view(name) == "Mapping" ? mapping : std::string_view(name) == "Sequence" ? sequence : real;
}

// An ABC's isinstance runs Python code (ABCMeta.__instancecheck__), where a pending Ctrl-C raises KeyboardInterrupt:
// an error propagates (taken for "no", it became "expected a number ..., got float" and the interrupt was lost).
bool is_instance(py::handle v, const py::object& cls) {
  const int r = PyObject_IsInstance(v.ptr(), cls.ptr());
  if (r < 0) throw py::error_already_set();
  return r == 1;
}

// A Python real as a double; an int beyond a double's range (10**400) is named, where the cast said only "Unable to
// cast Python instance to C++ type".
double real_number(py::handle v, const std::string& context) {
  const double x = PyFloat_AsDouble(v.ptr());
  if (x == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    const std::string r = py::repr(v).cast<std::string>();
    throw OptionFailure(fmt::format("{}: {} is beyond the range of a number (a double, up to about 1.8e308)", context,
                                    r.size() <= 24 ? r : fmt::format("{}... ({} characters)", r.substr(0, 12), r.size())));
  }
  return x;
}

OptionValue array_option(py::handle value, const std::string& context, int depth) {
  py::array a = py::module_::import("numpy").attr("asarray")(value);
  if (a.ndim() != 1)
    throw py::type_error(fmt::format("{}: an array option must be 1-D, got {} dimensions", context, a.ndim()));
  const char kind = a.dtype().kind();
  std::vector<OptionValue> out;
  out.reserve(static_cast<std::size_t>(a.size()));
  if (kind == 'f' || kind == 'i' || kind == 'u') {
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    const double* p = d.data();
    for (py::ssize_t i = 0; i < d.size(); ++i) out.push_back(OptionValue::of(p[i]));
    return OptionValue::of(std::move(out));
  }
  if (kind == 'b') {
    for (py::handle e : a.attr("tolist")()) out.push_back(OptionValue::of(e.cast<bool>()));
    return OptionValue::of(std::move(out));
  }
  py::ssize_t i = 0;
  for (py::handle e : a.attr("tolist")()) out.push_back(to_option(e, fmt::format("{}[{}]", context, i++), depth + 1));
  return OptionValue::of(std::move(out));
}

}  // namespace

OptionValue to_option(py::handle v, const std::string& context, int depth) {
  if (depth > kMaxOptionDepth)
    throw py::value_error(fmt::format("{}: values nested more than {} levels deep", context, kMaxOptionDepth));
  if (PyBool_Check(v.ptr())) return OptionValue::of(v.cast<bool>());
  if (py::isinstance<py::str>(v)) return OptionValue::of(v.cast<std::string>());
  if (py::isinstance<PyProfile>(v)) {
    const PyProfile& p = v.cast<const PyProfile&>();
    p.get(context.c_str());
    return OptionValue::of_object(p.profile, kProfileTypeName);
  }
  static const py::object numpy_scalar = py::module_::import("numpy").attr("generic");
  if (is_instance(v, numpy_scalar)) {  // numpy.float64, bool_: item() gives the Python value
    py::object item = v.attr("item")();
    // numpy.longdouble and clongdouble give themselves (no Python type holds them): a real one is a number, rounded to
    // a double as an array of them is; anything else is no option's value (handing it back here recursed forever).
    if (!is_instance(item, numpy_scalar)) return to_option(item, context, depth);
    if (is_instance(v, abc("Real"))) return OptionValue::of(real_number(v, context));
    type_error(context, v, "expected a number, bool, str, sequence, numpy array, mapping or wrc.Profile");
  }
  if (py::isinstance<py::array>(v)) {
    if (py::array(py::reinterpret_borrow<py::array>(v)).ndim() == 0) return to_option(v.attr("item")(), context, depth);
    return array_option(v, context, depth);
  }
  if (is_instance(v, abc("Real"))) return OptionValue::of(real_number(v, context));
  if (is_mapping(v)) return OptionValue::of(mapping_options(v, context, depth + 1));
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) || py::hasattr(v, "__array__")) {
    if (py::hasattr(v, "__array__")) return array_option(v, context, depth);  // a pandas Series
    std::vector<OptionValue> out;
    py::ssize_t i = 0;
    for (py::handle e : v) out.push_back(to_option(e, fmt::format("{}[{}]", context, i++), depth + 1));
    return OptionValue::of(std::move(out));
  }
  type_error(context, v, "expected a number, bool, str, sequence, numpy array, mapping or wrc.Profile");
}

bool is_mapping(py::handle value) { return is_instance(value, abc("Mapping")); }

OptionTable mapping_options(py::handle mapping, const std::string& context, int depth) {
  OptionTable t;
  t.dialect = OptionDialect::python;  // the engine's messages name a dict, a list
  for (py::handle key : mapping.attr("keys")()) {
    if (!py::isinstance<py::str>(key)) type_error(context, key, "option keys must be str");
    const std::string k = key.cast<std::string>();
    py::object v = mapping.attr("__getitem__")(key);
    if (v.is_none()) continue;  // None: not given
    t.set(k, to_option(v, fmt::format("{}: '{}'", context, k), depth));
  }
  return t;
}

OptionTable to_options(const py::kwargs& kwargs, const std::string& context) {
  return mapping_options(kwargs, context, 0);
}

namespace {

py::object result_class() {
  static py::object cls = py::module_::import("wrc._results").attr("Result");
  return cls;
}

// A result table kept in C++ until a Result made from it is first read (Result._deferred): the tree is shared by
// every Result made from it, each of which holds the table it stands for.
struct DeferredNode {
  std::shared_ptr<const FieldRecord> record;
  const FieldNode* node;
};

// A table becomes a deferred Result, a list a list of its items made so; any other field its value.
py::object shallow(const std::shared_ptr<const FieldRecord>& record, const FieldNode& n) {
  if (n.kind == FieldNode::Kind::table)
    return result_class().attr("_deferred")(DeferredNode{record, &n});
  if (n.kind == FieldNode::Kind::list) {
    py::list l(n.fields);
    std::size_t i = 0;
    for (const FieldNode& c : n.children()) l[i++] = shallow(record, c);
    return l;
  }
  return to_python(n);
}

// A deferred table's (fields, units), its tables and lists of tables deferred in turn.
py::tuple expand(const DeferredNode& d) {
  py::dict fields, units;
  for (const FieldNode& c : d.node->children()) {
    fields[py::str(c.key)] = shallow(d.record, c);
    if (!c.unit.empty()) units[py::str(c.key)] = py::str(c.unit);
  }
  return py::make_tuple(fields, units);
}

}  // namespace

void register_deferred(py::module_& m) {
  py::class_<DeferredNode>(m, "_DeferredNode", "A recorded result table, made into Python values when first read")
      .def("expand", &expand, "(fields, units) of the table");
}

py::object to_python(FieldRecord&& record) {
  const auto kept = std::make_shared<const FieldRecord>(std::move(record));
  return shallow(kept, kept->root());
}

py::object to_python(const FieldNode& n) {
  using K = FieldNode::Kind;
  switch (n.kind) {
    case K::number: return py::float_(n.number);
    case K::integer: return py::int_(n.integer);
    case K::boolean: return py::bool_(n.integer != 0);
    case K::string: return py::str(n.text);
    case K::numbers: {
      py::array_t<double> a(static_cast<py::ssize_t>(n.values.size()));
      std::copy(n.values.begin(), n.values.end(), a.mutable_data());
      return a;
    }
    case K::integers: {
      py::array_t<long long> a(static_cast<py::ssize_t>(n.integers.size()));
      std::copy(n.integers.begin(), n.integers.end(), a.mutable_data());
      return a;
    }
    case K::grid: {
      py::array_t<double> a({static_cast<py::ssize_t>(n.ny), static_cast<py::ssize_t>(n.nx)});
      std::copy(n.values.begin(), n.values.end(), a.mutable_data());  // row j: v[nx j .. nx j + nx - 1]
      return a;
    }
    case K::list: {
      py::list l(n.fields);
      std::size_t i = 0;
      for (const FieldNode& c : n.children()) l[i++] = to_python(c);
      return l;
    }
    case K::table: {
      py::dict fields, units;
      for (const FieldNode& c : n.children()) {
        fields[py::str(c.key)] = to_python(c);
        if (!c.unit.empty()) units[py::str(c.key)] = py::str(c.unit);
      }
      return result_class()(fields, units);
    }
  }
  return py::none();
}

}  // namespace wrc::python
