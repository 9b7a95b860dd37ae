// Kalker's creep coefficients (the table function) and the linear law built on them.
#include "wrc/halfspace/creep.hpp"
#include "wrc/core/error.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using wrc::test::within_rel;
using namespace wrc::halfspace;

TEST_CASE("kalker_coefficients returns Kalker's published values at the table's points") {
  // A few entries of Kalker (1990), Table E.3 (= Johnson, Contact Mechanics, Table 8.1), typed in again here.
  struct Entry {
    double a_over_b, nu, c11, c22, c23, c33;
  };
  const Entry entries[] = {
      {0.1, 0.0, 2.51, 2.51, 0.334, 6.42},  {0.3, 0.25, 3.44, 2.75, 0.715, 2.96}, {0.6, 0.5, 4.91, 3.31, 1.18, 1.86},
      {1.0, 0.25, 4.12, 3.67, 1.47, 1.19},  {1 / 0.7, 0.0, 3.82, 3.82, 1.76, 1.05},
      {1 / 0.4, 0.5, 6.57, 6.31, 3.70, 0.549}, {10.0, 0.25, 11.7, 12.8, 14.6, 0.526}, {2.0, 0.0, 4.37, 4.37, 2.35, 0.958},
  };
  for (const Entry& e : entries) {
    CAPTURE(e.a_over_b);
    CAPTURE(e.nu);
    const CreepCoefficients c = kalker_coefficients(e.a_over_b, e.nu);
    CHECK(c.tabulated);
    CHECK(c.c11 == within_rel(e.c11, 1e-9));
    CHECK(c.c22 == within_rel(e.c22, 1e-9));
    CHECK(c.c23 == within_rel(e.c23, 1e-9));
    CHECK(c.c33 == within_rel(e.c33, 1e-9));
  }
}

TEST_CASE("between the table's points: smooth, between the neighbours, and 1/C11 linear in nu where Kalker's is") {
  for (double x = std::log(0.1); x <= std::log(10.0); x += 0.01) {
    const double r = std::exp(x);
    const CreepCoefficients a = kalker_coefficients(r, 0.25), b = kalker_coefficients(r * std::exp(0.01), 0.25);
    CAPTURE(r);
    for (auto [u, v] : {std::pair{a.c11, b.c11}, {a.c22, b.c22}, {a.c23, b.c23}, {a.c33, b.c33}})
      CHECK(std::abs(v / u - 1) < 0.05);  // no jumps over a 1 % step of a/b
  }
  // Midway between a/b = 0.5 and 0.6 (nu = 0): between the tabulated 2.88 and 2.98.
  const CreepCoefficients m = kalker_coefficients(0.55, 0.0);
  CHECK(m.c11 > 2.88);
  CHECK(m.c11 < 2.98);
  // Railway steel (nu = 0.28), circle: between the nu = 1/4 and 1/2 columns, near the first.
  const CreepCoefficients s = kalker_coefficients(1.0, 0.28);
  CHECK(s.c11 > 4.12);
  CHECK(s.c11 < 4.30);
}

TEST_CASE("beyond the table: Kalker's asymptotic expansions, continuous at a/b = 0.1 and 10") {
  for (double nu : {0.0, 0.25, 0.5}) {
    const CreepCoefficients in_lo = kalker_coefficients(0.1, nu), out_lo = kalker_coefficients(0.0999, nu);
    const CreepCoefficients in_hi = kalker_coefficients(10.0, nu), out_hi = kalker_coefficients(10.01, nu);
    CHECK_FALSE(out_lo.tabulated);
    CHECK_FALSE(out_hi.tabulated);
    for (auto [u, v] : {std::pair{in_lo.c11, out_lo.c11}, {in_lo.c22, out_lo.c22}, {in_lo.c23, out_lo.c23},
                        {in_lo.c33, out_lo.c33}, {in_hi.c11, out_hi.c11}, {in_hi.c22, out_hi.c22},
                        {in_hi.c23, out_hi.c23}, {in_hi.c33, out_hi.c33}})
      CHECK(std::abs(v / u - 1) < 0.01);
    // Deep in the narrow limit the expansions themselves: C11 -> pi^2 / (4 (1 - nu)), C22 -> pi^2 / 4,
    // C33 ~ pi^2 / (16 (1 - nu) a/b).
    const double g = 1e-3;
    const CreepCoefficients n = kalker_coefficients(g, nu);
    CHECK(n.c11 == within_rel(std::numbers::pi * std::numbers::pi / (4 * (1 - nu)), 1e-12));
    CHECK(n.c22 == within_rel(std::numbers::pi * std::numbers::pi / 4, 1e-12));
    CHECK(n.c33 == within_rel(std::numbers::pi * std::numbers::pi / (16 * (1 - nu) * g), 1e-12));
    CHECK(kalker_coefficients(1e3, nu).c11 > kalker_coefficients(100, nu).c11);  // grows like (b/a)^-1
  }
}

TEST_CASE("Kalker's linear law and the FASTSIM flexibilities that reproduce it") {
  const Material m{2.1e11, 0.28};
  const double a = 6e-3, b = 4e-3, G = m.shear_modulus(), c = std::sqrt(a * b);
  const CreepCoefficients k = kalker_coefficients(a / b, m.nu);
  const CreepForce f = linear_creep_force(a, b, m, {1e-3, -2e-3, 0.5});
  CHECK(f.fx == within_rel(-G * c * c * k.c11 * 1e-3, 1e-5));
  CHECK(f.fy == within_rel(-G * c * c * k.c22 * -2e-3 - G * c * c * c * k.c23 * 0.5, 1e-5));
  CHECK(f.mz == within_rel(G * c * c * c * k.c23 * -2e-3 - G * c * c * c * c * k.c33 * 0.5, 1e-5));
  // Simplified theory on the ellipse in adhesion: p_x = -xi (a(y) - x) / L1 gives Fx = -xi 8 a^2 b / (3 L1), etc.
  const Flexibilities L = kalker_flexibilities(a, b, m);
  CHECK(-1e-3 * 8 * a * a * b / (3 * L.x) == within_rel(f.fx, 1e-5));
  CHECK(L.y == within_rel(8 * a / (3 * k.c22 * G), 1e-5));
  CHECK(-0.5 / L.spin * std::numbers::pi / 4 * a * a * a * b == within_rel(-G * c * c * c * k.c23 * 0.5, 1e-5));
  CHECK_THROWS_AS(kalker_coefficients(0, 0.3), wrc::Error);
  CHECK_THROWS_AS(kalker_coefficients(NAN, 0.3), wrc::Error);
  CHECK_THROWS_AS(kalker_coefficients(1, 0.6), wrc::Error);
  CHECK_THROWS_AS(kalker_coefficients(1, -0.1), wrc::Error);
  CHECK_THROWS_AS(linear_creep_force(-1, 1, m, {}), wrc::Error);
}
