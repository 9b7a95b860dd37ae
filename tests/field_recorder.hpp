// A FieldSink that records what a describe() emits, by path ("depths.1.von_mises"): the values of numbers and strings,
// the sizes of arrays and grids, the documentation of each path and how often it came, and whether every number was
// finite. Used by the tests of the results' fields.
#pragma once

#include "wrc/core/fields.hpp"

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace wrc::test {

class FieldRecorder final : public FieldSink {
 public:
  std::map<std::string, double> nums;
  std::map<std::string, std::string> strs;
  std::map<std::string, std::size_t> arrays;  // arrays and grids: their number of values
  std::map<std::string, FieldDoc> docs;
  std::map<std::string, int> emitted;  // how often each path was described
  bool finite = true;
  void number(std::string_view k, double v) override {
    nums[path(k)] = v;
    finite = finite && std::isfinite(v);
  }
  void integer(std::string_view k, long long v) override { nums[path(k)] = static_cast<double>(v); }
  void boolean(std::string_view k, bool v) override { nums[path(k)] = v; }
  void string(std::string_view k, std::string_view v) override { strs[path(k)] = std::string(v); }
  void numbers(std::string_view k, const double* v, std::size_t n) override {
    arrays[path(k)] = n;
    for (std::size_t i = 0; i < n; ++i) finite = finite && std::isfinite(v[i]);
  }
  void integers(std::string_view k, const long long*, std::size_t n) override { arrays[path(k)] = n; }
  void grid(std::string_view k, const double* v, int nx, int ny) override { numbers(k, v, std::size_t(nx) * ny); }
  void begin(std::string_view k) override { prefix.push_back(path(k) + "."); }
  void begin_list(std::string_view k, std::size_t) override {
    begin(k);
    items.push_back(0);
  }
  void item() override { prefix.push_back(prefix.back() + std::to_string(++items.back()) + "."); }
  void end() override { prefix.pop_back(); }

 protected:
  void document(std::string_view k, FieldDoc doc) override {
    docs[path(k)] = doc;
    ++emitted[path(k)];
  }

 private:
  std::string path(std::string_view k) const { return (prefix.empty() ? "" : prefix.back()) + std::string(k); }
  std::vector<std::string> prefix;
  std::vector<int> items;
};

}  // namespace wrc::test
