// Kalker's creep coefficients and the linear theory of rolling contact (creep.hpp).
#include "wrc/halfspace/creep.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace wrc::halfspace {
namespace {

using std::numbers::pi;

// Kalker (1990), Table E.3: rows a/b = 0.1, 0.2, .., 1.0, then b/a = 0.9, 0.8, .., 0.1; in each row C11, C22, C23,
// C33, each for nu = 0, 1/4, 1/2.
constexpr int kRows = 19;
constexpr double kTable[kRows][4][3] = {
    {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}},   // a/b = 0.1
    {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}},   // 0.2
    {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}},   // 0.3
    {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}},   // 0.4
    {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}},    // 0.5
    {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}},     // 0.6
    {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}},      // 0.7
    {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}},      // 0.8
    {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}},      // 0.9
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},      // 1.0
    {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}},      // b/a = 0.9
    {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.954}},     // 0.8
    {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.965, 0.852}},    // 0.7
    {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.892, 0.751}},    // 0.6
    {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.958, 0.819, 0.650}},   // 0.5
    {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.912, 0.747, 0.549}},   // 0.4
    {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.868, 0.674, 0.446}},   // 0.3
    {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.828, 0.601, 0.341}},   // 0.2
    {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.795, 0.526, 0.228}},   // 0.1
};

// ln(a/b) of table row r.
double row_x(int r) { return r < 10 ? std::log(0.1 * (r + 1)) : -std::log(0.1 * (19 - r)); }

// Coefficient k of table row r at Poisson's ratio nu: the parabola in nu through the three values of 1/C.
double at_nu(int r, int k, double nu) {
  const double* c = kTable[r][k];
  const double l0 = (nu - 0.25) * (nu - 0.5) / 0.125, l1 = -nu * (nu - 0.5) / 0.0625, l2 = nu * (nu - 0.25) / 0.125;
  return 1.0 / (l0 / c[0] + l1 / c[1] + l2 / c[2]);
}

// Cubic Hermite interpolation in x = ln(a/b) over the rows, slopes from the parabola through three neighbours
// (one-sided at the ends). x within [row_x(0), row_x(18)].
double interpolate(int k, double nu, double x) {
  int r = 0;
  while (r < kRows - 2 && x > row_x(r + 1)) ++r;
  const auto slope = [&](int i) {
    if (i == 0) return (at_nu(1, k, nu) - at_nu(0, k, nu)) / (row_x(1) - row_x(0));
    if (i == kRows - 1) return (at_nu(i, k, nu) - at_nu(i - 1, k, nu)) / (row_x(i) - row_x(i - 1));
    const double h0 = row_x(i) - row_x(i - 1), h1 = row_x(i + 1) - row_x(i);
    const double d0 = (at_nu(i, k, nu) - at_nu(i - 1, k, nu)) / h0, d1 = (at_nu(i + 1, k, nu) - at_nu(i, k, nu)) / h1;
    return (h1 * d0 + h0 * d1) / (h0 + h1);
  };
  const double x0 = row_x(r), x1 = row_x(r + 1), h = x1 - x0, t = (x - x0) / h;
  const double y0 = at_nu(r, k, nu), y1 = at_nu(r + 1, k, nu);
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t), h01 = t * t * (3 - 2 * t),
               h11 = t * t * (t - 1);
  return h00 * y0 + h10 * h * slope(r) + h01 * y1 + h11 * h * slope(r + 1);
}

// Kalker's asymptotic expansions (Table E.3, first and last rows) for g = a/b -> 0 (narrow) and g = b/a -> 0
// (long), coefficient k = 0..2 (C11, C22, C23); for a/b -> 0 also C33 (k = 3).
double asymptote(int k, double nu, double g, bool narrow) {
  if (narrow) {
    switch (k) {
      case 0: return pi * pi / (4 * (1 - nu));
      case 1: return pi * pi / 4;
      case 2: return pi * std::sqrt(g) / (3 * (1 - nu)) * (1 + nu * (std::log(16 / g) - 5));
      default: return pi * pi / (16 * (1 - nu) * g);
    }
  }
  const double L = std::log(16 / (g * g)), q = (1 - nu) * L + 2 * nu, k0 = 3 - std::log(4.0);
  switch (k) {
    case 0: return 2 * pi / ((L - 2 * nu) * g) * (1 + k0 / (L - 2 * nu));
    case 1: return 2 * pi / g * (1 + (1 - nu) * k0 / q) / q;
    default: return 2 * pi / (3 * std::pow(g, 1.5) * ((1 - nu) * L - 2 + 4 * nu));
  }
}

// Beyond the table (g < 0.1): the asymptote times the ratio table/asymptote at g = 0.1 raised to a weight that falls
// from 1 at g = 0.1 to 0 at g = 0.01 -- continuous with the table, and Kalker's expansion itself below 0.01. C33 of
// a long ellipse (no expansion used here): the straight line through the table's b/a = 0.2 and 0.1 values.
double beyond(int k, double nu, double g, bool narrow) {
  const int edge = narrow ? 0 : kRows - 1;
  const double at_edge = at_nu(edge, k, nu);
  if (k == 3 && !narrow) return at_edge + (g - 0.1) * (at_nu(kRows - 2, k, nu) - at_edge) / 0.1;
  const double w = std::clamp(std::log(g / 0.01) / std::log(10.0), 0.0, 1.0);
  return asymptote(k, nu, g, narrow) * std::pow(at_edge / asymptote(k, nu, 0.1, narrow), w);
}

}  // namespace

CreepCoefficients kalker_coefficients(double a_over_b, double nu) {
  if (!std::isfinite(a_over_b) || !(a_over_b > 0))
    fail("kalker_coefficients: a/b = {} must be finite and > 0", a_over_b);
  if (!std::isfinite(nu) || nu < 0 || nu > 0.5)
    fail("kalker_coefficients: Poisson's ratio nu = {} is outside Kalker's table (0 .. 0.5)", nu);
  CreepCoefficients c;
  double v[4];
  const double x = std::log(a_over_b);
  const double lo = row_x(0), hi = row_x(kRows - 1);
  c.tabulated = x >= lo - 1e-12 && x <= hi + 1e-12;
  for (int k = 0; k < 4; ++k) {
    if (c.tabulated) v[k] = interpolate(k, nu, std::clamp(x, lo, hi));
    else if (x < lo) v[k] = beyond(k, nu, a_over_b, true);
    else v[k] = beyond(k, nu, 1 / a_over_b, false);
  }
  c.c11 = v[0];
  c.c22 = v[1];
  c.c23 = v[2];
  c.c33 = v[3];
  return c;
}

CreepForce linear_creep_force(double a, double b, const Material& m, const Creepages& cr) {
  if (!(a > 0) || !(b > 0) || !std::isfinite(a) || !std::isfinite(b))
    fail("linear_creep_force: semi-axes a = {}, b = {} m must be finite and > 0", a, b);
  validate(m, "linear_creep_force");
  const CreepCoefficients k = kalker_coefficients(a / b, m.nu);
  const double G = m.shear_modulus(), c = std::sqrt(a * b), c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  return {-G * c2 * k.c11 * cr.xi, -G * c2 * k.c22 * cr.eta - G * c3 * k.c23 * cr.phi,
          G * c3 * k.c23 * cr.eta - G * c4 * k.c33 * cr.phi};
}

Flexibilities kalker_flexibilities(double a, double b, const Material& m) {
  if (!(a > 0) || !(b > 0) || !std::isfinite(a) || !std::isfinite(b))
    fail("kalker_flexibilities: semi-axes a = {}, b = {} m must be finite and > 0", a, b);
  const CreepCoefficients k = kalker_coefficients(a / b, m.nu);
  const double G = m.shear_modulus();
  return {8 * a / (3 * k.c11 * G), 8 * a / (3 * k.c22 * G), pi * a * std::sqrt(a / b) / (4 * k.c23 * G)};
}

}  // namespace wrc::halfspace
