// The result-field reference (docs/reference/fields.md): a FieldSink that records what a describe() writes -- each
// field's path pattern, kind, unit and meaning from the FieldDoc beside it (core/fields.hpp) -- instead of values,
// so that the reference is made by the same calls that fill results. tests/docs/field_reference.cpp writes the page.
//
// Paths: list items are N (1-based), the tables "left" and "right" (one per wheel, described alike) are <side>. Lua
// indexes lists with [N] ("<side>.patches[N].pmax"), the C API's wrc_result_fields lists them as ".N."
// ("<side>.patches.N.pmax"). Units: SI; "-" for a dimensionless number, an index or a count; "" for text, flags,
// tables and lists (a vector's table carries its components' unit).
#pragma once

#include "wrc/core/fields.hpp"

#include <string>
#include <vector>

namespace wrc {

struct FieldEntry {
  std::string lua;   // "<side>.patches[N].pmax"
  std::string c;     // "<side>.patches.N.pmax"
  std::string kind;  // number, integer, boolean, string, numbers, integers, grid, table, list
  std::string unit, meaning;
};

class DocSink final : public FieldSink {
 public:
  // Entries in the order the descriptions write them (a field first seen in a later description is placed after
  // the field written before it there).
  const std::vector<FieldEntry>& entries() const { return entries_; }
  // What is wrong with the documentation seen: a field without a FieldDoc, an empty meaning, a unit against the
  // rule above, one path documented two ways. Empty when every field is documented.
  const std::vector<std::string>& problems() const { return problems_; }
  // Each describe() call starts at the top (the insertion point for new fields is reset).
  void restart();

  void number(std::string_view key, double) override { add(key, "number"); }
  void integer(std::string_view key, long long) override { add(key, "integer"); }
  void boolean(std::string_view key, bool) override { add(key, "boolean"); }
  void string(std::string_view key, std::string_view) override { add(key, "string"); }
  void numbers(std::string_view key, const double*, std::size_t) override { add(key, "numbers"); }
  void integers(std::string_view key, const long long*, std::size_t) override { add(key, "integers"); }
  void grid(std::string_view key, const double*, int, int) override { add(key, "grid"); }
  void begin(std::string_view key) override;
  void begin_list(std::string_view key, std::size_t) override;
  void item() override;
  void end() override;

 protected:
  void document(std::string_view key, FieldDoc doc) override;

 private:
  struct Frame {
    std::string lua, c;  // path prefixes ("<side>.patches[N]", "<side>.patches.N.")
    bool list = false;
  };
  void add(std::string_view key, const char* kind);
  // Records what is wrong with one written field (once, however often it is written); `seen`: the same path before.
  void check(const FieldEntry& e, bool documented, const FieldEntry* seen);
  std::vector<FieldEntry> entries_;
  std::vector<std::string> problems_;
  std::vector<Frame> frames_;
  std::string pending_key_;
  FieldDoc pending_{};
  bool has_pending_ = false;
  std::size_t next_ = 0;  // where a new field goes
};

// The entries as Markdown table rows "| `lua` | `c` | kind | unit | meaning |" (for the reference page).
std::string field_table(const std::vector<FieldEntry>& entries);

}  // namespace wrc
