// The fast (CG + FFT) normal solver against the dense reference, the complementarity conditions, warm
// starts, threads and bad input.
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/influence.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/core/error.hpp"
#include "approx.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <thread>

using wrc::test::within_rel;
using namespace wrc::halfspace;
using namespace wrc::test;

namespace {

using wrc::test::steel;

// Deformed gap recomputed independently: g = sum_l I(x_k - x_l) p_l / (pi E*) - h - approach, with the
// closed form of influence.hpp evaluated directly (no table, no FFT).
std::vector<double> independent_gap(const NormalCase& c, const NormalSolution& s) {
  const Grid& g = c.grid;
  std::vector<double> gap(g.size());
  const double f = 1 / (std::numbers::pi * steel.combined_modulus());
  for (int k = 0; k < g.size(); ++k) {
    double u = 0;
    for (int l = 0; l < g.size(); ++l)
      if (s.pressure[l] != 0)
        u += rectangle_potential(g.x(k % g.nx) - g.x(l % g.nx), g.y(k / g.nx) - g.y(l / g.nx), 0.5 * g.dx,
                                 0.5 * g.dy) *
             s.pressure[l];
    gap[k] = f * u - c.h[k] - s.approach;
  }
  return gap;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const wrc::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("fast solver = dense solver on 120 random non-Hertzian patches, both controls") {
  std::mt19937 rng(20240601);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  int compared = 0, multi_lobe = 0;
  double worst_pressure = 0, worst_force = 0;
  for (int t = 0; t < 120; ++t) {
    const NormalCase c = random_case(rng);
    const bool force_control = t % 2 == 1;
    NormalLoad load = NormalLoad::penetration();
    if (force_control) {  // a force between light and heavy for this patch
      const NormalSolution ref = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
      load = NormalLoad::normal_force(ref.force * std::uniform_real_distribution<double>(0.2, 1.5)(rng));
    }
    CAPTURE(t);
    CAPTURE(c.grid.nx);
    CAPTURE(c.grid.ny);
    const NormalSolution dense = solve_normal_dense(steel, c.grid, c.h, load);
    const NormalSolution fast = solver.solve(c.grid, c.h, load, ws);
    REQUIRE(dense.elements_in_contact > 0);
    // Same contact set, pressures within 1e-6 of the peak.
    int different = 0;
    double dp = 0;
    for (int k = 0; k < c.grid.size(); ++k) {
      different += (dense.pressure[k] > 0) != (fast.pressure[k] > 0);
      dp = std::max(dp, std::abs(dense.pressure[k] - fast.pressure[k]));
    }
    CHECK(different == 0);
    CHECK(dp < 1e-6 * dense.max_pressure);
    CHECK(fast.force == within_rel(dense.force, 1e-7));
    CHECK(fast.approach == doctest::Approx(dense.approach).scale(std::abs(dense.approach) + 1e-9).epsilon(1e-6));
    worst_pressure = std::max(worst_pressure, dp / dense.max_pressure);
    worst_force = std::max(worst_force, std::abs(fast.force / dense.force - 1));
    // Complementarity, as reported and as recomputed independently.
    CHECK(fast.residual.negative_pressure == 0);
    CHECK(fast.residual.relative < 1.01e-8);  // the default tolerance
    CHECK(dense.residual.relative < 1e-9);
    const auto gap = independent_gap(c, fast);
    double hmax = 0;
    for (double h : c.h) hmax = std::max(hmax, h + fast.approach);
    for (int k = 0; k < c.grid.size(); ++k) {
      if (fast.pressure[k] > 0)
        CHECK(std::abs(gap[k]) < 1.01e-8 * hmax);
      else
        CHECK(gap[k] > -1.01e-8 * hmax);
    }
    // The contact lies inside the inter-penetration area (h + approach > 0 where p > 0: there h = 2Dp > 0).
    for (int k = 0; k < c.grid.size(); ++k)
      if (fast.pressure[k] > 0) CHECK(c.h[k] + fast.approach > 0);
    // The reported summary matches the pressure field.
    double F = 0, mx = 0;
    for (int k = 0; k < c.grid.size(); ++k) F += fast.pressure[k], mx += fast.pressure[k] * c.grid.x(k % c.grid.nx);
    CHECK(fast.force == within_rel(F * c.grid.element_area(), 1e-12));
    CHECK(fast.cop_x == within_rel(mx / F, 1e-12));
    CHECK(fast.area == within_rel(fast.elements_in_contact * c.grid.element_area(), 1e-14));
    int edge = 0;
    for (int j = 0; j < c.grid.ny; ++j)
      for (int i = 0; i < c.grid.nx; ++i)
        edge += fast.pressure[c.grid.index(i, j)] > 0 && (i == 0 || j == 0 || i == c.grid.nx - 1 || j == c.grid.ny - 1);
    CHECK(fast.edge_elements_in_contact == edge);
    if (force_control) CHECK(fast.force == within_rel(load.force, 1e-10));
    // Several separate groups of contact elements (4-connectivity) in this patch?
    std::vector<int> label(c.grid.size(), -1);
    int groups = 0;
    for (int k = 0; k < c.grid.size(); ++k) {
      if (fast.pressure[k] <= 0 || label[k] >= 0) continue;
      std::vector<int> stack{k};
      label[k] = groups;
      while (!stack.empty()) {
        const int e = stack.back();
        stack.pop_back();
        const int i = e % c.grid.nx, j = e / c.grid.nx;
        const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (const auto& n : nb)
          if (n[0] >= 0 && n[0] < c.grid.nx && n[1] >= 0 && n[1] < c.grid.ny) {
            const int m = c.grid.index(n[0], n[1]);
            if (fast.pressure[m] > 0 && label[m] < 0) label[m] = groups, stack.push_back(m);
          }
      }
      ++groups;
    }
    multi_lobe += groups > 1;
    ++compared;
  }
  CHECK(compared == 120);
  CHECK(multi_lobe >= 10);  // the set really contains non-Hertzian, multi-lobe contacts
  MESSAGE("fast vs dense on ", compared, " patches (", multi_lobe, " with several lobes): max |dp|/pmax = ",
          worst_pressure, ", max |dF|/F = ", worst_force);
}

// A weighted force (sum w p dA = F, the approach entering the gap as approach w) is the penetration problem with
// h + approach w: solve that one for a chosen approach, prescribe its weighted force, and both solvers must find the
// same approach and pressures. Weights vary across the rows, as the vertical parts of a curved surface's normals.
// Odd cases give the approach its own gap weights gw (w varied by up to 6 % across the columns): the gap is then
// u - h - approach gw, the force still sum w p dA.
TEST_CASE("weighted force control = the penetration problem with h + approach w (or gw), fast and dense") {
  std::mt19937 rng(8086);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  NormalOptions tight;
  tight.tolerance = 1e-11;
  for (int t = 0; t < 24; ++t) {
    const NormalCase c = t < 20 ? random_case(rng) : random_case(rng, 34, 44);  // the last ones nested
    const Grid& g = c.grid;
    const double w0 = std::uniform_real_distribution<double>(0.3, 1.0)(rng), slope = 0.6 * (1 - w0);
    std::vector<double> w(g.size());
    for (int k = 0; k < g.size(); ++k) w[k] = w0 + slope * (k / g.nx) / std::max(1, g.ny - 1);
    std::vector<double> gw = w;
    if (t % 2 == 1)
      for (int k = 0; k < g.size(); ++k) gw[k] *= 1 + 0.06 * (k % g.nx) / std::max(1, g.nx - 1) - 0.02;
    double hmax = 0;
    for (double h : c.h) hmax = std::max(hmax, h);
    const double approach = std::uniform_real_distribution<double>(-0.3, 0.5)(rng) * hmax;
    std::vector<double> shifted = c.h;
    for (int k = 0; k < g.size(); ++k) shifted[k] += approach * gw[k];
    const NormalSolution ref = solve_normal_dense(steel, g, shifted, NormalLoad::penetration());
    double F = 0;
    for (int k = 0; k < g.size(); ++k) F += w[k] * ref.pressure[k] * g.element_area();
    REQUIRE(F > 0);
    NormalLoad load = NormalLoad::normal_force(F, w);
    if (t % 2 == 1) load.gap_weights = gw;
    const NormalSolution fast = solver.solve(g, c.h, load, ws, tight);
    const NormalSolution dense = solve_normal_dense(steel, g, c.h, load);
    CAPTURE(t);
    for (const NormalSolution* s : {&fast, &dense}) {
      CHECK(s->approach == doctest::Approx(approach).scale(hmax).epsilon(1e-8));
      double dp = 0, Fw = 0;
      int different = 0;
      for (int k = 0; k < g.size(); ++k) {
        dp = std::max(dp, std::abs(s->pressure[k] - ref.pressure[k]));
        different += (s->pressure[k] > 0) != (ref.pressure[k] > 0);
        Fw += w[k] * s->pressure[k] * g.element_area();
      }
      CHECK(different == 0);
      CHECK(dp < 1e-6 * ref.max_pressure);
      CHECK(Fw == within_rel(F, 1e-10));
      CHECK(s->residual.relative < 1e-9);  // its gaps include approach gw
    }
  }
}

// The approach lifts the body by more than max h where the gap weights are small (a wheel's flange rows, whose normals
// are far from vertical, under a prescribed vertical force): max h + approach < 0 while max(h + approach gw) > 0. The
// fast solver's convergence test scaled with max h + approach, never met by any gap, and a trajectory's wheel step ran
// into the iteration limit (2000 CG iterations); it must scale with max(h + approach gw), as the complementarity.
TEST_CASE("weighted force control with the approach below -max h: converges to the dense solution") {
  std::mt19937 rng(2929);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  for (int t = 0; t < 12; ++t) {
    const NormalCase c = t < 8 ? random_case(rng) : random_case(rng, 34, 44);  // the last ones nested
    const Grid& g = c.grid;
    const double w0 = std::uniform_real_distribution<double>(0.15, 0.25)(rng);
    std::vector<double> w(g.size()), gw(g.size());
    for (int k = 0; k < g.size(); ++k) {
      w[k] = w0 * (1 + 0.2 * (k / g.nx) / std::max(1, g.ny - 1));
      gw[k] = t % 2 ? w[k] * (1 + 0.04 * (k % g.nx) / std::max(1, g.nx - 1)) : w[k];
    }
    double hmax = 0;
    for (double h : c.h) hmax = std::max(hmax, h);
    const double approach = -std::uniform_real_distribution<double>(1.2, 2.0)(rng) * hmax;
    std::vector<double> shifted = c.h;
    for (int k = 0; k < g.size(); ++k) shifted[k] += approach * gw[k];
    const NormalSolution ref = solve_normal_dense(steel, g, shifted, NormalLoad::penetration());
    double F = 0;
    for (int k = 0; k < g.size(); ++k) F += w[k] * ref.pressure[k] * g.element_area();
    if (!(F > 0)) continue;  // no element penetrates at this approach
    NormalLoad load = NormalLoad::normal_force(F, w);
    load.gap_weights = gw;
    CAPTURE(t);
    NormalSolution fast;
    REQUIRE_NOTHROW(fast = solver.solve(g, c.h, load, ws));
    CHECK(fast.approach < -hmax);
    CHECK(fast.approach == doctest::Approx(approach).scale(hmax).epsilon(1e-6));
    double dp = 0;
    for (int k = 0; k < g.size(); ++k) dp = std::max(dp, std::abs(fast.pressure[k] - ref.pressure[k]));
    CHECK(dp < 1e-5 * ref.max_pressure);
    CHECK(fast.residual.relative < 1e-7);
  }
}

TEST_CASE("plain CG, no nested start, and a warm start reach the same solution") {
  std::mt19937 rng(5);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  for (int t = 0; t < 10; ++t) {
    const NormalCase c = random_case(rng);
    for (const NormalLoad& load : {NormalLoad::penetration(), NormalLoad::normal_force(500.0)}) {
      const NormalSolution base = solver.solve(c.grid, c.h, load, ws);
      NormalOptions plain;
      plain.precondition = false;
      plain.nested = false;
      const NormalSolution p = solver.solve(c.grid, c.h, load, ws, plain);
      NormalOptions warm;
      warm.initial_pressure = base.pressure;
      const NormalSolution w = solver.solve(c.grid, c.h, load, ws, warm);
      // The solution's displacements are D p: given with the start, they replace its product (not with a NaN in the
      // contact; elsewhere outside the window the solve works on, a NaN does not matter).
      REQUIRE(base.displacement.size() == c.h.size());
      const std::vector<double> u = independent_gap(c, base);  // D p - h - approach, by direct sums
      for (int k = 0; k < c.grid.size(); ++k)
        CHECK(base.displacement[k] == doctest::Approx(u[k] + c.h[k] + base.approach * load.weight(k)).scale(1e-6));
      warm.initial_displacement = base.displacement;
      const NormalSolution wu = solver.solve(c.grid, c.h, load, ws, warm);
      std::vector<double> partial = base.displacement;
      partial[static_cast<std::size_t>(std::max_element(base.pressure.begin(), base.pressure.end()) - base.pressure.begin())] = NAN;
      warm.initial_displacement = partial;
      const NormalSolution wn = solver.solve(c.grid, c.h, load, ws, warm);
      CHECK(wn.products == w.products);
      CHECK(wu.products == w.products - 1);
      for (int k = 0; k < c.grid.size(); ++k) {
        CHECK(std::abs(p.pressure[k] - base.pressure[k]) < 1e-6 * base.max_pressure);
        CHECK(std::abs(w.pressure[k] - base.pressure[k]) < 1e-6 * base.max_pressure);
        CHECK(std::abs(wu.pressure[k] - base.pressure[k]) < 1e-6 * base.max_pressure);
      }
      CHECK(w.iterations <= 2);  // started at the solution
    }
  }
}

TEST_CASE("larger random patches (nested start active): fast = dense") {
  std::mt19937 rng(424242);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  for (int t = 0; t < 4; ++t) {
    const NormalCase c = random_case(rng, 34, 44);
    REQUIRE(c.grid.size() > NormalOptions{}.coarse_limit);
    const NormalLoad load = t % 2 ? NormalLoad::normal_force(3000.0) : NormalLoad::penetration();
    const NormalSolution fast = solver.solve(c.grid, c.h, load, ws);
    CHECK(fast.coarse_iterations > 0);
    const NormalSolution dense = solve_normal_dense(steel, c.grid, c.h, load);
    for (int k = 0; k < c.grid.size(); ++k) {
      CHECK((dense.pressure[k] > 0) == (fast.pressure[k] > 0));
      CHECK(std::abs(dense.pressure[k] - fast.pressure[k]) < 1e-6 * dense.max_pressure);
    }
  }
}

TEST_CASE("nested start on a larger grid: same answer as without it") {
  const double A = 1 / (2 * 0.45), B = 4 * A, delta = 70e-6;
  const NormalCase c = paraboloid_case(A, B, delta, 0.2e-3);
  REQUIRE(c.grid.size() > 3000);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  NormalOptions flat;
  flat.nested = false;
  for (const NormalLoad& load : {NormalLoad::penetration(), NormalLoad::normal_force(2e4)}) {
    const NormalSolution a = solver.solve(c.grid, c.h, load, ws);
    const NormalSolution b = solver.solve(c.grid, c.h, load, ws, flat);
    CHECK(a.coarse_iterations > 0);
    CHECK(b.coarse_iterations == 0);
    CHECK(a.elements_in_contact == b.elements_in_contact);
    for (int k = 0; k < c.grid.size(); ++k) CHECK(std::abs(a.pressure[k] - b.pressure[k]) < 1e-6 * a.max_pressure);
  }
}

// The estimate is the coarse grid's solution interpolated: on a Hertzian patch of ~25 x 50 coarse elements its
// approach is within a per cent or two of the fine grid's, its force near F; one fine product. With a warm start, or
// on a grid too small to nest, it is the ordinary solve.
TEST_CASE("estimate: the nested start as the solution, a fraction of the solve") {
  const double A = 1 / (2 * 0.45), B = 4 * A, delta = 70e-6;
  const NormalCase c = paraboloid_case(A, B, delta, 0.2e-3);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  NormalOptions quick;
  quick.estimate = true;
  std::vector<double> w(c.grid.size());
  for (int k = 0; k < c.grid.size(); ++k) w[k] = 0.8 + 0.2 * (k / c.grid.nx) / c.grid.ny;
  for (const NormalLoad& load : {NormalLoad::penetration(), NormalLoad::normal_force(2e4, w)}) {
    const bool force = load.control == NormalLoad::Control::force;
    CAPTURE(force);
    const NormalSolution full = solver.solve(c.grid, c.h, load, ws);
    const NormalSolution est = solver.solve(c.grid, c.h, load, ws, quick);
    CHECK(est.products == 1);
    CHECK(est.iterations == 0);
    CHECK(est.coarse_iterations > 0);
    CHECK(est.force == within_rel(full.force, 0.03));
    if (force) CHECK(est.approach == within_rel(full.approach, 0.02));
    quick.initial_pressure = full.pressure;  // warm: solved as usual
    const NormalSolution warm = solver.solve(c.grid, c.h, load, ws, quick);
    CHECK(warm.coarse_iterations == 0);
    CHECK(std::abs(warm.force - full.force) < 1e-6 * full.force);
    quick.initial_pressure = {};
  }
}

TEST_CASE("one solver, several threads, each with its own workspace: the sequential answers") {
  std::mt19937 rng(99);
  std::vector<NormalCase> cases;
  for (int t = 0; t < 12; ++t) cases.push_back(random_case(rng));
  const NormalSolver reference_solver(steel);
  std::vector<NormalSolution> expected;
  for (const NormalCase& c : cases) expected.push_back(reference_solver.solve(c.grid, c.h, NormalLoad::penetration()));
  const NormalSolver shared(steel);  // fresh cache: the threads build the spectra concurrently
  std::vector<int> mismatches(3, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t)
    threads.emplace_back([&, t] {
      NormalWorkspace ws;
      for (int rep = 0; rep < 4; ++rep)
        for (std::size_t k = 0; k < cases.size(); ++k) {
          const std::size_t which = (k * (t + 1) + rep) % cases.size();
          const NormalSolution s = shared.solve(cases[which].grid, cases[which].h, NormalLoad::penetration(), ws);
          if (s.pressure != expected[which].pressure) ++mismatches[t];
        }
    });
  for (auto& th : threads) th.join();
  for (int m : mismatches) CHECK(m == 0);
}

TEST_CASE("no contact, zero force, and touching bodies give clean zero solutions") {
  const NormalSolver solver(steel);
  const Grid g = Grid::square(7, 5, 0.2e-3);
  std::vector<double> apart(g.size(), -1e-6);
  apart[3] = -2e-7;
  for (const auto& s : {solver.solve(g, apart, NormalLoad::penetration()),
                        solve_normal_dense(steel, g, apart, NormalLoad::penetration())}) {
    CHECK(s.force == 0);
    CHECK(s.elements_in_contact == 0);
    CHECK(s.area == 0);
    CHECK(std::isfinite(s.cop_x));
    CHECK(s.residual.negative_gap == 0);
  }
  const auto zero = solver.solve(g, apart, NormalLoad::normal_force(0));
  CHECK(zero.force == 0);
  CHECK(zero.approach == within_rel(2e-7, 1e-5));  // just touching
  // Apart, but a force is prescribed: the approach closes the gap first.
  const auto pushed = solver.solve(g, apart, NormalLoad::normal_force(10.0));
  const auto pushed_dense = solve_normal_dense(steel, g, apart, NormalLoad::normal_force(10.0));
  CHECK(pushed.force == within_rel(10.0, 1e-10));
  CHECK(pushed.approach > 2e-7);
  CHECK(pushed.approach == within_rel(pushed_dense.approach, 1e-6));
  // A single element.
  const Grid one = Grid::square(1, 1, 0.2e-3);
  const std::vector<double> h1{1e-6};
  const auto s1 = solver.solve(one, h1, NormalLoad::penetration());
  const double expected = 1e-6 * std::numbers::pi * steel.combined_modulus() / rectangle_potential(0, 0, 0.1e-3, 0.1e-3);
  CHECK(s1.max_pressure == within_rel(expected, 1e-12));
}

TEST_CASE("dense solver: an active set beyond kDenseMaxElements is refused before its matrix is allocated") {
  // 200,000 elements in {h > 0}: a matrix of 8 bytes x 200,000^2 = 320 GB, which no test machine holds: the error
  // comes before the allocation (else std::bad_alloc, or the machine's memory exhausted), and names the active set,
  // the memory and the way out.
  const Grid huge = Grid::square(500, 400, 0.05e-3);
  const std::vector<double> flat(huge.size(), 1e-6);
  const std::string m = message_of([&] { solve_normal_dense(steel, huge, flat, NormalLoad::penetration()); });
  CHECK(m.find("solve_normal_dense: 200000 elements in the active set") != std::string::npos);
  CHECK(m.find("320000 MB") != std::string::npos);
  CHECK(m.find("solver = \"fast\"") != std::string::npos);
  // One row beyond the limit, the linearised response: a flat punch presses every element (p > 0 everywhere, from the
  // fast solver), 10,100 elements, 8 x 10,100^2 bytes = 816 MB.
  REQUIRE(kDenseMaxElements == 10'000);
  const Grid punch = Grid::square(101, 100, 0.2e-3);
  const std::vector<double> h(punch.size(), 1e-6);
  const NormalSolution s = NormalSolver(steel).solve(punch, h, NormalLoad::penetration());
  REQUIRE(s.elements_in_contact == punch.size());
  const std::string r = message_of([&] { normal_response_dense(steel, s, h); });
  CHECK(r.find("normal_response_dense: 10100 elements in the active set") != std::string::npos);
  CHECK(r.find("816 MB") != std::string::npos);
  CHECK(r.find("solver = \"fast\"") != std::string::npos);
}

TEST_CASE("bad input: a wrc::Error that names the problem") {
  const NormalSolver solver(steel);
  const Grid g = Grid::square(4, 3, 0.2e-3);
  const std::vector<double> h(g.size(), 1e-6);
  const auto both = [&](const Material& m, const Grid& grid, const std::vector<double>& hh, const NormalLoad& load,
                        const NormalOptions& o = {}) {
    const std::string a = message_of([&] { solve_normal_dense(m, grid, hh, load, o); });
    const std::string b = message_of([&] { NormalSolver(m).solve(grid, hh, load, o); });
    return a + " | " + b;
  };
  CHECK(both(steel, Grid{}, {}, NormalLoad::penetration()).find("empty grid") != std::string::npos);
  Grid bad_size = g;
  bad_size.dx = -1;
  CHECK(both(steel, bad_size, h, NormalLoad::penetration()).find("element size") != std::string::npos);
  bad_size.dx = NAN;
  CHECK(both(steel, bad_size, h, NormalLoad::penetration()).find("element size") != std::string::npos);
  std::vector<double> nan_h = h;
  nan_h[5] = NAN;
  const std::string m1 = both(steel, g, nan_h, NormalLoad::penetration());
  CHECK(m1.find("h is not finite at element 5 (i = 1, j = 1)") != std::string::npos);
  nan_h[5] = INFINITY;
  CHECK(both(steel, g, nan_h, NormalLoad::penetration()).find("not finite") != std::string::npos);
  CHECK(both(steel, g, std::vector<double>(3, 1e-6), NormalLoad::penetration()).find("h has 3 values") !=
        std::string::npos);
  CHECK(both({0, 0.3}, g, h, NormalLoad::penetration()).find("Young's modulus") != std::string::npos);
  CHECK(both({-2e11, 0.3}, g, h, NormalLoad::penetration()).find("Young's modulus") != std::string::npos);
  CHECK(both({NAN, 0.3}, g, h, NormalLoad::penetration()).find("Young's modulus") != std::string::npos);
  for (double nu : {0.5, -1.0, 0.7, static_cast<double>(NAN)})
    CHECK(both({2.1e11, nu}, g, h, NormalLoad::penetration()).find("Poisson's ratio") != std::string::npos);
  CHECK(both(steel, g, h, NormalLoad::normal_force(-1)).find("F = -1 N") != std::string::npos);
  CHECK(both(steel, g, h, NormalLoad::normal_force(NAN)).find("normal force") != std::string::npos);
  CHECK(both(steel, g, h, NormalLoad::normal_force(1, {1.0, 2.0})).find("weights has 2 values") != std::string::npos);
  std::vector<double> w(g.size(), 1.0);
  w[4] = 0;
  CHECK(both(steel, g, h, NormalLoad::normal_force(1, w)).find("weight 0 at element 4") != std::string::npos);
  w[4] = NAN;
  CHECK(both(steel, g, h, NormalLoad::normal_force(1, w)).find("at element 4 must be finite") != std::string::npos);
  NormalLoad weighted_penetration = NormalLoad::penetration();
  weighted_penetration.weights.assign(g.size(), 1.0);
  CHECK(both(steel, g, h, weighted_penetration).find("weights apply to a prescribed force only") != std::string::npos);
  NormalLoad gapped = NormalLoad::normal_force(1);
  gapped.gap_weights.assign(g.size(), 1.0);
  gapped.gap_weights[2] = 0;
  CHECK(both(steel, g, h, gapped).find("gap weight 0 at element 2 must be finite and > 0") != std::string::npos);
  gapped.gap_weights.pop_back();
  CHECK(both(steel, g, h, gapped).find("gap_weights has") != std::string::npos);
  NormalOptions o;
  o.tolerance = 0;
  CHECK(both(steel, g, h, NormalLoad::penetration(), o).find("tolerance") != std::string::npos);
  o = {};
  const std::vector<double> start(2, 1.0);
  o.initial_pressure = start;
  CHECK(both(steel, g, h, NormalLoad::penetration(), o).find("initial_pressure has 2 values") != std::string::npos);
  Grid huge = g;
  huge.nx = huge.ny = 1 << 14;
  CHECK(both(steel, huge, h, NormalLoad::penetration()).find("exceeds the limit") != std::string::npos);
  CHECK_THROWS_AS(NormalSolver(Material{1e11, 0.5}), wrc::Error);
  CHECK_THROWS_AS(Grid::covering(0, -1, 0, 1, 1e-3), wrc::Error);
  CHECK_THROWS_AS(Grid::covering(0, 1, 0, 1, 0), wrc::Error);
  // Responses: size and finiteness of the perturbation.
  const NormalSolution s = solver.solve(g, h, NormalLoad::penetration());
  NormalWorkspace ws;
  CHECK(message_of([&] { solver.response(s, std::vector<double>(2, 0.0), ws); }).find("dh has 2 values") !=
        std::string::npos);
  std::vector<double> bad_dh(g.size(), 0.0);
  bad_dh[0] = NAN;
  CHECK(message_of([&] { solver.response(s, bad_dh, ws); }).find("dh is not finite") != std::string::npos);
  CHECK(message_of([&] { normal_response_dense(steel, s, bad_dh); }).find("dh is not finite") != std::string::npos);
}

TEST_CASE("Grid helpers") {
  const Grid g = Grid::square(5, 3, 0.2e-3, 1e-3, -2e-3);
  CHECK(g.x(2) == within_rel(1e-3, 1e-5));
  CHECK(g.y(1) == within_rel(-2e-3, 1e-5));
  CHECK(g.index(4, 2) == 14);
  const Grid c = Grid::covering(-1e-3, 1.1e-3, 0, 0.5e-3, 0.2e-3);
  CHECK(c.nx == 11);
  CHECK(c.ny == 3);
  CHECK(c.x0 - 0.5 * c.dx <= -1e-3);
  CHECK(c.x(c.nx - 1) + 0.5 * c.dx >= 1.1e-3);
  CHECK(c.y0 - 0.5 * c.dy <= 0);
}
