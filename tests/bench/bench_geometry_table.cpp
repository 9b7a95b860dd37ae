// Benchmark of the rigid contact geometry table (issue 11) on the paper's wheelset: S1002 on 60E1 at 0.1 mm, 1:40,
// gauge 1435 mm, flange backs 1360 mm, r0 = 0.45 m, the default strategy. Prints:
//   1. one rigid solve at yaw 0 (the calling thread's CPU time, mean of repetitions): cold (no start, as ws:rigid is
//      called on its own) and from the neighbouring row's solution (continuation), roll free and fixed;
//   2. the 401-row table y = -10 .. 10 mm every 0.05 mm on ONE thread (the target: under 0.1 s): roll free and roll
//      fixed, best and median of N runs of thread CPU time, rows per second, the jumps found; and, in the same run,
//      the same 401 rows as independent cold solves (what a script calling ws:rigid in a loop gets), with the ratio;
//   3. the same table on 2 threads (wall time) and at yaw 1 deg (the general 3-D path, 1 thread).
//
//   bench_geometry_table [runs=7]
#include "bench/timing.hpp"
#include "lua/bindings.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/kinematics/table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
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
using wrc::bench::thread_cpu_s;
using wrc::bench::wall_s;

struct Stats {
  double best = 0, median = 0;
};

Stats summarise(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v.front(), v[v.size() / 2]};
}

// Thread CPU time of f() over `runs` runs.
template <class F>
Stats timed(int runs, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const double t0 = thread_cpu_s();
    f();
    t.push_back(thread_cpu_s() - t0);
  }
  return summarise(t);
}

}  // namespace

int main(int argc, char** argv) try {
  int runs = 7;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "runs=", 5) == 0) runs = std::max(1, std::atoi(argv[i] + 5));
  fmt::print("bench_geometry_table: {} runs, {} hardware threads, load average {}\n", runs,
             std::thread::hardware_concurrency(), loadavg());

  lua_State* L = wrc::lua::new_state();
  const char* code =
      "local w = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua', {step = 0.1e-3})\n"
      "local r = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua', {step = 0.1e-3})\n"
      "bench_ws = wrc.wheelset{wheel = w, rail = r}";
  if (luaL_dostring(L, code) != LUA_OK) {
    std::fprintf(stderr, "%s\n", lua_tostring(L, -1));
    return 1;
  }
  lua_getglobal(L, "bench_ws");
  const auto ws = wrc::lua::check_wheelset(L, -1, "bench_geometry_table");
  lua_pop(L, 1);
  const wrc::GeometryModel& g = ws->geometry();
  fmt::print("rail lines per side: {}, wheel cones per side: {}\n", g.side[0].rail.count(), g.side[0].wheel.cone_count());

  std::vector<double> ys;
  for (int i = -200; i <= 200; ++i) ys.push_back(i * 0.05e-3);

  // 1. One rigid solve.
  fmt::print("\n== one rigid solve at yaw 0 (thread CPU, mean over the 401 rows) ==\n");
  for (auto mode : {wrc::RollMode::free, wrc::RollMode::fixed}) {
    wrc::RigidOptions o;
    o.roll_mode = mode;
    const double t0 = thread_cpu_s();
    std::vector<wrc::RigidResult> cold;
    for (double y : ys) cold.push_back(wrc::solve_rigid(g, y, 0.0, o));
    const double t_cold = (thread_cpu_s() - t0) / ys.size();
    const double t1 = thread_cpu_s();
    for (std::size_t i = 1; i < ys.size(); ++i) {
      o.start = Eigen::Vector2d(cold[i - 1].z, cold[i - 1].roll);
      wrc::solve_rigid(g, ys[i], 0.0, o);
    }
    const double t_cont = (thread_cpu_s() - t1) / (ys.size() - 1);
    fmt::print("roll {:5}: cold {:6.1f} us, from the previous row {:6.1f} us\n",
               mode == wrc::RollMode::free ? "free" : "fixed", t_cold * 1e6, t_cont * 1e6);
  }

  // 2. The 401-row table on one thread, and the same rows as independent cold solves.
  fmt::print("\n== table y = -10 .. 10 mm every 0.05 mm (401 rows), one thread (thread CPU) ==\n");
  for (auto mode : {wrc::RollMode::free, wrc::RollMode::fixed}) {
    wrc::GeometryTableOptions o;
    o.y = ys;
    o.threads = 1;
    o.rigid.roll_mode = mode;
    wrc::GeometryTable t;
    const Stats table = timed(runs, [&] { t = wrc::run_geometry_table(g, o); });
    int failed = 0, two_point = 0;
    for (const auto& r : t.rows) {
      if (!r.touching()) ++failed;
      for (const auto& w : r.wheel) two_point += w.contacts.size() > 1;
    }
    wrc::RigidOptions ro;
    ro.roll_mode = mode;
    const Stats cold = timed(std::max(1, runs / 2), [&] {
      for (double y : ys) wrc::solve_rigid(g, y, 0.0, ro);
    });
    fmt::print("roll {:5}: table {:6.1f} ms best, {:6.1f} ms median ({:.0f} rows/s; {} jumps, {} rows without both "
               "wheels, {} two-point wheels); 401 cold solves {:6.1f} ms best: ratio {:.1f}\n",
               mode == wrc::RollMode::free ? "free" : "fixed", table.best * 1e3, table.median * 1e3,
               ys.size() / table.best, t.jumps.size(), failed, two_point, cold.best * 1e3, cold.best / table.best);
    for (const auto& j : t.jumps)
      fmt::print("    jump, {} wheel: y = {:.4f} .. {:.4f} mm, {:+.2f} mm on the wheel, {:+.2f} mm on the rail, "
                 "contact angle {:.1f} -> {:.1f} deg\n",
                 wrc::side_name(j.side), j.y_before * 1e3, j.y_after * 1e3,
                 (j.after.wheel_profile.x() - j.before.wheel_profile.x()) * 1e3,
                 (j.after.rail_profile.x() - j.before.rail_profile.x()) * 1e3, j.before.angle * 180 / std::numbers::pi,
                 j.after.angle * 180 / std::numbers::pi);
  }

  // 3. Two threads (wall time), and yaw 1 deg (the 3-D path).
  fmt::print("\n== the same table on 2 threads (wall), and at yaw 1 deg (1 thread, thread CPU) ==\n");
  {
    wrc::GeometryTableOptions o;
    o.y = ys;
    o.threads = 2;
    std::vector<double> w;
    for (int r = 0; r < runs; ++r) {
      const double w0 = wall_s();
      wrc::run_geometry_table(g, o);
      w.push_back(wall_s() - w0);
    }
    const Stats s = summarise(w);
    fmt::print("roll free, 2 threads: {:6.1f} ms best, {:6.1f} ms median wall\n", s.best * 1e3, s.median * 1e3);
    o.threads = 1;
    o.yaw = std::numbers::pi / 180;
    wrc::GeometryTable t;
    const Stats y1 = timed(1, [&] { t = wrc::run_geometry_table(g, o); });
    fmt::print("roll free, yaw 1 deg: {:6.1f} ms ({:.0f} rows/s, {} jumps)\n", y1.best * 1e3, ys.size() / y1.best,
               t.jumps.size());
  }
  fmt::print("load average after: {}\n", loadavg());
  lua_close(L);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_geometry_table: %s\n", e.what());
  return 1;
}
