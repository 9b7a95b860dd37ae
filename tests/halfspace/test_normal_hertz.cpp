// The normal solvers against the analytic Hertz solution (reference computed in hertz_reference.hpp).
#include "halfspace/hertz_reference.hpp"
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/normal.hpp"
#include "approx.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

using wrc::test::within_rel;
using namespace wrc::halfspace;
using namespace wrc::test;

namespace {

struct HertzErrors {
  double force, p0, a_elements, b_elements, l2;  // relative, relative, elements, elements, relative
};

// Compares a solution of paraboloid_case(A, B, ...) with the Hertz contact hz.
HertzErrors compare(const NormalCase& c, const NormalSolution& s, const HertzReference& hz) {
  const Grid& g = c.grid;
  double amax = 0, bmax = 0, num = 0, den = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.x(i), y = g.y(j), p = s.pressure[g.index(i, j)];
      if (p > 0) {  // outer edge of the outermost elements in contact
        amax = std::max(amax, std::abs(x) + 0.5 * g.dx);
        bmax = std::max(bmax, std::abs(y) + 0.5 * g.dy);
      }
      const double t = 1 - x * x / (hz.a * hz.a) - y * y / (hz.b * hz.b);
      const double ph = t > 0 ? hz.p0 * std::sqrt(t) : 0.0;
      num += (p - ph) * (p - ph);
      den += ph * ph;
    }
  return {s.force / hz.force - 1, s.max_pressure / hz.p0 - 1, (amax - hz.a) / g.dx, (bmax - hz.b) / g.dy,
          std::sqrt(num / den)};
}

using wrc::test::steel;

// Approach that makes the minor semi-axis `elements` elements of size `element`.
double approach_for(double A, double B, double element, double elements) {
  const HertzReference unit = hertz_from_approach(A, B, steel.combined_modulus(), 1e-6);
  return 1e-6 * std::pow(elements * element / std::min(unit.a, unit.b), 2);
}

}  // namespace

TEST_CASE("Hertz reference: elliptic integrals and the contact it builds") {
  // K(0) = E(0) = pi/2; K(1/sqrt 2) = Gamma(1/4)^2 / (4 sqrt(pi)); Legendre's relation at k = k'.
  const auto zero = elliptic_ke(1.0);
  CHECK(zero.K == within_rel(std::numbers::pi / 2, 1e-15));
  CHECK(zero.E == within_rel(std::numbers::pi / 2, 1e-15));
  const auto half = elliptic_ke(std::sqrt(0.5));
  CHECK(half.K == within_rel(std::pow(std::tgamma(0.25), 2) / (4 * std::sqrt(std::numbers::pi)), 1e-14));
  // K and E are each good to ~1e-14; the combination measured 1.5e-14 off.
  CHECK(2 * half.E * half.K - half.K * half.K == within_rel(std::numbers::pi / 2, 2e-14));
  // Small modulus series.
  const double k = 0.01, kp = std::sqrt(1 - k * k);
  const auto small = elliptic_ke(kp);
  CHECK(small.K == within_rel(std::numbers::pi / 2 * (1 + k * k / 4 + 9 * std::pow(k, 4) / 64), 1e-12));
  CHECK(small.E == within_rel(std::numbers::pi / 2 * (1 - k * k / 4 - 3 * std::pow(k, 4) / 64), 1e-12));
  // Circle: a^2 = R delta, F = 4/3 E* sqrt(R) delta^(3/2); nearly circular ellipses tend to it.
  const double R = 0.3, A = 1 / (2 * R), delta = 20e-6, Es = steel.combined_modulus();
  const auto circle = hertz_from_approach(A, A, Es, delta);
  CHECK(circle.a == within_rel(std::sqrt(R * delta), 1e-14));
  CHECK(circle.force == within_rel(4.0 / 3.0 * Es * std::sqrt(R) * std::pow(delta, 1.5), 1e-14));
  const auto near = hertz_from_approach(A, 1.0001 * A, Es, delta);
  CHECK(near.force == within_rel(circle.force, 1e-4));
  CHECK(near.a > near.b);
  // Force <-> approach round trip, and swapping the curvatures swaps the axes.
  const auto el = hertz_from_approach(A, 6 * A, Es, delta);
  CHECK(hertz_from_force(A, 6 * A, Es, el.force).delta == within_rel(delta, 1e-12));
  const auto swapped = hertz_from_approach(6 * A, A, Es, delta);
  CHECK(swapped.a == within_rel(el.b, 1e-14));
  CHECK(swapped.b == within_rel(el.a, 1e-14));
  // The shape equation holds: B/A from the solved axis ratio.
  const auto [K, E] = elliptic_ke(el.b / el.a);
  const double kp2 = std::pow(el.b / el.a, 2);
  CHECK((E / kp2 - K) / (K - E) == within_rel(6.0, 1e-10));
}

TEST_CASE("Hertz: force, peak pressure and semi-axes for curvature ratios 1 to 10, both controls") {
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  const double element = 0.2e-3, A = 1 / (2 * 0.45);
  for (double q : {1.0, 2.0, 4.0, 7.0, 10.0}) {
    for (bool along_y : {false, true}) {  // the long axis along x, then along y
      const double Ax = along_y ? q * A : A, By = along_y ? A : q * A;
      const double delta = approach_for(Ax, By, element, 8);
      const HertzReference hz = hertz_from_approach(Ax, By, steel.combined_modulus(), delta);
      const NormalCase c = paraboloid_case(Ax, By, delta, element);
      CAPTURE(q);
      CAPTURE(along_y);
      const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
      const HertzErrors e = compare(c, s, hz);
      CHECK(std::abs(e.force) < 0.01);
      CHECK(std::abs(e.p0) < 0.02);
      CHECK(std::abs(e.a_elements) <= 1.0);
      CHECK(std::abs(e.b_elements) <= 1.0);
      CHECK(s.residual.relative < 1.01e-8);
      CHECK(s.edge_elements_in_contact == 0);  // the margin holds the whole contact
      // Prescribed force: the solved approach is Hertz's to 1 %, the same distribution.
      const NormalSolution f = solver.solve(c.grid, c.h, NormalLoad::normal_force(hz.force), ws);
      CHECK(f.force == within_rel(hz.force, 1e-9));
      CHECK(std::abs(f.approach / delta) < 0.01);  // h already holds Hertz's approach
      const HertzErrors ef = compare(c, f, hz);
      CHECK(std::abs(ef.p0) < 0.02);
      CHECK(std::abs(ef.a_elements) <= 1.0);
      CHECK(std::abs(ef.b_elements) <= 1.0);
    }
  }
}

TEST_CASE("Hertz: the dense reference solver too") {
  const double element = 0.2e-3, A = 1 / (2 * 0.45);
  const double delta = approach_for(A, 3 * A, element, 5);
  const HertzReference hz = hertz_from_approach(A, 3 * A, steel.combined_modulus(), delta);
  const NormalCase c = paraboloid_case(A, 3 * A, delta, element, 1);
  REQUIRE(c.grid.size() < 800);
  const NormalSolution s = solve_normal_dense(steel, c.grid, c.h, NormalLoad::penetration());
  const HertzErrors e = compare(c, s, hz);
  CHECK(std::abs(e.force) < 0.01);
  CHECK(std::abs(e.p0) < 0.02);
  CHECK(std::abs(e.a_elements) <= 1.0);
  CHECK(std::abs(e.b_elements) <= 1.0);
}

TEST_CASE("Hertz: the dense solver on three sizes, against Hertz and the fast solver, cold and warm") {
  // Contacts of ~100, ~300 and ~700 elements (B/A = 3): Hertz's force within the discretisation error the fast
  // solver's Hertz cases allow at these sizes, the fast solver's solution to its tolerance, and a warm start (the
  // shallower pose's pressure, as an equilibrium's next evaluation passes it) lands on the cold solve.
  const double element = 0.2e-3, A = 1 / (2 * 0.45);
  const NormalSolver fast(steel);
  for (double semi_axis : {4.0, 7.0, 10.0}) {  // elements on the minor semi-axis
    CAPTURE(semi_axis);
    const double delta = approach_for(A, 3 * A, element, semi_axis);
    const HertzReference hz = hertz_from_approach(A, 3 * A, steel.combined_modulus(), delta);
    const NormalCase c = paraboloid_case(A, 3 * A, delta, element);
    const NormalSolution d = solve_normal_dense(steel, c.grid, c.h, NormalLoad::penetration());
    const HertzErrors e = compare(c, d, hz);
    CHECK(std::abs(e.force) < 0.005);  // measured 0.1 % at 4 elements on b, less on finer grids
    CHECK(std::abs(e.a_elements) <= 1.0);
    CHECK(std::abs(e.b_elements) <= 1.0);
    const NormalSolution f = fast.solve(c.grid, c.h, NormalLoad::penetration());
    for (int k = 0; k < c.grid.size(); ++k) {
      CHECK((d.pressure[k] > 0) == (f.pressure[k] > 0));
      CHECK(std::abs(d.pressure[k] - f.pressure[k]) < 1e-6 * d.max_pressure);
    }
    NormalCase shallower = c;
    for (double& h : shallower.h) h -= 0.05 * delta;
    const NormalSolution before = solve_normal_dense(steel, shallower.grid, shallower.h, NormalLoad::penetration());
    NormalOptions warm;
    warm.initial_pressure = before.pressure;
    const NormalSolution w = solve_normal_dense(steel, c.grid, c.h, NormalLoad::penetration(), warm);
    for (int k = 0; k < c.grid.size(); ++k) CHECK(std::abs(w.pressure[k] - d.pressure[k]) < 1e-9 * d.max_pressure);
    MESSAGE(fmt::format("dense Hertz, b = {} elements: {} in contact, {} iterations cold, {} warm; force {:+.3f} %",
                        semi_axis, d.elements_in_contact, d.iterations, w.iterations, 100 * e.force));
  }
}

TEST_CASE("Hertz: the error shrinks as the grid is refined") {
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  const double A = 1 / (2 * 0.45), delta = 15e-6;
  for (double q : {1.0, 5.0}) {
    const HertzReference hz = hertz_from_approach(A, q * A, steel.combined_modulus(), delta);
    HertzErrors previous{};
    std::string table = fmt::format("Hertz B/A = {}: elements on b, grid, force err %, p0 err %, a err (el), "
                                    "b err (el), L2 pressure err %\n",
                                    q);
    for (int level = 0; level < 3; ++level) {
      const double per_b = 4 << level;                            // 4, 8, 16 elements on the minor semi-axis
      const double element = std::min(hz.a, hz.b) / per_b * 1.013;  // not aligned with the contact edge
      const NormalCase c = paraboloid_case(A, q * A, delta, element);
      const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
      const HertzErrors e = compare(c, s, hz);
      table += fmt::format("  {:4.0f} {:4}x{:<4} {:+.4f} {:+.4f} {:+.2f} {:+.2f} {:.4f}\n", per_b, c.grid.nx, c.grid.ny,
                           100 * e.force, 100 * e.p0, e.a_elements, e.b_elements, 100 * e.l2);
      if (level > 0) {  // the peak converges to second order in the element size (at least halves per
                        // halving); the L2 error, limited by the square-root edge, decreases more slowly
        CHECK(std::abs(e.p0) < 0.5 * std::abs(previous.p0));
        CHECK(e.l2 < previous.l2);
        // In metres the semi-axes converge too: within one (ever smaller) element.
        CHECK(std::abs(e.a_elements) <= 1.0);
        CHECK(std::abs(e.b_elements) <= 1.0);
      }
      CHECK(std::abs(e.force) < 0.01);
      previous = e;
    }
    MESSAGE(table);
  }
}
