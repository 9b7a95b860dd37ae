// A described result recorded as a tree of C++ values (no Python in it), so that a result can be described on any
// thread -- a worker of a batch, without the GIL -- and turned into Python objects afterwards (convert.hpp).
#pragma once

#include "wrc/core/fields.hpp"

#include <string>
#include <vector>

namespace wrc::python {

// One field: a value, or a table / list of fields.
struct FieldNode {
  enum class Kind { number, integer, boolean, string, numbers, integers, grid, table, list };
  Kind kind = Kind::table;
  std::string key;   // "" for an item of a list
  std::string unit;  // the FieldDoc's unit ("" when the field has none)
  double number = 0;
  long long integer = 0;  // also a boolean (0 or 1)
  std::string text;
  std::vector<double> values;    // numbers; a grid's nx x ny values v[i + nx j]
  std::vector<long long> integers;
  int nx = 0, ny = 0;
  std::vector<FieldNode> children;  // a table's fields in the order described, a list's items
  const FieldNode* find(std::string_view name) const;  // a table's field, or nullptr
};

// The sink: describe(result, tree) fills root (a table).
class FieldTree final : public FieldSink {
 public:
  FieldTree();
  FieldNode root;

  // The documented forms of FieldSink (number(key, v, doc), ...) too.
  using FieldSink::begin, FieldSink::begin_list, FieldSink::boolean, FieldSink::grid, FieldSink::integer,
      FieldSink::integers, FieldSink::number, FieldSink::numbers, FieldSink::string;
  void number(std::string_view key, double v) override;
  void integer(std::string_view key, long long v) override;
  void boolean(std::string_view key, bool v) override;
  void string(std::string_view key, std::string_view v) override;
  void numbers(std::string_view key, const double* v, std::size_t n) override;
  void integers(std::string_view key, const long long* v, std::size_t n) override;
  void grid(std::string_view key, const double* v, int nx, int ny) override;
  void begin(std::string_view key) override;
  void begin_list(std::string_view key, std::size_t n) override;
  void item() override;
  void end() override;

 protected:
  void document(std::string_view key, FieldDoc doc) override;

 private:
  FieldNode& add(std::string_view key, FieldNode::Kind kind);
  // The open tables and lists, innermost last. A node's children grow only while it is innermost, so the
  // pointers to its ancestors stay valid.
  std::vector<FieldNode*> open_;
  std::string pending_unit_;  // the unit of the field document() named last
  std::string pending_key_;
};

// The tree of a described result.
template <class Result, class... Extra>
FieldNode describe_tree(const Result& r, Extra&&... extra) {
  FieldTree t;
  describe(r, t, std::forward<Extra>(extra)...);
  return std::move(t.root);
}

}  // namespace wrc::python
