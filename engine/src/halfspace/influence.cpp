// Love's closed form of the 1/r integral over a rectangle.
#include "wrc/halfspace/influence.hpp"

#include "wrc/core/error.hpp"

#include <cmath>
#include <numbers>

namespace wrc::halfspace {
namespace {

// Antiderivative G(X, Y) with d2G/dXdY = 1/sqrt(X^2 + Y^2), odd in X and in Y:
//   G = X asinh(Y/|X|) + Y asinh(X/|Y|).
// Love's logarithms ln(Y + r) differ from asinh(Y/|X|) by ln|X|, which cancels between corners that
// share X; the asinh form has no log of a difference, hence no cancellation near edges.
double love_corner(double X, double Y) {
  double g = 0;
  if (X != 0) g += X * std::asinh(Y / std::abs(X));
  if (Y != 0) g += Y * std::asinh(X / std::abs(Y));
  return g;
}

// Antiderivatives of the shear kernels X^2 / r^3, Y^2 / r^3 and X Y / r^3 (d2/dXdY of each gives the kernel): the
// two halves of `corner` and -r. X, Y are source minus field coordinates; X Y has the sign of (x - s)(y - t).
double corner_xx(double X, double Y) { return Y != 0 ? Y * std::asinh(X / std::abs(Y)) : 0.0; }
double corner_yy(double X, double Y) { return X != 0 ? X * std::asinh(Y / std::abs(X)) : 0.0; }
double corner_xy(double X, double Y) { return -std::hypot(X, Y); }

template <class F>
double over_rectangle(F f, double x, double y, double a, double b) {
  const double x1 = -a - x, x2 = a - x, y1 = -b - y, y2 = b - y;
  return f(x2, y2) - f(x1, y2) - f(x2, y1) + f(x1, y1);
}

}  // namespace

ShearPotentials rectangle_shear_potentials(double x, double y, double a, double b) {
  ShearPotentials s;
  s.xx = over_rectangle(corner_xx, x, y, a, b);
  s.yy = over_rectangle(corner_yy, x, y, a, b);
  s.xy = over_rectangle(corner_xy, x, y, a, b);
  s.I = s.xx + s.yy;
  return s;
}

TangentialDisplacement rectangle_shear_displacement(const Material& m, double x, double y, double a, double b,
                                                    double qx, double qy) {
  const ShearPotentials s = rectangle_shear_potentials(x, y, a, b);
  const double f = 1.0 / (2.0 * std::numbers::pi * m.shear_modulus());
  return {f * (((1 - m.nu) * s.I + m.nu * s.xx) * qx + m.nu * s.xy * qy),
          f * (m.nu * s.xy * qx + ((1 - m.nu) * s.I + m.nu * s.yy) * qy)};
}

double rectangle_potential(double x, double y, double a, double b) {
  // Source point s - field point (x, y) runs over [-a - x, a - x] x [-b - y, b - y].
  const double x1 = -a - x, x2 = a - x, y1 = -b - y, y2 = b - y;
  return love_corner(x2, y2) - love_corner(x1, y2) - love_corner(x2, y1) + love_corner(x1, y1);
}

double rectangle_displacement(const Material& material, double x, double y, double a, double b, double p) {
  return material.compliance() * p * rectangle_potential(x, y, a, b);
}

InfluenceTable::InfluenceTable(double dx, double dy, int mx, int my) : dx_(dx), dy_(dy), mx_(mx), my_(my) {
  if (!(dx > 0) || !(dy > 0) || !std::isfinite(dx) || !std::isfinite(dy))
    fail("InfluenceTable: element size {} x {} m must be finite and positive", dx, dy);
  if (mx < 1 || my < 1) fail("InfluenceTable: {} x {} offsets, expected at least 1 x 1", mx, my);
  // The corners of all elements lie on the lattice ((k - 1/2) dx, (l - 1/2) dy): evaluate G once per
  // lattice point and difference (a quarter of the cost of four corners per element).
  const int cx = mx + 1, cy = my + 1;
  std::vector<double> g(static_cast<std::size_t>(cx) * cy);
  for (int l = 0; l < cy; ++l)
    for (int k = 0; k < cx; ++k) g[k + cx * l] = love_corner((k - 0.5) * dx, (l - 0.5) * dy);
  values_.resize(static_cast<std::size_t>(mx) * my);
  for (int n = 0; n < my; ++n)
    for (int m = 0; m < mx; ++m)
      values_[m + mx * n] = g[(m + 1) + cx * (n + 1)] - g[m + cx * (n + 1)] - g[(m + 1) + cx * n] + g[m + cx * n];
}

ShearInfluenceTable::ShearInfluenceTable(const Material& material, double dx, double dy, int mx, int my)
    : mx_(mx), my_(my) {
  validate(material, "ShearInfluenceTable");
  if (!(dx > 0) || !(dy > 0) || !std::isfinite(dx) || !std::isfinite(dy))
    fail("ShearInfluenceTable: element size {} x {} m must be finite and positive", dx, dy);
  if (mx < 1 || my < 1) fail("ShearInfluenceTable: {} x {} offsets, expected at least 1 x 1", mx, my);
  // As InfluenceTable: the antiderivatives once per corner lattice point, then differenced per element.
  const int cx = mx + 1, cy = my + 1;
  std::vector<double> gxx(static_cast<std::size_t>(cx) * cy), gyy(gxx.size()), gxy(gxx.size());
  for (int l = 0; l < cy; ++l)
    for (int k = 0; k < cx; ++k) {
      const double X = (k - 0.5) * dx, Y = (l - 0.5) * dy;
      const std::size_t q = static_cast<std::size_t>(k + cx * l);
      gxx[q] = corner_xx(X, Y);
      gyy[q] = corner_yy(X, Y);
      gxy[q] = corner_xy(X, Y);
    }
  const auto rect = [&](const std::vector<double>& g, int m, int n) {
    return g[(m + 1) + cx * (n + 1)] - g[m + cx * (n + 1)] - g[(m + 1) + cx * n] + g[m + cx * n];
  };
  // rect(g, m, n) integrates source minus field over [(m - 1/2) dx, (m + 1/2) dx] x [(n - 1/2) dy, (n + 1/2) dy]: the
  // field element at offset (-m, -n) from the source, which J_xy (odd in both) shares with offset (m, n).
  const double f = 1.0 / (std::numbers::pi * material.shear_modulus()), nu = material.nu;
  xx_.resize(static_cast<std::size_t>(mx) * my);
  yy_.resize(xx_.size());
  xy_.resize(xx_.size());
  for (int n = 0; n < my; ++n)
    for (int m = 0; m < mx; ++m) {
      const double Jxx = rect(gxx, m, n), Jyy = rect(gyy, m, n), Jxy = rect(gxy, m, n);
      const std::size_t q = index(m, n);
      xx_[q] = f * ((1 - nu) * (Jxx + Jyy) + nu * Jxx);
      yy_[q] = f * ((1 - nu) * (Jxx + Jyy) + nu * Jyy);
      xy_[q] = f * nu * Jxy;
    }
}

}  // namespace wrc::halfspace
