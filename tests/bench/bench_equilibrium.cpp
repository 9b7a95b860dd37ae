// Benchmark of the wheelset equilibrium (issue 6) on the paper's case: S1002 on 60E1 at 0.1 mm, 1:40, gauge 1435 mm,
// flange backs 1360 mm, r0 = 0.45 m, E = 210 GPa, nu = 0.3, Q = 200 kN, grid 0.2 mm (the defaults of
// examples/paper_study.lua). Prints:
//   1. the cost of one contact evaluation (tread and flange-root poses, with and without the sensitivities);
//   2. the equilibrium solved cold (no start: rigid position, then the fallbacks) at y = -8 .. 8 mm every 1 mm, both
//      yaws: time, Newton iterations and contact evaluations per case;
//   3. the whole paper sweep (y = -8 .. 8 mm in 0.1 mm steps, 161 points, yaw 0 and 1 deg, with the rigid reference as
//      the study runs it) on 1 and 2 worker threads: wall and CPU time, the speed-up, time, iterations and
//      evaluations per equilibrium, the share of evaluations spent in slowly converging cases, the largest residuals,
//      and the agreement of the 1- and 2-thread results; then the elastic sweep alone and the rigid reference alone.
// The machine is shared: CPU time (getrusage, all threads of the process) is printed beside wall time, and the load
// average before and after. Per-evaluation times are the calling thread's CPU time.
//
//   bench_equilibrium [quick] [grid_mm=0.2] [step_mm=0.1] [threads=2]
//
// `quick` runs a 0.5 mm sweep step and fewer repetitions (a smoke run).
#include "bench/timing.hpp"
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/equilibrium/equilibrium.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

namespace {

using wrc::bench::loadavg;
using wrc::bench::process_cpu_s;
using wrc::bench::thread_cpu_s;
using wrc::bench::wall_s;

struct Args {
  bool quick = false;
  double grid_mm = 0.2, step_mm = 0.1;
  int threads = 2;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "quick") == 0) {
      a.quick = true;
      a.step_mm = 0.5;
      continue;
    }
    const char* eq = std::strchr(argv[i], '=');
    if (!eq) continue;
    const std::string k(argv[i], static_cast<std::size_t>(eq - argv[i]));
    if (k == "grid_mm") a.grid_mm = std::atof(eq + 1);
    else if (k == "step_mm") a.step_mm = std::atof(eq + 1);
    else if (k == "threads") a.threads = std::max(1, std::atoi(eq + 1));
  }
  return a;
}

// Wall and process CPU time of a section.
struct Timer {
  double w0 = wall_s(), c0 = process_cpu_s();
  double wall() const { return wall_s() - w0; }
  double cpu() const { return process_cpu_s() - c0; }
};

struct SweepStats {
  int cases = 0, failed = 0, slow = 0;
  double iterations = 0, evaluations = 0, slow_evaluations = 0, worst_force = 0, worst_moment = 0;
};

SweepStats stats(const wrc::SweepResult& r, double Q) {
  SweepStats s;
  for (const auto& e : r.elastic) {
    ++s.cases;
    if (!e.converged) {
      ++s.failed;
      continue;
    }
    s.iterations += e.iterations;
    s.evaluations += e.evaluations;
    if (e.iterations > 8) {  // linear convergence (poor Jacobian) or fallbacks
      ++s.slow;
      s.slow_evaluations += e.evaluations;
    }
    s.worst_force = std::max(s.worst_force, std::abs(e.residual_force) / Q);
    s.worst_moment = std::max(s.worst_moment, std::abs(e.residual_moment) / Q);
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) try {
  const Args a = parse(argc, argv);
  const double Q = 200e3, deg = std::numbers::pi / 180;
  fmt::print("bench_equilibrium: grid {} mm, sweep step {} mm, {} hardware threads, load average {}\n", a.grid_mm,
             a.step_mm, std::thread::hardware_concurrency(), loadavg());

  // The paper's wheelset, built by Lua as a study script builds it.
  lua_State* L = wrc::lua::new_state();
  const std::string code = fmt::format(
      "local w = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua', {{step = 0.1e-3}})\n"
      "local r = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua', {{step = 0.1e-3}})\n"
      "bench_ws = wrc.wheelset{{wheel = w, rail = r, radius = 0.45, back_to_back = 1.360, gauge = 1.435,\n"
      "  gauge_depth = 0.014, cant = 1 / 40, E = 2.1e11, nu = 0.3, grid = {}}}",
      a.grid_mm * 1e-3);
  if (luaL_dostring(L, code.c_str()) != LUA_OK) {
    std::fprintf(stderr, "%s\n", lua_tostring(L, -1));
    return 1;
  }
  lua_getglobal(L, "bench_ws");
  const std::shared_ptr<const wrc::ContactModel> model =
      wrc::lua::check_wheelset(L, -1, "bench_equilibrium")->contact_model_ptr();
  lua_pop(L, 1);
  auto make_workspace = [&] { return std::make_unique<wrc::ContactWorkspace>(*model); };

  // 1. One contact evaluation.
  {
    fmt::print("\n== one contact evaluation (calling thread's CPU time, mean of repetitions) ==\n");
    auto ws = make_workspace();
    const int reps = a.quick ? 5 : 20;
    for (double y : {3e-3, 6.4e-3}) {
      const wrc::EquilibriumResult e = wrc::solve_equilibrium(*model, {y, 0.0, Q}, *ws);
      for (bool sens : {false, true}) {
        wrc::ContactRequest req;
        req.sensitivity = sens;
        req.keep_grids = false;
        double t = 0;
        std::size_t elements = 0;
        for (int r = 0; r < reps; ++r) {
          const double t0 = thread_cpu_s();
          // A slightly different pose each time, as in a Newton iteration (the warm start stays useful).
          const wrc::ContactResult c = wrc::evaluate_contact(*model, {y, e.z - 1e-8 * r, e.roll, 0.0}, *ws, req);
          t += thread_cpu_s() - t0;
          elements = 0;
          for (const auto& w : c.wheel)
            for (const auto& p : w.patches) elements += static_cast<std::size_t>(p.solution.grid.nx) * p.solution.grid.ny;
        }
        fmt::print("y = {:.1f} mm at its equilibrium{}: {:7.2f} ms ({} potential contact elements)\n", y * 1e3,
                   sens ? ", with sensitivities" : "                   ", t / reps * 1e3, elements);
      }
    }
  }

  // 2. Cold equilibria.
  {
    fmt::print("\n== equilibrium from scratch (no start: rigid position pressed in, then the fallbacks) ==\n");
    auto ws = make_workspace();
    int n = 0, failed = 0, max_eval = 0;
    double t = 0, it = 0, ev = 0, worst_t = 0, worst_y = 0, worst_yaw = 0;
    for (double yaw : {0.0, deg}) {
      for (int k = -8; k <= 8; k += (a.quick ? 4 : 1)) {
        const double y = k * 1e-3;
        const double t0 = thread_cpu_s();
        const wrc::EquilibriumResult e = wrc::solve_equilibrium(*model, {y, yaw, Q}, *ws);
        const double dt = thread_cpu_s() - t0;
        ++n;
        if (!e.converged) ++failed;
        t += dt;
        it += e.iterations;
        ev += e.evaluations;
        if (dt > worst_t) worst_t = dt, worst_y = y, worst_yaw = yaw;
        max_eval = std::max(max_eval, e.evaluations);
      }
    }
    fmt::print("{} cases (y = -8 .. 8 mm, yaw 0 and 1 deg), {} failed: {:.1f} ms per equilibrium (CPU), {:.1f} Newton "
               "iterations (last Newton run) and {:.1f} contact evaluations per case; slowest {:.0f} ms at y = {:.0f} mm, "
               "yaw {:.0f} deg; most evaluations {}\n",
               n, failed, t / n * 1e3, it / n, ev / n, worst_t * 1e3, worst_y * 1e3, worst_yaw / deg, max_eval);
  }

  // 3. The paper sweep.
  std::vector<double> ys;
  const int half = static_cast<int>(std::lround(8.0 / a.step_mm));
  for (int i = -half; i <= half; ++i) ys.push_back(i * a.step_mm * 1e-3);
  const std::vector<double> yaws{0.0, deg};
  fmt::print("\n== the paper sweep: {} y values x {} yaws = {} cases, continuation along y ==\n", ys.size(), yaws.size(),
             ys.size() * yaws.size());
  std::vector<wrc::SweepResult> runs;
  std::vector<int> thread_counts{1};
  if (a.threads > 1) thread_counts.push_back(a.threads);
  std::vector<double> walls;
  for (int threads : thread_counts) {
    wrc::SweepOptions so;
    so.Q = Q;
    so.threads = threads;
    so.rigid = true;
    const Timer timer;
    runs.push_back(wrc::run_sweep(*model, ys, yaws, so, make_workspace));
    const double wall = timer.wall(), cpu = timer.cpu();
    walls.push_back(wall);
    const SweepStats s = stats(runs.back(), Q);
    fmt::print("{} thread{}: wall {:6.2f} s, CPU {:6.2f} s (CPU / wall {:.2f}); per case {:.1f} ms CPU, {:.2f} Newton "
               "iterations, {:.2f} evaluations; {} failed; largest residuals {:.1e} Q, {:.1e} Q m; {} slow cases "
               "(> 8 iterations) took {:.0f} % of the evaluations; load average {}\n",
               threads, threads > 1 ? "s" : " ", wall, cpu, cpu / wall, cpu / s.cases * 1e3, s.iterations / s.cases,
               s.evaluations / s.cases, s.failed, s.worst_force, s.worst_moment, s.slow,
               100 * s.slow_evaluations / std::max(1.0, s.evaluations), loadavg());
  }
  if (runs.size() == 2) {
    double dz = 0, droll = 0;
    for (std::size_t i = 0; i < runs[0].elastic.size(); ++i) {
      dz = std::max(dz, std::abs(runs[0].elastic[i].z - runs[1].elastic[i].z));
      droll = std::max(droll, std::abs(runs[0].elastic[i].roll - runs[1].elastic[i].roll));
    }
    fmt::print("speed-up {} threads / 1 thread (wall): {:.2f}; 1- vs {}-thread results differ by at most {:.1e} m in z, "
               "{:.1e} rad in roll\n",
               a.threads, walls[0] / walls[1], a.threads, dz, droll);
  }
  {
    // The parts: the elastic sweep alone, the rigid reference alone.
    wrc::SweepOptions so;
    so.Q = Q;
    so.threads = a.threads;
    const Timer timer;
    const wrc::SweepResult r = wrc::run_sweep(*model, ys, yaws, so, make_workspace);
    fmt::print("elastic only, {} threads: wall {:.2f} s, CPU {:.2f} s\n", a.threads, timer.wall(), timer.cpu());
    const Timer rigid_timer;
    double per_yaw[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const double t0 = thread_cpu_s();
      for (double y : ys) wrc::solve_rigid(model->geometry(), y, yaws[k], Q);
      per_yaw[k] = (thread_cpu_s() - t0) / ys.size();
    }
    fmt::print("rigid reference only, 1 thread: wall {:.2f} s, CPU {:.2f} s ({:.1f} ms per case at yaw 0, {:.1f} ms at "
               "yaw 1 deg)\n",
               rigid_timer.wall(), rigid_timer.cpu(), per_yaw[0] * 1e3, per_yaw[1] * 1e3);
  }
  fmt::print("\nload average at the end: {}\n", loadavg());
  lua_close(L);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_equilibrium: %s\n", e.what());
  return 1;
}
