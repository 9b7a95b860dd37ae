// wrc::UnionFind: sets, roots (the smallest element, whatever the order of the unions), reuse of storage.
#include "wrc/core/union_find.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

using wrc::UnionFind;

TEST_CASE("union-find: singletons, unions, roots are the smallest elements") {
  UnionFind sets;
  sets.reset(6);
  CHECK(sets.size() == 6);
  for (int i = 0; i < 6; ++i) CHECK(sets.find(i) == i);
  CHECK(sets.unite(4, 2));
  CHECK(sets.unite(5, 4));
  CHECK_FALSE(sets.unite(2, 5));  // already one set
  CHECK(sets.unite(3, 1));
  CHECK(sets.find(5) == 2);
  CHECK(sets.find(4) == 2);
  CHECK(sets.find(3) == 1);
  CHECK(sets.find(0) == 0);
  CHECK(sets.unite(5, 3));
  for (int i : {1, 2, 3, 4, 5}) CHECK(sets.find(i) == 1);
  sets.reset(3);  // all singletons again
  for (int i = 0; i < 3; ++i) CHECK(sets.find(i) == i);
}

TEST_CASE("union-find: the roots do not depend on the order of the unions") {
  std::mt19937 rng(7);
  const int n = 200;
  std::vector<std::pair<int, int>> pairs;
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int k = 0; k < 150; ++k) pairs.emplace_back(pick(rng), pick(rng));
  std::vector<int> first;
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(pairs.begin(), pairs.end(), rng);
    UnionFind sets;
    sets.reset(n);
    for (const auto& [a, b] : pairs) trial % 2 ? sets.unite(a, b) : sets.unite(b, a);
    std::vector<int> roots(n);
    for (int i = 0; i < n; ++i) roots[i] = sets.find(i);
    for (int i = 0; i < n; ++i) CHECK(roots[i] <= i);  // the smallest element of its set
    if (trial == 0) first = roots;
    CHECK(roots == first);
  }
}

TEST_CASE("union-find: adopts a vector's storage and gives it back") {
  std::vector<int> storage;
  storage.reserve(64);
  const int* data = storage.data();
  UnionFind sets(std::move(storage));
  sets.reset(50);
  sets.unite(10, 40);
  CHECK(sets.find(40) == 10);
  storage = std::move(sets).take_storage();
  CHECK(storage.data() == data);  // no reallocation
  CHECK(storage.size() == 50);
}
