// The patch interaction criterion against separate and joint solves of two Hertz-like bumps.
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/interaction.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/core/error.hpp"
#include "approx.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <string>

using wrc::test::within_rel;
using namespace wrc::halfspace;
using namespace wrc::test;

namespace {

using wrc::test::steel;

struct Bump {
  double R, delta, x;  // radius of relative curvature (m), depth (m), centre (m)
  double h(double px, double py) const { return delta - ((px - x) * (px - x) + py * py) / (2 * R); }
  PatchFootprint footprint() const {  // what the geometry knows: the inter-penetration circle and depth
    const double r = std::sqrt(2 * R * delta);
    return {x, 0, r, r, delta, 0};
  }
};

struct Pair {
  double separate[2], joint[2];  // forces (N)
};

Pair solve_pair(const NormalSolver& solver, NormalWorkspace& ws, const Bump (&b)[2], double element) {
  Pair out{};
  for (int k = 0; k < 2; ++k) {
    const Bump alone{b[k].R, b[k].delta, 0};
    const NormalCase c = paraboloid_case(1 / (2 * alone.R), 1 / (2 * alone.R), alone.delta, element);
    out.separate[k] = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws).force;
  }
  // One potential contact area covering both inter-penetration circles.
  const double r = std::max(b[0].footprint().half_length, b[1].footprint().half_length);
  const double xmin = std::min(b[0].x, b[1].x) - r, xmax = std::max(b[0].x, b[1].x) + r;
  const Grid g = Grid::covering(xmin - 2 * element, xmax + 2 * element, -r - 2 * element, r + 2 * element, element);
  std::vector<double> h(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) h[g.index(i, j)] = std::max(b[0].h(g.x(i), g.y(j)), b[1].h(g.x(i), g.y(j)));
  const NormalSolution s = solver.solve(g, h, NormalLoad::penetration(), ws);
  const double middle = 0.5 * (b[0].x + b[1].x);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) out.joint[g.x(i) < middle ? 0 : 1] += s.pressure[g.index(i, j)] * g.element_area();
  return out;
}

}  // namespace

TEST_CASE("interaction criterion: predicts the force change of solving two bumps apart") {
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  const double element = 0.2e-3, a = 8 * element, R = 0.3;  // contact radius a of the first bump
  const double tolerance = 0.05;
  for (double depth_ratio : {1.0, 2.0, 0.5}) {  // the second bump: sharper, as deep, deeper, shallower
    std::string table = fmt::format(
        "two bumps, depth ratio {}: s/a, patch, actual force change, predicted, first-order bound\n", depth_ratio);
    double previous_s = 0, previous_actual = 0;
    for (double s_over_a : {3.0, 4.0, 6.0, 8.0, 12.0, 16.0, 24.0}) {
      const double s = s_over_a * a;
      const Bump b[2] = {{R, a * a / R, -s / 2}, {0.7 * R, depth_ratio * a * a / R, s / 2}};
      const Pair p = solve_pair(solver, ws, b, element);
      const PatchInteraction predicted = patch_interaction(steel, b[0].footprint(), b[1].footprint());
      const bool merge = patches_interact(steel, b[0].footprint(), b[1].footprint(), tolerance);
      for (int k = 0; k < 2; ++k) {
        const double actual = 1 - p.joint[k] / p.separate[k];
        const double change = k == 0 ? predicted.change_a : predicted.change_b;
        const double first_order = interaction_ratio(steel, b[1 - k].footprint(), b[k].footprint());
        CAPTURE(depth_ratio);
        CAPTURE(s_over_a);
        CAPTURE(k);
        CHECK(actual > 0);
        CHECK(change == within_rel(actual, 0.06));
        CHECK(first_order >= actual);  // the one-way, first-order law bounds it from above
        // The decision at the stated tolerance, outside the prediction's own error band.
        if (actual > 1.06 * tolerance) CHECK(merge);
        table += fmt::format("  {:5.1f} {} {:.4f} {:.4f} {:.4f}\n", s_over_a, k, actual, change, first_order);
      }
      if (std::max(1 - p.joint[0] / p.separate[0], 1 - p.joint[1] / p.separate[1]) < tolerance / 1.06) CHECK(!merge);
      const double actual0 = 1 - p.joint[0] / p.separate[0];
      if (depth_ratio == 1.0 && previous_s > 0 && previous_actual > tolerance && actual0 <= tolerance) {
        // Where the actual change crosses the tolerance (interpolated) and where the criterion puts it.
        const double s_actual = previous_s + (s - previous_s) * (previous_actual - tolerance) / (previous_actual - actual0);
        double lo = previous_s, hi = s;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          const Bump m[2] = {{R, a * a / R, -mid / 2}, {0.7 * R, depth_ratio * a * a / R, mid / 2}};
          (patch_interaction(steel, m[0].footprint(), m[1].footprint()).change_a > tolerance ? lo : hi) = mid;
        }
        CHECK(lo == within_rel(s_actual, 0.05));
        table += fmt::format("  patch 0 crosses {}: actual s/a = {:.2f}, predicted {:.2f}\n", tolerance, s_actual / a, lo / a);
      }
      previous_s = s;
      previous_actual = actual0;
    }
    MESSAGE(table);
  }
}

TEST_CASE("interaction criterion: far-field law, known forces, bad input") {
  const PatchFootprint p{0, 0, 2e-3, 2e-3, 10e-6, 0};
  const double a = std::sqrt(0.5 * 2e-3 * 2e-3);
  for (double s_over_a : {50.0, 200.0, 1000.0}) {
    PatchFootprint q = p;
    q.x = s_over_a * a;
    CHECK(interaction_ratio(steel, p, q) == within_rel(2 / M_PI / s_over_a, 1.0 / (s_over_a * s_over_a)));
  }
  // A known force replaces the estimate: the ratio is proportional to it.
  PatchFootprint known = p, target = p;
  target.x = 0.05;
  known.force = 2 * estimated_force(steel, p);
  CHECK(interaction_ratio(steel, known, target) == within_rel(2 * interaction_ratio(steel, p, target), 1e-5));
  CHECK(estimated_force(steel, p) == within_rel(4.0 / 3.0 * steel.combined_modulus() * a * 10e-6, 1e-5));
  // Overlapping inter-penetration areas always merge; just apart, the tolerance decides.
  CHECK(patches_interact(steel, p, p, 0.99));
  PatchFootprint beside = p;
  beside.x = 4.01e-3;
  CHECK(!patches_interact(steel, p, beside, 0.99));
  CHECK(patches_interact(steel, p, beside, 0.01));
  const PatchInteraction same = patch_interaction(steel, p, beside);
  CHECK(same.change_a == within_rel(same.change_b, 1e-5));
  CHECK(same.change_a < interaction_ratio(steel, p, beside));
  PatchFootprint bad = p;
  bad.penetration = 0;
  CHECK_THROWS_WITH_AS(interaction_ratio(steel, bad, p), doctest::Contains("penetration"), wrc::Error);
  bad = p;
  bad.half_width = NAN;
  CHECK_THROWS_WITH_AS(interaction_ratio(steel, p, bad), doctest::Contains("half-extents"), wrc::Error);
  bad = p;
  bad.force = -1;
  CHECK_THROWS_WITH_AS(interaction_ratio(steel, bad, p), doctest::Contains("force"), wrc::Error);
  CHECK_THROWS_WITH_AS(patches_interact(steel, p, p, 0), doctest::Contains("tolerance"), wrc::Error);
  CHECK_THROWS_AS(interaction_ratio(Material{1e11, 0.6}, p, p), wrc::Error);
}
