// The count of separate contact regions of an area (patch.regions) against a flood fill written here: random
// pressure fields of blobs, lines and single elements, 8-connected, each region counted when it carries >= 0.1 %
// of the force.
#include "wheelset/area.hpp"

#include <doctest/doctest.h>

#include <random>
#include <vector>

using namespace wrc;

namespace {

int flood_fill_regions(const halfspace::NormalSolution& s) {
  const halfspace::Grid& g = s.grid;
  std::vector<int> seen(static_cast<std::size_t>(g.size()), 0);
  int regions = 0;
  for (int k = 0; k < g.size(); ++k) {
    if (!(s.pressure[k] > 0) || seen[k]) continue;
    std::vector<int> todo{k};
    seen[k] = 1;
    double force = 0;
    while (!todo.empty()) {
      const int e = todo.back();
      todo.pop_back();
      force += s.pressure[e] * g.element_area();
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int i = e % g.nx + di, j = e / g.nx + dj;
          if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) continue;
          const int m = g.index(i, j);
          if (s.pressure[m] > 0 && !seen[m]) seen[m] = 1, todo.push_back(m);
        }
    }
    regions += force >= 1e-3 * s.force;
  }
  return regions;
}

}  // namespace

TEST_CASE("contact_regions = an 8-connected flood fill with the force share, on random fields") {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> U(0, 1);
  int several = 0, small_dropped = 0;
  for (int t = 0; t < 400; ++t) {
    halfspace::NormalSolution s;
    s.grid = halfspace::Grid::square(1 + static_cast<int>(U(rng) * 40), 1 + static_cast<int>(U(rng) * 40), 0.2e-3);
    const halfspace::Grid& g = s.grid;
    s.pressure.assign(static_cast<std::size_t>(g.size()), 0.0);
    const double density = U(rng) * 0.6;
    for (int k = 0; k < g.size(); ++k)
      if (U(rng) < density) s.pressure[k] = U(rng) < 0.05 ? 1e3 * U(rng) : 1e8 * (0.1 + U(rng));  // some tiny loads
    for (double p : s.pressure) s.force += p * g.element_area();
    if (!(s.force > 0)) continue;
    CAPTURE(t);
    const int expected = flood_fill_regions(s);
    CHECK(areas::contact_regions(s) == expected);
    several += expected > 1;
    int all = 0;  // regions without the force share
    halfspace::NormalSolution any = s;
    any.force = 1e-300;
    all = flood_fill_regions(any);
    small_dropped += all > expected;
  }
  CHECK(several > 100);       // the fields do have several regions
  CHECK(small_dropped > 10);  // and regions below the share
}
