// Disjoint sets of the integers 0 .. n-1 (union-find), to group items that touch: segments into patches,
// patches into contact areas.
//
// The root of a set is its smallest element (unite links the larger root under the smaller), so roots, and
// anything ordered by them, do not depend on the order of the unions. find halves the path it walks.
// reset() keeps the storage's capacity: a UnionFind kept across calls stops allocating once it is large
// enough; one can also adopt a workspace's vector and hand it back (take_storage).
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace wrc {

class UnionFind {
 public:
  UnionFind() = default;
  // Uses `storage` as the parent array (its contents are replaced by reset; its capacity is reused).
  explicit UnionFind(std::vector<int>&& storage) : parent_(std::move(storage)) {}
  // Gives the parent array back, e.g. to the workspace it was adopted from.
  std::vector<int> take_storage() && { return std::move(parent_); }

  // n singletons {0}, {1}, ..., {n-1}.
  void reset(int n) {
    parent_.resize(static_cast<std::size_t>(n));
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int size() const { return static_cast<int>(parent_.size()); }

  // The root of i's set: its smallest element.
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }

  // Merges the sets of a and b; false if they were one set already.
  bool unite(int a, int b) {
    const int ra = find(a), rb = find(b);
    if (ra == rb) return false;
    parent_[std::max(ra, rb)] = std::min(ra, rb);
    return true;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace wrc
