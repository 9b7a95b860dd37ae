// Material and grid: validation and construction helpers.
#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/material.hpp"
#include "wrc/core/error.hpp"

#include <cmath>
#include <numbers>

namespace wrc::halfspace {

double Material::compliance() const { return (1.0 - nu * nu) / (std::numbers::pi * E); }

double Material::pair_compliance() const { return 1.0 / (std::numbers::pi * combined_modulus()); }

void validate(const Material& material, std::string_view context) {
  if (!std::isfinite(material.E) || !(material.E > 0))
    fail("{}: Young's modulus E = {} Pa must be finite and positive", context, material.E);
  if (!std::isfinite(material.nu) || !(material.nu > -1.0 && material.nu < 0.5))
    fail("{}: Poisson's ratio nu = {} must be in ]-1, 0.5[", context, material.nu);
}

Grid Grid::square(int nx, int ny, double element, double xc, double yc) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = g.dy = element;
  g.x0 = xc - 0.5 * (nx - 1) * element;
  g.y0 = yc - 0.5 * (ny - 1) * element;
  return g;
}

Grid Grid::covering(double xmin, double xmax, double ymin, double ymax, double element) {
  if (!(std::isfinite(xmin) && std::isfinite(xmax) && std::isfinite(ymin) && std::isfinite(ymax)) ||
      xmax < xmin || ymax < ymin)
    fail("Grid::covering: rectangle [{}, {}] x [{}, {}] m is not a finite, ordered rectangle", xmin, xmax,
         ymin, ymax);
  if (!std::isfinite(element) || !(element > 0))
    fail("Grid::covering: element size {} m must be finite and positive", element);
  const double nxf = std::ceil((xmax - xmin) / element - 1e-9);
  const double nyf = std::ceil((ymax - ymin) / element - 1e-9);
  if (nxf * nyf > kMaxGridElements)
    fail("Grid::covering: {:.0f} x {:.0f} elements of {} m exceed the limit of {} elements", nxf, nyf,
         element, kMaxGridElements);
  return square(std::max(1, static_cast<int>(nxf)), std::max(1, static_cast<int>(nyf)), element,
                0.5 * (xmin + xmax), 0.5 * (ymin + ymax));
}

void validate(const Grid& grid, std::string_view context) {
  if (grid.nx < 1 || grid.ny < 1) fail("{}: empty grid ({} x {} elements)", context, grid.nx, grid.ny);
  if (static_cast<double>(grid.nx) * grid.ny > kMaxGridElements)
    fail("{}: grid of {} x {} elements exceeds the limit of {} elements", context, grid.nx, grid.ny,
         kMaxGridElements);
  if (!std::isfinite(grid.dx) || !(grid.dx > 0) || !std::isfinite(grid.dy) || !(grid.dy > 0))
    fail("{}: element size {} x {} m must be finite and positive", context, grid.dx, grid.dy);
  if (!std::isfinite(grid.x0) || !std::isfinite(grid.y0))
    fail("{}: grid origin ({}, {}) m is not finite", context, grid.x0, grid.y0);
}

}  // namespace wrc::halfspace
