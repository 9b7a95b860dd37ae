// Regular grid of the potential contact area in the contact plane (paper section 3): nx x ny rectangular
// elements of size dx x dy on which the pressure is constant. Element (i, j) has its centre at
// (x0 + i dx, y0 + j dy) and index i + nx j (x runs fastest). x is the rolling direction, y lateral; the
// frame is the contact plane's own (the bridge from a patch maps it to the track frame).
#pragma once

#include <string_view>

namespace wrc::halfspace {

struct Grid {
  int nx = 0, ny = 0;     // elements along x and y
  double dx = 0, dy = 0;  // element sizes (m)
  double x0 = 0, y0 = 0;  // centre of element (0, 0) (m)

  int size() const { return nx * ny; }
  int index(int i, int j) const { return i + nx * j; }
  double x(int i) const { return x0 + i * dx; }  // element centre (m)
  double y(int j) const { return y0 + j * dy; }
  double element_area() const { return dx * dy; }  // m^2

  // nx x ny square elements of side `element` (m), the grid's centre at (xc, yc).
  static Grid square(int nx, int ny, double element, double xc = 0, double yc = 0);
  // The smallest grid of square elements of side `element` covering [xmin, xmax] x [ymin, ymax] (m),
  // centred on that rectangle.
  static Grid covering(double xmin, double xmax, double ymin, double ymax, double element);
};

// Largest grid the solvers accept (elements); far beyond any contact patch, it only stops absurd
// allocations from bad input.
inline constexpr int kMaxGridElements = 1 << 22;

// Throws wrc::Error naming `context` when the grid is empty, too large, or has non-finite or
// non-positive element sizes or a non-finite origin.
void validate(const Grid& grid, std::string_view context);

}  // namespace wrc::halfspace
