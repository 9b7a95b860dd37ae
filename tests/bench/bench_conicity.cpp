// Benchmark of the equivalent conicity of a Δr table (wrc.conicity) against the table's length: a measured-looking Δr
// (a cone of 0.05 with a ripple, -10 .. 10 mm) at 2001, 4001 and 8001 points, 20 amplitudes 0.5 .. 5 mm, each method.
// Prints this thread's CPU time per call (median of `runs`) and, per method, the ratio of the longest table's time to
// the shortest's: 4 for 4x the points is linear growth, 16 quadratic.
//
//   bench_conicity [runs=5]
#include "bench/timing.hpp"
#include "wrc/kinematics/conicity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using wrc::bench::cpu_ms;

wrc::DeltaRFunction ripple_table(int n) {
  wrc::DeltaRFunction d;
  for (int i = 0; i < n; ++i) {
    const double y = -10e-3 + 20e-3 * i / (n - 1);
    d.y.push_back(y);
    d.dr.push_back(2 * 0.05 * y + 1e-3 * std::sin(3000 * y) * y);
  }
  return d;
}

double median_ms(int runs, const wrc::DeltaRFunction& d, const wrc::ConicityOptions& o, double& tan_mid) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const double t0 = cpu_ms();
    const wrc::ConicityResult res = wrc::equivalent_conicity(d, o);
    t.push_back(cpu_ms() - t0);
    tan_mid = res.tan_gamma[res.tan_gamma.size() / 2];
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) try {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const std::vector<int> sizes{2001, 4001, 8001};
  wrc::ConicityOptions o;
  for (int k = 0; k < 20; ++k) o.yhat.push_back(0.5e-3 + 4.5e-3 * k / 19);
  fmt::print("wrc.conicity, 20 amplitudes 0.5 .. 5 mm, this thread's CPU ms per call (median of {})\n", runs);
  fmt::print("{:>11} {:>8} {:>12} {:>16}\n", "method", "points", "ms", fmt::format("tan at {:.2f} mm", o.yhat[10] * 1e3));
  for (const wrc::ConicityMethod m : {wrc::ConicityMethod::integral, wrc::ConicityMethod::harmonic}) {
    o.method = m;
    std::vector<double> ms;
    for (const int n : sizes) {
      double tan = 0;
      ms.push_back(median_ms(runs, ripple_table(n), o, tan));
      fmt::print("{:>11} {:>8} {:>12.2f} {:>16.6f}\n", wrc::to_string(m), n, ms.back(), tan);
    }
    fmt::print("{:>11} growth {} -> {} points: x{:.1f} (x4 linear, x16 quadratic)\n", wrc::to_string(m), sizes.front(),
               sizes.back(), ms.back() / ms.front());
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_conicity: %s\n", e.what());
  return 1;
}
