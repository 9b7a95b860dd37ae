// Benchmark of the dense reference normal solver (solve_normal_dense): time, memory and active-set iterations
// against the number of elements in contact, on Hertz cases (h = delta - A x^2 - B y^2, B/A = 3, the grid refined
// for more elements), both controls, cold (the paper's start {h > 0}) and warm (from the solution of a pose 1 %
// deeper, as an equilibrium's next evaluation), and the linearised response. Times are CPU time of the calling
// thread, one run each (a dense solve of thousands of elements takes seconds); memory is the active block's (8 m^2
// bytes for m active elements, the largest block of the solve) and the process's peak resident size.
// Arguments: `max=N` the largest contact in elements (default 4000; 8000 shows the refusal beyond kDenseMaxElements),
// `fast` also times the fast solver.
#include "bench/timing.hpp"
#include "halfspace/hertz_reference.hpp"
#include "halfspace/materials.hpp"
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/core/error.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace wrc::halfspace;
using namespace wrc::test;
using wrc::bench::cpu_ms;

namespace {

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // kB on Linux
}

}  // namespace

int main(int argc, char** argv) {
  int max_contact = 4000;
  bool with_fast = false;
  for (int a = 1; a < argc; ++a) {
    const std::string s = argv[a];
    if (s.rfind("max=", 0) == 0) max_contact = std::stoi(s.substr(4));
    if (s == "fast") with_fast = true;
  }
  const double A = 1 / (2 * 0.45), B = 3 * A, delta = 15e-6;
  const HertzReference hz = hertz_from_approach(A, B, steel.combined_modulus(), delta);
  fmt::print("bench_dense: solve_normal_dense on Hertz cases B/A = 3, delta = {} um, E = {} Pa (CPU ms, one core)\n",
             delta * 1e6, steel.E);
  fmt::print("m0 = elements of {{h > 0}} (the cold start's first block), block MB = 8 m0^2 / 1e6, it = active-set "
             "iterations;\nforce: prescribed 1.01 x the cold solve's force; warm: 1 % deeper, from the cold pressure; "
             "resp: one linearised response; RSS: the process's peak so far\n");
  fmt::print("{:>7} {:>8} {:>6} {:>6} {:>8} | {:>8} {:>3} | {:>8} {:>3} | {:>8} {:>3} | {:>8} | {:>7} {:>7}{}\n",
             "contact", "grid", "el um", "m0", "block MB", "cold ms", "it", "force ms", "it", "warm ms", "it", "resp ms",
             "F err %", "RSS MB", with_fast ? " fast ms" : "");
  const NormalSolver fast(steel);
  NormalWorkspace ws;
  for (int target : {200, 500, 1000, 2000, 4000, 8000}) {
    if (target > max_contact) break;
    const double element = std::sqrt(std::numbers::pi * hz.a * hz.b / target);
    const NormalCase c = paraboloid_case(A, B, delta, element);
    const int m0 = static_cast<int>(std::count_if(c.h.begin(), c.h.end(), [](double h) { return h > 0; }));
    NormalSolution s, f, w;
    double t0 = cpu_ms();
    try {
      s = solve_normal_dense(steel, c.grid, c.h, NormalLoad::penetration());
    } catch (const wrc::Error& e) {  // beyond kDenseMaxElements: refused at once
      fmt::print("~{:6} {:>8} {:6.1f} {:6}: refused in {:.3f} ms: {}\n", target,
                 fmt::format("{}x{}", c.grid.nx, c.grid.ny), element * 1e6, m0, cpu_ms() - t0, e.what());
      continue;
    }
    const double cold = cpu_ms() - t0;
    t0 = cpu_ms();
    f = solve_normal_dense(steel, c.grid, c.h, NormalLoad::normal_force(1.01 * s.force));
    const double force = cpu_ms() - t0;
    NormalCase deeper = c;  // the next evaluation of an equilibrium: 1 % deeper, warm from this solution
    for (double& h : deeper.h) h += 0.01 * delta;
    NormalOptions o;
    o.initial_pressure = s.pressure;
    t0 = cpu_ms();
    w = solve_normal_dense(steel, deeper.grid, deeper.h, NormalLoad::penetration(), o);
    const double warm = cpu_ms() - t0;
    std::vector<double> up(c.grid.size(), 1.0);
    t0 = cpu_ms();
    normal_response_dense(steel, s, up);
    const double resp = cpu_ms() - t0;
    std::string fast_ms;
    if (with_fast) {
      t0 = cpu_ms();
      fast.solve(c.grid, c.h, NormalLoad::penetration(), ws);
      fast_ms = fmt::format(" {:7.2f}", cpu_ms() - t0);
    }
    fmt::print("{:7} {:>8} {:6.1f} {:6} {:8.1f} | {:8.1f} {:3} | {:8.1f} {:3} | {:8.1f} {:3} | {:8.1f} | {:+7.3f} {:7.0f}{}\n",
               s.elements_in_contact, fmt::format("{}x{}", c.grid.nx, c.grid.ny), element * 1e6, m0,
               dense_block_bytes(m0) / 1e6, cold, s.iterations, force, f.iterations, warm, w.iterations, resp,
               100 * (s.force / hz.force - 1), peak_rss_mb(), fast_ms);
    std::fflush(stdout);
  }
  return 0;
}
