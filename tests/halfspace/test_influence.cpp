// Love's influence coefficients and the FFT products built on them.
#include "wrc/halfspace/convolution.hpp"
#include "wrc/halfspace/influence.hpp"
#include "wrc/halfspace/shear.hpp"
#include "wrc/core/error.hpp"

#include "ray_integral.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

using wrc::test::within_abs;
using wrc::test::within_rel;
using namespace wrc::halfspace;

namespace {

// Direct product u_k = sum_l I(x_k - x_l, y_k - y_l) p_l with rectangle_potential itself.
std::vector<double> direct_product(const Grid& g, const std::vector<double>& p) {
  std::vector<double> u(g.size(), 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      for (int l = 0; l < g.ny; ++l)
        for (int k = 0; k < g.nx; ++k)
          u[g.index(i, j)] +=
              rectangle_potential((i - k) * g.dx, (j - l) * g.dy, 0.5 * g.dx, 0.5 * g.dy) * p[g.index(k, l)];
  return u;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST_CASE("centre displacement of a uniformly loaded square: 8 a ln(1 + sqrt 2) (1 - nu^2) p / (pi E)") {
  const Material m{2.1e11, 0.3};
  for (double a : {1e-4, 2.5e-3, 1.0}) {
    const double p = 1e9;
    const double expected = 8 * a * std::log(1 + std::sqrt(2.0)) * (1 - m.nu * m.nu) * p / (std::numbers::pi * m.E);
    CHECK(rectangle_displacement(m, 0, 0, a, a, p) == within_rel(expected, 1e-14));
  }
}

TEST_CASE("Love's closed form agrees with an independent quadrature inside, on edges, at corners, outside") {
  const double a = 0.7e-3, b = 0.3e-3;
  const double points[][2] = {{0, 0},         {0.2e-3, -0.1e-3}, {a, 0},        {0, -b},       {a, b},
                              {-a, b},        {1.5e-3, 0.2e-3},  {-3e-3, 4e-3}, {0.69e-3, 0},  {2e-2, -1e-2},
                              {0.5e-3, 0.3e-3}};
  for (const auto& pt : points) {
    const double exact = rectangle_potential(pt[0], pt[1], a, b);
    const double quad = wrc::test::ray_integral(pt[0], pt[1], a, b, [](double) { return 1.0; });  // 1 / r
    CAPTURE(pt[0]);
    CAPTURE(pt[1]);
    CHECK(exact == within_rel(quad, 1e-11));
  }
}

TEST_CASE("influence function symmetries") {
  const double a = 0.4e-3, b = 0.25e-3;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-3e-3, 3e-3);
  for (int t = 0; t < 100; ++t) {
    const double x = U(rng), y = U(rng);
    const double v = rectangle_potential(x, y, a, b);
    CHECK(v > 0);
    CHECK(rectangle_potential(-x, y, a, b) == within_rel(v, 1e-13));
    CHECK(rectangle_potential(x, -y, a, b) == within_rel(v, 1e-13));
    CHECK(rectangle_potential(y, x, b, a) == within_rel(v, 1e-13));  // transpose
  }
  // Superposition: the 2a x 2b rectangle is the sum of its four quarters.
  for (int t = 0; t < 20; ++t) {
    const double x = U(rng), y = U(rng);
    const double whole = rectangle_potential(x, y, a, b);
    const double quarters = rectangle_potential(x - a / 2, y - b / 2, a / 2, b / 2) +
                            rectangle_potential(x + a / 2, y - b / 2, a / 2, b / 2) +
                            rectangle_potential(x - a / 2, y + b / 2, a / 2, b / 2) +
                            rectangle_potential(x + a / 2, y + b / 2, a / 2, b / 2);
    CHECK(whole == within_rel(quarters, 1e-12));
  }
}

TEST_CASE("far field tends to Boussinesq's point load, with the quadrupole correction") {
  const Material m{2.1e11, 0.3};
  const double a = 0.1e-3, b = 0.1e-3, p = 1e9;
  const double F = 4 * a * b * p;
  double previous = INFINITY;
  for (double r : {5 * a, 20 * a, 80 * a, 320 * a}) {
    const double x = 0.6 * r, y = 0.8 * r;
    const double boussinesq = (1 - m.nu * m.nu) * F / (std::numbers::pi * m.E * r);
    const double u = rectangle_displacement(m, x, y, a, b, p);
    const double relative = std::abs(u / boussinesq - 1);
    CHECK(relative < previous / 10);  // decays like (a/r)^2: 16x per step of 4x
    previous = relative;
    // Second-order multipole term of 1/|r - s| integrated over the rectangle.
    const double quad = (x * x * a * a + y * y * b * b - r * r * (a * a + b * b) / 3) / (2 * std::pow(r, 4));
    CHECK(std::abs(u / boussinesq - 1 - quad) < 10 * std::pow(a / r, 4));
  }
}

TEST_CASE("InfluenceTable holds the coefficients of the grid offsets") {
  const InfluenceTable t(0.2e-3, 0.3e-3, 9, 7);
  for (int n = -6; n <= 6; ++n)
    for (int m = -8; m <= 8; ++m)
      CHECK(t(m, n) == within_rel(rectangle_potential(m * 0.2e-3, n * 0.3e-3, 0.1e-3, 0.15e-3), 1e-13));
  CHECK_THROWS_AS(InfluenceTable(0, 1e-3, 3, 3), wrc::Error);
  CHECK_THROWS_AS(InfluenceTable(1e-3, NAN, 3, 3), wrc::Error);
}

TEST_CASE("FFT sizes: fft_size, and the shapes of least cost") {
  const auto smooth = [](int v) {
    for (int f : {2, 3, 5, 7})
      while (v % f == 0) v /= f;
    return v == 1;
  };
  for (int n = 1; n < 3000; ++n) {
    const int P = fft_size(n);
    CHECK(P >= n);
    CHECK(smooth(P));
    CHECK(P <= std::max(16, n * 6 / 5 + 1));  // at most 1/5 larger
  }
  // fft_shape: at least the sizes asked for, 7-smooth, never more than twice as large (plus 16), and the same for the
  // same question (a fixed table, not a timing).
  for (int nx = 1; nx < 400; nx += 7)
    for (int ny = 1; ny < 400; ny += 11)
      for (bool pruned : {true, false}) {
        const FftShape s = fft_shape(nx, ny, pruned);
        CAPTURE(nx);
        CAPTURE(ny);
        CHECK(s.Mx >= nx);
        CHECK(s.My >= ny);
        CHECK(smooth(s.Mx));
        CHECK(smooth(s.My));
        CHECK(s.Mx <= 2 * nx + 16);
        CHECK(s.My <= 2 * ny + 16);
        const FftShape again = fft_shape(nx, ny, pruned);
        CHECK((again.Mx == s.Mx && again.My == s.My));
      }
  const FftShape big = fft_shape(5000, 3, true);  // beyond the measured lengths: fft_size
  CHECK(big.Mx == fft_size(5000));
  CHECK_THROWS_AS(fft_shape(0, 5, true), wrc::Error);
}

TEST_CASE("FFT product equals the direct product with the influence coefficients") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  InfluenceCache cache;
  ConvolutionWorkspace ws;  // one workspace across shapes: stale data must not leak between them
  const int shapes[][2] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {7, 5}, {16, 16}, {13, 4}, {5, 17}, {24, 11}, {3, 3}};
  for (const auto& sh : shapes) {
    for (double dy : {0.2e-3, 0.35e-3}) {
      Grid g;
      g.nx = sh[0];
      g.ny = sh[1];
      g.dx = 0.2e-3;
      g.dy = dy;
      std::vector<double> p(g.size()), u(g.size());
      for (double& v : p) v = U(rng);
      const auto spectrum = cache.get(g);
      REQUIRE(spectrum->serves(g));
      convolve(*spectrum, g, p.data(), u.data(), ws);
      const auto direct = direct_product(g, p);
      std::vector<double> diff(g.size());
      for (int k = 0; k < g.size(); ++k) diff[k] = u[k] - direct[k];
      CAPTURE(g.nx);
      CAPTURE(g.ny);
      CHECK(max_abs(diff) < 1e-12 * max_abs(direct));
    }
  }
}

TEST_CASE("split columns: FFT products whose column transforms run as two of half the length equal the direct product") {
  // split_columns: pruned, even, and cheaper by the table (two 128-point columns against one 256-point one); not for a
  // full transform, an odd length, or where the table has the whole length cheaper (64 against 2 x 32).
  CHECK(split_columns(256, 129));
  CHECK(split_columns(24, 12));
  CHECK_FALSE(split_columns(24, 24));
  CHECK_FALSE(split_columns(25, 12));
  CHECK_FALSE(split_columns(64, 33));
  // Grids whose data fill fewer rows than half the period, exactly half, and one row more (the normal product's
  // M >= 2 ny - 2 lets offsets +-(ny - 1) share a slot); direct sums as the reference.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  ConvolutionWorkspace ws;
  for (const auto& [nx, ny, My] : {std::array{5, 7, 24}, {5, 12, 24}, {6, 13, 24}, {4, 100, 256}, {3, 129, 256}}) {
    Grid g;
    g.nx = nx;
    g.ny = ny;
    g.dx = 0.2e-3;
    g.dy = 0.35e-3;
    const InfluenceSpectrum s(InfluenceSpectrum::Kind::linear, g.dx, g.dy, 16, My);
    CAPTURE(ny);
    CAPTURE(My);
    REQUIRE(s.fft().split());
    REQUIRE(s.serves(g));
    std::vector<double> p(g.size()), u(g.size());
    for (double& v : p) v = U(rng);
    convolve(s, g, p.data(), u.data(), ws);
    const auto direct = direct_product(g, p);
    std::vector<double> diff(g.size());
    for (int k = 0; k < g.size(); ++k) diff[k] = u[k] - direct[k];
    CHECK(max_abs(diff) < 1e-12 * max_abs(direct));
  }
}

TEST_CASE("split columns: the transforms of data in more than half the period equal a direct DFT") {
  // The products fill at most half the period plus one row, so only the first row pair takes both rows there; data
  // in 20 of 24 rows make pairs 0..7 take both (twiddles other than 1) and 8..11 one. Reference: the DFT summed
  // directly, in the split order (row k: frequency 2k, row 12 + k: 2k + 1).
  const int Mx = 8, My = 24, rows = 20, H = Mx / 2 + 1;
  const PrunedFft f(Mx, My, rows, FftPlanning::estimate);
  REQUIRE(f.split());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<double> x(static_cast<std::size_t>(Mx) * rows);
  for (double& v : x) v = U(rng);
  ConvolutionWorkspace ws;
  ws.prepare(f, Grid::square(Mx, rows, 1e-3));
  std::copy(x.begin(), x.end(), ws.input());
  f.forward(ws.input(), ws.spectrum_buffer(), rows);
  const auto* spec = static_cast<const double*>(ws.spectrum_buffer());
  double worst = 0, largest = 0;
  for (int row = 0; row < My; ++row) {
    const int ky = row < My / 2 ? 2 * row : 2 * (row - My / 2) + 1;
    for (int kx = 0; kx < H; ++kx) {
      double re = 0, im = 0;
      for (int j = 0; j < rows; ++j)
        for (int i = 0; i < Mx; ++i) {
          const double a = -2 * std::numbers::pi * (double(kx) * i / Mx + double(ky) * j / My);
          re += x[i + Mx * j] * std::cos(a), im += x[i + Mx * j] * std::sin(a);
        }
      const double* s = spec + 2 * (kx + H * row);
      worst = std::max({worst, std::abs(s[0] - re), std::abs(s[1] - im)});
      largest = std::max({largest, std::abs(re), std::abs(im)});
    }
  }
  CHECK(worst < 1e-12 * largest);
  // Back: Mx My times the data on the rows asked for.
  f.backward(ws.spectrum_buffer(), ws.output(), rows);
  for (std::size_t q = 0; q < x.size(); ++q) CHECK(ws.output()[q] == within_abs(Mx * My * x[q], 1e-12 * Mx * My));
}

TEST_CASE("the circulants are positive definite (the preconditioner needs it)") {
  InfluenceCache cache;
  for (double ratio : {1.0, 0.5, 2.0, 0.1, 10.0})
    for (int n : {1, 2, 5, 16, 33, 100}) {
      Grid g;
      g.nx = n;
      g.ny = std::max(1, n / 2);
      g.dx = 0.2e-3;
      g.dy = 0.2e-3 * ratio;
      for (auto kind : {InfluenceSpectrum::Kind::linear, InfluenceSpectrum::Kind::periodic}) {
        const auto s = cache.get(g, kind);
        CAPTURE(n);
        CAPTURE(ratio);
        CHECK(s->min_eigenvalue() > 0);
      }
    }
}

TEST_CASE("cache: spectra shared by shape, products identical from several threads") {
  InfluenceCache cache;
  Grid a = Grid::square(30, 20, 0.2e-3), b = Grid::square(32, 19 + 1, 0.2e-3), c = Grid::square(30, 20, 0.25e-3);
  const FftShape sa = fft_shape(2 * 30 - 2, 2 * 20 - 2, true), sb = fft_shape(2 * 32 - 2, 2 * 20 - 2, true);
  REQUIRE((sa.Mx == sb.Mx && sa.My == sb.My));
  CHECK(cache.get(a) == cache.get(b));  // same padded shape
  CHECK(cache.get(a) != cache.get(c));  // another element size
  CHECK(cache.size() == 2);
  CHECK_THROWS_AS(cache.get(Grid{}), wrc::Error);

  std::vector<Grid> grids;
  for (int k = 0; k < 6; ++k) grids.push_back(Grid::square(10 + 7 * k, 30 - 3 * k, 0.2e-3));
  std::vector<std::vector<double>> inputs, expected;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  {
    ConvolutionWorkspace ws;
    for (const Grid& g : grids) {
      std::vector<double> p(g.size()), u(g.size());
      for (double& v : p) v = U(rng);
      convolve(*cache.get(g), g, p.data(), u.data(), ws);
      inputs.push_back(p);
      expected.push_back(u);
    }
  }
  InfluenceCache shared;  // fresh: the threads also race to build the spectra
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      ConvolutionWorkspace ws;
      for (int rep = 0; rep < 20; ++rep)
        for (std::size_t k = 0; k < grids.size(); ++k) {
          const std::size_t which = (k + t + rep) % grids.size();
          std::vector<double> u(grids[which].size());
          convolve(*shared.get(grids[which]), grids[which], inputs[which].data(), u.data(), ws);
          if (u != expected[which]) ++mismatches[t];
        }
    });
  for (auto& th : threads) th.join();
  for (int m : mismatches) CHECK(m == 0);
}

TEST_CASE("FFT plans: built once per shape for the process, shared by new models, exact from several threads") {
  // Two models of the same grids (as the wear loop's wheelsets of each step, each with its own caches): the second
  // builds its spectra but plans nothing, and runs the first one's plans.
  const Material material{2.1e11, 0.3};
  const Grid g = Grid::square(37, 23, 0.17e-3);
  ShearCache first(material), second(material);
  InfluenceCache normal_first, normal_second;
  const auto a = first.get(g, ShearSpectrum::Kind::linear), pa = first.get(g, ShearSpectrum::Kind::periodic);
  const auto na = normal_first.get(g);
  const FftPlanStats after_first = fft_plan_stats();  // the plans of these shapes exist now (built here or before)
  const auto b = second.get(g, ShearSpectrum::Kind::linear), pb = second.get(g, ShearSpectrum::Kind::periodic);
  const auto nb = normal_second.get(g);
  CHECK(a != b);
  CHECK(na != nb);
  CHECK(a->fft().shares_plans(b->fft()));
  CHECK(pa->fft().shares_plans(pb->fft()));
  CHECK(na->fft().shares_plans(nb->fft()));
  CHECK(fft_plan_stats().built == after_first.built);
  CHECK(a->xx() == b->xx());  // the kernel spectra through the shared 2-D plan: the same bits

  // Threads with fresh caches race for the plans of new shapes; each alternates a linear and a periodic spectrum in
  // one workspace (two layouts in one buffer, as the shear products do); the products equal the dense ones.
  std::vector<Grid> grids;
  for (int k = 0; k < 4; ++k) grids.push_back(Grid::square(9 + 5 * k, 21 - 3 * k, 0.13e-3));
  std::vector<std::vector<double>> inputs, dense;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  for (const Grid& gr : grids) {
    inputs.emplace_back(gr.size());
    for (double& v : inputs.back()) v = U(rng);
    dense.push_back(direct_product(gr, inputs.back()));
  }
  std::vector<std::vector<std::vector<double>>> results(4);
  std::vector<int> changed(4, 0);  // products that changed after the workspace served the other layout
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      InfluenceCache cache;
      ConvolutionWorkspace ws;
      for (std::size_t k = 0; k < grids.size(); ++k) {
        const Grid& gr = grids[(k + t) % grids.size()];
        std::vector<double> u(gr.size()), z(gr.size());
        convolve(*cache.get(gr), gr, inputs[(k + t) % grids.size()].data(), u.data(), ws);
        deconvolve(*cache.get(gr, InfluenceSpectrum::Kind::periodic), gr, u.data(), z.data(), ws);
        convolve(*cache.get(gr), gr, inputs[(k + t) % grids.size()].data(), z.data(), ws);  // after the other layout
        if (z != u) ++changed[t];
        results[t].push_back(u);
      }
    });
  for (auto& th : threads) th.join();
  for (int c : changed) CHECK(c == 0);
  for (int t = 0; t < 4; ++t)
    for (std::size_t k = 0; k < grids.size(); ++k) {
      const std::size_t which = (k + t) % grids.size();
      std::vector<double> diff(dense[which].size());
      for (std::size_t q = 0; q < diff.size(); ++q) diff[q] = results[t][k][q] - dense[which][q];
      CHECK(max_abs(diff) < 1e-12 * max_abs(dense[which]));
      CHECK(results[t][k] == results[0][which]);  // the same bits in every thread
    }
}

TEST_CASE("FFT plans: the cache is bounded and plans it dropped still serve their owners") {
  // More row counts of one size than the cache holds: it keeps at most kFftPlanCacheSize sets; the first transform
  // (its set dropped meanwhile) still runs: a forward and backward round trip gives Mx My times the input's rows.
  const int Mx = 6, My = static_cast<int>(kFftPlanCacheSize) + 20;
  std::vector<std::unique_ptr<PrunedFft>> ffts;
  for (int rows = 1; rows <= My; ++rows) ffts.push_back(std::make_unique<PrunedFft>(Mx, My, rows, FftPlanning::estimate));
  CHECK(fft_plan_stats().cached <= kFftPlanCacheSize);
  const PrunedFft again(Mx, My, 1, FftPlanning::estimate);  // dropped: built anew
  CHECK_FALSE(again.shares_plans(*ffts.front()));
  Grid g = Grid::square(Mx / 2, 1, 1e-3);
  for (const PrunedFft* f : {static_cast<const PrunedFft*>(ffts.front().get()), &again}) {
    ConvolutionWorkspace ws;
    ws.prepare(*f, g);
    const double values[] = {0.5, -1.25, 2.0};
    std::copy(values, values + 3, ws.input());
    f->forward(ws.input(), ws.spectrum_buffer(), 1);
    f->backward(ws.spectrum_buffer(), ws.output(), 1);
    for (int i = 0; i < Mx; ++i) CHECK(ws.output()[i] == within_abs(Mx * My * (i < 3 ? values[i] : 0.0), 1e-9 * Mx * My));
  }
}
