// Parametric smoothing splines of profiles (spline.hpp): Reinsch's algorithm with a pentadiagonal LDL^T solve.
#include "wrc/profile/spline.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <functional>
#include <tuple>
#include <cmath>
#include <limits>

namespace wrc {
namespace {

// Solves the symmetric positive definite pentadiagonal system M x = b in place for two right-hand sides
// (M: diagonal d, first off-diagonal e (M[j][j+1]), second off-diagonal f (M[j][j+2])).
void solve_pentadiagonal(std::vector<double> d, const std::vector<double>& e, const std::vector<double>& f,
                         std::vector<double>& b1, std::vector<double>& b2) {
  const std::size_t m = d.size();
  std::vector<double> l1(m, 0.0), l2(m, 0.0);  // L[j+1][j], L[j+2][j]
  for (std::size_t j = 0; j < m; ++j) {
    if (j >= 1) d[j] -= l1[j - 1] * l1[j - 1] * d[j - 1];
    if (j >= 2) d[j] -= l2[j - 2] * l2[j - 2] * d[j - 2];
    if (!(d[j] > 0)) fail("smoothing spline: the system is not positive definite (coincident points?)");
    if (j + 1 < m) l1[j] = (e[j] - (j >= 1 ? l1[j - 1] * l2[j - 1] * d[j - 1] : 0.0)) / d[j];
    if (j + 2 < m) l2[j] = f[j] / d[j];
  }
  for (std::vector<double>* b : {&b1, &b2}) {
    std::vector<double>& x = *b;
    for (std::size_t j = 0; j < m; ++j) {
      if (j >= 1) x[j] -= l1[j - 1] * x[j - 1];
      if (j >= 2) x[j] -= l2[j - 2] * x[j - 2];
    }
    for (std::size_t j = 0; j < m; ++j) x[j] /= d[j];
    for (std::size_t k = m; k-- > 0;) {
      if (k + 1 < m) x[k] -= l1[k] * x[k + 1];
      if (k + 2 < m) x[k] -= l2[k] * x[k + 2];
    }
  }
}

int monotone_order(const std::vector<double>& y) {
  if (std::is_sorted(y.begin(), y.end())) return 1;
  if (std::is_sorted(y.rbegin(), y.rend())) return -1;
  return 0;
}

// Knot indices [first, last) whose y lies within [lo, hi], by bisection on monotone knots (all knots otherwise).
std::pair<std::size_t, std::size_t> knots_in(const ProfileSpline& s, double lo, double hi) {
  if (s.y_order == 0) return {0, s.y.size()};
  if (s.y_order > 0)
    return {static_cast<std::size_t>(std::lower_bound(s.y.begin(), s.y.end(), lo) - s.y.begin()),
            static_cast<std::size_t>(std::upper_bound(s.y.begin(), s.y.end(), hi) - s.y.begin())};
  const auto first = std::lower_bound(s.y.begin(), s.y.end(), hi, std::greater<double>());
  const auto last = std::upper_bound(s.y.begin(), s.y.end(), lo, std::greater<double>());
  return {static_cast<std::size_t>(first - s.y.begin()), static_cast<std::size_t>(last - s.y.begin())};
}

// Interval i (t[i] <= t <= t[i+1]) holding t, clamped.
std::size_t interval(const std::vector<double>& t, double tq) {
  const auto it = std::upper_bound(t.begin(), t.end(), tq);
  const auto i = static_cast<std::ptrdiff_t>(it - t.begin()) - 1;
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(t.size()) - 2));
}

}  // namespace

ProfileSpline fit_profile_spline(const std::vector<double>& y, const std::vector<double>& z, double ell,
                                 const std::string& context) {
  const std::size_t n = y.size();
  if (n < 3 || z.size() != n) fail("{}: a spline needs at least 3 points with y and z each, got {}", context, n);
  if (!(ell >= 0) || !std::isfinite(ell) || ell > 1.0)
    fail("{}: smooth = {} must be a smoothing length in metres, 0 .. 1 (0: interpolating cubic spline)", context, ell);
  ProfileSpline s;
  s.smoothing = ell;
  s.t.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) {
    const double h = std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
    if (!(h > 0) || !std::isfinite(h)) fail("{}: points {} and {} coincide or are not finite", context, i, i + 1);
    s.t[i] = s.t[i - 1] + h;
  }
  std::vector<double> h(n - 1), w(n);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = s.t[i + 1] - s.t[i];
  for (std::size_t i = 0; i < n; ++i) w[i] = 0.5 * ((i > 0 ? h[i - 1] : 0.0) + (i + 1 < n ? h[i] : 0.0));
  const double alpha = ell * ell * ell * ell;  // m^4
  // Unknowns: the second derivatives at the interior knots j = 1 .. n-2 (index j-1 in the system).
  const std::size_t m = n - 2;
  std::vector<double> d(m), e(m, 0.0), f(m, 0.0), by(m), bz(m);
  auto q = [&](std::size_t row, std::size_t col) {  // Q[row][col] for an interior knot col (1 .. n-2)
    if (row + 1 == col) return 1.0 / h[col - 1];
    if (row == col) return -1.0 / h[col - 1] - 1.0 / h[col];
    if (row == col + 1) return 1.0 / h[col];
    return 0.0;
  };
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t j = k + 1;
    d[k] = (h[j - 1] + h[j]) / 3.0;
    if (k + 1 < m) e[k] = h[j] / 6.0;
    double qq = 0;
    for (std::size_t r = j - 1; r <= j + 1; ++r) qq += q(r, j) * q(r, j) / w[r];
    d[k] += alpha * qq;
    if (k + 1 < m) e[k] += alpha * (q(j, j) * q(j, j + 1) / w[j] + q(j + 1, j) * q(j + 1, j + 1) / w[j + 1]);
    if (k + 2 < m) f[k] = alpha * q(j + 1, j) * q(j + 1, j + 2) / w[j + 1];
    by[k] = (y[j + 1] - y[j]) / h[j] - (y[j] - y[j - 1]) / h[j - 1];
    bz[k] = (z[j + 1] - z[j]) / h[j] - (z[j] - z[j - 1]) / h[j - 1];
  }
  solve_pentadiagonal(d, e, f, by, bz);
  s.yy.assign(n, 0.0);
  s.zz.assign(n, 0.0);
  for (std::size_t k = 0; k < m; ++k) {
    s.yy[k + 1] = by[k];
    s.zz[k + 1] = bz[k];
  }
  // Values: g = f - alpha W^-1 Q gamma.
  s.y = y;
  s.z = z;
  if (alpha > 0) {
    for (std::size_t i = 0; i < n; ++i) {
      auto qg = [&](const std::vector<double>& g) {
        double v = 0;
        if (i + 1 < n) v += (g[i + 1] - g[i]) / h[i];
        if (i > 0) v -= (g[i] - g[i - 1]) / h[i - 1];
        return v;
      };
      s.y[i] -= alpha * qg(s.yy) / w[i];
      s.z[i] -= alpha * qg(s.zz) / w[i];
    }
  }
  s.y_order = monotone_order(s.y);
  return s;
}

ProfileSpline::Point ProfileSpline::at(double tq) const {
  const std::size_t i = interval(t, tq);
  const double h = t[i + 1] - t[i];
  tq = std::clamp(tq, t.front(), t.back());
  const double a = (t[i + 1] - tq) / h, b = (tq - t[i]) / h;
  Point p;
  auto value = [&](const std::vector<double>& g, const std::vector<double>& gg) {
    return a * g[i] + b * g[i + 1] + ((a * a * a - a) * gg[i] + (b * b * b - b) * gg[i + 1]) * h * h / 6.0;
  };
  auto slope = [&](const std::vector<double>& g, const std::vector<double>& gg) {
    return (g[i + 1] - g[i]) / h - (3 * a * a - 1) / 6.0 * h * gg[i] + (3 * b * b - 1) / 6.0 * h * gg[i + 1];
  };
  p.p = {value(y, yy), value(z, zz)};
  p.d1 = {slope(y, yy), slope(z, zz)};
  p.d2 = {a * yy[i] + b * yy[i + 1], a * zz[i] + b * zz[i + 1]};
  return p;
}

double ProfileSpline::curvature(double tq) const {
  const Point p = at(tq);
  const double speed = p.d1.norm();
  if (!(speed > 0)) return 0.0;
  const double k = (p.d1.x() * p.d2.y() - p.d1.y() * p.d2.x()) / (speed * speed * speed);
  // Orient the tangent toward +y (toward +z on a vertical run).
  const bool backward = p.d1.x() < -1e-12 * speed || (std::abs(p.d1.x()) <= 1e-12 * speed && p.d1.y() < 0);
  return backward ? -k : k;
}

double ProfileSpline::closest(const Eigen::Vector2d& qpt) const {
  // The nearest knot: any knot nearer than the one found so far lies within that distance in y.
  auto [a, b] = knots_in(*this, qpt.x(), qpt.x());
  std::size_t best = std::min(a, t.size() - 1);
  if (b == a && a > 0 && y_order != 0) best = a - 1;  // between two knots: start from the one before
  double bd = (Eigen::Vector2d(y[best], z[best]) - qpt).squaredNorm();
  for (int round = 0; round < 2; ++round) {
    const double d = std::sqrt(bd);
    std::tie(a, b) = knots_in(*this, qpt.x() - d, qpt.x() + d);
    for (std::size_t i = a; i < b; ++i) {
      const double dd = (Eigen::Vector2d(y[i], z[i]) - qpt).squaredNorm();
      if (dd < bd) {
        bd = dd;
        best = i;
      }
    }
  }
  // Refine on the two intervals beside the nearest knot: Newton on (c(t) - q) . c'(t) = 0, kept in the interval.
  double tb = t[best];
  for (std::size_t i : {best > 0 ? best - 1 : best, std::min(best, t.size() - 2)}) {
    double tt = std::clamp(t[best], t[i], t[i + 1]);
    for (int it = 0; it < 20; ++it) {
      const Point p = at(tt);
      const Eigen::Vector2d r = p.p - qpt;
      const double g = r.dot(p.d1), dg = p.d1.squaredNorm() + r.dot(p.d2);
      if (!(dg > 0)) break;
      const double next = std::clamp(tt - g / dg, t[i], t[i + 1]);
      if (std::abs(next - tt) < 1e-15) break;
      tt = next;
    }
    const double dd = (at(tt).p - qpt).squaredNorm();
    if (dd < bd) {
      bd = dd;
      tb = tt;
    }
  }
  return tb;
}

double ProfileSpline::param_at_y(double yq) const {
  const std::size_t n = t.size();
  // On monotone knots, start at the first interval that can bracket yq.
  const std::size_t start = y_order == 0 ? 0 : knots_in(*this, yq, yq).first;
  for (std::size_t i = start > 0 ? start - 1 : 0; i + 1 < n; ++i) {
    const double lo = std::min(y[i], y[i + 1]), hi = std::max(y[i], y[i + 1]);
    if (yq < lo || yq > hi || lo == hi) continue;
    // Bisection with secant steps on y(t) - yq over the interval (y(t) may overshoot its knots slightly).
    double a = t[i], b = t[i + 1], fa = y[i] - yq, fb = y[i + 1] - yq;
    if (fa == 0) return a;
    if (fb == 0) return b;
    for (int it = 0; it < 60 && b - a > 1e-15; ++it) {
      double c = a - fa * (b - a) / (fb - fa);
      if (!(c > a && c < b)) c = 0.5 * (a + b);
      const double fc = at(c).p.x() - yq;
      if (fc == 0) return c;
      if ((fc < 0) == (fa < 0)) {
        a = c;
        fa = fc;
      } else {
        b = c;
        fb = fc;
      }
    }
    return std::abs(fa) < std::abs(fb) ? a : b;
  }
  // Beyond the ends: the end nearer in y.
  return std::abs(y.front() - yq) <= std::abs(y.back() - yq) ? t.front() : t.back();
}

Profile smooth_profile(const Profile& p, double ell) {
  const ProfileSpline s = fit_profile_spline(p.y, p.z, ell, p.source);
  Profile r = make_profile(p.kind, s.y, s.z, p.name, p.source);
  if (r.size() != p.size())
    fail("{}: the smoothing spline (smooth = {} m) merges points of the profile; choose a smaller smooth", p.source, ell);
  r.transforms = p.transforms;
  r.transforms.push_back(
      ell > 0 ? fmt::format("smoothing spline (smooth = {:.6g} m: waviness of wavelength {:.3g} mm halved)", ell,
                            2 * 3.14159265358979 * ell * 1e3)
              : "interpolating cubic spline (smooth = 0)");
  r.metadata = p.metadata;
  r.duplicates_dropped = p.duplicates_dropped;
  r.warnings = p.warnings;
  r.spline = std::make_shared<const ProfileSpline>(s);
  return r;
}

std::shared_ptr<const ProfileSpline> profile_curve(const Profile& p) {
  if (p.spline) return p.spline;
  return std::make_shared<const ProfileSpline>(fit_profile_spline(p.y, p.z, 0.0, p.source));
}

double surface_curvature(const ProfileSpline& curve, ProfileKind kind, double tq) {
  // Oriented toward +y, a counter-clockwise turn bends the curve up: convex for a body above it (the wheel),
  // concave for a body below it (the rail).
  const double k = curve.curvature(tq);
  return kind == ProfileKind::wheel ? k : -k;
}

double profile_curvature(const Profile& p, double yq) {
  if (!(yq >= p.y.front() && yq <= p.y.back()))
    fail("curvature: y = {} m lies outside the profile ({} .. {} m)", yq, p.y.front(), p.y.back());
  const auto c = profile_curve(p);
  return surface_curvature(*c, p.kind, c->param_at_y(yq));
}

ProfileSpline mapped_spline(const ProfileSpline& s, double sy, double dy, double sz, double dz) {
  ProfileSpline r = s;
  r.y_order = sy * s.y_order > 0 ? 1 : (s.y_order == 0 ? 0 : -1);
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    r.y[i] = sy * s.y[i] + dy;
    r.z[i] = sz * s.z[i] + dz;
    r.yy[i] = sy * s.yy[i];
    r.zz[i] = sz * s.zz[i];
  }
  return r;
}

}  // namespace wrc
