// Benchmark of the whole normal-contact pipeline (evaluate_contact: location, contact plane, h, normal solve,
// forces) on S1002 / 60E1 with the default strategy, at poses from the tread to the flange (the left wheel at
// ~100 kN vertical): time per pose for the location alone, for a cold evaluation (no warm start: the fast solver
// starts from the nested coarse solution), for a warm one (after an evaluation 0.5 um away, as in a Newton step
// or a sweep), and for the dense reference solver in the same run (coarse grids only): repeated at the same pose
// (its start is its own solution: one active-set iteration) and warm after an evaluation 0.5 um away (its active
// sets gain and lose elements), per element size.
//
//   bench_contact_pipeline [reps=5] [dense_max=3000]
//
// Times are CPU time of the calling thread (one core), best of `reps` (of at most 2 for the dense solver); the dense
// solver runs only where the potential contact area has at most dense_max elements.
#include "bench/timing.hpp"
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/wheelset/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using wrc::bench::cpu_ms;

namespace {

// Best time (ms) of `reps` runs of f; `before` runs untimed ahead of each.
double best_ms(int reps, const std::function<void()>& f, const std::function<void()>& before = {}) {
  double best = INFINITY;
  for (int r = 0; r < reps; ++r) {
    if (before) before();
    const double t0 = cpu_ms();
    f();
    best = std::min(best, cpu_ms() - t0);
  }
  return best;
}

void run(lua_State* L, const std::string& code) {
  if (luaL_loadstring(L, code.c_str()) != LUA_OK || wrc::lua::pcall_traceback(L, 0, 0) != LUA_OK) {
    std::fprintf(stderr, "lua: %s\n", lua_tostring(L, -1));
    std::exit(1);
  }
}

struct Totals {
  long long potential = 0, contact = 0;
  int areas = 0, iterations = 0, coarse_iterations = 0;
};

Totals totals(const wrc::ContactResult& r) {
  Totals t;
  for (const auto& w : r.wheel)
    for (const auto& pc : w.patches) {
      ++t.areas;
      t.potential += pc.solution.grid.size();
      t.contact += pc.solution.elements_in_contact;
      t.iterations += pc.solution.iterations;
      t.coarse_iterations += pc.solution.coarse_iterations;
    }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  long long dense_max = 3000;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "reps=", 5) == 0) reps = std::max(1, std::atoi(argv[i] + 5));
    if (std::strncmp(argv[i], "dense_max=", 10) == 0) dense_max = std::atoll(argv[i] + 10);
  }
  lua_State* L = wrc::lua::new_state();
  run(L, "bench_ws = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua'), "
         "rail = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua')}");
  lua_getglobal(L, "bench_ws");
  const auto lws = wrc::lua::check_wheelset(L, -1, "bench");
  const auto geometry = lws->geometry_ptr();
  const wrc::halfspace::Material material = lws->contact_model().material();
  fmt::print("S1002 / 60E1, strategy '{}', cant 1/40; the left wheel at ~100 kN vertical; CPU ms per pose (best of {})\n",
             geometry->strategy.name, reps);

  // (y, z): the left wheel carries ~100 kN vertical (found with ws:wheel), from the tread to the flange.
  const std::vector<std::pair<double, double>> poses = {{0, -0.075e-3},    {2e-3, 0.022e-3},  {4e-3, 0.196e-3},
                                                        {5e-3, 0.321e-3},  {5.5e-3, 0.421e-3}, {6e-3, 0.572e-3},
                                                        {6.5e-3, 0.794e-3}, {7e-3, 1.443e-3}};
  fmt::print("{:>6} {:>5} {:>6} {:>6} {:>9} {:>8} {:>9} {:>10} {:>9} {:>9} {:>9} {:>9} {:>8} {:>9} {:>9}\n", "el_mm",
             "y_mm", "z_mm", "areas", "potential", "contact", "CG_its", "locate_us", "cold_ms", "warm_ms", "warm_its",
             "dense_ms", "dense/x", "dwarm_ms", "dwarm_its");
  for (double element : {0.4e-3, 0.2e-3, 0.1e-3}) {
    wrc::ContactOptions opt;
    opt.element = element;
    const wrc::ContactModel fast(geometry, material, opt);
    opt.dense = true;
    const wrc::ContactModel dense(geometry, material, opt);
    wrc::ContactWorkspace ws(fast), wd(dense);
    double sum_cold = 0, sum_warm = 0;
    for (const auto& [y, z] : poses) {
      const wrc::Pose pose{y, z, 0, 0}, near{y, z + 0.5e-6, 0, 0};
      const double t_locate = best_ms(reps, [&] { ws.locator.locate(pose); });
      ws.warm_start = false;
      wrc::ContactResult r;
      const double t_cold = best_ms(reps, [&] { r = wrc::evaluate_contact(fast, pose, ws); });
      const Totals tc = totals(r);
      ws.warm_start = true;
      const double t_warm =
          best_ms(reps, [&] { r = wrc::evaluate_contact(fast, pose, ws); }, [&] { wrc::evaluate_contact(fast, near, ws); });
      const Totals tw = totals(r);
      std::string dense_ms = "-", ratio = "-", dwarm_ms = "-", dwarm_its = "-";
      if (tc.potential <= dense_max) {
        const double t_dense = best_ms(std::min(reps, 2), [&] { wrc::evaluate_contact(dense, pose, wd); });
        dense_ms = fmt::format("{:.1f}", t_dense);
        ratio = fmt::format("{:.0f}", t_dense / t_cold);
        const double t_dwarm = best_ms(
            std::min(reps, 2), [&] { r = wrc::evaluate_contact(dense, pose, wd); },
            [&] { wrc::evaluate_contact(dense, near, wd); });
        dwarm_ms = fmt::format("{:.1f}", t_dwarm);
        dwarm_its = fmt::format("{}", totals(r).iterations);
      }
      sum_cold += t_cold;
      sum_warm += t_warm;
      fmt::print("{:6.2f} {:5.1f} {:6.3f} {:6d} {:9d} {:8d} {:>9} {:10.0f} {:9.2f} {:9.2f} {:9d} {:>9} {:>8} {:>9} "
                 "{:>9}\n",
                 element * 1e3, y * 1e3, z * 1e3, tc.areas, tc.potential, tc.contact,
                 fmt::format("{}+{}", tc.iterations, tc.coarse_iterations), t_locate * 1e3, t_cold, t_warm,
                 tw.iterations, dense_ms, ratio, dwarm_ms, dwarm_its);
    }
    fmt::print("{:6.2f} mean: cold {:.2f} ms, warm {:.2f} ms per pose\n", element * 1e3,
               sum_cold / static_cast<double>(poses.size()), sum_warm / static_cast<double>(poses.size()));
  }
  lua_pop(L, 1);
  lua_close(L);
  return 0;
}
