// Hertzian test patches for the tangential solvers: the pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) sampled at the
// element centres of a square grid (written for the tests, independent of the engine).
#pragma once

#include "wrc/halfspace/rolling.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wrc::test {

struct HertzPatch {
  halfspace::Grid grid;
  std::vector<double> pressure;  // Pa
  double a = 0, b = 0;           // semi-axes (m)
  double force = 0;              // N: sum p dA of the sampled pressure
};

// Semi-axes a (along x) and b; n elements on the smaller semi-axis; the ellipse's centre at (shift_x, shift_y)
// elements from a grid point (the reference point of the creepages is the ellipse's centre, x = y = 0).
inline HertzPatch hertz_patch(double a, double b, double p0, int n, double shift_x = 0, double shift_y = 0) {
  HertzPatch h;
  h.a = a;
  h.b = b;
  const double e = std::min(a, b) / n;
  h.grid = halfspace::Grid::square(2 * static_cast<int>(std::ceil(a / e)) + 3, 2 * static_cast<int>(std::ceil(b / e)) + 3,
                                 e, shift_x * e, shift_y * e);
  h.pressure.assign(static_cast<std::size_t>(h.grid.size()), 0.0);
  for (int j = 0; j < h.grid.ny; ++j)
    for (int i = 0; i < h.grid.nx; ++i) {
      const double x = h.grid.x(i), y = h.grid.y(j), q = 1 - x * x / (a * a) - y * y / (b * b);
      const double p = q > 0 ? p0 * std::sqrt(q) : 0.0;
      h.pressure[static_cast<std::size_t>(h.grid.index(i, j))] = p;
      h.force += p * e * e;
    }
  return h;
}

inline halfspace::TangentialProblem rolling_problem(const HertzPatch& h, const halfspace::Creepages& c, double mu,
                                                  int direction = 1) {
  halfspace::TangentialProblem pb;
  pb.grid = h.grid;
  pb.pressure = h.pressure;
  pb.creepages = c;
  pb.friction = halfspace::Friction::coulomb(mu);
  pb.direction = direction;
  return pb;
}

}  // namespace wrc::test
