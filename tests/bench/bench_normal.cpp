// Benchmark of the normal contact solvers: time per solve against the number of potential elements, dense
// vs fast in the same run, CG iteration counts, what the preconditioner and the nested start gain, the FFT
// library choice, and the Hertz convergence table. Times are CPU time of the calling thread (one core),
// best of several repetitions (the machine is shared); `quick` as first argument runs a shorter version.
#include "bench/timing.hpp"
#include "halfspace/hertz_reference.hpp"
#include "halfspace/materials.hpp"
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/convolution.hpp"
#include "wrc/halfspace/normal.hpp"

#include <fftw3.h>
#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace wrc::halfspace;
using namespace wrc::test;

using wrc::bench::cpu_ms;

namespace {

// Best CPU time (ms) of `reps` runs of f, at least `min_ms` of total work.
double best_ms(const std::function<void()>& f, int reps, double min_ms = 50) {
  double best = INFINITY, total = 0;
  for (int r = 0; r < reps || total < min_ms; ++r) {
    const double t0 = cpu_ms();
    f();
    const double t = cpu_ms() - t0;
    best = std::min(best, t);
    total += t;
    if (r > 1000) break;
  }
  return best;
}

// A potential contact area of about n elements (0.2 mm squares) as the bridge from a patch builds it: the
// inter-penetration area plus a 2-element margin. kind 0: Hertz-like ellipse (B/A = 2.25); kind 1:
// non-Hertzian, two overlapping lobes of different depth with a tilt.
NormalCase patch_case(int n, int kind) {
  const double element = 0.2e-3;
  const int ny = std::max(3, static_cast<int>(std::lround(std::sqrt(n / 1.5))));
  const int nx = std::max(3, static_cast<int>(std::lround(static_cast<double>(n) / ny)));
  NormalCase c{Grid::square(nx, ny, element), std::vector<double>(static_cast<std::size_t>(nx) * ny)};
  const double X = 0.5 * (nx - 4) * element, Y = 0.5 * (ny - 4) * element;  // inter-penetration half-axes
  const double delta = 20e-6;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = c.grid.x(i), y = c.grid.y(j);
      double h;
      if (kind == 0) {
        h = delta * (1 - x * x / (X * X) - y * y / (Y * Y));
      } else {
        const double x1 = x + 0.35 * X, x2 = x - 0.45 * X;
        const double h1 = delta * (1 - x1 * x1 / std::pow(0.65 * X, 2) - y * y / (Y * Y)) + 2e-3 * x;
        const double h2 = 0.6 * delta * (1 - x2 * x2 / std::pow(0.55 * X, 2) - std::pow(y - 0.2 * Y, 2) / std::pow(0.7 * Y, 2));
        h = std::max(h1, h2);
      }
      c.h[c.grid.index(i, j)] = h;
    }
  return c;
}

void fft_choice() {
  fmt::print("\n== FFT library: one convolution round trip (forward + pointwise product + backward) ==\n");
  fmt::print("{:>7} {:>6} | {:>12} {:>12} | {:>12} {:>12} | {:>12} | {:>8}\n", "n", "M", "FFTW est ms", "plan ms",
             "FFTW meas ms", "plan ms", "Eigen ms", "Eigen/est");
  for (int n : {1000, 10000, 100000}) {
    const int side = static_cast<int>(std::sqrt(n));
    const Grid g = Grid::square(side, side, 0.2e-3);
    std::vector<double> p(g.size(), 1.0), u(g.size());
    double t_est = 0, t_meas = 0, plan_est = 0, plan_meas = 0;
    int M = 0;
    for (FftPlanning planning : {FftPlanning::estimate, FftPlanning::measure}) {
      const double t0 = cpu_ms();
      const FftShape shape = fft_shape(2 * g.nx - 2, 2 * g.ny - 2, true);
      const InfluenceSpectrum s(InfluenceSpectrum::Kind::linear, g.dx, g.dy, shape.Mx, shape.My, planning);
      const double plan = cpu_ms() - t0;
      ConvolutionWorkspace ws;
      const double t = best_ms([&] { convolve(s, g, p.data(), u.data(), ws); }, 20);
      M = s.Mx();
      (planning == FftPlanning::estimate ? t_est : t_meas) = t;
      (planning == FftPlanning::estimate ? plan_est : plan_meas) = plan;
    }
    // Eigen's FFT module (its default kissfft back end), the same padded round trip: rows then columns.
    Eigen::FFT<double> fft;
    std::vector<double> row(M);
    std::vector<std::complex<double>> crow(M), col(M), col2(M), S(static_cast<std::size_t>(M) * M);
    const double t_eigen = best_ms(
        [&] {
          for (int j = 0; j < M; ++j) {
            for (int i = 0; i < M; ++i) row[i] = i < side && j < side ? p[i + side * j] : 0.0;
            fft.fwd(crow, row);
            std::copy(crow.begin(), crow.end(), S.begin() + static_cast<std::ptrdiff_t>(M) * j);
          }
          for (int i = 0; i < M; ++i) {
            for (int j = 0; j < M; ++j) col[j] = S[i + static_cast<std::size_t>(M) * j];
            fft.fwd(col2, col);
            for (auto& v : col2) v *= 0.5;
            fft.inv(col, col2);
            for (int j = 0; j < M; ++j) S[i + static_cast<std::size_t>(M) * j] = col[j];
          }
          for (int j = 0; j < side; ++j) {
            std::copy(S.begin() + static_cast<std::ptrdiff_t>(M) * j, S.begin() + static_cast<std::ptrdiff_t>(M) * (j + 1),
                      crow.begin());
            fft.inv(row, crow);
            for (int i = 0; i < side; ++i) u[i + side * j] = row[i];
          }
        },
        3);
    fmt::print("{:>7} {:>6} | {:12.4f} {:12.1f} | {:12.4f} {:12.1f} | {:12.4f} | {:8.1f}\n", g.size(), M, t_est, plan_est,
               t_meas, plan_meas, t_eigen, t_eigen / t_est);
  }
}

void solve_times(bool quick) {
  fmt::print("\n== Time per normal solve (CPU ms, one core) vs potential elements ==\n");
  fmt::print("fast: CG + FFT, FFTW_ESTIMATE plans, spectra cached (first solve of a shape separately);\n");
  fmt::print("it = CG iterations on the grid (+ on the coarser grids of the nested start), prod = FFT round trips\n");
  fmt::print("meas ms: the same with FFTW_MEASURE plans (planned once per shape, not included)\n");
  fmt::print("{:>7} {:>9} {:>5} | {:>9} {:>9} {:>12} {:>5} | {:>7} {:>10} {:>8} | {:>8} {:>9} {:>8}\n", "n", "grid",
             "case", "control", "fast ms", "it (coarse)", "prod", "meas ms", "1st ms", "ns/nlogn", "dense ms",
             "dense it", "ratio");
  const NormalSolver solver(steel);
  const NormalSolver measured(steel, FftPlanning::measure);
  NormalWorkspace ws;
  std::vector<int> sizes = {1000, 3000, 10000, 50000, 100000};
  if (quick) sizes = {1000, 3000, 10000};
  for (int n : sizes)
    for (int kind : {0, 1}) {
      const NormalCase c = patch_case(n, kind);
      const NormalSolution reference = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
      for (bool force : {false, true}) {
        const NormalLoad load = force ? NormalLoad::normal_force(0.8 * reference.force) : NormalLoad::penetration();
        const NormalSolver fresh(steel);
        NormalWorkspace fresh_ws;
        const double t0 = cpu_ms();
        fresh.solve(c.grid, c.h, load, fresh_ws);
        const double first = cpu_ms() - t0;
        NormalSolution s;
        const double t = best_ms([&] { s = solver.solve(c.grid, c.h, load, ws); }, n > 30000 ? 4 : 15, 200);
        measured.solve(c.grid, c.h, load, ws);  // plans
        const double tm = best_ms([&] { measured.solve(c.grid, c.h, load, ws); }, n > 30000 ? 4 : 15, 200);
        const int N = c.grid.size();
        std::string dense = "-", dense_it = "-", ratio = "-";
        if (N <= 3500 && !(quick && N > 1500)) {
          NormalSolution d;
          const double td = best_ms([&] { d = solve_normal_dense(steel, c.grid, c.h, load); }, 1, 0);
          dense = fmt::format("{:.1f}", td);
          dense_it = fmt::format("{}", d.iterations);
          ratio = fmt::format("{:.0f}", td / t);
        }
        fmt::print("{:>7} {:>9} {:>5} | {:>9} {:9.3f} {:>12} {:5} | {:7.3f} {:10.1f} {:8.2f} | {:>8} {:>9} {:>8}\n", N,
                   fmt::format("{}x{}", c.grid.nx, c.grid.ny), kind == 0 ? "Hertz" : "2lobe",
                   force ? "force" : "penetr.", t, fmt::format("{} ({})", s.iterations, s.coarse_iterations),
                   s.products + s.coarse_products, tm, first, t * 1e6 / (N * std::log2(N)), dense, dense_it, ratio);
      }
    }
  fmt::print("targets: 3,000 elements < 2 ms, 50,000 < 150 ms; ns/nlogn constant = N log N growth\n");
}

void variants(bool quick) {
  fmt::print("\n== What the preconditioner and the nested start gain (prescribed penetration, Hertz-like) ==\n");
  fmt::print("{:>7} | {:>22} | {:>22} | {:>22} | {:>22}\n", "n", "plain CG  it / ms", "+precond  it / ms",
             "+nested  it(coarse)/ms", "warm start  it / ms");
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  std::vector<int> sizes = {1000, 3000, 10000, 50000, 100000};
  if (quick) sizes = {1000, 3000};
  for (int n : sizes) {
    const NormalCase c = patch_case(n, 0);
    std::string cells[4];
    NormalSolution base;
    for (int v = 0; v < 4; ++v) {
      NormalOptions o;
      o.precondition = v >= 1;
      o.nested = v >= 2;
      NormalCase shifted = c;
      if (v == 3) {  // warm start from the solution of a nearby pose (h + 0.2 um + 1e-5 x, a Newton step)
        o.initial_pressure = base.pressure;
        for (std::size_t k = 0; k < shifted.h.size(); ++k) shifted.h[k] += 0.2e-6 + 1e-5 * shifted.grid.x(k % shifted.grid.nx);
      }
      NormalSolution s;
      const double t = best_ms([&] { s = solver.solve(shifted.grid, shifted.h, NormalLoad::penetration(), ws, o); },
                               n > 30000 ? 3 : 10, 100);
      if (v == 2) base = s;
      cells[v] = v == 2 ? fmt::format("{} ({}) / {:.3f}", s.iterations, s.coarse_iterations, t)
                        : fmt::format("{} / {:.3f}", s.iterations, t);
    }
    fmt::print("{:>7} | {:>22} | {:>22} | {:>22} | {:>22}\n", c.grid.size(), cells[0], cells[1], cells[2], cells[3]);
  }
}

void response_times() {
  fmt::print("\n== Linearised response (uniform approach and tilt) on the contact set ==\n");
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  for (int n : {3000, 50000}) {
    const NormalCase c = patch_case(n, 0);
    const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
    std::vector<double> up(c.grid.size(), 1.0), tilt(c.grid.size());
    for (int k = 0; k < c.grid.size(); ++k) tilt[k] = c.grid.x(k % c.grid.nx);
    NormalResponse r;
    const double t1 = best_ms([&] { r = solver.response(s, up, ws); }, 5);
    const int it1 = r.iterations;
    const double t2 = best_ms([&] { r = solver.response(s, tilt, ws); }, 5);
    fmt::print("{:>7} elements: uniform {:.3f} ms ({} it), tilt {:.3f} ms ({} it)\n", c.grid.size(), t1, it1, t2,
               r.iterations);
  }
}

void hertz_convergence(bool quick) {
  fmt::print("\n== Hertz convergence (prescribed penetration): errors vs elements on the minor semi-axis ==\n");
  fmt::print("{:>5} {:>6} {:>10} | {:>9} {:>9} {:>9} {:>9} {:>9}\n", "B/A", "el/b", "grid", "F err %", "p0 err %",
             "a err el", "b err el", "L2 err %");
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  const double A = 1 / (2 * 0.45), delta = 15e-6;
  for (double q : {1.0, 5.0, 10.0}) {
    const HertzReference hz = hertz_from_approach(A, q * A, steel.combined_modulus(), delta);
    for (int per_b : {4, 8, 16, 32, 64}) {
      if (quick && per_b > 16) continue;
      const double element = std::min(hz.a, hz.b) / per_b * 1.013;
      const NormalCase c = paraboloid_case(A, q * A, delta, element);
      const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
      double amax = 0, bmax = 0, num = 0, den = 0;
      for (int j = 0; j < c.grid.ny; ++j)
        for (int i = 0; i < c.grid.nx; ++i) {
          const double x = c.grid.x(i), y = c.grid.y(j), p = s.pressure[c.grid.index(i, j)];
          if (p > 0) amax = std::max(amax, std::abs(x) + 0.5 * element), bmax = std::max(bmax, std::abs(y) + 0.5 * element);
          const double t = 1 - x * x / (hz.a * hz.a) - y * y / (hz.b * hz.b);
          const double ph = t > 0 ? hz.p0 * std::sqrt(t) : 0.0;
          num += (p - ph) * (p - ph);
          den += ph * ph;
        }
      fmt::print("{:5.0f} {:6} {:>10} | {:+9.4f} {:+9.4f} {:+9.2f} {:+9.2f} {:9.4f}\n", q, per_b,
                 fmt::format("{}x{}", c.grid.nx, c.grid.ny), 100 * (s.force / hz.force - 1),
                 100 * (s.max_pressure / hz.p0 - 1), (amax - hz.a) / element, (bmax - hz.b) / element,
                 100 * std::sqrt(num / den));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::string(argv[1]) == "quick";
  fmt::print("bench_normal: Kalker's normal problem on a regular grid, E = {} Pa, nu = {}\n", steel.E, steel.nu);
  fft_choice();
  solve_times(quick);
  variants(quick);
  response_times();
  hertz_convergence(quick);
  return 0;
}
