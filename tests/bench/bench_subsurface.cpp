// Benchmark of the subsurface stresses (halfspace/subsurface.hpp): time per depth on wheel-rail patches of 0.2 mm
// elements, the FFT and the direct sum in the same run, with and without traction, with and without the field grids.
//
//   bench_subsurface [reps=5] [quick]
//
// The patches: an elliptic Hertz pressure (p0 = 1.2 GPa) filling a 60 x 40 grid (12 x 8 mm, the tread patch of a
// 100 kN wheel) and a 200 x 100 grid (40 x 20 mm, a long conformal patch), with the traction of a braking wheel
// (0.3 p in x over the trailing 60 %, a linear rise before it). Times are CPU time of the calling thread (one core),
// the median of `reps` calls (the machine is shared); per depth = the call's time over its depths.
#include "bench/timing.hpp"
#include "wrc/halfspace/subsurface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace wrc::halfspace;

using wrc::bench::cpu_ms;
using wrc::bench::median_ms;

namespace {

struct Patch {
  Grid grid;
  std::vector<double> p, px;
  int loaded = 0;
};

// A Hertz ellipse filling the grid but for a border of one element, with a braking traction.
Patch patch(int nx, int ny) {
  Patch s;
  s.grid = Grid::square(nx, ny, 0.2e-3);
  const double a = 0.5 * (nx - 2) * 0.2e-3, b = 0.5 * (ny - 2) * 0.2e-3, p0 = 1.2e9;
  s.p.assign(s.grid.size(), 0.0);
  s.px.assign(s.grid.size(), 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = s.grid.x(i), y = s.grid.y(j), t = 1 - x * x / (a * a) - y * y / (b * b);
      if (t <= 0) continue;
      const int k = s.grid.index(i, j);
      s.p[k] = p0 * std::sqrt(t);
      const double edge = a * std::sqrt(1 - y * y / (b * b));  // the leading edge at +edge
      const double share = std::min(1.0, (edge - x) / (0.8 * edge));  // adhesion rises from the leading edge
      s.px[k] = 0.3 * s.p[k] * share;
      ++s.loaded;
    }
  return s;
}

std::vector<double> depths(int n) {
  std::vector<double> z;
  for (int k = 1; k <= n; ++k) z.push_back(k * 0.5e-3);  // 0.5 .. n x 0.5 mm
  return z;
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "reps=", 5) == 0) reps = std::max(1, std::atoi(argv[i] + 5));
    if (std::strcmp(argv[i], "quick") == 0) quick = true;
  }
  const Material steel{2.1e11, 0.3};
  fmt::print("subsurface stresses: ms per depth (CPU, one thread, median of {} calls)\n", reps);
  fmt::print("{:>9} {:>7} {:>9} | {:>9} {:>9} {:>7} | {:>9} {:>9} | {:>7}\n", "grid", "loaded", "traction", "fft",
             "direct", "direct/", "fft", "auto", "auto");
  fmt::print("{:>9} {:>7} {:>9} | {:>9} {:>9} {:>7} | {:>9} {:>9} | {:>7}\n", "", "", "", "", "", "fft", "no grids",
             "", "chose");
  for (const auto& [nx, ny] : {std::pair{60, 40}, std::pair{200, 100}}) {
    const Patch s = patch(nx, ny);
    for (const bool traction : {false, true}) {
      const SurfaceLoad load{s.grid, s.p, traction ? std::span<const double>(s.px) : std::span<const double>()};
      const auto time = [&](SubsurfaceMethod m, int n, bool fields, int r) {
        SubsurfaceRequest rq;
        rq.z = depths(n);
        rq.method = m;
        rq.fields = fields;
        return median_ms(r, [&] { compute_subsurface(steel, load, rq); }) / n;
      };
      const bool large = nx * ny > 10000;
      const int nfft = quick ? 2 : 10, ndirect = 1, rdirect = large || quick ? 1 : reps;
      const double fft = time(SubsurfaceMethod::fft, nfft, true, reps);
      const double direct = time(SubsurfaceMethod::direct, ndirect, true, rdirect);
      const double bare = time(SubsurfaceMethod::fft, nfft, false, reps);
      const double automatic = time(SubsurfaceMethod::automatic, nfft, true, reps);
      SubsurfaceRequest rq;
      rq.z = {1e-3};
      rq.fields = false;
      const SubsurfaceMethod chose = compute_subsurface(steel, load, rq).method;
      fmt::print("{:>9} {:>7} {:>9} | {:>9.2f} {:>9.1f} {:>7.1f} | {:>9.2f} {:>9.2f} | {:>7}\n",
                 fmt::format("{}x{}", nx, ny), s.loaded, traction ? "yes" : "no", fft, direct, direct / fft, bare,
                 automatic, method_name(chose));
    }
  }
  // The cost of the choice: small grids, where the direct sum may win.
  fmt::print("\nsmall grids (traction on): ms per depth\n{:>9} {:>9} {:>9} {:>7}\n", "grid", "fft", "direct", "auto chose");
  for (const int n : {6, 10, 16, 24, 32}) {
    const Patch s = patch(n, n);
    const SurfaceLoad load{s.grid, s.p, s.px};
    const auto time = [&](SubsurfaceMethod m) {
      SubsurfaceRequest rq;
      rq.z = depths(10);
      rq.method = m;
      return median_ms(reps, [&] { compute_subsurface(steel, load, rq); }) / 10;
    };
    SubsurfaceRequest rq;
    rq.z = {1e-3};
    fmt::print("{:>9} {:>9.3f} {:>9.3f} {:>7}\n", fmt::format("{}x{}", n, n), time(SubsurfaceMethod::fft),
               time(SubsurfaceMethod::direct), method_name(compute_subsurface(steel, load, rq).method));
  }
  return 0;
}
