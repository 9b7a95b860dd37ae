// A described result recorded as a tree of plain C++ values: the one FieldSink that records (core/fields.hpp). Every
// front end records a result with it and converts the tree -- Lua into tables (lua/results_binding), Python into
// wrc.Result objects (python/convert, python/batch_fields), the C API into its flat "left.patches.1.force.z" paths --
// so the bookkeeping of begin / item / end is written once.
//
// Ownership and lifetime: a FieldRecord owns copies of everything it was given (keys, units, text, arrays); nothing
// in it points into the described result or the sink's caller, so it outlives both and may be moved to another
// thread and converted there (a batch records on its workers without the GIL and converts later). Its nodes and
// their views (key, text, values, ...) stay valid, at the same addresses, while the record lives, moves included. A
// recorder is used by one thread at a time.
#pragma once

#include "wrc/core/fields.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace wrc {

// One field: a value, or a table / list of fields. A table's fields keep the order they were described in, repeats
// included (a front end decides what a repeated key means, as it did when it received the calls itself). The nodes
// of a record lie in one array, each followed by its fields' subtrees; a node's views point into its record.
struct FieldNode {
  enum class Kind : std::uint8_t { number, integer, boolean, string, numbers, integers, grid, table, list };
  class Fields;

  Kind kind = Kind::table;
  bool documented = false;   // the field came with a FieldDoc
  std::uint32_t fields = 0;  // a table's fields, a list's items
  std::size_t below = 0;     // the nodes after this one that are its fields and theirs
  std::string_view key;      // "" for an item of a list
  std::string_view unit;     // the FieldDoc's unit ("" when the field has none)
  std::string_view meaning;  // the FieldDoc's meaning, recorded only when the recorder was asked to (tests check it)
  std::string_view text;     // a string's value
  std::string_view object_type;  // a table: FieldSink::object_type's name ("wrc.Patch"), "" when none
  double number = 0;
  long long integer = 0;  // also a boolean (0 or 1)
  std::span<const double> values;  // numbers; a grid's nx x ny values v[i + nx j]
  std::span<const long long> integers;
  int nx = 0, ny = 0;
  std::size_t count = 0;  // a list: the length begin_list announced

  Fields children() const;  // a table's fields in the order described; a list's items (tables, key "")
  const FieldNode* find(std::string_view name) const;  // a table's first field of that name, or nullptr
  const FieldNode* child(std::size_t k) const;         // the k-th field or item (from 0), or nullptr
};

// The fields of a node, in order (a forward range).
class FieldNode::Fields {
 public:
  class iterator {
   public:
    using value_type = FieldNode;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    explicit iterator(const FieldNode* p) : p_(p) {}
    const FieldNode& operator*() const { return *p_; }
    const FieldNode* operator->() const { return p_; }
    iterator& operator++() {
      p_ += 1 + p_->below;
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++*this;
      return old;
    }
    bool operator==(const iterator&) const = default;

   private:
    const FieldNode* p_ = nullptr;
  };
  Fields(const FieldNode* first, const FieldNode* last, std::size_t n) : first_(first), last_(last), n_(n) {}
  iterator begin() const { return iterator(first_); }
  iterator end() const { return iterator(last_); }
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }

 private:
  const FieldNode *first_, *last_;
  std::size_t n_;
};

inline FieldNode::Fields FieldNode::children() const { return {this + 1, this + 1 + below, fields}; }

// A recorded result: its root table and the storage of every node and value.
class FieldRecord {
 public:
  FieldRecord();  // an empty table
  FieldRecord(FieldRecord&& other) noexcept;
  FieldRecord& operator=(FieldRecord&& other) noexcept;
  FieldRecord(const FieldRecord&) = delete;
  FieldRecord& operator=(const FieldRecord&) = delete;
  ~FieldRecord() = default;

  const FieldNode& root() const { return nodes_.front(); }

  // A node's numbers or grid values as a vector: a large array's own storage moved out (the node's values are then
  // empty views' worth: read nothing of them afterwards), a small one copied. For a converter that keeps the values
  // (Lua's grids) without a second copy.
  std::vector<double> take_values(const FieldNode& node);

  // Drops the content and keeps the memory for the next recording (the nodes' array, and one block the size of all
  // the copies made, unless that is over 64 MiB): a front end that converts a result at once and records the next
  // into the same storage then allocates nothing in the steady state (no fresh pages for every result).
  void clear();

  // The memory the record holds (bytes): its nodes' array, its copies and its large arrays. A front end keeping many
  // records (a batch) counts them against its budget.
  std::size_t bytes() const;

 private:
  friend class FieldRecorder;
  std::string_view copy(std::string_view s);
  template <class T>
  std::span<const T> copy(const T* v, std::size_t n);
  void* allocate(std::size_t bytes);

  std::vector<FieldNode> nodes_;  // the root first; each node followed by its fields' subtrees
  // The copies of keys, units, text and arrays, in blocks that never move (the nodes' views point into them); arrays
  // of numbers too large for a block in vectors of their own (take_values).
  std::vector<std::unique_ptr<std::byte[]>> blocks_;
  std::vector<std::vector<double>> large_;
  std::byte* free_ = nullptr;  // the rest of the current block
  std::size_t left_ = 0;
  std::size_t size_ = 0;  // the current block's size
  std::size_t used_ = 0;  // the bytes copied, in all blocks
};

// The sink: describe(result, recorder), then take() the record.
class FieldRecorder final : public FieldSink {
 public:
  // with_meanings: keep each FieldDoc's meaning too (the front ends need only units; tests check the meanings).
  explicit FieldRecorder(bool with_meanings = false);
  // Records into the memory of `storage` (cleared first: FieldRecord::clear).
  explicit FieldRecorder(FieldRecord&& storage);

  // The record so far (tables left open are closed); the recorder then starts an empty one.
  FieldRecord take();
  std::size_t bytes() const { return record_.bytes(); }  // the record's memory so far (FieldRecord::bytes)

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
  // Kept until the next field (FieldSink calls it just before, with the same key, within the same call).
  void document(std::string_view key, FieldDoc doc) override;

 private:
  FieldNode& add(std::string_view key, FieldNode::Kind kind);
  FieldRecord record_;
  std::vector<std::size_t> open_;  // the open tables and lists (indices of nodes), innermost last
  bool with_meanings_;
  bool pending_ = false;  // document() named pending_key_ last
  std::string_view pending_key_;
  FieldDoc pending_doc_;
};

// The calling thread's storage for records converted at once (record_and_convert): its memory stays with the thread
// (at most the nodes' array and 64 MiB of copies, FieldRecord::clear).
FieldRecord& thread_record_storage();

// describe(r, sink, extra...) recorded into the calling thread's storage, then convert(FieldRecord&) -- for a
// front end that converts the record at once (Lua tables, C paths) and keeps nothing of it: in the steady state no
// memory is allocated for recording.
template <class Convert, class Result, class... Extra>
void record_and_convert(Convert&& convert, const Result& r, Extra&&... extra) {
  FieldRecorder t(std::move(thread_record_storage()));
  describe(r, t, std::forward<Extra>(extra)...);
  FieldRecord record = t.take();
  convert(record);  // FieldRecord&: it may take_values
  thread_record_storage() = std::move(record);
}

// The record of a described result (describe(r, sink, extra...)).
template <class Result, class... Extra>
FieldRecord record_fields(const Result& r, Extra&&... extra) {
  FieldRecorder t;
  describe(r, t, std::forward<Extra>(extra)...);
  return t.take();
}

}  // namespace wrc
