// An independent reference for contact location (tests/geometry, tests/wheelset): where a rail line is inside the
// closed solid of revolution of a wheel's generatrix polyline, from the definitions alone (frames, the polyline's
// radius), by sampling and bisection -- never the closed form of the engine.
#pragma once

#include "wrc/geometry/cone_line.hpp"
#include "wrc/geometry/model.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace wrc::test {

// The solid: radius r(Y) = the polyline's upper envelope between points `first` .. `last` (without the closing points
// on the axle), linear between points; outside beyond the end faces.
struct RefSolid {
  const WheelCones& w;
  int first, last;
  double radius(double Y) const {
    if (Y < w.y[first] || Y > w.y[last]) return -1;
    // The points with y in a small bracket of Y (a vertical run shares one y).
    const auto lo = std::lower_bound(w.y.begin() + first, w.y.begin() + last + 1, Y) - w.y.begin();
    double r = -1;
    for (long i = std::max<long>(first, lo - 2); i < std::min<long>(last, lo + 2); ++i) {
      const double y0 = w.y[i], y1 = w.y[i + 1];
      if (Y < y0 || Y > y1) continue;
      if (y1 == y0) r = std::max({r, -w.z[i], -w.z[i + 1]});
      else r = std::max(r, -w.z[i] + (Y - y0) / (y1 - y0) * (w.z[i] - w.z[i + 1]));
    }
    return r;
  }
  // > 0 outside, < 0 inside (m: the distance to the axle minus the radius).
  double outside(const PoseFrame& f, double x, double y_r, double z_r) const {
    const Eigen::Vector3d p = f.to_wheelset({x, y_r, z_r});
    const double R = radius(p.y());
    const double rho = std::hypot(p.x(), p.z());
    return R < 0 ? 1.0 : rho - R;
  }
};

// The line's inside intervals [enter, leave] (m, track x): a grid of step h over |x| <= X, bisection at each change.
// Intervals shorter than h may hide between the grid's points.
inline std::vector<std::pair<double, double>> reference_segments(const RefSolid& solid, const PoseFrame& f, double y_r,
                                                                 double z_r, double X = 0.08, double h = 1e-4) {
  std::vector<std::pair<double, double>> out;
  const int n = static_cast<int>(2 * X / h);
  auto g = [&](double x) { return solid.outside(f, x, y_r, z_r); };
  auto root = [&](double a, double b) {
    const bool ina = g(a) < 0;
    for (int i = 0; i < 80; ++i) {
      const double m = 0.5 * (a + b);
      if ((g(m) < 0) == ina) a = m; else b = m;
    }
    return 0.5 * (a + b);
  };
  double prev_x = -X;
  bool prev_in = g(prev_x) < 0;
  double enter = 0;
  for (int i = 1; i <= n; ++i) {
    const double x = -X + i * h;
    const bool in = g(x) < 0;
    if (in != prev_in) {
      const double r = root(prev_x, x);
      if (in) enter = r;
      else out.emplace_back(enter, r);
    }
    prev_x = x;
    prev_in = in;
  }
  return out;
}

// The same for a line that may only graze the solid (segments of micrometres): the deepest point of the line is found
// first (a grid of step h, then golden-section search around the grid's minimum), and when it is inside, the two ends
// by steps outward and bisection. One interval at most (the deepest), or none.
inline std::vector<std::pair<double, double>> reference_graze(const RefSolid& solid, const PoseFrame& f, double y_r,
                                                              double z_r, double X = 0.1, double h = 2e-5) {
  auto g = [&](double x) { return solid.outside(f, x, y_r, z_r); };
  const int n = static_cast<int>(2 * X / h);
  double xb = -X, gb = g(xb);
  for (int i = 1; i <= n; ++i) {
    const double x = -X + i * h, v = g(x);
    if (v < gb) xb = x, gb = v;
  }
  double a = xb - h, b = xb + h;
  for (int i = 0; i < 200 && b - a > 1e-15; ++i) {
    const double m1 = a + 0.381966 * (b - a), m2 = a + 0.618034 * (b - a);
    if (g(m1) < g(m2)) b = m2; else a = m1;
  }
  const double xm = 0.5 * (a + b);
  if (!(g(xm) < 0)) return {};
  auto end = [&](double in, double step) {  // outward from an inside point by doubling steps, then bisection
    double out = in + step;
    while (g(out) < 0) in = out, step *= 2, out = in + step;
    for (int i = 0; i < 200 && std::abs(out - in) > 1e-16; ++i) {
      const double m = 0.5 * (in + out);
      (g(m) < 0 ? in : out) = m;
    }
    return 0.5 * (in + out);
  };
  return {{end(xm, -h), end(xm, h)}};
}

}  // namespace wrc::test
