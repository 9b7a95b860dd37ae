// The rule that judges whether a grid resolves a contact's peak pressure (kMinSpan elements across each way), against
// the analytic Hertz solution: Hertzian contacts on grids whose element ranges from a fifth of the minor semi-axis to
// twice it, the grid shifted against the contact, the normal force prescribed. Every contact the rule passes has its
// pmax close to Hertz's p0; among those it fails are some far off (what the rule is for).
#include "halfspace/hertz_reference.hpp"
#include "halfspace/materials.hpp"
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/ellipse.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/wheelset/contact.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace wrc;
using namespace wrc::halfspace;
using namespace wrc::test;

namespace {

// Elements of each region in one row (x) and one column (y), counted directly from the pressure.
RegionSpan brute_span(const Grid& g, const std::vector<int>& label, int region) {
  RegionSpan s;
  for (int j = 0; j < g.ny; ++j) {
    int n = 0;
    for (int i = 0; i < g.nx; ++i) n += label[static_cast<std::size_t>(g.index(i, j))] == region;
    s.x = std::max(s.x, n);
  }
  for (int i = 0; i < g.nx; ++i) {
    int n = 0;
    for (int j = 0; j < g.ny; ++j) n += label[static_cast<std::size_t>(g.index(i, j))] == region;
    s.y = std::max(s.y, n);
  }
  return s;
}

}  // namespace

TEST_CASE("resolution: contacts spanning kMinSpan elements have Hertz's peak pressure, narrower ones may not") {
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  const double A = 1 / (2 * 0.45);  // a wheel of 0.45 m on a flat rail along x
  double worst_resolved = 0, worst_unresolved = 0;
  int resolved = 0, unresolved = 0;
  std::string table = "B/A, minor semi-axis in elements, span x, span y, pmax / p0 - 1 (%):\n";
  for (double q : {1.0, 5.0, 20.0}) {
    const HertzReference hz = hertz_from_force(A, q * A, steel.combined_modulus(), 10e3);
    for (double per_b : {0.5, 0.7, 0.9, 1.1, 1.4, 1.8, 2.3, 3.0, 4.0, 5.0}) {
      for (double shift : {0.0, 0.23, 0.5}) {  // the contact's centre off an element's, in elements
        const double element = hz.b / per_b;
        NormalCase c = paraboloid_case(A, q * A, hz.delta, element, 3);
        for (int j = 0; j < c.grid.ny; ++j)
          for (int i = 0; i < c.grid.nx; ++i) {
            const double x = c.grid.x(i) - shift * element, y = c.grid.y(j) - 0.7 * shift * element;
            c.h[static_cast<std::size_t>(c.grid.index(i, j))] = hz.delta - A * x * x - q * A * y * y;
          }
        const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::normal_force(hz.force), ws);
        std::vector<int> label;
        const auto regions = equivalent_ellipses(c.grid, s.pressure, label);
        REQUIRE(regions.size() == 1);
        const auto spans = region_spans(c.grid, label, std::vector<int>{0});
        const RegionSpan brute = brute_span(c.grid, label, 0);
        CHECK(spans[0].x == brute.x);
        CHECK(spans[0].y == brute.y);
        PatchContact pc;
        pc.regions = 1;
        pc.span_x = spans[0].x;
        pc.span_y = spans[0].y;
        const double error = s.max_pressure / hz.p0 - 1;
        table += fmt::format("  {:4.0f} {:4.1f} {:3} {:3} {:+7.2f}\n", q, per_b, pc.span_x, pc.span_y, 100 * error);
        if (wrc::resolved(pc)) {
          ++resolved;
          worst_resolved = std::max(worst_resolved, std::abs(error));
        } else {
          ++unresolved;
          worst_unresolved = std::max(worst_unresolved, std::abs(error));
        }
      }
    }
  }
  MESSAGE(table);
  CHECK(resolved >= 30);
  CHECK(unresolved >= 20);
  CHECK(worst_resolved < 0.035);  // the 3.3 % the rule's comment states (4-5 elements across)
  CHECK(worst_unresolved > 0.2);  // what a grid too coarse does: 74 % measured
}

TEST_CASE("resolution: the spans of the regions asked for, in their order") {
  // Two separate rectangles of pressure on one grid: 6 x 3 and 2 x 9 elements.
  const Grid g = Grid::square(20, 14, 1e-3);
  std::vector<double> p(static_cast<std::size_t>(g.size()), 0.0);
  for (int j = 1; j <= 3; ++j)
    for (int i = 1; i <= 6; ++i) p[static_cast<std::size_t>(g.index(i, j))] = 1e6;
  for (int j = 2; j <= 10; ++j)
    for (int i = 12; i <= 13; ++i) p[static_cast<std::size_t>(g.index(i, j))] = 2e6;
  std::vector<int> label;
  const auto regions = equivalent_ellipses(g, p, label);
  REQUIRE(regions.size() == 2);
  const auto spans = region_spans(g, label, std::vector<int>{1, 0, 7});  // in the order asked; 7 is no region
  REQUIRE(spans.size() == 3);
  CHECK(spans[0].x == 2);
  CHECK(spans[0].y == 9);
  CHECK(spans[1].x == 6);
  CHECK(spans[1].y == 3);
  CHECK(spans[2].x == 0);
  CHECK(spans[2].y == 0);
}
