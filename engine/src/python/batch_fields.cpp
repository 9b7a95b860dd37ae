#include "python/batch_fields.hpp"

#include "python/convert.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <unordered_set>

namespace wrc::python {
namespace {

using Kind = FieldNode::Kind;

// One node of each element (or of each slot of a padded list), nullptr where the element has none: the tables of a
// BatchNode, or the lists of a BatchList (`list`). The nodes live in `trees`.
struct BatchNodes {
  std::shared_ptr<const BatchTrees> trees;
  std::vector<const FieldNode*> nodes;
  bool list = false;
};

// A table "grid" with its description gets the element centres x and y as arrays in its wrc.Result
// (python/wrc/_results.py): they are fields of the batch's tables too, that do not stack.
bool is_grid(const FieldNode& t) {
  if (t.key != "grid") return false;
  for (const char* k : {"nx", "ny", "dx", "dy", "x0", "y0"})
    if (!t.find(k)) return false;
  return true;
}

const FieldNode* field_of(const FieldNode* table, std::string_view name) {
  static const FieldNode centres = [] {
    FieldNode n;
    n.kind = Kind::numbers;
    return n;
  }();
  if (!table) return nullptr;
  if (const FieldNode* c = table->find(name)) return c;
  if ((name == "x" || name == "y") && is_grid(*table)) return &centres;
  return nullptr;
}

// The fields of the tables, in the order the elements give them (first seen first).
std::vector<std::string> keys(const BatchNodes& s) {
  std::vector<std::string> out;
  std::unordered_set<std::string_view> seen;
  auto add = [&](std::string_view k) {
    if (seen.insert(k).second) out.emplace_back(k);
  };
  for (const FieldNode* t : s.nodes) {
    if (!t) continue;
    for (const FieldNode& c : t->children()) add(c.key);
    if (is_grid(*t)) {
      add("x");
      add("y");
    }
  }
  return out;
}

template <class T, class F>
py::array_t<T> filled(const std::vector<const FieldNode*>& v, F value) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  T* p = a.mutable_data();
  for (std::size_t i = 0; i < v.size(); ++i) p[i] = value(v[i]);
  return a;
}

// The field `name` stacked over the elements (flat; batch.py gives it the batch's shape): the tables or lists as
// BatchNodes; booleans as a bool array and integers as an int64 array when every element has them; text as an
// object array (None where absent); any other mix of numbers, integers and booleans as float64, NaN where absent.
// None when it does not stack: arrays, grids, values of different kinds, or no element has it.
py::object field(const BatchNodes& s, const std::string& name) {
  std::vector<const FieldNode*> v(s.nodes.size());
  std::size_t present = 0;
  bool tables = true, lists = true, booleans = true, integers = true, texts = true, scalars = true;
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = field_of(s.nodes[i], name);
    if (!v[i]) continue;
    ++present;
    const Kind k = v[i]->kind;
    tables &= k == Kind::table;
    lists &= k == Kind::list;
    booleans &= k == Kind::boolean;
    integers &= k == Kind::integer;
    texts &= k == Kind::string;
    scalars &= k == Kind::number || k == Kind::integer || k == Kind::boolean;
  }
  if (present == 0) return py::none();
  if (tables || lists) return py::cast(BatchNodes{s.trees, std::move(v), lists});
  const bool full = present == v.size();
  if (booleans && full) return filled<bool>(v, [](const FieldNode* n) { return n->integer != 0; });
  if (integers && full) return filled<std::int64_t>(v, [](const FieldNode* n) { return n->integer; });
  if (texts) {
    py::list l(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) l[i] = v[i] ? py::object(py::str(v[i]->text)) : py::none();
    py::object a = py::module_::import("numpy").attr("empty")(v.size(), py::arg("dtype") = "object");
    a[py::slice(0, static_cast<py::ssize_t>(v.size()), 1)] = l;
    return a;
  }
  if (!scalars) return py::none();
  return filled<double>(v, [](const FieldNode* n) {
    if (!n) return std::numeric_limits<double>::quiet_NaN();
    return n->kind == Kind::number ? n->number : static_cast<double>(n->integer);
  });
}

// Each list's length (0 where absent).
py::array_t<std::int64_t> counts(const BatchNodes& s) {
  return filled<std::int64_t>(s.nodes, [](const FieldNode* l) {
    return l ? static_cast<std::int64_t>(l->fields) : std::int64_t{0};
  });
}

const FieldNode* item_of(const FieldNode* list, std::size_t k) {
  return list ? list->child(k) : nullptr;
}

// The k-th item of each list.
BatchNodes item(const BatchNodes& s, std::size_t k) {
  BatchNodes out{s.trees, {}, false};
  out.nodes.reserve(s.nodes.size());
  for (const FieldNode* l : s.nodes) out.nodes.push_back(item_of(l, k));
  return out;
}

// The items 0 .. longest - 1 of each list, element after element (row-major over batch shape + (longest,)).
BatchNodes padded(const BatchNodes& s, std::size_t longest) {
  BatchNodes out{s.trees, {}, false};
  out.nodes.reserve(s.nodes.size() * longest);
  for (const FieldNode* l : s.nodes)
    for (std::size_t k = 0; k < longest; ++k) out.nodes.push_back(item_of(l, k));
  return out;
}

// Each element's wrc.Result (None where absent).
py::list results(const BatchNodes& s) {
  py::list out(s.nodes.size());
  for (std::size_t i = 0; i < s.nodes.size(); ++i) out[i] = s.nodes[i] ? to_python(*s.nodes[i]) : py::none();
  return out;
}

py::array_t<bool> present(const BatchNodes& s) {
  return filled<bool>(s.nodes, [](const FieldNode* n) { return n != nullptr; });
}

}  // namespace

py::object batch_nodes(std::shared_ptr<const BatchTrees> trees, const std::vector<bool>& present) {
  BatchNodes s{trees, {}, false};
  s.nodes.reserve(present.size());
  for (std::size_t i = 0; i < present.size(); ++i) s.nodes.push_back(present[i] ? &trees->records[i].root() : nullptr);
  return py::cast(std::move(s));
}

void register_batch_fields(py::module_& m) {
  py::class_<BatchNodes>(m, "_BatchNodes",
                         "The results of a batch's elements kept in the engine's form (python/wrc/batch.py reads them)")
      .def("__len__", [](const BatchNodes& s) { return s.nodes.size(); })
      .def_readonly("is_list", &BatchNodes::list)
      .def("keys", &keys, "the tables' fields, first seen first")
      .def("field", &field, py::arg("name"), "the field stacked over the elements (flat), or None")
      .def("counts", &counts, "each list's length, 0 where absent")
      .def("item", &item, py::arg("k"), "the k-th item of each list")
      .def("padded", &padded, py::arg("longest"), "items 0 .. longest - 1 of each list, element after element")
      .def("present", &present, "whether each element has a node")
      .def("results", &results, "each element's wrc.Result, None where absent");
}

}  // namespace wrc::python
