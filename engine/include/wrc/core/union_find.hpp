// Disjoint sets over 0..n-1 (union-find with path halving), for grouping connected segments and interacting
// patches. unite(a, b) puts b's set under a's root; reset() reuses the storage (no allocation once it is large
// enough).
#pragma once

#include <numeric>
#include <vector>

namespace wrc {

class UnionFind {
 public:
  UnionFind() = default;
  explicit UnionFind(int n) { reset(n); }
  void reset(int n) {
    parent_.resize(static_cast<std::size_t>(n));
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(int a, int b) { parent_[find(b)] = find(a); }

 private:
  std::vector<int> parent_;
};

}  // namespace wrc
