// Half-space influence coefficients of uniform pressure on a rectangular element (Love 1929; Johnson,
// Contact Mechanics, 1985, section 3.3). A uniform pressure p on [-a, a] x [-b, b] of the surface of an
// elastic half-space (E, nu) displaces the surface point (x, y) normally by
//   u = (1 - nu^2) / (pi E) * p * I(x, y),   I = integral over the rectangle of dA / r   (I in m).
// With identical bodies the two surfaces approach by 2 u, so the normal problem on a grid reads
// 2 D p = h with 2 D_kl = I(x_k - x_l, y_k - y_l) / (pi E*), E* = Material::combined_modulus().
//
// Tangential (Cerruti) influence: a uniform shear traction (q_x, q_y) on the same rectangle displaces the surface of
// ONE half-space tangentially by (Johnson, Contact Mechanics, eq. 3.86, a point force integrated over the rectangle)
//   u_x = [(1 - nu) I + nu J_xx] q_x / (2 pi G) + nu J_xy q_y / (2 pi G),
//   u_y = nu J_xy q_x / (2 pi G) + [(1 - nu) I + nu J_yy] q_y / (2 pi G),
// with J_xx, J_yy, J_xy the integrals of (x - s)^2 / r^3, (y - t)^2 / r^3 and (x - s)(y - t) / r^3 over the rectangle
// (source point (s, t); J_xx + J_yy = I) and G = E / (2 (1 + nu)). It also displaces the surface normally, by
// -(1 - 2 nu) / (4 pi G) times the integral of (x - s) / r^2 q_x (and the same in y); on the other body the opposite
// traction acts on a half-space facing the other way, so for identical bodies the two normal displacements are
// equal and of the same sign: the gap does not change (Kalker's quasi-identity) and the tangential displacement
// DIFFERENCE of the pair is twice the one-body value, u = B q with B = [(1 - nu) I + nu J] / (pi G).
#pragma once

#include "wrc/halfspace/material.hpp"

#include <cstdlib>
#include <vector>

namespace wrc::halfspace {

// I(x, y) of the header (m): the integral of 1/r over the rectangle [-a, a] x [-b, b] (a, b > 0, m)
// seen from the surface point (x, y) (m). Closed form with asinh, accurate everywhere (including on
// element edges and corners); far away it tends to 4 a b / r.
double rectangle_potential(double x, double y, double a, double b);

// Normal surface displacement (m) of ONE half-space at (x, y) from a uniform pressure p (Pa) on
// [-a, a] x [-b, b].
double rectangle_displacement(const Material& material, double x, double y, double a, double b, double p);

// The shear integrals of the rectangle [-a, a] x [-b, b] seen from (x, y) (m): I (as rectangle_potential), J_xx, J_yy
// and J_xy of the header. Closed forms (antiderivatives Y asinh(X/|Y|), X asinh(Y/|X|) and -sqrt(X^2 + Y^2) at the
// corners), accurate on edges and corners.
struct ShearPotentials {
  double I = 0, xx = 0, yy = 0, xy = 0;
};
ShearPotentials rectangle_shear_potentials(double x, double y, double a, double b);

// Tangential surface displacement (m) of ONE half-space at (x, y) from a uniform traction (q_x, q_y) (Pa) on
// [-a, a] x [-b, b] (the formula of the header). The pair's displacement difference is twice this.
struct TangentialDisplacement {
  double x = 0, y = 0;
};
TangentialDisplacement rectangle_shear_displacement(const Material& material, double x, double y, double a, double b,
                                                    double qx, double qy);

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

// The pair's tangential coefficients of elements dx x dy (m) for offsets |m| < mx, |n| < my (the field element minus
// the loaded one, in elements): the displacement difference (m) per unit traction (Pa), B_xx = [(1 - nu) I + nu J_xx]
// / (pi G), B_yy likewise and B_xy = nu J_xy / (pi G). B_xx and B_yy are even in each offset, B_xy odd in each.
class ShearInfluenceTable {
 public:
  ShearInfluenceTable(const Material& material, double dx, double dy, int mx, int my);
  double xx(int m, int n) const { return xx_[index(m, n)]; }  // m/Pa
  double yy(int m, int n) const { return yy_[index(m, n)]; }
  double xy(int m, int n) const {
    const double v = xy_[index(m, n)];
    return (m < 0) != (n < 0) ? -v : v;
  }
  int mx() const { return mx_; }
  int my() const { return my_; }

 private:
  std::size_t index(int m, int n) const { return static_cast<std::size_t>(std::abs(m) + mx_ * std::abs(n)); }
  int mx_, my_;
  std::vector<double> xx_, yy_, xy_;
};

}  // namespace wrc::halfspace
