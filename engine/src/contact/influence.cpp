// Love's closed form of the 1/r integral over a rectangle.
#include "wrc/contact/influence.hpp"

#include "wrc/core/error.hpp"

#include <cmath>

namespace wrc::contact {
namespace {

// Antiderivative G(X, Y) with d2G/dXdY = 1/sqrt(X^2 + Y^2), odd in X and in Y:
//   G = X asinh(Y/|X|) + Y asinh(X/|Y|).
// Love's logarithms ln(Y + r) differ from asinh(Y/|X|) by ln|X|, which cancels between corners that
// share X; the asinh form has no log of a difference, hence no cancellation near edges.
double corner(double X, double Y) {
  double g = 0;
  if (X != 0) g += X * std::asinh(Y / std::abs(X));
  if (Y != 0) g += Y * std::asinh(X / std::abs(Y));
  return g;
}

}  // namespace

double rectangle_potential(double x, double y, double a, double b) {
  // Source point s - field point (x, y) runs over [-a - x, a - x] x [-b - y, b - y].
  const double x1 = -a - x, x2 = a - x, y1 = -b - y, y2 = b - y;
  return corner(x2, y2) - corner(x1, y2) - corner(x2, y1) + corner(x1, y1);
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
    for (int k = 0; k < cx; ++k) g[k + cx * l] = corner((k - 0.5) * dx, (l - 0.5) * dy);
  values_.resize(static_cast<std::size_t>(mx) * my);
  for (int n = 0; n < my; ++n)
    for (int m = 0; m < mx; ++m)
      values_[m + mx * n] = g[(m + 1) + cx * (n + 1)] - g[m + cx * (n + 1)] - g[(m + 1) + cx * n] + g[m + cx * n];
}

}  // namespace wrc::contact
