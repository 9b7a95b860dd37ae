// The slip of a tangential solution recomputed by direct sums over the influence coefficients (no FFT), an
// independent check of the solvers' convolutions; used by the tests of the exact rolling solver.
#pragma once

#include "wrc/halfspace/influence.hpp"
#include "wrc/halfspace/rolling.hpp"

#include <cstddef>
#include <vector>

namespace wrc::test {

// The slip per |V| of a traction field at every grid element: s = w - (u_{I+} - u_I) / dx, u including the
// displacement of the element upstream of the grid's edge.
inline void direct_slip(const halfspace::Material& m, const halfspace::TangentialProblem& pb,
                        const halfspace::TangentialSolution& s, std::vector<double>& sx, std::vector<double>& sy) {
  const halfspace::Grid& g = pb.grid;
  const halfspace::ShearInfluenceTable t(m, g.dx, g.dy, g.nx + 2, g.ny);
  const auto u = [&](int i, int j, double& ux, double& uy) {  // displacement at cell (i, j), i may be -1 or nx
    ux = uy = 0;
    for (int l = 0; l < g.ny; ++l)
      for (int k = 0; k < g.nx; ++k) {
        const auto q = static_cast<std::size_t>(g.index(k, l));
        ux += t.xx(i - k, j - l) * s.px[q] + t.xy(i - k, j - l) * s.py[q];
        uy += t.xy(i - k, j - l) * s.px[q] + t.yy(i - k, j - l) * s.py[q];
      }
  };
  std::vector<double> wx, wy;
  halfspace::rigid_slip(pb, wx, wy);
  sx.assign(static_cast<std::size_t>(g.size()), 0.0);
  sy.assign(sx.size(), 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto q = static_cast<std::size_t>(g.index(i, j));
      if (!(pb.pressure[q] > 0)) continue;
      double ax, ay, bx, by;
      u(i, j, ax, ay);
      u(i + pb.direction, j, bx, by);
      sx[q] = wx[q] - (bx - ax) / g.dx;
      sy[q] = wy[q] - (by - ay) / g.dx;
    }
}

}  // namespace wrc::test
