// What multibody tables carry (halfspace/ellipse.hpp): Hertz's ellipse against the tests' own Hertz solution and the
// closed form of a circle, FASTSIM's equivalent ellipse of the exact normal solution against Hertz, Kalker's
// coefficients for the Hertz ellipse against Kalker's published table.
#include "wrc/halfspace/ellipse.hpp"
#include "wrc/core/error.hpp"
#include "wrc/halfspace/normal.hpp"
#include "approx.hpp"
#include "hertz_reference.hpp"
#include "normal_cases.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>

using wrc::test::within_rel;
using namespace wrc::halfspace;

namespace {

using wrc::test::steel;

// Kalker's coefficient within the rounding of his table (3 significant digits): half a unit of the last digit.
bool within_table(double value, double table) {
  const double unit = std::pow(10.0, std::floor(std::log10(table)) - 2);
  return std::abs(value - table) <= 0.5 * unit + 1e-9;
}

}  // namespace

TEST_CASE("hertz_contact: semi-axes, peak pressure and approach equal the tests' own Hertz solution") {
  const double Es = steel.combined_modulus();
  // (kx, ky): a wheel of radius 0.45 m on rails of lateral radius 0.3 m, 80 mm, 13 mm, 1 m, and both ways round.
  const double cases[][2] = {{1 / 0.45, 1 / 0.3}, {1 / 0.45, 1 / 0.08}, {1 / 0.45, 1 / 0.013}, {1 / 0.45, 1.0},
                             {1 / 0.08, 1 / 0.45}, {5.0, 5.0}, {1.0, 1000.0}};
  for (const auto& k : cases)
    for (double F : {1e3, 100e3, 500e3}) {
      CAPTURE(k[0]);
      CAPTURE(k[1]);
      CAPTURE(F);
      const auto h = hertz_contact(k[0], k[1], F, steel);
      REQUIRE(h);
      const wrc::test::HertzReference ref = wrc::test::hertz_from_force(k[0] / 2, k[1] / 2, Es, F);
      CHECK(h->a == within_rel(ref.a, 1e-7));
      CHECK(h->b == within_rel(ref.b, 1e-7));
      CHECK(h->p0 == within_rel(ref.p0, 1e-7));
      CHECK(h->approach == within_rel(ref.delta, 1e-7));
      CHECK(h->force == F);
      CHECK((k[0] <= k[1]) == (h->a >= h->b));  // the smaller curvature has the longer axis
    }
}

TEST_CASE("hertz_contact: a circle has Hertz's closed form") {
  // Two spheres' relative radius R = 1 / k: a^3 = 3 F R / (4 E*), p0 = 3 F / (2 pi a^2), approach a^2 / R.
  const double R = 0.2, F = 50e3, Es = steel.combined_modulus();
  const auto h = hertz_contact(1 / R, 1 / R, F, steel);
  REQUIRE(h);
  const double a = std::cbrt(3 * F * R / (4 * Es));
  CHECK(h->a == within_rel(a, 1e-12));
  CHECK(h->b == within_rel(a, 1e-12));
  CHECK(h->p0 == within_rel(3 * F / (2 * std::numbers::pi * a * a), 1e-12));
  CHECK(h->approach == within_rel(a * a / R, 1e-12));
  // Nearly a circle: continuous with it (no cancellation in K - E as the eccentricity vanishes).
  const auto near = hertz_contact(1 / R, (1 + 1e-9) / R, F, steel);
  REQUIRE(near);
  CHECK(near->a == within_rel(a, 1e-8));
  CHECK(near->b == within_rel(a, 1e-8));
}

TEST_CASE("hertz_contact: no ellipse for a concave pair or no load, an error on non-finite input") {
  CHECK_FALSE(hertz_contact(2.0, -1.0, 1e5, steel));
  CHECK_FALSE(hertz_contact(0.0, 1.0, 1e5, steel));
  CHECK_FALSE(hertz_contact(2.0, 3.0, 0.0, steel));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(hertz_contact(nan, 1.0, 1e5, steel), wrc::Error);
  CHECK_THROWS_WITH_AS(hertz_contact(1.0, 1.0, INFINITY, steel), doctest::Contains("must be finite"), wrc::Error);
  CHECK_THROWS_AS(hertz_contact(1.0, 1.0, 1e5, Material{-1, 0.3}), wrc::Error);
}

TEST_CASE("wheel_rail_curvature: the wheel's circle seen along the contact normal, the profiles summed across") {
  const RelativeCurvature k = wheel_rail_curvature(0.45, 0.3, -2.0, 5.0);
  CHECK(k.kx == within_rel(std::cos(0.3) / 0.45, 1e-15));
  CHECK(k.ky == within_rel(3.0, 1e-15));
}

TEST_CASE("FASTSIM's equivalent ellipse of the exact normal solution is Hertz's within 1 % on a fine grid") {
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  // (kx, ky) as a wheel on a rail crown: a/b about 1.6, 1 and 0.4.
  const double cases[][2] = {{1 / 0.45, 1 / 0.3}, {1 / 0.3, 1 / 0.3}, {1 / 0.45, 1 / 0.05}, {1 / 0.05, 1 / 0.45}};
  for (const auto& k : cases) {
    CAPTURE(k[0]);
    CAPTURE(k[1]);
    const auto shape = hertz_contact(k[0], k[1], 100e3, steel);
    REQUIRE(shape);
    const double element = std::min(shape->a, shape->b) / 60;
    const wrc::test::NormalCase c = wrc::test::paraboloid_case(k[0] / 2, k[1] / 2, shape->approach, element);
    const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
    const auto ellipse = fastsim_ellipse(c.grid, s.pressure);
    REQUIRE(ellipse);
    CHECK(ellipse->force == within_rel(s.force, 1e-12));  // one region
    const auto hertz = hertz_contact(k[0], k[1], s.force, steel);  // Hertz for the solved load
    REQUIRE(hertz);
    CHECK(ellipse->a == within_rel(hertz->a, 0.01));
    CHECK(ellipse->b == within_rel(hertz->b, 0.01));
  }
}

TEST_CASE("equivalent_ellipses: two separate regions, each its own ellipse and force, labelled") {
  Grid g = Grid::square(20, 10, 1e-3);
  std::vector<double> p(static_cast<std::size_t>(g.size()), 0.0);
  for (int j = 2; j <= 5; ++j)
    for (int i = 1; i <= 8; ++i) p[g.index(i, j)] = 1e6;  // 8 x 4 elements
  for (int j = 3; j <= 8; ++j)
    for (int i = 13; i <= 15; ++i) p[g.index(i, j)] = 2e6;  // 3 x 6
  std::vector<int> label;
  const std::vector<EquivalentEllipse> e = equivalent_ellipses(g, p, label);
  REQUIRE(e.size() == 2);
  // A rectangle: a/b = its length / width, pi a b its area.
  CHECK(e[0].a == within_rel(std::sqrt(32e-6 * 2 / std::numbers::pi), 1e-12));
  CHECK(e[0].b == within_rel(std::sqrt(32e-6 / 2 / std::numbers::pi), 1e-12));
  CHECK(e[0].force == within_rel(32e-6 * 1e6, 1e-12));
  CHECK(e[1].force == within_rel(18e-6 * 2e6, 1e-12));
  CHECK(label[static_cast<std::size_t>(g.index(1, 2))] == 0);
  CHECK(label[static_cast<std::size_t>(g.index(15, 8))] == 1);
  CHECK(label[0] == -1);
  const auto largest = fastsim_ellipse(g, p);  // the second carries more force
  REQUIRE(largest);
  CHECK(largest->force == within_rel(e[1].force, 1e-15));
}

// An element entering a region with pressure q grows its ellipse continuously and monotonically: as q -> 0 the
// ellipse tends to the region's without it, and from 5 % of the region's peak pressure on the element counts whole
// (FASTSIM's creep forces jumped when an element entered with any pressure at all).
TEST_CASE("equivalent_ellipses: an element entering a region grows its ellipse continuously from zero pressure") {
  const Grid g = Grid::square(20, 10, 1e-3);
  std::vector<double> p(static_cast<std::size_t>(g.size()), 0.0);
  for (int j = 2; j <= 5; ++j)
    for (int i = 1; i <= 8; ++i) p[g.index(i, j)] = 1e6;  // 8 x 4 elements
  const auto ellipse = [&](double q) {
    std::vector<double> with = p;
    with[g.index(9, 3)] = q;  // one element past the rectangle's end, in its third row
    std::vector<int> label;
    const std::vector<EquivalentEllipse> e = equivalent_ellipses(g, with, label);
    REQUIRE(e.size() == 1);
    return e[0];
  };
  // Rectangles of n elements along x (1 mm each) by 4 across: a/b = n / 4, pi a b = its area.
  const auto a_of = [](double n, double area) { return std::sqrt(area * 1e-6 * (n / 4) / std::numbers::pi); };
  const auto b_of = [](double n, double area) { return std::sqrt(area * 1e-6 / (n / 4) / std::numbers::pi); };
  const EquivalentEllipse tiny = ellipse(1e-3);  // 1e-9 of the peak
  CHECK(tiny.a == within_rel(a_of(8, 32), 1e-8));
  CHECK(tiny.b == within_rel(b_of(8, 32), 1e-8));
  const EquivalentEllipse whole = ellipse(0.05e6);  // counted whole: a ninth column of one element
  CHECK(whole.a == within_rel(a_of(9, 33), 1e-12));
  CHECK(whole.b == within_rel(b_of(9, 33), 1e-12));
  double last = tiny.a;
  for (double q = 1e3; q <= 0.05e6; q += 1e3) {  // steps of 1/50 of the way: a grows by at most 1.5/50 of its rise
    const double a = ellipse(q).a;
    CHECK(a >= last);
    CHECK(a - last <= 1.5 * (whole.a - tiny.a) / 50);  // the weight s^2 (3 - 2 s) rises at most 1.5 x as fast as s
    last = a;
  }
}

TEST_CASE("hertz_ellipses: Kalker's coefficients for the Hertz ellipse equal Kalker's published table") {
  // Kalker (1990), Table E.3 = Johnson, Contact Mechanics (1985), Table 8.1, nu = 0.25, typed in again here:
  // g = a/b = 1:   C11 4.12, C22 3.67, C23 1.47, C33 1.19;
  // a/b = 0.5:     C11 3.62, C22 3.01, C23 0.929, C33 1.93;
  // b/a = 0.5:     C11 5.10, C22 4.90, C23 2.62, C33 0.819.
  const Material m{2.1e11, 0.25};
  // The curvature ratio of Hertz's shape equation for the axis ratio kp (the tests' own elliptic integrals).
  const auto ratio = [](double kp) {
    const auto [K, E] = wrc::test::elliptic_ke(kp);
    return (E / (kp * kp) - K) / (K - E);
  };
  struct Row {
    double kx, ky, a_over_b, c11, c22, c23, c33;
  };
  const double q = ratio(0.5);
  const Row rows[] = {{3.0, 3.0, 1.0, 4.12, 3.67, 1.47, 1.19},
                      {q * 2.0, 2.0, 0.5, 3.62, 3.01, 0.929, 1.93},
                      {2.0, q * 2.0, 2.0, 5.10, 4.90, 2.62, 0.819}};
  for (const Row& r : rows) {
    CAPTURE(r.a_over_b);
    const ContactEllipses e = hertz_ellipses({r.kx, r.ky}, 80e3, m);
    REQUIRE(e.hertz);
    CHECK(e.hertz->a / e.hertz->b == within_rel(r.a_over_b, 1e-7));
    REQUIRE(e.kalker);
    CHECK(within_table(e.kalker->c11, r.c11));
    CHECK(within_table(e.kalker->c22, r.c22));
    CHECK(within_table(e.kalker->c23, r.c23));
    CHECK(within_table(e.kalker->c33, r.c33));
    CHECK(e.kalker->tabulated);
    CHECK_FALSE(e.ellipse);
  }
  // A concave pair: no Hertz ellipse, no coefficients.
  const ContactEllipses none = hertz_ellipses({2.0, -1.0}, 80e3, m);
  CHECK_FALSE(none.hertz);
  CHECK_FALSE(none.kalker);
  // A Poisson's ratio below Kalker's table: the Hertz ellipse, no coefficients (and no error).
  const ContactEllipses auxetic = hertz_ellipses({3.0, 3.0}, 80e3, Material{2.1e11, -0.2});
  CHECK(auxetic.hertz);
  CHECK_FALSE(auxetic.kalker);
}
