#include "python/batch_fields.hpp"

#include "python/convert.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <string>
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

// ---- pickle and copy: each element's node as bytes ----
//
// A node is written depth first: its kind (1 byte), whether it was documented (1 byte), its key, unit and object
// type, then its value -- a number or an integer (8 bytes as in memory: a float's bits are kept, NaN payloads
// included), a text, an array (its length, then its values), a grid (nx, ny, then nx ny values), a table's fields
// (their count, then each), a list's announced length and items (their count, then each: tables). Lengths are
// 8-byte unsigned integers. The bytes are read back by recording the same calls into a FieldRecorder: the tree read
// back is the tree written, field for field and bit for bit. Data of another build's layout or cut short is
// refused with an error, never read past its end.

class NodeWriter {
 public:
  std::string bytes;
  template <class T>
  void put(T v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void text(std::string_view s) {
    put<std::uint64_t>(s.size());
    bytes.append(s);
  }
  template <class T>
  void array(std::span<const T> v) {
    put<std::uint64_t>(v.size());
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size_bytes());
  }
  void node(const FieldNode& n) {
    put(static_cast<std::uint8_t>(n.kind));
    put(static_cast<std::uint8_t>(n.documented));
    text(n.key);
    text(n.unit);
    text(n.object_type);
    switch (n.kind) {
      case Kind::number: put(n.number); break;
      case Kind::integer:
      case Kind::boolean: put<std::int64_t>(n.integer); break;
      case Kind::string: text(n.text); break;
      case Kind::numbers: array(n.values); break;
      case Kind::integers: array(n.integers); break;
      case Kind::grid:
        put<std::int32_t>(n.nx);
        put<std::int32_t>(n.ny);
        array(n.values);
        break;
      case Kind::list: put<std::uint64_t>(n.count); [[fallthrough]];
      case Kind::table:
        put<std::uint64_t>(n.fields);
        for (const FieldNode& c : n.children()) node(c);
        break;
    }
  }
};

class NodeReader {
 public:
  explicit NodeReader(std::string_view in) : in_(in) {}

  // Records the node at the reader's position into `t`; `item`: it is an item of a list (a table opened by item()).
  // Results nest a few levels (an equilibrium: 6, lists counted); kDepth bounds the recursion on damaged data.
  void node(FieldRecorder& t, bool item = false, int depth = 0) {
    constexpr int kDepth = 64;
    if (depth > kDepth) damaged("nested too deep");
    const auto kind = static_cast<Kind>(get<std::uint8_t>());
    const bool documented = get<std::uint8_t>() != 0;
    const std::string key(text()), unit(text()), type(text());
    if (kind > Kind::list || (item && kind != Kind::table)) damaged("a node of unknown kind");
    const FieldDoc doc{unit.c_str(), ""};
    switch (kind) {
      case Kind::number: documented ? t.number(key, get<double>(), doc) : t.number(key, get<double>()); break;
      case Kind::integer:
        documented ? t.integer(key, get<std::int64_t>(), doc) : t.integer(key, get<std::int64_t>());
        break;
      case Kind::boolean:
        documented ? t.boolean(key, get<std::int64_t>() != 0, doc) : t.boolean(key, get<std::int64_t>() != 0);
        break;
      case Kind::string: {
        const std::string v(text());
        documented ? t.string(key, v, doc) : t.string(key, v);
        break;
      }
      case Kind::numbers: {
        const std::vector<double> v = array<double>();
        documented ? t.numbers(key, v.data(), v.size(), doc) : t.numbers(key, v.data(), v.size());
        break;
      }
      case Kind::integers: {
        const std::vector<long long> v = array<long long>();
        documented ? t.integers(key, v.data(), v.size(), doc) : t.integers(key, v.data(), v.size());
        break;
      }
      case Kind::grid: {
        const int nx = get<std::int32_t>(), ny = get<std::int32_t>();
        const std::vector<double> v = array<double>();
        if (nx < 0 || ny < 0 || v.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny))
          damaged("a grid whose size is not nx ny");
        documented ? t.grid(key, v.data(), nx, ny, doc) : t.grid(key, v.data(), nx, ny);
        break;
      }
      case Kind::table:
      case Kind::list: {
        const bool list = kind == Kind::list;
        const std::uint64_t count = list ? get<std::uint64_t>() : 0;
        if (item) t.item();
        else if (list) documented ? t.begin_list(key, count, doc) : t.begin_list(key, count);
        else documented ? t.begin(key, doc) : t.begin(key);
        if (!type.empty()) t.object_type(type);
        const std::uint64_t fields = get<std::uint64_t>();
        for (std::uint64_t k = 0; k < fields; ++k) node(t, list, depth + 1);
        t.end();
        break;
      }
    }
  }

  void finish() const {
    if (at_ != in_.size()) damaged("bytes after its end");
  }

  [[noreturn]] static void damaged(std::string_view what) {
    fail("wrc.Batch: the pickled results are damaged ({}): pickle and unpickle with the same wrc", what);
  }

 private:
  std::string_view take(std::uint64_t n) {
    if (n > in_.size() - at_) damaged("cut short");
    const std::string_view s = in_.substr(at_, static_cast<std::size_t>(n));
    at_ += static_cast<std::size_t>(n);
    return s;
  }
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, take(sizeof v).data(), sizeof v);
    return v;
  }
  std::string_view text() { return take(get<std::uint64_t>()); }
  template <class T>
  std::vector<T> array() {
    const std::uint64_t n = get<std::uint64_t>();
    if (n > (in_.size() - at_) / sizeof(T)) damaged("cut short");
    std::vector<T> v(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(v.data(), take(n * sizeof(T)).data(), v.size() * sizeof(T));
    return v;
  }

  std::string_view in_;
  std::size_t at_ = 0;
};

// (list, [bytes of each element's node, None where it has none]).
py::tuple pickled(const BatchNodes& s) {
  py::list nodes(s.nodes.size());
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    if (!s.nodes[i]) {
      nodes[i] = py::none();
      continue;
    }
    NodeWriter w;
    w.node(*s.nodes[i]);
    nodes[i] = py::bytes(w.bytes);
  }
  return py::make_tuple(s.list, nodes);
}

// The nodes read back: each into a record of its own, as the only field of its root.
BatchNodes unpickled(const py::tuple& state) {
  if (state.size() != 2) NodeReader::damaged("not a pair");
  auto trees = std::make_shared<BatchTrees>();
  const py::list given = state[1].cast<py::list>();
  std::vector<int> record_of;
  for (py::handle b : given) {
    if (b.is_none()) {
      record_of.push_back(-1);
      continue;
    }
    const std::string bytes = b.cast<std::string>();
    NodeReader r(bytes);
    FieldRecorder t;
    r.node(t);
    r.finish();
    record_of.push_back(static_cast<int>(trees->records.size()));
    trees->records.push_back(t.take());
  }
  BatchNodes s{trees, {}, state[0].cast<bool>()};
  for (int k : record_of)
    s.nodes.push_back(k < 0 ? nullptr : trees->records[static_cast<std::size_t>(k)].root().child(0));
  return s;
}

}  // namespace

py::object batch_nodes(std::shared_ptr<const BatchTrees> trees, const std::vector<bool>& present) {
  BatchNodes s{trees, {}, false};
  s.nodes.reserve(present.size());
  for (std::size_t i = 0; i < present.size(); ++i) s.nodes.push_back(present[i] ? &trees->records[i].root() : nullptr);
  return py::cast(std::move(s));
}

void register_batch_fields(py::module_& m) {
  m.def("_batch_nodes", &unpickled, py::arg("state"), "a batch's results from what pickling them gave");
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
      .def("results", &results, "each element's wrc.Result, None where absent")
      // pickle: made again by wrc.batch._nodes_from(state), a Python function (pickle names it; a compiled one it
      // cannot), rather than by __setstate__ on a bare instance (which pybind11 cannot make under protocols 0 and 1)
      .def("__reduce__", [](const BatchNodes& s) {
        return py::make_tuple(py::module_::import("wrc.batch").attr("_nodes_from"), py::make_tuple(pickled(s)));
      })
      // The results never change once recorded: a copy shares them (the wrc.Batch copied makes its arrays anew).
      .def("__copy__", [](const BatchNodes& s) { return s; })
      .def("__deepcopy__", [](const BatchNodes& s, const py::dict&) { return s; }, py::arg("memo"));
}

}  // namespace wrc::python
