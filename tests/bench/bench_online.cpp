// Benchmark of the costs that matter to online callers (a multibody code calling wrc at every time step) and to
// large studies, on the paper's case (S1002/60E1 at 0.1 mm, 1:40, gauge 1435 mm, r0 = 450 mm, E = 210 GPa,
// nu = 0.3, the default grid 0.2 mm and strategy "accurate"). Prints:
//   1. one contact evaluation of the wheelset at y = 3 mm (at its equilibrium) and in the flange root (y = 6 mm):
//      thread CPU time, cold (as every top-level call starts) and warm (the previous evaluation's pressures), and
//      where the time goes (location, geometry: planes, grids and h, the normal solves, results, sensitivities);
//      the first evaluation of a new wheelset (its influence spectra and FFT plans); the Lua overhead of ws:contact
//      with and without the grids;
//   2. one equilibrium from scratch at y = 3 and 6 mm (as ws:equilibrium): evaluations and the same breakdown;
//   3. one wheel with its vertical force given (ws:wheel) over the tread-to-flange poses y = 0 .. 7 mm: median;
//   4. the paper's sweep (161 y x 2 yaws, with the rigid reference) on 2 threads: wall and CPU;
//   5. a trajectory (hunting-like: y = 5 mm sin, yaw following) at 1 kHz steps with the warm-started trajectory
//      state, per wheel and step, at 0.5 and 0.2 mm: the poses prescribed (tr:contact), with FASTSIM creep forces,
//      then each wheel's vertical force (tr:wheel);
//   6. rolling contact at time steps: the left wheel's Fz = 100 kN given (tr:wheel) along y = 5 mm sin(2 pi 1.5 Hz t)
//      at 1 kHz (yaw following, V = 30 m/s, mu = 0.3), frictionless, with FASTSIM and with the exact solver, at 0.5
//      and 0.2 mm: the three trajectories stepped in turn (so that the machine's load falls on all three alike), the
//      median per step and its ratio to the frictionless step; the exact solver's Newton and GMRES iterations and
//      products, of the step's last solve and of all its solves.
// The machine may be shared: CPU times (thread or process) are printed; wall times only where threads matter.
//
//   bench_online [quick] [reps=20] [surface=conformal|planar] [only=N] [poses] [passes=K] [steps=N] [grid=G]
//                [variants=N]
//   (default surface: conformal; only=N runs section N alone, for a profiler; section 1 runs 2 as well, for its poses;
//   poses: section 3's time and evaluations per pose; passes=K: K more passes of section 3, e.g. for a profiler;
//   steps=N: section 6's time steps, 667 (one period; quick: 200); grid=G: section 6 at G mm alone; variants=N:
//   section 6's first N variants alone, e.g. 2: frictionless and FASTSIM, for a profiler)
#include "lua/lua.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/lua/host.hpp"
#include "wrc/equilibrium/trajectory.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <numbers>
#include <string>
#include <vector>

namespace {

double thread_cpu() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double process_cpu() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double wall() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

wrc::ContactSurface surface = wrc::ContactSurface::conformal;

std::shared_ptr<const wrc::Wheelset> paper_wheelset(double grid) {
  wrc::WheelsetProfiles p;
  const auto w = wrc::lua::load_profile("profiles/s1002.lua", {});
  const auto r = wrc::lua::load_profile("profiles/60e1.lua", {});
  p.wheel = {*w, *w};
  p.rail = {*r, *r};
  wrc::WheelsetParams params;
  params.contact.element = grid;
  params.contact.surface = surface;
  return wrc::build_wheelset(p, params);
}

void print_times(const char* what, const wrc::ContactWorkspace::Times& t, int n) {
  const double total = t.locate + t.geometry + t.solve + t.sensitivity + t.results;
  fmt::print("  {:<44}: {:7.2f} ms = location {:.2f} + geometry {:.2f} + normal solves {:.2f} + results {:.2f} + "
             "sensitivities {:.2f}; {:.1f} areas, {:.0f} potential elements, {:.1f} CG iterations per evaluation\n",
             what, 1e3 * total / n, 1e3 * t.locate / n, 1e3 * t.geometry / n, 1e3 * t.solve / n, 1e3 * t.results / n,
             1e3 * t.sensitivity / n, double(t.areas) / t.evaluations, double(t.elements) / t.evaluations,
             double(t.iterations) / t.evaluations);
}

// Evaluations at a pose: `reps` times, cold or warm, with or without sensitivities; the breakdown per evaluation.
void evaluations(const wrc::Wheelset& ws, const wrc::Pose& pose, int reps, bool warm, bool sensitivity, const char* what) {
  auto work = ws.make_workspace();
  wrc::ContactRequest req;
  req.keep_grids = sensitivity;
  req.sensitivity = sensitivity;
  evaluate_contact(ws.contact_model(), pose, *work, req);  // spectra and plans exist from here on
  work->timing = true;
  work->times = {};
  for (int i = 0; i < reps; ++i) {
    if (!warm) work->forget();
    evaluate_contact(ws.contact_model(), pose, *work, req);
  }
  print_times(what, work->times, reps);
}

double lua_ms(wrc::lua::Session& s, const std::string& call, int reps) {
  const std::string code = fmt::format("local t0 = os.clock(); for i = 1, {} do {} end; bench_t = (os.clock() - t0) / {}",
                                       reps, call, reps);
  if (auto err = s.run(code)) {
    fmt::print(stderr, "{}\n", *err);
    std::exit(1);
  }
  auto* L = static_cast<lua_State*>(s.state());
  lua_getglobal(L, "bench_t");
  const double t = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return 1e3 * t;
}

}  // namespace

// Step k of the hunting-like motion replayed at 1 kHz: y = 5 mm sin(2 pi 1.5 Hz t), the yaw following the path at
// 100 km/h (yaw = -dy/dx), and their rates.
struct HuntingStep {
  double y, yaw, vy, yaw_rate;
};
constexpr double kHuntingSpeed = 100 / 3.6;  // m/s
HuntingStep hunting(int k) {
  const double w = 2 * std::numbers::pi * 1.5, t = k * 1e-3, A = 5e-3, V = kHuntingSpeed;
  return {A * std::sin(w * t), -A * w / V * std::cos(w * t), A * w * std::cos(w * t), A * w * w / V * std::sin(w * t)};
}

// Section 6: the left wheel's Fz given along the hunting motion at V = 30 m/s, frictionless, FASTSIM and exact, the
// three trajectories stepped in turn; per variant the median thread CPU per step and its ratio to the frictionless.
void rolling_steps_table(const std::shared_ptr<const wrc::Wheelset>& ws, double grid, int steps, int variants) {
  constexpr double V = 30, mu = 0.3, Fz = 100e3;
  const char* names[3] = {"frictionless", "FASTSIM", "exact"};
  std::vector<wrc::Trajectory> traj;
  for (int v = 0; v < 3; ++v) {
    traj.emplace_back(ws);
    traj.back().workspace().timing = true;
  }
  std::vector<double> t[3];
  int evaluations[3] = {0, 0, 0}, failed[3] = {0, 0, 0};
  double creep_iterations = 0, creep_linear = 0, creep_products = 0;
  // The results summed over the steps, to compare builds: the height and the wheel's force (creep forces included).
  double sum_z[3] = {0, 0, 0};
  Eigen::Vector3d sum_force[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (int k = 0; k < steps; ++k) {
    const double w = 2 * std::numbers::pi * 1.5, time = k * 1e-3, A = 5e-3;
    const double y = A * std::sin(w * time), vy = A * w * std::cos(w * time), yaw = -vy / V;
    const double yaw_rate = A * w * w / V * std::sin(w * time);
    for (int v = 0; v < variants; ++v) {
      std::optional<wrc::RollingRequest> rolling;
      if (v > 0) {
        rolling.emplace();
        rolling->kinematics = wrc::Kinematics{V, std::nullopt, vy, yaw_rate};
        rolling->friction = wrc::halfspace::Friction::coulomb(mu);
        rolling->method = v == 1 ? wrc::RollingMethod::fastsim : wrc::RollingMethod::exact;
      }
      const double c0 = thread_cpu();
      const wrc::WheelResult r = traj[static_cast<std::size_t>(v)].wheel({wrc::kLeft, y, yaw, 0.0, Fz}, rolling);
      t[v].push_back(thread_cpu() - c0);
      evaluations[v] += r.iterations;
      failed[v] += !r.converged;
      sum_z[v] += r.z;
      sum_force[v] += r.wheel.force;
      if (v == 2)
        for (const auto& pc : r.wheel.patches)
          if (pc.rolling) {
            creep_iterations += pc.rolling->solution.iterations;
            creep_linear += pc.rolling->solution.linear_iterations;
            creep_products += pc.rolling->solution.products;
          }
    }
  }
  const double base = median(t[0]);
  fmt::print("grid {:.1f} mm:\n", grid * 1e3);
  for (int v = 0; v < variants; ++v)
    fmt::print("  {:<12}: {:7.3f} ms per step ({:.2f}x the frictionless), {:.2f} evaluations per step, {} failed\n",
               names[v], 1e3 * median(t[v]), median(t[v]) / base, double(evaluations[v]) / steps, failed[v]);
  for (int v = 0; v < variants; ++v)
    fmt::print("  {:<12}: summed over the steps z {:.17g} m, force ({:.17g}, {:.17g}, {:.17g}) N\n", names[v],
               sum_z[v], sum_force[v].x(), sum_force[v].y(), sum_force[v].z());
  for (int v = 0; v < variants; ++v)
    print_times(fmt::format("{}, per evaluation (normal part)", names[v]).c_str(), traj[static_cast<std::size_t>(v)].workspace().times,
                traj[static_cast<std::size_t>(v)].workspace().times.evaluations);
  if (variants < 3) return;
  fmt::print("  exact, the step's last tangential solve: {:.2f} Newton iterations, {:.1f} GMRES iterations, {:.1f} products "
             "with the influence matrix\n", creep_iterations / steps, creep_linear / steps, creep_products / steps);
  const auto& all = traj[2].workspace().rolling.totals;
  fmt::print("  exact, all tangential solves per step: {:.2f} solves, {:.2f} Newton iterations, {:.1f} GMRES iterations, "
             "{:.1f} products\n", double(all.solves) / steps, double(all.iterations) / steps,
             double(all.linear_iterations) / steps, double(all.products) / steps);
}

int main(int argc, char** argv) {
  bool quick = false;
  int reps = 20, only = 0;
  bool per_pose = false;
  int extra_passes = 0, rolling_steps = 667, rolling_variants = 3;
  double rolling_grid = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "quick") == 0) quick = true, reps = 5;
    if (std::strncmp(argv[i], "reps=", 5) == 0) reps = std::max(1, std::atoi(argv[i] + 5));
    if (std::strcmp(argv[i], "surface=planar") == 0) surface = wrc::ContactSurface::planar;
    if (std::strncmp(argv[i], "only=", 5) == 0) only = std::atoi(argv[i] + 5);
    if (std::strcmp(argv[i], "poses") == 0) per_pose = true;
    if (std::strncmp(argv[i], "passes=", 7) == 0) extra_passes = std::atoi(argv[i] + 7);
    if (std::strncmp(argv[i], "steps=", 6) == 0) rolling_steps = std::max(1, std::atoi(argv[i] + 6));
    if (std::strncmp(argv[i], "grid=", 5) == 0) rolling_grid = 1e-3 * std::atof(argv[i] + 5);
    if (std::strncmp(argv[i], "variants=", 9) == 0) rolling_variants = std::clamp(std::atoi(argv[i] + 9), 1, 3);
  }
  if (quick) rolling_steps = std::min(rolling_steps, 200);
  auto run = [&](int section) { return only == 0 || only == section; };
  double loads[3] = {0, 0, 0};
  if (getloadavg(loads, 3) < 0) loads[0] = -1;
  fmt::print("bench_online: S1002/60E1, grid 0.2 mm, strategy accurate, {} surface; load average {:.2f}\n",
             wrc::surface_name(surface), loads[0]);
  const double t0 = thread_cpu();
  const auto ws = paper_wheelset(0.2e-3);
  fmt::print("building the wheelset: {:.1f} ms\n", 1e3 * (thread_cpu() - t0));
  const wrc::ContactModel& m = ws->contact_model();
  {
    // The process's first evaluations pay for the influence spectra and FFT plans of their grid shapes (kept in a
    // process-wide cache for every later evaluation, of any wheelset with the same element size).
    auto w = ws->make_workspace();
    const wrc::Pose pose{3e-3, -0.018e-3, 0.164e-3, 0};
    const double c1 = thread_cpu();
    evaluate_contact(m, pose, *w);
    const double first = thread_cpu() - c1;
    w->forget();
    const double c2 = thread_cpu();
    evaluate_contact(m, pose, *w);
    const double second = thread_cpu() - c2;
    fmt::print("the process's first evaluation {:.2f} ms, the same again (cold) {:.2f} ms: influence spectra and FFT "
               "plans {:.2f} ms\n", 1e3 * first, 1e3 * second, 1e3 * (first - second));
  }

  // Equilibrium poses (also section 2).
  auto work = ws->make_workspace();
  work->timing = true;
  if (run(1) || run(2)) fmt::print("\n== 2. one equilibrium from scratch (as ws:equilibrium: a cold workspace) ==\n");
  std::vector<wrc::Pose> poses;
  for (double y : {3e-3, 6e-3}) {
    if (!run(1) && !run(2)) break;
    work->forget();
    work->times = {};
    const double c0 = thread_cpu();
    const wrc::EquilibriumResult e = solve_equilibrium(m, {y, 0.0, 200e3}, *work);
    const double c = thread_cpu() - c0;
    fmt::print("y = {:.0f} mm: {:.1f} ms, {} evaluations ({} Newton iterations), converged {}\n", y * 1e3, 1e3 * c,
               e.evaluations, e.iterations, e.converged);
    print_times("per evaluation", work->times, work->times.evaluations);
    poses.push_back({y, e.z, e.roll, 0.0});
  }

  if (run(1)) fmt::print("\n== 1. one contact evaluation at the equilibrium pose (thread CPU, mean of {}) ==\n", reps);
  for (std::size_t k = 0; k < poses.size() && run(1); ++k) {
    fmt::print("y = {:.0f} mm:\n", poses[k].y * 1e3);
    evaluations(*ws, poses[k], reps, false, false, "cold");
    evaluations(*ws, poses[k], reps, true, false, "warm (same pose)");
    evaluations(*ws, poses[k], reps, false, true, "cold, with sensitivities");
  }
  if (run(1)) {
    wrc::lua::Session s;
    if (auto err = s.run("ws = wrc.wheelset{wheel = wrc.profile.load('profiles/s1002.lua'), "
                         "rail = wrc.profile.load('profiles/60e1.lua'), surface = '" +
                         std::string(wrc::surface_name(surface)) + "'}")) {
      fmt::print(stderr, "{}\n", *err);
      return 1;
    }
    const std::string pose = fmt::format("y = {}, z = {}, roll = {}", poses[0].y, poses[0].z, poses[0].roll);
    auto engine = ws->make_workspace();
    const double c0 = thread_cpu();
    for (int i = 0; i < reps; ++i) {
      engine->forget();
      evaluate_contact(m, poses[0], *engine);
    }
    const double e_ms = 1e3 * (thread_cpu() - c0) / reps;
    const double with = lua_ms(s, "ws:contact{" + pose + "}", reps);
    const double without = lua_ms(s, "ws:contact{" + pose + ", grids = false}", reps);
    fmt::print("Lua ws:contact at y = 3 mm: {:.2f} ms with the grids, {:.2f} ms without; the engine alone {:.2f} ms: "
               "Lua overhead {:.2f} / {:.2f} ms\n", with, without, e_ms, with - e_ms, without - e_ms);
  }

  if (run(3)) {
    fmt::print("\n== 3. one wheel with Fz = 100 kN given (as ws:wheel), y = 0 .. 7 mm ==\n");
    // Twice over the same poses: the first pass also builds the influence spectra of grid shapes the process has not
    // met yet (cached for good), the second shows a caller whose cache already holds them.
    std::vector<const char*> passes{"first pass", "second pass"};
    for (int k = 0; k < extra_passes; ++k) passes.push_back("again");  // as the second
    for (const char* pass : passes) {
      std::vector<double> t;
      int evaluations = 0;
      work->times = {};
      const std::size_t built = m.solver().cache().built();
      for (double y = 0; y <= 7e-3 + 1e-12; y += 0.5e-3) {
        work->forget();
        const double c0 = thread_cpu();
        const wrc::WheelResult r = solve_wheel(m, {wrc::kLeft, y, 0.0, 0.0, 100e3}, *work);
        t.push_back(thread_cpu() - c0);
        evaluations += r.iterations;
        if (!r.converged) fmt::print("  y = {:.1f} mm did not converge: {}\n", y * 1e3, r.message);
        if (per_pose) fmt::print("  y = {:.1f} mm: {:.2f} ms, {} evaluations\n", y * 1e3, 1e3 * t.back(), r.iterations);
      }
      fmt::print("{}: median {:.2f} ms, max {:.2f} ms over {} poses; {:.1f} evaluations per solve; {} influence "
                 "spectra built\n", pass, 1e3 * median(t), 1e3 * *std::max_element(t.begin(), t.end()), t.size(),
                 double(evaluations) / t.size(), m.solver().cache().built() - built);
      print_times("per evaluation", work->times, work->times.evaluations);
    }
  }

  if (run(4)) {
    fmt::print("\n== 4. the paper's sweep (y = -8 .. 8 mm every 0.1 mm, yaw 0 and 1 deg, rigid reference), 2 threads ==\n");
    std::vector<double> ys;
    for (int i = 0; i <= 160; ++i) ys.push_back((-8.0 + 0.1 * i) * 1e-3);
    if (quick) ys = {-6e-3, -3e-3, 0.0, 3e-3, 5e-3, 6e-3};
    wrc::SweepOptions so;
    so.threads = 2;
    so.rigid = true;
    // Twice: the first run builds the influence spectra of the grid shapes the process has not met yet (as a
    // study's first sweep does), the second finds them cached (as every later sweep of the process).
    for (const char* pass : {"first run", "second run"}) {
      const std::size_t built = m.solver().cache().built();
      const double w0 = wall(), c0 = process_cpu();
      const wrc::SweepResult r = run_sweep(m, ys, {0.0, std::numbers::pi / 180}, so, [&] { return ws->make_workspace(); });
      const double wl = wall() - w0, cpu = process_cpu() - c0;
      int failed = 0, evals = 0;
      for (const auto& e : r.elastic) failed += !e.converged, evals += e.evaluations;
      fmt::print("{}: {} cases: wall {:.2f} s, CPU {:.2f} s ({:.1f} ms per case), {:.2f} evaluations per case, {} "
                 "failed; {} influence spectra built\n", pass, r.cases.size(), wl, cpu, 1e3 * cpu / r.cases.size(),
                 double(evals) / r.cases.size(), failed, m.solver().cache().built() - built);
    }
  }

  if (run(5))
    fmt::print("\n== 5. trajectory: hunting y = 5 mm sin(2 pi 1.5 Hz t), yaw following, 1 kHz, z and roll at the "
               "equilibrium of each y (prescribed poses, as a multibody code gives them) ==\n");
  for (double grid : {0.5e-3, 0.2e-3}) {
    if (!run(5)) break;
    const auto wsg = paper_wheelset(grid);
    // The prescribed poses: the equilibrium z and roll of y, from a coarse table (interpolated), yaw = -dy/dx.
    std::vector<double> ty, tz, troll;
    {
      wrc::SweepOptions so;
      so.threads = 2;
      for (double y = -5.5e-3; y <= 5.5e-3 + 1e-12; y += 0.5e-3) ty.push_back(y);
      const wrc::SweepResult r = run_sweep(wsg->contact_model(), ty, {0.0}, so, [&] { return wsg->make_workspace(); });
      for (const auto& e : r.elastic) tz.push_back(e.z), troll.push_back(e.roll);
    }
    const int steps = quick ? 200 : 1000;
    double ms[2] = {0, 0};
    for (bool extrapolate : {true, false}) {
      wrc::TrajectoryOptions to;
      to.extrapolate = extrapolate;
      wrc::Trajectory traj(wsg, to);
      traj.workspace().timing = true;
      std::vector<double> per_step;
      for (int k = 0; k < steps; ++k) {
        const HuntingStep h = hunting(k);
        const double z = wrc::interpolate(ty, tz, h.y), roll = wrc::interpolate(ty, troll, h.y);
        const double c0 = thread_cpu();
        traj.contact({h.y, z, roll, h.yaw});
        per_step.push_back(thread_cpu() - c0);
      }
      ms[extrapolate ? 0 : 1] = 1e3 * median(per_step);
      fmt::print("grid {:.1f} mm, {}: {:.3f} ms per wheel and step (median {:.3f} ms per step for both wheels, {} steps)\n",
                 grid * 1e3, extrapolate ? "extrapolated starts" : "the last step as start", 1e3 * median(per_step) / 2,
                 1e3 * median(per_step), steps);
      print_times("per step", traj.workspace().times, steps);
    }
    fmt::print("  the last step as start / extrapolated: {:.2f}\n", ms[1] / ms[0]);
    // The same poses with the creep forces by FASTSIM (100 km/h, mu = 0.3, the motion's lateral and yaw velocities).
    {
      wrc::Trajectory traj(wsg);
      std::vector<double> per_step;
      for (int k = 0; k < steps; ++k) {
        const HuntingStep h = hunting(k);
        wrc::RollingRequest rolling;
        rolling.kinematics = wrc::Kinematics{kHuntingSpeed, std::nullopt, h.vy, h.yaw_rate};
        rolling.friction = wrc::halfspace::Friction::coulomb(0.3);
        rolling.method = wrc::RollingMethod::fastsim;
        const double z = wrc::interpolate(ty, tz, h.y), roll = wrc::interpolate(ty, troll, h.y);
        const double c0 = thread_cpu();
        traj.contact({h.y, z, roll, h.yaw}, rolling);
        per_step.push_back(thread_cpu() - c0);
      }
      fmt::print("grid {:.1f} mm, with FASTSIM creep forces: {:.3f} ms per wheel and step\n", grid * 1e3,
                 1e3 * median(per_step) / 2);
    }
    // The same motion with each wheel's vertical force prescribed (100 kN; tr:wheel, from the previous approach).
    wrc::Trajectory traj(wsg);
    std::vector<double> per_step;
    int evaluations = 0, failed = 0;
    for (int k = 0; k < steps; ++k) {
      const HuntingStep h = hunting(k);
      const double roll = wrc::interpolate(ty, troll, h.y);
      const double c0 = thread_cpu();
      for (int side : {wrc::kLeft, wrc::kRight}) {
        const wrc::WheelResult r = traj.wheel({side, h.y, h.yaw, roll, 100e3});
        evaluations += r.iterations;
        failed += !r.converged;
      }
      per_step.push_back(thread_cpu() - c0);
    }
    fmt::print("grid {:.1f} mm, each wheel's Fz given (tr:wheel): {:.3f} ms per wheel and step, {:.2f} evaluations per "
               "wheel and step, {} failed\n", grid * 1e3, 1e3 * median(per_step) / 2,
               double(evaluations) / (2.0 * steps), failed);
  }

  if (run(6)) {
    fmt::print("\n== 6. rolling contact at time steps: the left wheel, Fz = 100 kN (tr:wheel), y = 5 mm sin(2 pi 1.5 Hz t) "
               "at 1 kHz, yaw following, V = 30 m/s, mu = 0.3; {} steps ==\n", rolling_steps);
    std::vector<double> grids{0.5e-3, 0.2e-3};
    if (rolling_grid > 0) grids = {rolling_grid};
    for (double grid : grids) rolling_steps_table(paper_wheelset(grid), grid, rolling_steps, rolling_variants);
  }
  return 0;
}
