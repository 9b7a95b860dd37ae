// Conformal against planar contact areas (issue 15) on S1002 / 60E1, the paper's track:
//  1. one contact evaluation (location, surface or plane, h, normal solve, forces) at poses from the tread to the
//     flange with the left wheel at ~100 kN, cold (no warm start), with and without sensitivities: thread CPU time,
//     best of `reps`, both surfaces in one run, and the ratio conformal / planar;
//  2. the paper's elastic sweep (y from -8 to 8 mm, yaw 0 and 1 deg, Q = 200 kN, continuation along y) with each
//     surface: wall and process CPU time, the ratio, Newton iterations and evaluations per case, where Y/Q first
//     exceeds 0.8 at yaw 0;
//  3. what corrected coefficients (D_kl n_k . n_l, tests/wheelset/angle_corrected.hpp) would change on the conformal
//     flange-root areas of the sweep's equilibria: the forces at the same pose.
//
//   bench_conformal [reps=5] [step_mm=0.1] [threads=2] [sweep=1]
#include "bench/timing.hpp"
#include "wheelset/angle_corrected.hpp"

#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/wheelset/contact.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

namespace {

using wrc::bench::cpu_ms;
using wrc::bench::loadavg;
using wrc::bench::process_cpu_s;
using wrc::bench::wall_s;

double best_ms(int reps, const std::function<void()>& f) {
  double best = INFINITY;
  for (int r = 0; r < reps; ++r) {
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

double arg(int argc, char** argv, const char* key, double fallback) {
  const std::size_t n = std::strlen(key);
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], key, n) == 0 && argv[i][n] == '=') return std::atof(argv[i] + n + 1);
  return fallback;
}

struct Count {
  long long elements = 0;
  int iterations = 0;
};
Count count(const wrc::ContactResult& r) {
  Count c;
  for (const auto& w : r.wheel)
    for (const auto& pc : w.patches) {
      c.elements += pc.solution.grid.size();
      c.iterations += pc.solution.iterations + pc.solution.coarse_iterations;
    }
  return c;
}

// Where Y/Q first exceeds `limit` going from y = 0 toward +y at yaw index 0 (linear between cases), or NaN.
double first_crossing(const wrc::SweepResult& s, double limit) {
  const wrc::EquilibriumResult* prev = nullptr;
  for (std::size_t i = 0; i < s.cases.size(); ++i) {
    const auto& e = s.elastic[i];
    if (s.cases[i].yaw != 0 || !e.converged || s.cases[i].y < 0) continue;
    const double q = e.Y / e.Q;
    if (prev && prev->Y / prev->Q <= limit && q > limit)
      return prev->y + (limit - prev->Y / prev->Q) * (e.y - prev->y) / (q - prev->Y / prev->Q);
    prev = &e;
  }
  return NAN;
}

}  // namespace

int main(int argc, char** argv) try {
  const int reps = std::max(1, static_cast<int>(arg(argc, argv, "reps", 5)));
  const double step_mm = arg(argc, argv, "step_mm", 0.1);
  const int threads = std::max(1, static_cast<int>(arg(argc, argv, "threads", 2)));
  const bool sweep = arg(argc, argv, "sweep", 1) != 0;
  const double deg = std::numbers::pi / 180;
  lua_State* L = wrc::lua::new_state();
  run(L, "bench_planar = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua'), "
         "rail = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua'), surface = 'planar'}; "
         "bench_conformal = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua'), "
         "rail = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua'), surface = 'conformal'}");
  lua_getglobal(L, "bench_planar");
  const auto planar = wrc::lua::check_wheelset(L, -1, "bench");
  lua_getglobal(L, "bench_conformal");
  const auto conformal = wrc::lua::check_wheelset(L, -1, "bench");
  fmt::print("bench_conformal: S1002 / 60E1, grid {} mm, strategy '{}'; load average {}\n",
             planar->contact_model().options().element * 1e3, planar->geometry().strategy.name, loadavg());

  // 1. One evaluation.
  fmt::print("\n== one contact evaluation, cold, left wheel at ~100 kN: thread CPU ms, best of {} ==\n", reps);
  fmt::print("{:>5} {:>7} | {:>9} {:>6} {:>8} {:>8} | {:>9} {:>6} {:>8} {:>8} | {:>6} {:>6}\n", "y_mm", "z_mm",
             "planar el", "CG its", "ms", "+sens ms", "conf. el", "CG its", "ms", "+sens ms", "ratio", "+sens");
  const std::vector<std::pair<double, double>> poses = {{0, -0.075e-3},   {2e-3, 0.022e-3},  {4e-3, 0.196e-3},
                                                        {5e-3, 0.321e-3}, {5.5e-3, 0.421e-3}, {6e-3, 0.572e-3},
                                                        {6.5e-3, 0.794e-3}, {7e-3, 1.443e-3}};
  double sum[2] = {0, 0}, sum_sens[2] = {0, 0}, worst = 0;
  for (const auto& [y, z] : poses) {
    const wrc::Pose pose{y, z, 0, 0};
    double ms[2], ms_sens[2];
    Count c[2];
    int k = 0;
    for (const auto* ws : {planar.get(), conformal.get()}) {
      auto work = ws->make_workspace();
      work->warm_start = false;
      wrc::ContactResult r;
      ms[k] = best_ms(reps, [&] { r = wrc::evaluate_contact(ws->contact_model(), pose, *work); });
      c[k] = count(r);
      wrc::ContactRequest req;
      req.sensitivity = true;
      ms_sens[k] = best_ms(reps, [&] { wrc::evaluate_contact(ws->contact_model(), pose, *work, req); });
      sum[k] += ms[k];
      sum_sens[k] += ms_sens[k];
      ++k;
    }
    worst = std::max(worst, ms[1] / ms[0]);
    fmt::print("{:5.1f} {:7.3f} | {:9d} {:6d} {:8.2f} {:8.2f} | {:9d} {:6d} {:8.2f} {:8.2f} | {:6.2f} {:6.2f}\n", y * 1e3,
               z * 1e3, c[0].elements, c[0].iterations, ms[0], ms_sens[0], c[1].elements, c[1].iterations, ms[1],
               ms_sens[1], ms[1] / ms[0], ms_sens[1] / ms_sens[0]);
  }
  fmt::print("sum over the poses: planar {:.1f} ms, conformal {:.1f} ms, ratio {:.2f} (largest per pose {:.2f}); with "
             "sensitivities {:.2f}\n",
             sum[0], sum[1], sum[1] / sum[0], worst, sum_sens[1] / sum_sens[0]);

  if (!sweep) return 0;
  // 2. The paper's sweep.
  std::vector<double> ys;
  const int half = static_cast<int>(std::lround(8.0 / step_mm));
  for (int i = -half; i <= half; ++i) ys.push_back(i * step_mm * 1e-3);
  const std::vector<double> yaws{0.0, deg};
  fmt::print("\n== the paper's elastic sweep: {} cases, {} threads ==\n", ys.size() * yaws.size(), threads);
  wrc::SweepResult runs[2];
  double cpu[2];
  for (int k = 0; k < 2; ++k) {
    const auto& ws = k == 0 ? planar : conformal;
    wrc::SweepOptions so;
    so.threads = threads;
    const double w0 = wall_s(), c0 = process_cpu_s();
    runs[k] = wrc::run_sweep(ws->contact_model(), ys, yaws, so, [&] { return ws->make_workspace(); });
    const double wall = wall_s() - w0;
    cpu[k] = process_cpu_s() - c0;
    int failed = 0;
    double it = 0, ev = 0;
    for (const auto& e : runs[k].elastic) {
      failed += !e.converged;
      it += e.iterations;
      ev += e.evaluations;
    }
    const double n = static_cast<double>(runs[k].elastic.size());
    fmt::print("{:>9}: wall {:6.2f} s, CPU {:6.2f} s, {:.2f} Newton iterations and {:.2f} evaluations per case, {} "
               "failed; Y/Q first exceeds 0.8 at y = {:.2f} mm (yaw 0); load average {}\n",
               k == 0 ? "planar" : "conformal", wall, cpu[k], it / n, ev / n, failed,
               first_crossing(runs[k], 0.8) * 1e3, loadavg());
  }
  fmt::print("CPU time conformal / planar: {:.2f}\n", cpu[1] / cpu[0]);

  // 3. Corrected coefficients on the conformal flange-root areas (the forces at the same pose).
  fmt::print("\n== coefficients corrected by n_k . n_l on the conformal areas of the sweep's equilibria (yaw 0), the "
             "same pose ==\n{:>5} {:>12} | {:>9} {:>9} {:>7} | {:>9} {:>9} {:>7} | {:>7} {:>7}\n",
             "y_mm", "angles_deg", "Fy_kN", "Fz_kN", "deg", "Fy_kN", "Fz_kN", "deg", "dFy_%", "d|F|_%");
  auto work = conformal->make_workspace();
  const wrc::ContactModel& model = conformal->contact_model();
  for (double y : {3e-3, 5e-3, 5.5e-3, 6e-3, 6.2e-3, 6.3e-3, 6.4e-3, 6.6e-3}) {
    const std::size_t i = static_cast<std::size_t>(std::lround(y * 1e3 / step_mm)) + static_cast<std::size_t>(half);
    const auto& e = runs[1].elastic[i];
    if (!e.converged) continue;
    const wrc::ContactResult r = wrc::evaluate_contact(model, wrc::Pose{e.y, e.z, e.roll, 0}, *work);
    for (const auto& pc : r.wheel[wrc::kLeft].patches) {
      const std::vector<double> p = wrc::test::angle_corrected(model, pc);
      Eigen::Vector3d F = Eigen::Vector3d::Zero();
      const auto& g = pc.solution.grid;
      for (int k = 0; k < g.size(); ++k) F += p[k] * g.element_area() * pc.conformal->normal(k / g.nx);
      fmt::print("{:5.1f} {:5.1f}..{:4.1f} | {:9.2f} {:9.2f} {:7.2f} | {:9.2f} {:9.2f} {:7.2f} | {:+7.2f} {:+7.2f}\n",
                 y * 1e3, pc.angle_min / deg, pc.angle_max / deg, pc.force.y() / 1e3, pc.force.z() / 1e3,
                 pc.angle / deg, F.y() / 1e3, F.z() / 1e3, wrc::contact_angle(wrc::kLeft, F) / deg,
                 100 * (F.y() / pc.force.y() - 1), 100 * (F.norm() / pc.normal_force - 1));
    }
  }
  lua_close(L);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_conformal: %s\n", e.what());
  return 1;
}
