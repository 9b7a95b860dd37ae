// Independent quadrature (written for the tests, not the engine's closed forms) of the integral of f(theta) / r over
// the rectangle [-a, a] x [-b, b] seen from (x, y): in polar coordinates about the field point dA / r = dr dtheta, so
// the integral is that of f(theta) times the chord of the ray inside the rectangle (slab clipping), by Gauss-Legendre
// between the corner directions (where the chord has kinks). f = 1 gives the normal kernel 1 / r; the shear kernels
// X^2 / r^3, Y^2 / r^3 and X Y / r^3 are cos^2, sin^2 and cos sin of the direction (source minus field) over r.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace wrc::test {

inline double ray_integral(double x, double y, double a, double b, const std::function<double(double)>& f) {
  const auto chord = [&](double t) {
    const double c = std::cos(t), s = std::sin(t);
    double lo = 0, hi = INFINITY;
    const auto slab = [&](double origin, double dir, double min, double max) {
      if (std::abs(dir) < 1e-300) {
        if (origin < min || origin > max) hi = -1;
        return;
      }
      double t0 = (min - origin) / dir, t1 = (max - origin) / dir;
      if (t0 > t1) std::swap(t0, t1);
      lo = std::max(lo, t0);
      hi = std::min(hi, t1);
    };
    slab(x, c, -a, a);
    slab(y, s, -b, b);
    return hi > lo ? hi - lo : 0.0;
  };
  std::vector<double> cuts = {-std::numbers::pi, std::numbers::pi};
  for (double cx : {-a, a})
    for (double cy : {-b, b})
      if (cx != x || cy != y) cuts.push_back(std::atan2(cy - y, cx - x));
  std::sort(cuts.begin(), cuts.end());
  constexpr int n = 20;  // Gauss-Legendre nodes by Newton on P_20
  double nodes[n], weights[n];
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    nodes[i] = z;
    weights[i] = 2 / ((1 - z * z) * dp * dp);
  }
  double total = 0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double t0 = cuts[c], t1 = cuts[c + 1];
    if (t1 - t0 < 1e-15) continue;
    constexpr int sub = 8;
    for (int s = 0; s < sub; ++s) {
      const double u0 = t0 + (t1 - t0) * s / sub, u1 = t0 + (t1 - t0) * (s + 1) / sub;
      for (int i = 0; i < n; ++i) {
        const double t = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * nodes[i];
        total += 0.5 * (u1 - u0) * weights[i] * f(t) * chord(t);
      }
    }
  }
  return total;
}

}  // namespace wrc::test
