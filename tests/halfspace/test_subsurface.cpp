// Subsurface stresses (halfspace/subsurface.hpp) against independent references written here: the point-force
// solutions of Boussinesq and Cerruti integrated numerically, Johnson's closed form on the axis of a Hertz contact
// (eq. 3.45) and Hamilton's explicit equations for a sliding spherical contact (Proc. IMechE C 197, 1983).
#include "wrc/halfspace/subsurface.hpp"
#include "wrc/core/error.hpp"
#include "approx.hpp"
#include "field_recorder.hpp"
#include "halfspace/hamilton_reference.hpp"
#include "halfspace/materials.hpp"

#include <Eigen/Eigenvalues>
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using wrc::test::within_abs;
using wrc::test::within_rel;
using namespace wrc::halfspace;

namespace {

constexpr double kPi = std::numbers::pi;

double component(const Stress& s, int c) {
  const double v[6] = {s.xx, s.yy, s.zz, s.xy, s.xz, s.yz};
  return v[c];
}
Stress operator+(Stress a, const Stress& b) {
  return {a.xx + b.xx, a.yy + b.yy, a.zz + b.zz, a.xy + b.xy, a.xz + b.xz, a.yz + b.yz};
}
Stress operator*(double k, Stress a) { return {k * a.xx, k * a.yy, k * a.zz, k * a.xy, k * a.xz, k * a.yz}; }
double max_abs_difference(const Stress& a, const Stress& b) {
  double d = 0;
  for (int c = 0; c < 6; ++c) d = std::max(d, std::abs(component(a, c) - component(b, c)));
  return d;
}

// ---- references: point forces on the surface of a half-space (z into the body, tension positive) ----

// A normal force P pressing into the half-space at the origin (Johnson eq. 3.20, cylindrical, rotated to x, y).
Stress boussinesq(double nu, double x, double y, double z, double P) {
  const double r2 = x * x + y * y, r = std::sqrt(r2), rho = std::sqrt(r2 + z * z), rho5 = std::pow(rho, 5);
  const double szz = -3 * P * z * z * z / (2 * kPi * rho5), srz = -3 * P * r * z * z / (2 * kPi * rho5);
  const double sr = P / (2 * kPi) * ((1 - 2 * nu) / r2 * (1 - z / rho) - 3 * z * r2 / rho5);
  const double st = -P / (2 * kPi) * (1 - 2 * nu) * (1 / r2 * (1 - z / rho) - z / (rho * rho * rho));
  const double c = x / r, s = y / r;
  return {sr * c * c + st * s * s, sr * s * s + st * c * c, szz, (sr - st) * s * c, srz * c, srz * s};
}

// A tangential force Q along +x on the half-space at the origin (Cerruti; Johnson section 3.2).
Stress cerruti(double nu, double x, double y, double z, double Q) {
  const double rho = std::sqrt(x * x + y * y + z * z), rz = rho + z, rho3 = rho * rho * rho, rho5 = rho3 * rho * rho;
  const double k = (1 - 2 * nu) / (rz * rz);
  return {-Q * x / (2 * kPi * rho3) * (3 * x * x / (rho * rho) - k * (rho * rho - y * y - 2 * rho * y * y / rz)),
          -Q * x / (2 * kPi * rho3) * (3 * y * y / (rho * rho) - k * (3 * rho * rho - x * x - 2 * rho * x * x / rz)),
          -3 * Q * x * z * z / (2 * kPi * rho5),
          -Q * y / (2 * kPi * rho3) * (3 * x * x / (rho * rho) + k * (rho * rho - x * x - 2 * rho * x * x / rz)),
          -3 * Q * x * x * z / (2 * kPi * rho5),
          -3 * Q * x * y * z / (2 * kPi * rho5)};
}

// The Cerruti force along +y: Cerruti along x with x and y exchanged.
Stress cerruti_y(double nu, double x, double y, double z, double Q) {
  const Stress s = cerruti(nu, y, x, z, Q);
  return {s.yy, s.xx, s.zz, s.xy, s.yz, s.xz};
}

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre polynomial).
struct Rule {
  std::vector<double> x, w;
};
Rule gauss_legendre(int n) {
  Rule r;
  for (int i = 1; i <= n; ++i) {
    double t = std::cos(kPi * (i - 0.25) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    r.x.push_back(t);
    r.w.push_back(2 / ((1 - t * t) * dp * dp));
  }
  return r;
}

// The integral of a point-force stress field over the loaded rectangle [-a, a] x [-b, b] (unit traction): composite
// Gauss-Legendre on sub x sub cells.
Stress integrate_rectangle(const std::function<Stress(double, double)>& point, double a, double b, int sub) {
  static const Rule rule = gauss_legendre(20);
  Stress sum;
  const double hx = 2 * a / sub, hy = 2 * b / sub;
  for (int i = 0; i < sub; ++i)
    for (int j = 0; j < sub; ++j)
      for (std::size_t p = 0; p < rule.x.size(); ++p)
        for (std::size_t q = 0; q < rule.x.size(); ++q) {
          const double s = -a + (i + 0.5 + 0.5 * rule.x[p]) * hx, t = -b + (j + 0.5 + 0.5 * rule.x[q]) * hy;
          sum = sum + (rule.w[p] * rule.w[q] * hx * hy / 4) * point(s, t);
        }
  return sum;
}

// ---- references: Hertz's circular contact (radius 1, peak pressure 1) ----

// Johnson eq. 3.45, on the axis at depth z: sigma_z and sigma_r (= sigma_theta), in p0.
Stress to_stress(const wrc::test::HamiltonStress& h) { return {h.xx, h.yy, h.zz, h.xy, h.xz, h.yz}; }
Stress hamilton_normal_stress(double nu, double x, double y, double z) {
  return to_stress(wrc::test::hamilton_normal(nu, x, y, z));
}
Stress hamilton_tangential_stress(double nu, double x, double y, double z) {
  return to_stress(wrc::test::hamilton_tangential(nu, x, y, z));
}
using wrc::test::axis_srr;
using wrc::test::axis_szz;

// A grid of (2 n + 1 + 2 pad)^2 square elements centred on the origin, n elements on the contact radius a.
Grid hertz_grid(double a, int n, int pad) { return Grid::square(2 * (n + pad) + 1, 2 * (n + pad) + 1, a / n); }

std::vector<double> hertz_pressure(const Grid& g, double a, double p0) {
  std::vector<double> p(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double t = 1 - (g.x(i) * g.x(i) + g.y(j) * g.y(j)) / (a * a);
      p[g.index(i, j)] = t > 0 ? p0 * std::sqrt(t) : 0.0;
    }
  return p;
}

std::vector<double> range(double from, double to, double step) {
  std::vector<double> v;
  for (int k = 0; from + k * step <= to + 1e-9 * step; ++k) v.push_back(from + k * step);
  return v;
}

Stress stress_at(const SubsurfaceDepth& d, std::size_t k) {
  return {d.sxx[k], d.syy[k], d.szz[k], d.sxy[k], d.sxz[k], d.syz[k]};
}

// The maximum of f(z) on [lo, hi] (unimodal) by golden section: {z, f}.
std::pair<double, double> golden_max(const std::function<double(double)>& f, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = lo, b = hi;
  for (int it = 0; it < 200 && b - a > 1e-12; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (f(c) > f(d)) b = d;
    else a = c;
  }
  const double z = 0.5 * (a + b);
  return {z, f(z)};
}

using wrc::test::steel;

}  // namespace

TEST_CASE("point-force references: equilibrium (finite differences) and free surface") {
  // div sigma = 0 inside; sigma_zz, sigma_xz, sigma_yz vanish on the surface away from the force.
  for (const auto& field : {std::function<Stress(double, double, double)>(
                                [](double x, double y, double z) { return boussinesq(0.3, x, y, z, 1); }),
                            std::function<Stress(double, double, double)>(
                                [](double x, double y, double z) { return cerruti(0.3, x, y, z, 1); })}) {
    for (const auto& p : {std::array<double, 3>{0.3, -0.7, 0.5}, {1.2, 0.4, 0.2}, {-0.5, 0.9, 1.5}}) {
      const double h = 1e-4;
      const auto d = [&](int axis) {
        std::array<double, 3> a = p, b = p;
        a[axis] += h;
        b[axis] -= h;
        return (1 / (2 * h)) * (field(a[0], a[1], a[2]) + (-1.0) * field(b[0], b[1], b[2]));
      };
      const Stress dx = d(0), dy = d(1), dz = d(2);
      const double scale = max_abs_difference(field(p[0], p[1], p[2]), Stress{}) / std::hypot(p[0], p[1], p[2]);
      CHECK(std::abs(dx.xx + dy.xy + dz.xz) < 1e-6 * scale);
      CHECK(std::abs(dx.xy + dy.yy + dz.yz) < 1e-6 * scale);
      CHECK(std::abs(dx.xz + dy.yz + dz.zz) < 1e-6 * scale);
    }
    const Stress surface = field(0.4, -0.3, 1e-12);
    CHECK(std::abs(surface.zz) < 1e-9);
    CHECK(std::abs(surface.xz) < 1e-9);
    CHECK(std::abs(surface.yz) < 1e-9);
  }
}

TEST_CASE("rectangle_stress: closed forms against quadrature of Boussinesq's and Cerruti's point forces") {
  const double nu = 0.28, a = 0.1e-3, b = 0.06e-3;
  // Under the element, beside it, diagonal to it, far; depths from 0.3 b to 10 a.
  const double points[][3] = {{0.3e-3 * 0.1, 0.01e-3, 0.05e-3}, {0.03e-3, -0.02e-3, 0.02e-3},
                              {0.17e-3, -0.04e-3, 0.08e-3},     {-0.25e-3, 0.19e-3, 0.06e-3},
                              {0.02e-3, 0.03e-3, 0.3e-3},       {-0.12e-3, -0.09e-3, 0.03e-3},
                              {1.1e-3, 0.4e-3, 0.2e-3},         {0.0, 0.0, 1e-3}};
  double worst = 0;
  for (const auto& pt : points) {
    const double x = pt[0], y = pt[1], z = pt[2];
    CAPTURE(x);
    CAPTURE(y);
    CAPTURE(z);
    const int sub = z < 0.05e-3 ? 24 : 8;
    const Stress qn = integrate_rectangle([&](double s, double t) { return boussinesq(nu, x - s, y - t, z, 1); }, a, b, sub);
    const Stress qx = integrate_rectangle([&](double s, double t) { return cerruti(nu, x - s, y - t, z, 1); }, a, b, sub);
    const Stress qy = integrate_rectangle([&](double s, double t) { return cerruti_y(nu, x - s, y - t, z, 1); }, a, b, sub);
    const Stress sn = rectangle_stress(nu, x, y, z, a, b, 1, 0, 0);
    const Stress sx = rectangle_stress(nu, x, y, z, a, b, 0, 1, 0);
    const Stress sy = rectangle_stress(nu, x, y, z, a, b, 0, 0, 1);
    for (int c = 0; c < 6; ++c) {
      CAPTURE(c);
      CHECK(std::abs(component(sn, c) - component(qn, c)) < 1e-10);
      CHECK(std::abs(component(sx, c) - component(qx, c)) < 1e-10);
      CHECK(std::abs(component(sy, c) - component(qy, c)) < 1e-10);
    }
    worst = std::max({worst, max_abs_difference(sn, qn), max_abs_difference(sx, qx), max_abs_difference(sy, qy)});
    // Superposition: the combined load is the sum.
    const Stress all = rectangle_stress(nu, x, y, z, a, b, 2, -0.5, 0.3);
    CHECK(max_abs_difference(all, 2 * sn + (-0.5) * sx + 0.3 * sy) < 1e-14);
  }
  MESSAGE(fmt::format("rectangle_stress vs quadrature of the point forces: largest difference {:.1e} (per unit load)",
                      worst));
  // The surface under the element: the traction itself (sigma_zz -> -p, sigma_xz -> -qx, sigma_yz -> -qy).
  const Stress s = rectangle_stress(nu, 0.02e-3, -0.01e-3, 1e-12, a, b, 3, 0.7, -0.4);
  CHECK(s.zz == within_rel(-3, 1e-6));
  CHECK(s.xz == within_rel(-0.7, 1e-6));
  CHECK(s.yz == within_rel(0.4, 1e-6));
  CHECK_THROWS_AS(rectangle_stress(nu, 0, 0, 0, a, b, 1, 0, 0), wrc::Error);
}

TEST_CASE("principal stresses and von Mises against Eigen's eigenvalues") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e9, 1e9);
  for (int k = 0; k < 200; ++k) {
    Stress s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    if (k % 4 == 1) s.xy = s.xz = 0, s.yy = s.xx;  // two equal principal stresses
    if (k % 4 == 2) s = {5e8, 5e8, 5e8, 0, 0, 0};  // hydrostatic
    Eigen::Matrix3d m;
    m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
    const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues();  // ascending
    const PrincipalStresses p = principal_stresses(s);
    const double tol = 1e-13 * m.norm();  // rounding of stresses ~1e9 Pa
    CHECK(std::abs(p.s1 - e(2)) < tol);
    CHECK(std::abs(p.s2 - e(1)) < tol);
    CHECK(std::abs(p.s3 - e(0)) < tol);
    const double vm = std::sqrt(0.5 * ((e(0) - e(1)) * (e(0) - e(1)) + (e(1) - e(2)) * (e(1) - e(2)) +
                                       (e(2) - e(0)) * (e(2) - e(0))));
    CHECK(std::abs(von_mises(s) - vm) < tol);
    CHECK(std::abs(tresca(s) - (e(2) - e(0))) < tol);
  }
}

TEST_CASE("subsurface on a grid: both methods equal the sum of rectangle_stress over the elements") {
  // Random loads on every element of a small grid of non-square elements (all signs of the offsets).
  const Grid g{9, 6, 0.2e-3, 0.13e-3, -0.7e-3, 0.1e-3};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1e9), v(-3e8, 3e8);
  std::vector<double> p(g.size()), px(g.size()), py(g.size());
  for (int k = 0; k < g.size(); ++k) p[k] = u(rng), px[k] = v(rng), py[k] = v(rng);
  p[4] = 0;  // an unloaded element in between
  for (const StressedBody body : {StressedBody::wheel, StressedBody::rail}) {
    const double sign = body == StressedBody::rail ? -1 : 1;
    for (const SubsurfaceMethod method : {SubsurfaceMethod::direct, SubsurfaceMethod::fft}) {
      SubsurfaceRequest rq;
      rq.z = {0.05e-3, 0.3e-3};
      rq.method = method;
      rq.body = body;
      const SubsurfaceResult r = compute_subsurface(steel, {g, p, px, py}, rq);
      CHECK(r.method == method);
      for (const SubsurfaceDepth& d : r.depths)
        for (int j = 0; j < g.ny; ++j)
          for (int i = 0; i < g.nx; ++i) {
            Stress ref;
            for (int l = 0; l < g.ny; ++l)
              for (int k = 0; k < g.nx; ++k) {
                const int e = g.index(k, l);
                ref = ref + rectangle_stress(steel.nu, g.x(i) - g.x(k), g.y(j) - g.y(l), d.z, g.dx / 2, g.dy / 2,
                                             p[e], sign * px[e], sign * py[e]);
              }
            CHECK(max_abs_difference(stress_at(d, g.index(i, j)), ref) < 1e-6 * 1e9 * 1e-3);  // 1 kPa of ~GPa
          }
    }
  }
}

TEST_CASE("subsurface: the FFT path equals the direct path to rounding, and the symmetries of a sliding Hertz load") {
  const double a = 4e-3, p0 = 1.2e9, mu = 0.25;
  const Grid g = hertz_grid(a, 15, 3);  // 37 x 37
  const std::vector<double> p = hertz_pressure(g, a, p0);
  std::vector<double> px(p.size()), py(p.size(), 0.0);
  for (std::size_t k = 0; k < p.size(); ++k) px[k] = mu * p[k];
  SubsurfaceRequest rq;
  rq.z = {0.05 * a, 0.3 * a, 0.7 * a, 2 * a};
  rq.method = SubsurfaceMethod::fft;
  const SubsurfaceResult f = compute_subsurface(steel, {g, p, px, py}, rq);
  rq.method = SubsurfaceMethod::direct;
  const SubsurfaceResult d = compute_subsurface(steel, {g, p, px, py}, rq);
  rq.body = StressedBody::rail;
  const SubsurfaceResult rail = compute_subsurface(steel, {g, p, px, py}, rq);
  double worst = 0;
  for (std::size_t l = 0; l < rq.z.size(); ++l) {
    const SubsurfaceDepth &F = f.depths[l], &D = d.depths[l], &R = rail.depths[l];
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t k = g.index(i, j);
        worst = std::max(worst, max_abs_difference(stress_at(F, k), stress_at(D, k)));
        // Even in y: sigma_xx, yy, zz, xz; odd in y: sigma_xy, yz.
        const Stress s = stress_at(D, k), m = stress_at(D, g.index(i, g.ny - 1 - j));
        CHECK(std::abs(s.xx - m.xx) < 1e-6 * p0);
        CHECK(std::abs(s.zz - m.zz) < 1e-6 * p0);
        CHECK(std::abs(s.xz - m.xz) < 1e-6 * p0);
        CHECK(std::abs(s.xy + m.xy) < 1e-6 * p0);
        CHECK(std::abs(s.yz + m.yz) < 1e-6 * p0);
        // The rail carries the reversed traction: the wheel's field mirrored in x (sigma_xy and sigma_xz change sign).
        const Stress w = stress_at(D, g.index(g.nx - 1 - i, j)), r = stress_at(R, k);
        CHECK(std::abs(r.xx - w.xx) < 1e-6 * p0);
        CHECK(std::abs(r.yy - w.yy) < 1e-6 * p0);
        CHECK(std::abs(r.zz - w.zz) < 1e-6 * p0);
        CHECK(std::abs(r.xy + w.xy) < 1e-6 * p0);
        CHECK(std::abs(r.xz + w.xz) < 1e-6 * p0);
        CHECK(std::abs(r.yz - w.yz) < 1e-6 * p0);
      }
    CHECK(F.von_mises_max.value == within_rel(D.von_mises_max.value, 1e-12));
  }
  MESSAGE(fmt::format("FFT vs direct, 37 x 37 elements, sliding Hertz load: largest difference {:.2e} p0", worst / p0));
  CHECK(worst < 1e-11 * p0);
  CHECK(f.von_mises_max.x == d.von_mises_max.x);
  CHECK(f.von_mises_max.z == d.von_mises_max.z);
}

TEST_CASE("circular Hertz contact: the axis against Johnson eq. 3.45, tau_1 max 0.31 p0 at 0.48 a, convergence") {
  const double nu = steel.nu, a = 5e-3, p0 = 1e9;
  // The closed form's maxima on the axis: tau_1 = (sigma_r - sigma_z) / 2, von Mises = 2 tau_1 (sigma_r = sigma_theta).
  const auto [zt, tau_ref] = golden_max([&](double z) { return 0.5 * (axis_srr(nu, z) - axis_szz(z)); }, 0.1, 1.5);
  CHECK(tau_ref == within_rel(0.31, 0.01));  // Johnson: 0.31 p0 at 0.48 a
  CHECK(zt == within_rel(0.48, 0.01));
  const std::vector<double> axis_depths = {0.25, 0.5, 1.0, 2.0};
  std::vector<double> depths;
  for (double z : axis_depths) depths.push_back(z * a);
  for (double z : range(0.40, 0.56, 0.005)) depths.push_back(z * a);
  std::string table = "elements on a | tau1_max/p0 err | its z err (parabola) | von Mises max err | axis sigma err (max)\n";
  double previous = INFINITY;
  for (int n : {5, 10, 20, 40}) {
    const Grid g = hertz_grid(a, n, 2);
    const std::vector<double> p = hertz_pressure(g, a, p0);
    SubsurfaceRequest rq;
    rq.z = depths;
    const SubsurfaceResult r = compute_subsurface(steel, {g, p}, rq);
    // On the axis: the centre element.
    const std::size_t centre = g.index(g.nx / 2, g.ny / 2);
    double axis_error = 0;
    for (std::size_t l = 0; l < axis_depths.size(); ++l) {
      const double z = axis_depths[l];
      const SubsurfaceDepth& d = r.depths[l];
      axis_error = std::max({axis_error, std::abs(d.szz[centre] / p0 - axis_szz(z)),
                             std::abs(d.sxx[centre] / p0 - axis_srr(nu, z)),
                             std::abs(d.syy[centre] / p0 - axis_srr(nu, z))});
      CHECK(std::abs(d.sxz[centre]) < 1e-9 * p0);
    }
    const double tau = 0.5 * r.tresca_max.value / p0, vm = r.von_mises_max.value / p0;
    // The depth of the maximum between the samples: the vertex of the parabola through the best depth and its two
    // neighbours (the depths from axis_depths.size() on are 0.005 a apart).
    std::size_t best = axis_depths.size();
    for (std::size_t l = best; l < r.depths.size(); ++l)
      if (r.depths[l].tresca_max.value > r.depths[best].tresca_max.value) best = l;
    REQUIRE(best > axis_depths.size());
    REQUIRE(best + 1 < r.depths.size());
    const double f0 = r.depths[best - 1].tresca_max.value, f1 = r.depths[best].tresca_max.value,
                 f2 = r.depths[best + 1].tresca_max.value;
    const double z_vertex = r.depths[best].z + 0.005 * a * (f0 - f2) / (2 * (f0 - 2 * f1 + f2));
    const double tau_error = tau / tau_ref - 1, z_error = z_vertex / a / zt - 1, vm_error = vm / (2 * tau_ref) - 1;
    table += fmt::format("{:13d} | {:+15.4f} | {:+20.4f} | {:+17.4f} | {:.4f}\n", n, tau_error, z_error, vm_error,
                         axis_error);
    if (n >= 10) {  // 2 % from 10 elements on the radius
      CHECK(std::abs(tau_error) < 0.02);
      CHECK(std::abs(z_error) < 0.02);
      CHECK(std::abs(vm_error) < 0.02);
      CHECK(axis_error < 0.02);
      CHECK(r.von_mises_max.x == 0);  // on the axis
      CHECK(r.von_mises_max.y == 0);
      CHECK(std::abs(r.von_mises_max.z / a / zt - 1) < 0.02);  // the sampled depth
      CHECK(std::abs(r.tresca_max.z / a / zt - 1) < 0.02);
    }
    CHECK(std::abs(tau_error) < previous);
    previous = std::abs(tau_error);
    // The patch's own first yield: von Mises 0.62 p0 gives p0 = 1.60 Y (Johnson), p0/k = sqrt(3) / 0.62 = 2.79.
    if (n == 40) CHECK(r.shakedown.elastic_limit == within_rel(1.60 * std::numbers::sqrt3, 0.02));
  }
  MESSAGE(fmt::format("Hertz circle, nu = 0.3: tau_1 max {:.4f} p0 at z = {:.4f} a (closed form)\n{}", tau_ref, zt,
                      table));
}

TEST_CASE("sliding Hertz contact: the maximum von Mises stress and its place against Hamilton (1983)") {
  const double nu = steel.nu, a = 5e-3, p0 = 1e9;
  const int n = 20;
  const Grid g = hertz_grid(a, n, 4);
  const std::vector<double> p = hertz_pressure(g, a, p0);
  SubsurfaceRequest rq;
  rq.z = {0.0025 * a, 0.005 * a, 0.01 * a};  // near the surface, where the maximum goes for mu > 0.3
  for (double z : range(0.02, 1.0, 0.02)) rq.z.push_back(z * a);
  std::string table = "mu   | Hamilton max vM (x/a, z/a) | wrc max vM (x/a, z/a) | error | Hamilton continuous\n";
  double previous_z = INFINITY;
  for (double mu : {0.0, 0.1, 0.2, 0.3, 0.35, 0.4}) {
    std::vector<double> px(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) px[k] = mu * p[k];
    const SubsurfaceResult r = compute_subsurface(steel, {g, p, px}, rq);
    // Hamilton at the same points (element centres, requested depths).
    StressMaximum h;
    for (double z : rq.z)
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
          const double x = g.x(i) / a, y = g.y(j) / a;
          const double vm = von_mises(p0 * hamilton_normal_stress(nu, x, y, z / a) +
                                      mu * p0 * hamilton_tangential_stress(nu, x, y, z / a));
          if (vm > h.value) h = {vm, g.x(i), g.y(j), z};
        }
    // Hamilton's own maximum, off the samples (plane y = 0, x and z every 0.0025 a).
    StressMaximum c;
    for (double z = 0.0025; z <= 1.0; z += 0.0025)
      for (double x = -1.25 + 0.00125; x < 1.25; x += 0.0025) {
        const double vm = von_mises(hamilton_normal_stress(nu, x, 0, z) + mu * hamilton_tangential_stress(nu, x, 0, z));
        if (vm > c.value) c = {vm, x, 0, z};
      }
    const double error = r.von_mises_max.value / h.value - 1;
    table += fmt::format("{:.2f} | {:.4f} p0 ({:+.3f}, {:.4f})   | {:.4f} p0 ({:+.3f}, {:.4f}) | {:+.4f} | {:.4f} p0 "
                         "({:+.3f}, {:.4f})\n",
                         mu, h.value / p0, h.x / a, h.z / a, r.von_mises_max.value / p0, r.von_mises_max.x / a,
                         r.von_mises_max.z / a, error, c.value, c.x, c.z);
    CAPTURE(mu);
    CHECK(std::abs(error) < 0.02);
    CHECK(std::abs(r.von_mises_max.x - h.x) < 0.02 * a + 1e-12);
    CHECK(std::abs(r.von_mises_max.z - h.z) < 0.02 * a + 1e-12);
    CHECK(std::abs(r.von_mises_max.y) < 1e-12);
    // Hamilton's own maximum: within 2 %, one element in x, 0.02 a in depth.
    CHECK(std::abs(r.von_mises_max.value / p0 / c.value - 1) < 0.02);
    CHECK(std::abs(r.von_mises_max.x / a - c.x) < 1.0 / n);
    CHECK(std::abs(r.von_mises_max.z / a - c.z) < 0.02);
    CHECK(r.von_mises_max.z <= previous_z);  // moves toward the surface as mu grows
    previous_z = r.von_mises_max.z;
    if (mu >= 0.35) {  // at the surface, at the trailing edge (behind the traction)
      CHECK(r.von_mises_max.z == rq.z.front());
      CHECK(r.von_mises_max.x / a < -0.9);
      CHECK(c.z < 0.005);
      CHECK(c.x < -0.95);
    }
    CHECK(r.shakedown.traction_coefficient == within_abs(mu, 1e-12));  // mu includes 0
  }
  MESSAGE(fmt::format("sliding Hertz circle, nu = 0.3, 20 elements on a, depths 0.0025, 0.005, 0.01, 0.02 .. 1.0 a:\n{}",
                      table));
}

TEST_CASE("shakedown point: load factor, traction coefficient and the regime on Johnson's map") {
  const double a = 5e-3, p0 = 1e9;
  const Grid g = hertz_grid(a, 10, 1);
  const std::vector<double> p = hertz_pressure(g, a, p0);
  SubsurfaceRequest rq;
  rq.z = range(0.3 * a, 0.7 * a, 0.02 * a);
  rq.fields = false;
  const auto regime = [&](double lambda, double mu, ShakedownMap map) {
    std::vector<double> px(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) px[k] = mu * p[k];
    rq.shear_yield = p0 / lambda;
    rq.map = map;
    const SubsurfaceResult r = compute_subsurface(steel, {g, p, px}, rq);
    CHECK(r.shakedown.load_factor == within_rel(lambda, 1e-12));
    CHECK(r.shakedown.p0 == within_rel(p0, 1e-12));
    CHECK(r.depths.front().sxx.empty());  // fields = false
    return r.shakedown.regime;
  };
  CHECK(regime(2.0, 0, ShakedownMap::point) == ShakedownRegime::elastic);  // first yield at 2.79
  CHECK(regime(3.5, 0, ShakedownMap::point) == ShakedownRegime::elastic_shakedown);
  CHECK(regime(4.5, 0.1, ShakedownMap::point) == ShakedownRegime::elastic_shakedown);  // below 4.7
  CHECK(regime(4.5, 0.1, ShakedownMap::line) == ShakedownRegime::plastic_shakedown);   // above 4.0
  CHECK(regime(5.5, 0.1, ShakedownMap::point) == ShakedownRegime::plastic_shakedown);
  CHECK(regime(3.0, 0.4, ShakedownMap::point) == ShakedownRegime::ratchetting);  // mu p0 > k
  // The patch's first yield: sqrt(3) p0 / von Mises max (over the requested depths), whatever k.
  rq.shear_yield = 300e6;
  const SubsurfaceResult r = compute_subsurface(steel, {g, p}, rq);
  CHECK(r.shakedown.elastic_limit == within_rel(std::numbers::sqrt3 * p0 / r.von_mises_max.value, 1e-14));
  CHECK(r.shakedown.surface_limit == INFINITY);
  CHECK(r.shakedown.subsurface_limit == kPointShakedownLimit);
}

TEST_CASE("describe: the maxima, the shakedown point and the grids of every depth, all finite") {
  const double a = 3e-3;
  const Grid g = hertz_grid(a, 6, 1);
  const std::vector<double> p = hertz_pressure(g, a, 9e8);
  SubsurfaceRequest rq;
  rq.z = {0.5 * a, 0.2 * a};
  rq.shear_yield = 400e6;  // p0 / k = 2.25, below first yield at 2.79
  const SubsurfaceResult r = compute_subsurface(steel, {g, p}, rq);
  const auto rec = wrc::test::field_paths(r);
  CHECK(rec.finite);
  CHECK(rec.nums.at("von_mises_max") == r.von_mises_max.value);
  CHECK(rec.nums.at("von_mises_max_z") == r.von_mises_max.z);
  CHECK(rec.nums.at("tresca_max") == r.tresca_max.value);
  CHECK(rec.nums.at("tresca_max_z") == r.tresca_max.z);
  CHECK(rec.nums.at("tau1_max") == 0.5 * r.tresca_max.value);
  CHECK(rec.nums.at("depths.2.z") == 0.2 * a);
  CHECK(rec.nums.count("shakedown.surface_limit") == 0);  // mu = 0: no surface limit (infinite), not written
  CHECK(rec.strs.at("shakedown.regime") == "elastic");
  CHECK(rec.strs.at("method") == method_name(r.method));
  for (const char* name : {"sigma_xx", "sigma_yy", "sigma_zz", "sigma_xy", "sigma_xz", "sigma_yz", "sigma_1", "sigma_2",
                           "sigma_3", "von_mises", "tresca", "max_shear"})
    CHECK(rec.arrays.at(fmt::format("depths.1.{}", name)) == static_cast<std::size_t>(g.size()));
  // Without load: zeros everywhere, no NaN, limits absent.
  const std::vector<double> zero(g.size(), 0.0);
  const auto empty = wrc::test::field_paths(compute_subsurface(steel, {g, zero}, rq));
  CHECK(empty.finite);
  CHECK(empty.nums.at("von_mises_max") == 0);
  CHECK(empty.nums.count("shakedown.elastic_limit") == 0);
}

TEST_CASE("subsurface: bad input names what is wrong") {
  const Grid g = Grid::square(4, 3, 1e-4);
  std::vector<double> p(g.size(), 1e8), bad = p;
  SubsurfaceRequest rq;
  rq.z = {1e-4};
  const auto message = [&](const SurfaceLoad& load, const SubsurfaceRequest& r) -> std::string {
    try {
      compute_subsurface(steel, load, r);
    } catch (const wrc::Error& e) {
      return e.what();
    }
    return "";
  };
  bad[5] = -1;
  CHECK(message({g, bad}, rq).find("pressure of element 5 is -1") != std::string::npos);
  bad[5] = NAN;
  CHECK(message({g, bad}, rq).find("pressure of element 5 is NaN") != std::string::npos);
  CHECK(message({g, std::span(p).first(5)}, rq).find("pressure has 5 values, the grid 12") != std::string::npos);
  CHECK(message({g, p, bad}, rq).find("traction px of element 5") != std::string::npos);
  SubsurfaceRequest r2 = rq;
  r2.z = {1e-4, 0};
  CHECK(message({g, p}, r2).find("the 2nd value of z (= 0) must be a finite depth > 0") != std::string::npos);
  r2.z = {};
  CHECK(message({g, p}, r2).find("no depth") != std::string::npos);
  r2.z = {INFINITY};
  CHECK(message({g, p}, r2).find("the 1st value of z (= inf)") != std::string::npos);
  r2.z = {0.5e-3, 2};  // 0.5 and 2 mm meant; a wheel's rim is 70 mm thick
  CHECK(message({g, p}, r2).find("the 2nd value of z (= 2 m) is deeper than 0.1 m") != std::string::npos);
  r2.z = {0.07};  // the whole rim: accepted
  CHECK(message({g, p}, r2).empty());
  r2 = rq;
  r2.shear_yield = 0;
  CHECK(message({g, p}, r2).find("shear_yield = 0") != std::string::npos);
  r2.shear_yield = 300;  // ER7's k (EN 13262: ReH 520 MPa / sqrt 3) in MPa
  CHECK(message({g, p}, r2).find("shear_yield = 300 Pa must be in [1e+06, 1e+10] Pa") != std::string::npos);
  CHECK(message({g, p}, r2).find("is it in MPa?") != std::string::npos);
  r2 = rq;
  r2.z.assign(kMaxSubsurfaceDepths, 1e-4);
  const Grid big = Grid::square(100, 100, 1e-4);
  const std::vector<double> pb(big.size(), 0.0);
  CHECK(message({big, pb}, r2).find("fields = false") != std::string::npos);
  r2.fields = false;
  r2.z.resize(2);
  CHECK(message({big, pb}, r2).empty());
  r2 = rq;
  r2.z = {1e170};  // a depth beyond any body, refused as such before the closed forms overflow
  CHECK(message({g, p}, r2).find("is deeper than") != std::string::npos);
  r2.z = {0.05};  // elements of 1e160 m: the closed forms overflow: an error, never a NaN
  const Grid huge = Grid::square(4, 3, 1e160);
  CHECK(message({huge, p}, r2).find("not finite") != std::string::npos);
  Material m = steel;
  m.nu = 0.5;
  CHECK_THROWS_AS(compute_subsurface(m, {g, p}, rq), wrc::Error);
  // The request's keys as Lua and C give them.
  {
    wrc::OptionTable t;
    t.set("z", wrc::OptionValue::of(std::vector<wrc::OptionValue>{wrc::OptionValue::of(1e-4), wrc::OptionValue::of(2e-4)}));
    t.set("method", wrc::OptionValue::of(std::string("direct")));
    t.set("body", wrc::OptionValue::of(std::string("rail")));
    t.set("shear_yield", wrc::OptionValue::of(350e6));
    t.set("shakedown_map", wrc::OptionValue::of(std::string("line")));
    t.set("fields", wrc::OptionValue::of(false));
    wrc::OptionReader o(t, "p:subsurface");
    const SubsurfaceRequest q = read_subsurface_request(o);
    o.finish();
    CHECK(q.z == std::vector<double>{1e-4, 2e-4});
    CHECK(q.method == SubsurfaceMethod::direct);
    CHECK(q.body == StressedBody::rail);
    CHECK(q.shear_yield == 350e6);
    CHECK(q.map == ShakedownMap::line);
    CHECK_FALSE(q.fields);
  }
  {
    wrc::OptionTable t;
    t.set("method", wrc::OptionValue::of(std::string("fast")));
    wrc::OptionReader o(t, "p:subsurface");
    CHECK_THROWS_WITH_AS(read_subsurface_request(o), doctest::Contains("'z' is required"), wrc::Error);
    t.set("z", wrc::OptionValue::of(1e-4));
    wrc::OptionReader o2(t, "p:subsurface");
    CHECK_THROWS_WITH_AS(read_subsurface_request(o2), doctest::Contains("method"), wrc::Error);
  }
}
