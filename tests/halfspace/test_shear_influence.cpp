// The tangential (Cerruti) influence coefficients and the FFT products built on them.
#include "wrc/halfspace/influence.hpp"
#include "wrc/halfspace/shear.hpp"
#include "wrc/core/error.hpp"

#include "ray_integral.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using wrc::test::within_rel;
using namespace wrc::halfspace;

TEST_CASE("shear integrals: closed forms against an independent quadrature inside, on edges, at corners, outside") {
  const double a = 0.7e-3, b = 0.3e-3;
  const double points[][2] = {{0, 0},         {0.2e-3, -0.1e-3}, {a, 0},   {0, -b},      {a, b},        {-a, b},
                              {1.5e-3, 0.2e-3}, {-3e-3, 4e-3},   {0.69e-3, 0}, {2e-2, -1e-2}, {0.5e-3, 0.3e-3}};
  for (const auto& pt : points) {
    CAPTURE(pt[0]);
    CAPTURE(pt[1]);
    const ShearPotentials s = rectangle_shear_potentials(pt[0], pt[1], a, b);
    const double scale = s.I;
    const auto c2 = [](double t) { return std::cos(t) * std::cos(t); };
    const auto s2 = [](double t) { return std::sin(t) * std::sin(t); };
    const auto cs = [](double t) { return std::cos(t) * std::sin(t); };
    CHECK(std::abs(s.xx - wrc::test::ray_integral(pt[0], pt[1], a, b, c2)) < 1e-11 * scale);
    CHECK(std::abs(s.yy - wrc::test::ray_integral(pt[0], pt[1], a, b, s2)) < 1e-11 * scale);
    CHECK(std::abs(s.xy - wrc::test::ray_integral(pt[0], pt[1], a, b, cs)) < 1e-11 * scale);
    CHECK(s.I == within_rel(rectangle_potential(pt[0], pt[1], a, b), 1e-12));
  }
}

TEST_CASE("Cerruti far field: a point force Q_x displaces by Q (1 - nu + nu x^2 / r^2) / (2 pi G r), and nu x y Q / "
          "(2 pi G r^3) across") {
  const Material m{2.1e11, 0.28};
  const double a = 0.1e-3, b = 0.15e-3, q = 1e8, Q = 4 * a * b * q, G = m.shear_modulus();
  double previous = INFINITY;
  for (double r : {10 * a, 40 * a, 160 * a}) {
    const double x = 0.6 * r, y = -0.8 * r;
    const TangentialDisplacement u = rectangle_shear_displacement(m, x, y, a, b, q, 0);
    const double ux = Q * (1 - m.nu + m.nu * x * x / (r * r)) / (2 * std::numbers::pi * G * r);
    const double uy = m.nu * Q * x * y / (2 * std::numbers::pi * G * r * r * r);
    const double error = std::max(std::abs(u.x / ux - 1), std::abs(u.y / uy - 1));
    CHECK(error < previous / 10);  // (a / r)^2: 16x per step of 4x
    previous = error;
    // The lateral traction: x and y exchange roles.
    const TangentialDisplacement v = rectangle_shear_displacement(m, y, x, b, a, 0, q);
    CHECK(v.y == within_rel(u.x, 1e-12));
    CHECK(v.x == within_rel(u.y, 1e-12));
  }
}

TEST_CASE("ShearInfluenceTable: the pair's coefficients, B_xy odd in each offset") {
  const Material m{2.1e11, 0.3};
  const double dx = 0.2e-3, dy = 0.3e-3;
  const ShearInfluenceTable t(m, dx, dy, 6, 5);
  for (int n = -4; n <= 4; ++n)
    for (int k = -5; k <= 5; ++k) {
      // The field element at offset (k, n) from the loaded one: twice the one-body displacement per unit traction.
      const TangentialDisplacement ux = rectangle_shear_displacement(m, k * dx, n * dy, dx / 2, dy / 2, 1, 0);
      const TangentialDisplacement uy = rectangle_shear_displacement(m, k * dx, n * dy, dx / 2, dy / 2, 0, 1);
      CHECK(t.xx(k, n) == within_rel(2 * ux.x, 1e-12));
      CHECK(t.yy(k, n) == within_rel(2 * uy.y, 1e-12));
      CHECK(std::abs(t.xy(k, n) - 2 * ux.y) < 1e-12 * t.xx(0, 0));
      CHECK(std::abs(t.xy(k, n) - 2 * uy.x) < 1e-12 * t.xx(0, 0));  // symmetric
    }
  CHECK(t.xy(0, 3) == 0);
  CHECK(t.xy(2, 0) == 0);
  CHECK(t.xy(2, 3) > 0);
  CHECK(t.xy(-2, 3) == -t.xy(2, 3));
}

namespace {

// u = B q by direct sums over the table.
void direct(const ShearInfluenceTable& t, const Grid& g, const std::vector<double>& qx, const std::vector<double>& qy,
            std::vector<double>& ux, std::vector<double>& uy) {
  ux.assign(g.size(), 0.0);
  uy.assign(g.size(), 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      for (int l = 0; l < g.ny; ++l)
        for (int k = 0; k < g.nx; ++k) {
          const int f = g.index(i, j), s = g.index(k, l);
          ux[f] += t.xx(i - k, j - l) * qx[s] + t.xy(i - k, j - l) * qy[s];
          uy[f] += t.xy(i - k, j - l) * qx[s] + t.yy(i - k, j - l) * qy[s];
        }
}

}  // namespace

TEST_CASE("shear FFT product equals the direct product, the periodic inverse undoes the periodic product") {
  const Material m{2.1e11, 0.3};
  ShearCache cache(m);
  ShearWorkspace ws;  // one workspace across shapes
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  const int shapes[][2] = {{1, 1}, {1, 8}, {7, 1}, {2, 2}, {9, 6}, {16, 16}, {13, 4}, {5, 17}};
  for (const auto& sh : shapes) {
    Grid g = Grid::square(sh[0], sh[1], 0.2e-3);
    g.dy = 0.35e-3;
    CAPTURE(g.nx);
    CAPTURE(g.ny);
    std::vector<double> qx(g.size()), qy(g.size()), ux(g.size()), uy(g.size()), dx_, dy_;
    for (int k = 0; k < g.size(); ++k) qx[k] = 1e8 * U(rng), qy[k] = 1e8 * U(rng);
    const ShearInfluenceTable t(m, g.dx, g.dy, g.nx, g.ny);
    direct(t, g, qx, qy, dx_, dy_);
    shear_convolve(*cache.get(g, ShearSpectrum::Kind::linear), g, qx.data(), qy.data(), ux.data(), uy.data(), ws);
    double scale = 0, error = 0;
    for (int k = 0; k < g.size(); ++k) {
      scale = std::max({scale, std::abs(dx_[k]), std::abs(dy_[k])});
      error = std::max({error, std::abs(ux[k] - dx_[k]), std::abs(uy[k] - dy_[k])});
    }
    CHECK(error < 1e-12 * scale);
    // The periodic product on the grid made periodic (the periodic spectrum's period), by direct sums over wrapped
    // offsets, then its inverse.
    const auto periodic = cache.get(g, ShearSpectrum::Kind::periodic);
    const int Mx = periodic->fft().Mx(), My = periodic->fft().My();
    const ShearInfluenceTable tp(m, g.dx, g.dy, Mx / 2 + 1, My / 2 + 1);
    const auto wrap = [](int d, int M, bool& nyquist) {
      d = ((d % M) + M) % M;
      nyquist = M % 2 == 0 && d == M / 2;
      return d <= M / 2 ? d : d - M;
    };
    std::vector<double> px(g.size(), 0.0), py(g.size(), 0.0), rx(g.size()), ry(g.size());
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        for (int l = 0; l < g.ny; ++l)
          for (int k = 0; k < g.nx; ++k) {
            bool nx_ = false, ny_ = false;
            const int di = wrap(i - k, Mx, nx_), dj = wrap(j - l, My, ny_);
            const double xy = (nx_ || ny_) ? 0.0 : tp.xy(di, dj);
            const int f = g.index(i, j), s = g.index(k, l);
            px[f] += tp.xx(di, dj) * qx[s] + xy * qy[s];
            py[f] += xy * qx[s] + tp.yy(di, dj) * qy[s];
          }
    if (Mx == g.nx && My == g.ny) {  // the grid is itself the period: the inverse is exact
      shear_deconvolve(*periodic, g, px.data(), py.data(), rx.data(), ry.data(), ws);
      double err = 0, q = 0;
      for (int k = 0; k < g.size(); ++k) {
        q = std::max({q, std::abs(qx[k]), std::abs(qy[k])});
        err = std::max({err, std::abs(rx[k] - qx[k]), std::abs(ry[k] - qy[k])});
      }
      CHECK(err < 1e-9 * q);
    }
  }
  CHECK_THROWS_AS(shear_convolve(*cache.get(Grid::square(4, 4, 0.2e-3), ShearSpectrum::Kind::linear),
                                 Grid::square(40, 4, 0.2e-3), nullptr, nullptr, nullptr, nullptr, ws),
                  wrc::Error);
}

TEST_CASE("shear FFT product with split columns (two transforms of half the length) equals the direct product") {
  const Material m{2.1e11, 0.3};
  ShearWorkspace ws;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  // Data in fewer rows than half the period and in all of its first half (2 ny - 1 <= My).
  for (const auto& [nx, ny, My] : {std::array{5, 7, 24}, {8, 12, 24}, {3, 128, 256}}) {
    Grid g = Grid::square(nx, ny, 0.2e-3);
    g.dy = 0.35e-3;
    const ShearSpectrum s(ShearSpectrum::Kind::linear, m, g.dx, g.dy, 16, My);
    CAPTURE(ny);
    REQUIRE(s.fft().split());
    REQUIRE(s.serves(g));
    std::vector<double> qx(g.size()), qy(g.size()), ux(g.size()), uy(g.size()), dx_, dy_;
    for (int k = 0; k < g.size(); ++k) qx[k] = 1e8 * U(rng), qy[k] = 1e8 * U(rng);
    direct(ShearInfluenceTable(m, g.dx, g.dy, g.nx, g.ny), g, qx, qy, dx_, dy_);
    shear_convolve(s, g, qx.data(), qy.data(), ux.data(), uy.data(), ws);
    double scale = 0, error = 0;
    for (int k = 0; k < g.size(); ++k) {
      scale = std::max({scale, std::abs(dx_[k]), std::abs(dy_[k])});
      error = std::max({error, std::abs(ux[k] - dx_[k]), std::abs(uy[k] - dy_[k])});
    }
    CHECK(error < 1e-12 * scale);
  }
}
