// Half-space influence coefficients of uniform pressure on a rectangular element (Love 1929; Johnson,
// Contact Mechanics, 1985, section 3.3). A uniform pressure p on [-a, a] x [-b, b] of the surface of an
// elastic half-space (E, nu) displaces the surface point (x, y) normally by
//   u = (1 - nu^2) / (pi E) * p * I(x, y),   I = integral over the rectangle of dA / r   (I in m).
// With identical bodies the two surfaces approach by 2 u, so the normal problem on a grid reads
// 2 D p = h with 2 D_kl = I(x_k - x_l, y_k - y_l) / (pi E*), E* = Material::combined_modulus().
#pragma once

#include "wrc/contact/material.hpp"

#include <cstdlib>
#include <vector>

namespace wrc::contact {

// I(x, y) of the header (m): the integral of 1/r over the rectangle [-a, a] x [-b, b] (a, b > 0, m)
// seen from the surface point (x, y) (m). Closed form with asinh, accurate everywhere (including on
// element edges and corners); far away it tends to 4 a b / r.
double rectangle_potential(double x, double y, double a, double b);

// Normal surface displacement (m) of ONE half-space at (x, y) from a uniform pressure p (Pa) on
// [-a, a] x [-b, b].
double rectangle_displacement(const Material& material, double x, double y, double a, double b, double p);

// The coefficients I(m dx, n dy) of elements of size dx x dy (m) for the offsets 0 <= m < mx,
// 0 <= n < my (elements). I is even in each offset, so this quarter table serves all signs.
class InfluenceTable {
 public:
  InfluenceTable(double dx, double dy, int mx, int my);
  double operator()(int m, int n) const { return values_[std::abs(m) + mx_ * std::abs(n)]; }  // m
  const double* row(int n) const { return values_.data() + mx_ * std::abs(n); }  // offsets (0..mx-1, n)
  int mx() const { return mx_; }
  int my() const { return my_; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }

 private:
  double dx_, dy_;
  int mx_, my_;
  std::vector<double> values_;
};

}  // namespace wrc::contact
