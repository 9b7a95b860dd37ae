// A described result recorded as a tree of plain C++ values: the one FieldSink that records (core/fields.hpp). Every
// front end records a result with it and converts the tree -- Lua into tables (lua/results_binding), Python into
// wrc.Result objects (python/convert, python/batch_fields), the C API into its flat "left.patches.1.force.z" paths --
// so the bookkeeping of begin / item / end is written once.
//
// Ownership and lifetime: the tree owns copies of everything it was given (keys, units, text, values); nothing in it
// points into the described result or the sink's caller, so it outlives both, may be moved to another thread and
// converted there (a batch records on its workers without the GIL and converts later). A recorder is used by one
// thread at a time; its root is complete when describe() returns, and moving the root out ends the recorder's use.
#pragma once

#include "wrc/core/fields.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wrc {

// One field: a value, or a table / list of fields. Fields keep the order they were described in, repeats included
// (a front end decides what a repeated key means, as it did when it received the calls itself).
struct FieldNode {
  enum class Kind { number, integer, boolean, string, numbers, integers, grid, table, list };
  Kind kind = Kind::table;
  std::string key;   // "" for an item of a list
  std::string unit;  // the FieldDoc's unit ("" when the field has none)
  std::string meaning;  // the FieldDoc's meaning, recorded only when the recorder was asked to (a test's check)
  bool documented = false;  // the field came with a FieldDoc
  double number = 0;
  long long integer = 0;  // also a boolean (0 or 1)
  std::string text;
  std::vector<double> values;  // numbers; a grid's nx x ny values v[i + nx j]
  std::vector<long long> integers;
  int nx = 0, ny = 0;
  std::size_t count = 0;            // a list: the length begin_list announced
  std::string object_type;          // a table: FieldSink::object_type's name ("wrc.Patch"), "" when none
  std::vector<FieldNode> children;  // a table's fields in the order described; a list's items (tables, key "")
  const FieldNode* find(std::string_view name) const;  // a table's first field of that name, or nullptr
};

// The sink: describe(result, recorder) fills root (a table).
class FieldRecorder final : public FieldSink {
 public:
  // with_meanings: keep each FieldDoc's meaning too (the front ends need only units; tests check the meanings).
  explicit FieldRecorder(bool with_meanings = false);
  FieldRecorder(const FieldRecorder&) = delete;
  FieldRecorder& operator=(const FieldRecorder&) = delete;
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
  void end() override;  // an end() without an open table is ignored (the root stays open)
  void object_type(std::string_view name) override;

 protected:
  void document(std::string_view key, FieldDoc doc) override;

 private:
  FieldNode& add(std::string_view key, FieldNode::Kind kind);
  // The open tables and lists, innermost last. A node's children grow only while it is innermost, so the
  // pointers to its ancestors stay valid.
  std::vector<FieldNode*> open_;
  bool with_meanings_;
  bool pending_ = false;  // document() named pending_key_ last
  std::string pending_key_, pending_unit_, pending_meaning_;
};

// The tree of a described result (describe(r, sink, extra...)).
template <class Result, class... Extra>
FieldNode record_fields(const Result& r, Extra&&... extra) {
  FieldRecorder t;
  describe(r, t, std::forward<Extra>(extra)...);
  return std::move(t.root);
}

}  // namespace wrc
