// Persson's problem, solved for the tests independently of the engine: a cylindrical pin of radius R pressed by a
// force P (per unit length) into a cylindrical hole of radius R + dR in an infinite plate, frictionless, plane
// strain, both of the same material (Persson 1964; Johnson, Contact Mechanics, 1985, section 5.3), exactly within
// linear elasticity (dR << R), by a one-dimensional integral equation over the contact arc.
//
// The kernel, from Michell's solution. Let the pressure on the common boundary be p(phi) = sum a_n cos(n phi). For
// the mode n >= 2 the disc's boundary moves inward and the hole's outward (plane strain, kappa = 3 - 4 nu, shear
// modulus mu) by
//     disc:  a_n R / (4 mu) (kappa / (n + 1) + 1 / (n - 1)) cos(n theta),
//     hole:  a_n R / (4 mu) (kappa / (n - 1) + 1 / (n + 1)) cos(n theta),
// together (R / E*) a_n 2 n / (n^2 - 1) cos(n theta), 1/E* = (kappa + 1) / (4 mu) = 2 (1 - nu^2) / E (the pair's
// modulus, docs/design.md section 2); the uniform mode n = 0 opens the gap by (R / E*) a_0 (disc and hole under
// uniform pressure); the mode n = 1 (the net force, balanced at the pin's centre and at infinity) moves both
// boundaries by multiples of cos(theta) only, like the pin's rigid approach, so it merges into the unknown approach
// D. Summing the series,
//     w(theta) = (R / E*) a_0 + R / (pi E*) int p(phi) K(theta - phi) dphi,
//     K(x) = sum_{n >= 2} 2 n / (n^2 - 1) cos(n x) = -2 cos(x) log|2 sin(x / 2)| - 1 - cos(x) / 2,
// whose log|x| singularity is the half-plane's: for small angles the problem is Hertz's line contact with the
// relative radius R^2 / dR. (The cos(x) factor is the far field turning with the boundary: a half-space laid on the
// arc would push every point along its own normal.) Contact: the gap dR (1 - cos theta) - D cos theta + w(theta)
// is 0 where p > 0 and >= 0 elsewhere; equilibrium P = R int p cos(phi) dphi. In the units R = E* = dR = 1 the
// solution depends only on P / (E* dR).
//
// Numerics: p piecewise constant on `panels` panels over [0, theta_max] (p symmetric), collocation at the panel
// centres, the log singularity integrated exactly and the smooth rest by 8-point Gauss, an active set iterated
// (drop negative pressures, add penetrated panels) with D fixed by the force. The contact semi-angle comes from the
// pressure's square-root edge: p^2 linear in theta through the last three loaded panels. With 1 deg panels the
// semi-angle is good to ~0.1 deg; the small-angle limit is Hertz's alpha^2 = 4 P / (pi E* dR).
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace wrc::test {

inline double persson_kernel(double x) {
  return -2 * std::cos(x) * std::log(std::abs(2 * std::sin(0.5 * x))) - 1 - 0.5 * std::cos(x);
}

// int_a^b K(x) dx: -2 log|x| exactly, the smooth rest K + 2 log|x| by Gauss.
inline double persson_kernel_integral(double a, double b) {
  static const double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                               0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                               0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  auto xlogx = [](double x) { return x == 0 ? 0.0 : x * std::log(std::abs(x)) - x; };
  double s = -2 * (xlogx(b) - xlogx(a));
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  for (int k = 0; k < 8; ++k) {
    const double x = m + h * gx[k];
    s += gw[k] * h * (std::abs(x) < 1e-9 ? -1.5 : persson_kernel(x) + 2 * std::log(std::abs(x)));
  }
  return s;
}

struct PerssonSolution {
  double alpha = 0;             // contact semi-angle (rad)
  std::vector<double> theta;    // panel centres (rad)
  std::vector<double> p;        // pressure p R / (E* dR) at the panel centres
  double D = 0;                 // approach / dR (rigid + the mode-1 elastic part)
  // The pressure (p R / (E* dR)) at |theta|, linear between panel centres, 0 beyond the contact.
  double pressure(double t) const {
    t = std::abs(t);
    if (t >= alpha) return 0;
    if (t <= theta.front()) return p.front();
    for (std::size_t k = 1; k < theta.size(); ++k)
      if (t <= theta[k]) return p[k - 1] + (p[k] - p[k - 1]) * (t - theta[k - 1]) / (theta[k] - theta[k - 1]);
    return 0;
  }
};

// load = P / (E* dR).
inline PerssonSolution persson_solve(double load, int panels = 120, double theta_max = 110 * std::numbers::pi / 180) {
  if (!(load > 0)) throw std::invalid_argument("persson_solve: the load must be positive");
  const int N = panels;
  const double d = theta_max / N;
  PerssonSolution s;
  s.theta.resize(N);
  for (int i = 0; i < N; ++i) s.theta[i] = (i + 0.5) * d;
  Eigen::MatrixXd A(N, N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)  // the panel at +phi and its mirror at -phi, and the a_0 term
      A(i, j) = (persson_kernel_integral(s.theta[i] - (j + 1) * d, s.theta[i] - j * d) +
                 persson_kernel_integral(s.theta[i] + j * d, s.theta[i] + (j + 1) * d)) / std::numbers::pi +
                2 * d / (2 * std::numbers::pi);
  std::vector<char> active(N);
  for (int i = 0; i < N; ++i) active[i] = s.theta[i] < std::sqrt(4 * load / std::numbers::pi);  // the Hertz arc
  s.p.assign(N, 0.0);
  for (int round = 0; round < 200; ++round) {
    std::vector<int> idx;
    for (int i = 0; i < N; ++i)
      if (active[i]) idx.push_back(i);
    if (idx.empty()) throw std::runtime_error("persson_solve: empty contact set");
    const int n = static_cast<int>(idx.size());
    Eigen::MatrixXd M(n + 1, n + 1);
    Eigen::VectorXd r(n + 1);
    for (int a = 0; a < n; ++a) {  // gap = 0 on the active panels
      for (int b = 0; b < n; ++b) M(a, b) = A(idx[a], idx[b]);
      M(a, n) = -std::cos(s.theta[idx[a]]);
      r[a] = -(1 - std::cos(s.theta[idx[a]]));
    }
    for (int b = 0; b < n; ++b) M(n, b) = 2 * d * std::cos(s.theta[idx[b]]);  // the force
    M(n, n) = 0;
    r[n] = load;
    const Eigen::VectorXd x = M.partialPivLu().solve(r);
    std::fill(s.p.begin(), s.p.end(), 0.0);
    for (int a = 0; a < n; ++a) s.p[idx[a]] = x[a];
    s.D = x[n];
    bool changed = false;
    for (int i = 0; i < N; ++i)
      if (active[i] && s.p[i] < 0) active[i] = 0, changed = true;
    if (!changed)
      for (int i = 0; i < N; ++i) {
        if (active[i]) continue;
        double g = (1 - std::cos(s.theta[i])) - s.D * std::cos(s.theta[i]);
        for (int j = 0; j < N; ++j) g += A(i, j) * s.p[j];
        if (g < -1e-12) active[i] = 1, changed = true;
      }
    if (!changed) break;
  }
  int last = -1;
  for (int i = 0; i < N; ++i)
    if (s.p[i] > 0) last = i;
  if (last < 3 || last >= N - 1) throw std::runtime_error("persson_solve: the contact must span > 3 panels, inside the range");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = last - 2; i <= last; ++i) {
    const double x = s.theta[i], y = s.p[i] * s.p[i];
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double c1 = (3 * sxy - sx * sy) / (3 * sxx - sx * sx), c0 = (sy - c1 * sx) / 3;
  s.alpha = -c0 / c1;
  return s;
}

inline double persson_hertz_alpha(double load) { return std::sqrt(4 * load / std::numbers::pi); }

}  // namespace wrc::test
