// Benchmark and convergence study of the tangential solvers (halfspace/rolling.hpp):
//   1. the S1002 / 60E1 contact area at y = 0 (the paper's wheelset under 200 kN, 0.2 mm elements): the normal solve
//      of that area, the exact steady-rolling solve and FASTSIM on the same grid, at 100 km/h (pure rolling at the
//      nominal radius: the creepages of the wide patch) and braking (xi = 2e-3 more, partial slip);
//   2. times against the grid size: that area at 0.4, 0.2, 0.1 mm, and Hertzian circles of 10 to 80 elements on
//      the radius;
//   3. Kalker's table: C11, C22, C23, C33 from the exact solver at every tabulated a/b and nu, errors at 20 and 40
//      elements on the smaller semi-axis (each the mean over four placements of the ellipse's centre in an element)
//      and of their Richardson extrapolation (quick: 6 and 12);
//   4. FASTSIM against the exact solver along the saturation curves of xi, eta and spin on Hertzian patches;
//   5. the tolerance against the forces' error (the 0.2 mm area of 1.).
//
//   bench_rolling [reps=7] [quick] [only=1..5]   (only: that section)
//
// Times are CPU time of the calling thread (one core), the median of `reps` runs (the machine is shared).
#include "bench/timing.hpp"
#include "halfspace/rolling_cases.hpp"
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/halfspace/rolling.hpp"
#include "wrc/equilibrium/equilibrium.hpp"

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

using namespace wrc::halfspace;

using wrc::bench::cpu_ms;
using wrc::bench::median_ms;

namespace {

void run(lua_State* L, const std::string& code) {
  if (luaL_loadstring(L, code.c_str()) != LUA_OK || wrc::lua::pcall_traceback(L, 0, 0) != LUA_OK) {
    std::fprintf(stderr, "lua: %s\n", lua_tostring(L, -1));
    std::exit(1);
  }
}

// The left area of the centred wheelset's equilibrium under 200 kN with the given element size, with its tangential
// problem at 100 km/h (pure rolling at r0) solved once to get the rigid slip field.
struct Area {
  wrc::PatchContact pc;
  TangentialProblem problem;
  std::vector<double> extra_x, extra_y;
};

Area paper_area(const std::shared_ptr<const wrc::GeometryModel>& geometry, const Material& material, double element) {
  wrc::ContactOptions opt;
  opt.element = element;
  const wrc::ContactModel model(geometry, material, opt);
  wrc::ContactWorkspace ws(model);
  const wrc::EquilibriumResult e = wrc::solve_equilibrium(model, {0, 0, 200e3}, ws);
  wrc::RollingRequest rq;
  rq.kinematics = wrc::Kinematics{100 / 3.6, std::nullopt, 0, 0};
  rq.friction = Friction::coulomb(0.3);
  wrc::ContactRequest req;
  req.only_side = wrc::kLeft;
  req.rolling = rq;
  const wrc::ContactResult c = wrc::evaluate_contact(model, e.contact.pose, ws, req);
  Area a;
  a.pc = c.wheel[wrc::kLeft].patches.front();
  const wrc::PatchRolling& r = *a.pc.rolling;
  const Grid& g = a.pc.solution.grid;
  a.extra_x.resize(r.rigid_x.size());
  a.extra_y.resize(r.rigid_y.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, j));
      a.extra_x[k] = r.rigid_x[k] - (r.creepage.xi - r.creepage.phi * g.y(j));
      a.extra_y[k] = r.rigid_y[k] - (r.creepage.eta + r.creepage.phi * g.x(i));
    }
  a.problem.grid = g;
  a.problem.pressure = a.pc.solution.pressure;
  a.problem.creepages = r.creepage;
  a.problem.extra_x = a.extra_x;
  a.problem.extra_y = a.extra_y;
  a.problem.friction = rq.friction;
  return a;
}

void paper_patch(const std::shared_ptr<const wrc::GeometryModel>& geometry, const Material& m, int reps, bool quick) {
  fmt::print("\n== 1-2. S1002 / 60E1 at y = 0, 200 kN, left area: normal solve vs exact rolling vs FASTSIM (CPU ms, "
             "median of {}) ==\n", reps);
  fmt::print("{:>6} {:>9} {:>8} {:>10} | {:>9} {:>9} {:>7} {:>6} {:>6} | {:>9} {:>9} {:>7} {:>6} | {:>9} {:>9}\n",
             "el_mm", "potential", "contact", "normal_ms", "pure_ms", "ratio", "adh", "newton", "gmres", "brake_ms",
             "ratio", "adh", "newton", "fastsim", "fs_brake");
  const NormalSolver normal(m);
  const RollingSolver exact(m);
  std::vector<double> elements = {0.4e-3, 0.2e-3};
  if (!quick) elements.push_back(0.1e-3);
  for (double element : elements) {
    const Area a = paper_area(geometry, m, element);
    NormalWorkspace nw;
    RollingWorkspace rw;
    const double t_normal = median_ms(reps, [&] { normal.solve(a.problem.grid, a.pc.h, NormalLoad::penetration(), nw); });
    TangentialSolution pure, brake;
    const double t_pure = median_ms(reps, [&] { pure = exact.solve(a.problem, rw); });
    TangentialProblem braking = a.problem;
    braking.creepages.xi += 2e-3;
    const double t_brake = median_ms(reps, [&] { brake = exact.solve(braking, rw); });
    TangentialSolution fs;
    const double t_fastsim = median_ms(std::max(reps, 21), [&] { solve_fastsim(m, a.problem, fs); });
    const double t_fs_brake = median_ms(std::max(reps, 21), [&] { solve_fastsim(m, braking, fs); });
    fmt::print("{:>6.1f} {:>9} {:>8} {:>10.2f} | {:>9.2f} {:>9.2f} {:>7.3f} {:>6} {:>6} | {:>9.2f} {:>9.2f} {:>7.3f} "
               "{:>6} | {:>9.4f} {:>9.4f}\n",
               element * 1e3, a.problem.grid.size(), a.pc.solution.elements_in_contact, t_normal, t_pure,
               t_pure / t_normal, pure.adhesion_fraction(), pure.iterations, pure.linear_iterations + pure.coarse_iterations,
               t_brake, t_brake / t_normal, brake.adhesion_fraction(), brake.iterations, t_fastsim, t_fs_brake);
  }
  fmt::print("(pure: the creepages of pure rolling at r0, xi = {:.2e}, phi = {:.3f} 1/m and the curved patch's own slip "
             "field; brake: xi + 2e-3. ratio = exact / normal on the same grid; FASTSIM ms, reusing its output grids.)\n",
             paper_area(geometry, m, 0.4e-3).problem.creepages.xi, paper_area(geometry, m, 0.4e-3).problem.creepages.phi);
}

// The solver's tolerance against the forces' accuracy: the paper's area at 0.2 mm, pure rolling and braking, solved
// to 1e-10 as the reference.
void tolerance_study(const std::shared_ptr<const wrc::GeometryModel>& geometry, const Material& m, int reps) {
  fmt::print("\n== 5. The tolerance: the 0.2 mm area (pure rolling, then braking), forces against a solve to 1e-10 "
             "(CPU ms, median of {}) ==\n", reps);
  const RollingSolver exact(m);
  const Area a = paper_area(geometry, m, 0.2e-3);
  TangentialProblem braking = a.problem;
  braking.creepages.xi += 2e-3;
  for (const TangentialProblem* pb : std::vector<const TangentialProblem*>{&a.problem, &braking}) {
    TangentialOptions ro;
    ro.tolerance = 1e-10;
    RollingWorkspace rw0;
    const TangentialSolution ref = exact.solve(*pb, rw0, ro);
    double N = 0;
    for (double p : pb->pressure) N += p * pb->grid.element_area();
    for (double tol : {1e-4, 3e-5, 1e-5, 3e-6, 1e-6}) {
      TangentialOptions o;
      o.tolerance = tol;
      RollingWorkspace rw;
      TangentialSolution s;
      const double t = median_ms(reps, [&] { s = exact.solve(*pb, rw, o); });
      fmt::print("tolerance {:.0e}: {:6.2f} ms, Newton {}, GMRES {} + {} coarse, products {}; error of Fx {:+.1e}, Fy {:+.1e} "
                 "mu N, Mz {:+.1e} mu N (5 mm)\n",
                 tol, t, s.iterations, s.linear_iterations, s.coarse_iterations, s.products, (s.fx - ref.fx) / (0.3 * N),
                 (s.fy - ref.fy) / (0.3 * N), (s.mz - ref.mz) / (0.3 * N * 0.005));
    }
  }
}

void hertz_times(const Material& m, int reps, bool quick) {
  fmt::print("\n== 2. Hertzian circle, xi = 0.5 xi_s and phi: exact and FASTSIM vs elements (CPU ms, median of {}) ==\n",
             reps);
  fmt::print("{:>5} {:>8} | {:>9} {:>6} {:>6} {:>8} {:>8} | {:>10}\n", "n", "contact", "exact_ms", "newton", "gmres",
             "coarse", "products", "fastsim_ms");
  const RollingSolver exact(m);
  std::vector<int> ns = {10, 20, 40};
  if (!quick) ns.push_back(80);
  for (int n : ns) {
    const wrc::test::HertzPatch h = wrc::test::hertz_patch(5e-3, 5e-3, 1e9, n);
    const double xi_s = 3 * 0.3 * h.force / linear_creep_force(h.a, h.b, m, {-1, 0, 0}).fx;
    const TangentialProblem pb = wrc::test::rolling_problem(h, {0.5 * xi_s, 0, 20 * xi_s}, 0.3);
    RollingWorkspace ws;
    TangentialSolution s;
    const double t = median_ms(reps, [&] { s = exact.solve(pb, ws); });
    const double tf = median_ms(reps, [&] { solve_fastsim(m, pb); });
    fmt::print("{:>5} {:>8.0f} | {:>9.2f} {:>6} {:>6} {:>8} {:>8} | {:>10.3f}\n", n, s.contact_area / h.grid.element_area(),
               t, s.iterations, s.linear_iterations, s.coarse_iterations, s.products, tf);
  }
}

// Kalker's coefficients from the exact solver in the linear regime on a Hertzian patch with n elements on the smaller
// semi-axis, averaged over four placements of the ellipse's centre in an element (the boundary-sampling noise).
void measure(const Material& m, double aob, int n, double c[4]) {
  const RollingSolver s(m);
  const double a = aob >= 1 ? aob * 1e-3 : 1e-3, b = aob >= 1 ? 1e-3 : 1e-3 / aob;
  const double G = m.shear_modulus(), cc = std::sqrt(a * b), e = 1e-6;
  for (int i = 0; i < 4; ++i) c[i] = 0;
  for (auto [sx, sy] : {std::pair{0.0, 0.0}, {0.5, 0.0}, {0.0, 0.5}, {0.5, 0.5}}) {
    const wrc::test::HertzPatch h = wrc::test::hertz_patch(a, b, 1e9, n, sx, sy);
    const auto f = [&](Creepages cr) { return s.solve(wrc::test::rolling_problem(h, cr, 1e9)); };
    const TangentialSolution x = f({e, 0, 0}), y = f({0, e, 0}), p = f({0, 0, e / cc});
    c[0] += -x.fx / (G * cc * cc * e) / 4;
    c[1] += -y.fy / (G * cc * cc * e) / 4;
    c[2] += -p.fy / (G * cc * cc * e) / 4;
    c[3] += -p.mz / (G * cc * cc * cc * e) / 4;
  }
}

void kalker_table(int n) {
  fmt::print("\n== 3. Kalker's table (1990, Table E.3) vs the exact solver: error (%) at n = {}, {} elements on the "
             "smaller semi-axis (each the mean of 4 placements of the centre), and of 2 C({}) - C({}) ==\n", n, 2 * n,
             2 * n, n);
  fmt::print("{:>6} {:>5} | {:>20} | {:>20} | {:>20} | {:>20}\n", "a/b", "nu", "C11 (n, 2n, R)", "C22", "C23",
             "C33");
  double worst = 0, worst_raw = 0;
  std::vector<double> ratios;
  for (int r = 1; r <= 10; ++r) ratios.push_back(0.1 * r);
  for (int r = 9; r >= 1; --r) ratios.push_back(1 / (0.1 * r));
  const double t0 = cpu_ms();
  for (double aob : ratios)
    for (double nu : {0.0, 0.25, 0.5}) {
      const Material m{2.1e11, nu == 0.5 ? 0.4999 : nu};
      const CreepCoefficients k = kalker_coefficients(aob, nu);
      const double ref[4] = {k.c11, k.c22, k.c23, k.c33};
      double c[2][4];
      measure(m, aob, n, c[0]);
      measure(m, aob, 2 * n, c[1]);
      std::string row = fmt::format("{:>6.3f} {:>5.2f}", aob, nu);
      for (int i = 0; i < 4; ++i) {
        const double e1 = 100 * (c[0][i] / ref[i] - 1), e2 = 100 * (c[1][i] / ref[i] - 1);
        const double er = 100 * ((2 * c[1][i] - c[0][i]) / ref[i] - 1);
        worst = std::max(worst, std::abs(er));
        worst_raw = std::max(worst_raw, std::abs(e2));
        row += fmt::format(" | {:>+6.2f} {:>+6.2f} {:>+6.2f}", e1, e2, er);
      }
      fmt::print("{}\n", row);
    }
  fmt::print("largest |error| of the extrapolation: {:.2f} %; at n = {}: {:.2f} % (C33 of long ellipses converges "
             "slowly: first order with a large constant); {:.0f} s CPU\n", worst, 2 * n, worst_raw,
             (cpu_ms() - t0) / 1e3);
}

void saturation(const Material& m, bool quick) {
  fmt::print("\n== 4. FASTSIM vs exact along the saturation curves (Hertzian patches, mu = 0.3, 24 elements on the "
             "smaller semi-axis): F / (mu N) ==\n");
  const RollingSolver exact(m);
  for (double aob : {0.5, 1.0, 2.0}) {
    const double a = aob >= 1 ? 5e-3 : 5e-3 * aob, b = aob >= 1 ? 5e-3 / aob : 5e-3;
    const wrc::test::HertzPatch h = wrc::test::hertz_patch(a, b, 1e9, quick ? 12 : 24);
    const double N = h.force, mu = 0.3, c = std::sqrt(a * b);
    const CreepForce unit = linear_creep_force(a, b, m, {-1, -1, -1 / c});
    const double xi_s = 3 * mu * N / unit.fx, eta_s = 3 * mu * N / unit.fy;
    const double phi_s = 3 * mu * N / linear_creep_force(a, b, m, {0, 0, -1}).fy;
    fmt::print("a/b = {}: {:>6} | {:>8} {:>8} {:>7} | {:>8} {:>8} {:>7} | {:>8} {:>8} {:>7}\n", aob, "w/w_s", "Fx ex",
               "Fx fs", "diff", "Fy ex", "Fy fs", "diff", "Fy(phi)", "fs", "diff");
    double worst[3] = {0, 0, 0};
    for (double r : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.5}) {
      const auto pair = [&](Creepages cr, bool x) {
        const TangentialProblem pb = wrc::test::rolling_problem(h, cr, mu);
        const TangentialSolution e = exact.solve(pb), f = solve_fastsim(m, pb);
        return std::pair{-(x ? e.fx : e.fy) / (mu * N), -(x ? f.fx : f.fy) / (mu * N)};
      };
      const auto [xe, xf] = pair({r * xi_s, 0, 0}, true);
      const auto [ye, yf] = pair({0, r * eta_s, 0}, false);
      const auto [se, sf] = pair({0, 0, r * phi_s}, false);
      worst[0] = std::max(worst[0], std::abs(xe - xf));
      worst[1] = std::max(worst[1], std::abs(ye - yf));
      worst[2] = std::max(worst[2], std::abs(se - sf));
      fmt::print("{:>18.2f} | {:>8.4f} {:>8.4f} {:>+7.4f} | {:>8.4f} {:>8.4f} {:>+7.4f} | {:>8.4f} {:>8.4f} {:>+7.4f}\n", r,
                 xe, xf, xf - xe, ye, yf, yf - ye, se, sf, sf - se);
    }
    fmt::print("  largest |FASTSIM - exact| / (mu N): xi {:.3f}, eta {:.3f}, spin {:.3f}\n", worst[0], worst[1], worst[2]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 7;
  bool quick = false;
  int only = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "reps=", 5) == 0) reps = std::max(1, std::atoi(argv[i] + 5));
    if (std::strncmp(argv[i], "only=", 5) == 0) only = std::atoi(argv[i] + 5);
    if (std::strcmp(argv[i], "quick") == 0) quick = true;
  }
  lua_State* L = wrc::lua::new_state();
  run(L, "bench_ws = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua'), "
         "rail = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua')}");
  lua_getglobal(L, "bench_ws");
  const auto lws = wrc::lua::check_wheelset(L, -1, "bench");
  const Material material = lws->contact_model().material();
  fmt::print("bench_rolling: E = {} Pa, nu = {}, mu = 0.3\n", material.E, material.nu);
  if (only == 0 || only == 1) paper_patch(lws->geometry_ptr(), material, reps, quick);
  if (only == 0 || only == 2) hertz_times(material, reps, quick);
  if (only == 0 || only == 3) kalker_table(quick ? 6 : 20);
  if (only == 0 || only == 4) saturation(material, quick);
  if (only == 0 || only == 5) tolerance_study(lws->geometry_ptr(), material, reps);
  lua_close(L);
  return 0;
}
