// The exact depth of a point inside a wheel, by brute force over its generatrix: the reference the surfaces' undeformed
// distance h is checked against (the conformal and the planar surface under yaw).
#pragma once

#include "wrc/geometry/model.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::test {

// Signed distance of the meridian point (Y, rho) (wheelset-frame lateral position, distance to the axle) from the
// wheel's generatrix, by brute force over every running-surface segment: > 0 inside the wheel. For a surface of
// revolution this is the exact 3-D depth of the point (its closest wheel point lies in its meridian plane).
inline double exact_depth(const WheelCones& w, double Y, double rho) {
  double best = INFINITY;
  const int n = static_cast<int>(w.y.size());
  for (int k = 1; k + 2 < n; ++k) {
    const double ay = w.y[k], ar = -w.z[k], dy = w.y[k + 1] - ay, dr = -w.z[k + 1] - ar;
    const double L2 = dy * dy + dr * dr;
    const double t = L2 > 0 ? std::clamp(((Y - ay) * dy + (rho - ar) * dr) / L2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(Y - (ay + t * dy), rho - (ar + t * dr)));
  }
  int k = 1;
  while (k + 2 < n && w.y[k + 1] < Y) ++k;
  const double t = std::clamp((Y - w.y[k]) / (w.y[k + 1] - w.y[k]), 0.0, 1.0);
  return -(w.z[k] + t * (w.z[k + 1] - w.z[k])) > rho ? best : -best;
}

}  // namespace wrc::test
