// Test problems for the normal solvers: analytic h fields on grids.
#pragma once

#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/normal.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace wrc::test {

struct NormalCase {
  halfspace::Grid grid;
  std::vector<double> h;  // m
};

// h = delta - A x^2 - B y^2 on square elements of side `element`, grid centred on the origin with an
// element centre there (odd counts), covering the inter-penetration ellipse plus `margin` elements.
inline NormalCase paraboloid_case(double A, double B, double delta, double element, int margin = 2) {
  const double X = std::sqrt(delta / A), Y = std::sqrt(delta / B);
  const int nx = 2 * (static_cast<int>(std::ceil(X / element)) + margin) + 1;
  const int ny = 2 * (static_cast<int>(std::ceil(Y / element)) + margin) + 1;
  NormalCase c{halfspace::Grid::square(nx, ny, element), {}};
  c.h.resize(c.grid.size());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = c.grid.x(i), y = c.grid.y(j);
      c.h[c.grid.index(i, j)] = delta - A * x * x - B * y * y;
    }
  return c;
}

// Random non-Hertzian patch: a sum of 1-3 elliptical bumps of random curvature, depth and position
// (possibly overlapping into one lobe or separate into two), a random tilt, on a random grid shape
// (element aspect ratio 1 or not), sides of min_side..max_side elements. Depths are micrometres.
inline NormalCase random_case(std::mt19937& rng, int min_side = 6, int max_side = 26) {
  std::uniform_int_distribution<int> N(min_side, max_side), bumps(1, 3);
  std::uniform_real_distribution<double> U(0, 1);
  halfspace::Grid g;
  g.nx = N(rng);
  g.ny = N(rng);
  g.dx = 0.2e-3;
  g.dy = U(rng) < 0.5 ? 0.2e-3 : 0.2e-3 * (0.5 + U(rng));
  g.x0 = -0.5 * (g.nx - 1) * g.dx + 1e-3 * (U(rng) - 0.5);
  g.y0 = -0.5 * (g.ny - 1) * g.dy;
  const double Lx = 0.5 * g.nx * g.dx, Ly = 0.5 * g.ny * g.dy;
  NormalCase c{g, std::vector<double>(g.size(), -INFINITY)};
  const int nb = bumps(rng);
  for (int b = 0; b < nb; ++b) {
    const double xc = g.x0 + g.nx * g.dx * (0.2 + 0.6 * U(rng)), yc = g.y0 + g.ny * g.dy * (0.2 + 0.6 * U(rng));
    const double depth = 5e-6 + 20e-6 * U(rng);
    // Curvatures such that the bump's inter-penetration reaches 30-90 % of the half-grid.
    const double A = depth / std::pow((0.3 + 0.6 * U(rng)) * Lx, 2), B = depth / std::pow((0.3 + 0.6 * U(rng)) * Ly, 2);
    const double cx = 0.3 * depth / Lx * (U(rng) - 0.5), cy = 0.3 * depth / Ly * (U(rng) - 0.5);  // tilt
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const double x = g.x(i) - xc, y = g.y(j) - yc;
        double& h = c.h[g.index(i, j)];
        h = std::max(h, depth - A * x * x - B * y * y + cx * x + cy * y);  // union of the bodies' overlaps
      }
  }
  return c;
}

}  // namespace wrc::test
