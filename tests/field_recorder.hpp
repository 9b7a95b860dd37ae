// What a describe() emits, by path ("depths.1.von_mises"), read from the engine's one recorder
// (wrc/core/field_record.hpp): the values of numbers and strings, the sizes of arrays and grids, the documentation of
// each path and how often it came, and whether every number was finite. Used by the tests of the results' fields.
#pragma once

#include "wrc/core/field_record.hpp"

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace wrc::test {

struct FieldPaths {
  struct Doc {
    std::string unit, meaning;
  };
  std::map<std::string, double> nums;  // numbers, integers, booleans (0 / 1)
  std::map<std::string, std::string> strs;
  std::map<std::string, std::size_t> arrays;  // arrays and grids: their number of values
  std::map<std::string, Doc> docs;
  std::map<std::string, int> emitted;  // how often each documented path was described
  bool finite = true;                  // every number, array of numbers and grid

  // The fields of `parent`, a table or a list (whose items are "prefix1.", "prefix2.", ...).
  void add(const FieldNode& parent, const std::string& prefix) {
    using K = FieldNode::Kind;
    int items = 0;
    for (const FieldNode& c : parent.children()) {
      const bool item = parent.kind == K::list && c.kind == K::table && c.key.empty();
      const std::string p = prefix + (item ? std::to_string(++items) : std::string(c.key));
      if (c.documented) {
        docs[p] = {std::string(c.unit), std::string(c.meaning)};
        ++emitted[p];
      }
      switch (c.kind) {
        case K::number: nums[p] = c.number, finite = finite && std::isfinite(c.number); break;
        case K::integer:
        case K::boolean: nums[p] = static_cast<double>(c.integer); break;
        case K::string: strs[p] = std::string(c.text); break;
        case K::numbers:
        case K::grid:
          arrays[p] = c.values.size();
          for (double v : c.values) finite = finite && std::isfinite(v);
          break;
        case K::integers: arrays[p] = c.integers.size(); break;
        case K::table:
        case K::list: add(c, p + "."); break;
      }
    }
  }
};

// The fields of describe(r, sink, extra...) by path.
template <class Result, class... Extra>
FieldPaths field_paths(const Result& r, Extra&&... extra) {
  FieldRecorder rec(true);
  describe(r, rec, std::forward<Extra>(extra)...);
  FieldPaths out;
  out.add(rec.take().root(), "");
  return out;
}

}  // namespace wrc::test
