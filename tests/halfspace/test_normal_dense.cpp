// The dense solver's Cholesky factor kept across active-set iterations (halfspace/dense_factor.hpp) against a fresh
// factorisation of each set, and the solver through it against the active-set iteration with a fresh factorisation
// at every step. Both references build the influence matrix from the closed form (rectangle_potential, no table) in
// the elements' index order and factorise it with Eigen's LLT.
#include "halfspace/dense_factor.hpp"
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/influence.hpp"
#include "wrc/halfspace/normal.hpp"
#include "approx.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using wrc::test::within_rel;
using namespace wrc::halfspace;
using namespace wrc::test;

namespace {

using wrc::test::steel;

// 2 D between grid elements k and l (m/Pa), from the closed form.
double influence(const Grid& g, int k, int l) {
  return rectangle_potential(g.x(k % g.nx) - g.x(l % g.nx), g.y(k / g.nx) - g.y(l / g.nx), 0.5 * g.dx, 0.5 * g.dy) /
         (std::numbers::pi * steel.combined_modulus());
}

// A fresh Cholesky factorisation of 2 D_AA, the elements in A's order.
Eigen::LLT<Eigen::MatrixXd> fresh_llt(const Grid& g, const std::vector<int>& A) {
  const int m = static_cast<int>(A.size());
  Eigen::MatrixXd K(m, m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) K(a, b) = influence(g, A[a], A[b]);
  Eigen::LLT<Eigen::MatrixXd> llt(K);
  REQUIRE(llt.info() == Eigen::Success);
  return llt;
}

// x = (2 D_AA)^-1 r_A by a fresh Cholesky factorisation, A in index order.
Eigen::VectorXd fresh_solve(const Grid& g, const std::vector<int>& A, const Eigen::VectorXd& r) {
  return fresh_llt(g, A).solve(r);
}

struct Reference {
  std::vector<double> pressure;
  double approach = 0, force = 0;
  int iterations = 0;
  int outgrown = 0;  // iterations whose set had more elements than every set before
};

// The paper's active-set iteration with CONTACT's check, as solve_normal_dense documents it (start {h > 0} or the
// warm pressure's support, drop tensile elements, re-add elements with a negative deformed gap), each set
// factorised afresh.
Reference fresh_active_set(const NormalCase& c, const NormalLoad& load, const std::vector<double>& warm = {}) {
  const Grid& g = c.grid;
  const int n = g.size();
  const bool force_control = load.control == NormalLoad::Control::force;
  const double hmax = *std::max_element(c.h.begin(), c.h.end());
  std::vector<char> in(n, 0);
  for (int k = 0; k < n; ++k) in[k] = warm.empty() ? c.h[k] > 0 : warm[k] > 0;
  Reference ref;
  int largest = 0;
  for (ref.iterations = 1; ref.iterations <= 200; ++ref.iterations) {
    std::vector<int> A;
    for (int k = 0; k < n; ++k)
      if (in[k]) A.push_back(k);
    const int m = static_cast<int>(A.size());
    ref.outgrown += ref.iterations > 1 && m > largest;
    largest = std::max(largest, m);
    Eigen::VectorXd h(m), w(m);
    for (int a = 0; a < m; ++a) h[a] = c.h[A[a]], w[a] = load.weight(A[a]);
    Eigen::VectorXd p = fresh_solve(g, A, h);
    ref.approach = 0;
    if (force_control) {
      const Eigen::VectorXd v = fresh_solve(g, A, w);
      ref.approach = (load.force / g.element_area() - w.dot(p)) / w.dot(v);
      p += ref.approach * v;
    }
    ref.pressure.assign(n, 0.0);
    bool changed = false;
    for (int a = 0; a < m; ++a) {
      if (p[a] < 0) in[A[a]] = 0, changed = true;
      else ref.pressure[A[a]] = p[a];
    }
    if (changed) continue;
    for (int k = 0; k < n; ++k) {
      if (in[k]) continue;
      double u = 0;
      for (int l : A) u += influence(g, k, l) * ref.pressure[l];
      if (u - c.h[k] - ref.approach * load.weight(k) < -1e-12 * (hmax + ref.approach)) in[k] = 1, changed = true;
    }
    if (!changed) break;
  }
  ref.force = 0;
  for (int k = 0; k < n; ++k) ref.force += load.weight(k) * ref.pressure[k] * g.element_area();
  return ref;
}

// The solver's answer against the reference: the same contact set, iterations, pressures and force. Returns
// max |dp| / pmax.
double check_same(const NormalSolution& s, const Reference& ref) {
  double pmax = 0, dp = 0;
  int different = 0;
  for (std::size_t k = 0; k < s.pressure.size(); ++k) {
    pmax = std::max(pmax, ref.pressure[k]);
    dp = std::max(dp, std::abs(s.pressure[k] - ref.pressure[k]));
    different += (s.pressure[k] > 0) != (ref.pressure[k] > 0);
  }
  CHECK(different == 0);
  CHECK(s.iterations == ref.iterations);
  CHECK(dp <= 1e-10 * pmax);
  CHECK(s.force == within_rel(ref.force, 1e-11));
  if (ref.approach != 0) CHECK(s.approach == within_rel(ref.approach, 1e-10));
  return dp / pmax;
}

}  // namespace

TEST_CASE("dense factor kept across set changes = a fresh factorisation of each set") {
  // A Hertz-like gap on 35 x 23 elements of 0.25 mm; the factor orders its elements deepest first.
  const NormalCase c = paraboloid_case(1 / 0.9, 3 / 0.9, 15e-6, 0.25e-3);
  const Grid& g = c.grid;
  const InfluenceTable table(g.dx, g.dy, g.nx, g.ny);
  const double factor = 1 / (std::numbers::pi * steel.combined_modulus());
  detail::DenseActiveFactor L(table, factor, g, c.h, "test");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto set_of = [&](auto&& predicate) {
    std::vector<char> in(g.size());
    for (int k = 0; k < g.size(); ++k) in[k] = predicate(k);
    return in;
  };
  const double hmax = *std::max_element(c.h.begin(), c.h.end());
  const int deepest = static_cast<int>(std::max_element(c.h.begin(), c.h.end()) - c.h.begin());
  struct Step {
    const char* what;
    std::vector<char> in;
    bool kept, joined, grew;  // expected: leading columns kept, rows appended, the block grown
  };
  const std::vector<Step> steps = {
      {"{h > 0}", set_of([&](int k) { return c.h[k] > 0; }), false, false, false},
      {"its rim dropped", set_of([&](int k) { return c.h[k] > 0.3 * hmax; }), true, false, false},
      {"more rim dropped, part of it back (x > 0)",
       set_of([&](int k) { return c.h[k] > 0.5 * hmax || (c.h[k] > 0.2 * hmax && g.x(k % g.nx) > 0); }), true, true,
       false},
      {"every 5th element of the rim dropped, the rest of the x < 0 half back",
       set_of([&](int k) { return c.h[k] > 0.2 * hmax && (c.h[k] > 0.6 * hmax || k % 5 != 0); }), true, true, false},
      {"the deepest element dropped", set_of([&](int k) { return c.h[k] > 0.2 * hmax && k != deepest; }), false,
       false, false},
      {"a ring beyond {h > 0} added, more than the block holds: every column kept",
       set_of([&](int k) { return c.h[k] > -0.2 * hmax; }), true, true, true},
      {"its outer half dropped", set_of([&](int k) { return c.h[k] > -0.1 * hmax; }), true, false, false},
      {"every 4th element of 0 < h < 0.3 hmax dropped and a wider ring joining, beyond the block",
       set_of([&](int k) { return c.h[k] > -0.35 * hmax && !(c.h[k] > 0 && c.h[k] < 0.3 * hmax && k % 4 == 0); }),
       true, true, true},
      {"the same set again: nothing left to factorise",
       set_of([&](int k) { return c.h[k] > -0.35 * hmax && !(c.h[k] > 0 && c.h[k] < 0.3 * hmax && k % 4 == 0); }),
       true, false, false},
  };
  double worst_factor = 0, worst_solve = 0;
  for (const Step& step : steps) {
    CAPTURE(step.what);
    L.factorise(step.in);
    const std::vector<int>& order = L.order();
    std::vector<int> A;  // index order
    for (int k = 0; k < g.size(); ++k)
      if (step.in[k]) A.push_back(k);
    const int m = static_cast<int>(A.size());
    REQUIRE(static_cast<int>(order.size()) == m);
    CHECK(std::is_permutation(order.begin(), order.end(), A.begin()));
    CHECK((L.kept_columns() > 0) == step.kept);
    CHECK((L.joined() > 0) == step.joined);
    CHECK(L.grew() == step.grew);
    // The Cholesky factor is unique: the kept one must be a fresh LLT's of the set in the factor's order.
    const Eigen::MatrixXd lower = L.lower(), fresh = fresh_llt(g, order).matrixL();
    REQUIRE(lower.rows() == m);
    const double dL = (lower - fresh).cwiseAbs().maxCoeff() / fresh.cwiseAbs().maxCoeff();
    CHECK(dL <= 1e-12);
    worst_factor = std::max(worst_factor, dL);
    std::vector<double> r(g.size());
    for (double& v : r) v = U(rng);
    Eigen::VectorXd r_order(m), r_index(m);
    for (int a = 0; a < m; ++a) r_order[a] = r[order[a]], r_index[a] = r[A[a]];
    const Eigen::VectorXd x = L.solve(r_order), ref = fresh_solve(g, A, r_index);
    std::vector<double> x_grid(g.size(), 0.0);
    for (int a = 0; a < m; ++a) x_grid[order[a]] = x[a];
    double dx = 0;
    for (int a = 0; a < m; ++a) dx = std::max(dx, std::abs(x_grid[A[a]] - ref[a]));
    CHECK(dx <= 1e-10 * ref.cwiseAbs().maxCoeff());
    worst_solve = std::max(worst_solve, dx / ref.cwiseAbs().maxCoeff());
  }
  MESSAGE("kept factor vs fresh LLT: max |dL| / max |L| = ", worst_factor, ", solves max |dx| / max |x| = ",
          worst_solve);
}

TEST_CASE("dense solver = the active-set iteration with a fresh factorisation at every step") {
  SUBCASE("Hertz, B/A = 3, cold: the set shrinks 4 times or more, then settles") {
    const NormalCase c = paraboloid_case(1 / 0.9, 3 / 0.9, 15e-6, 0.2e-3);
    const Reference ref = fresh_active_set(c, NormalLoad::penetration());
    REQUIRE(ref.iterations >= 5);
    const double cold = check_same(solve_normal_dense(steel, c.grid, c.h, NormalLoad::penetration()), ref);
    const NormalLoad load = NormalLoad::normal_force(1.3 * ref.force);  // the set grows beyond {h > 0}
    const double force = check_same(solve_normal_dense(steel, c.grid, c.h, load), fresh_active_set(c, load));
    MESSAGE("Hertz, ", ref.iterations, " iterations: max |dp| / pmax = ", cold, ", force control ", force);
  }
  SUBCASE("warm start from the solution shifted by 3 elements: elements dropped on one side, added on the other") {
    const NormalCase c = paraboloid_case(1 / 0.9, 3 / 0.9, 15e-6, 0.2e-3);
    const Reference cold = fresh_active_set(c, NormalLoad::penetration());
    std::vector<double> shifted(c.grid.size(), 0.0);
    for (int k = 0; k < c.grid.size(); ++k)
      if (k % c.grid.nx >= 3) shifted[k] = cold.pressure[k - 3];
    NormalOptions o;
    o.initial_pressure = shifted;
    const Reference ref = fresh_active_set(c, NormalLoad::penetration(), shifted);
    REQUIRE(ref.iterations >= 3);
    MESSAGE("shifted warm start, ", ref.iterations, " iterations: max |dp| / pmax = ",
            check_same(solve_normal_dense(steel, c.grid, c.h, NormalLoad::penetration(), o), ref));
  }
  SUBCASE("40 random patches (one to three lobes), both controls") {
    std::mt19937 rng(31);
    double worst = 0;
    for (int t = 0; t < 40; ++t) {
      const NormalCase c = random_case(rng, 10, 24);
      CAPTURE(t);
      NormalLoad load = NormalLoad::penetration();
      if (t % 2 == 1) load = NormalLoad::normal_force(fresh_active_set(c, load).force * (0.3 + 0.05 * t));
      worst = std::max(worst, check_same(solve_normal_dense(steel, c.grid, c.h, load), fresh_active_set(c, load)));
    }
    MESSAGE("kept factor vs fresh factorisations on 40 random patches: max |dp| / pmax = ", worst);
  }
  SUBCASE("40 random patches warm-started from a neighbour's solution: sets that lose and gain elements") {
    // The start: the solution of the patch 0.1 hmax shallower, shifted by up to one element along x and y. Its
    // support lies partly outside the new contact (dropped) and short of it (joining, beyond the first set: the
    // block grows).
    std::mt19937 rng(43);
    std::uniform_int_distribution<int> shift(-1, 1);
    double worst = 0;
    int outgrown = 0, lost_and_gained = 0;
    for (int t = 0; t < 40; ++t) {
      const NormalCase c = random_case(rng, 10, 24);
      CAPTURE(t);
      const Grid& g = c.grid;
      const double hmax = *std::max_element(c.h.begin(), c.h.end());
      NormalCase shallower = c;
      for (double& h : shallower.h) h -= 0.1 * hmax;
      const Reference before = fresh_active_set(shallower, NormalLoad::penetration());
      const int sx = shift(rng), sy = shift(rng);
      std::vector<double> start(g.size(), 0.0);
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
          if (i - sx >= 0 && i - sx < g.nx && j - sy >= 0 && j - sy < g.ny)
            start[g.index(i, j)] = before.pressure[g.index(i - sx, j - sy)];
      NormalLoad load = NormalLoad::penetration();
      if (t % 2 == 1) load = NormalLoad::normal_force(fresh_active_set(c, load).force * 1.1);
      NormalOptions o;
      o.initial_pressure = start;
      const Reference ref = fresh_active_set(c, load, start);
      outgrown += ref.outgrown;
      int lost = 0, gained = 0;
      for (int k = 0; k < g.size(); ++k) {
        lost += start[k] > 0 && ref.pressure[k] == 0;
        gained += start[k] == 0 && ref.pressure[k] > 0;
      }
      lost_and_gained += lost > 0 && gained > 0;
      worst = std::max(worst, check_same(solve_normal_dense(steel, g, c.h, load, o), ref));
    }
    CHECK(outgrown >= 20);
    CHECK(lost_and_gained >= 20);
    MESSAGE("warm starts on 40 random patches (", lost_and_gained, " losing and gaining elements, ", outgrown,
            " sets beyond every earlier one): max |dp| / pmax = ", worst);
  }
  SUBCASE("a warm start wholly beside the contact (its support turns tensile): the cold solve's solution") {
    // A start shifted too far (a pose that jumped) can lie where h < 0 throughout: every element of it leaves at
    // the first iteration; the solver goes on from the cold start {h > 0} rather than stopping with an empty set.
    const NormalCase c = paraboloid_case(1 / 0.9, 3 / 0.9, 15e-6, 0.2e-3);
    const Grid& g = c.grid;
    Reference cold = fresh_active_set(c, NormalLoad::penetration());
    ++cold.iterations;  // the start's own iteration, all of it dropped
    for (int width : {1, 2}) {  // a corner element, a 2 x 2 corner block
      CAPTURE(width);
      std::vector<double> start(g.size(), 0.0);
      for (int j = 0; j < width; ++j)
        for (int i = 0; i < width; ++i) {
          REQUIRE(c.h[g.index(i, j)] < 0);
          start[g.index(i, j)] = 1e8;
        }
      NormalOptions o;
      o.initial_pressure = start;
      MESSAGE("warm start beside the contact (", width, " x ", width, "): max |dp| / pmax = ",
              check_same(solve_normal_dense(steel, g, c.h, NormalLoad::penetration(), o), cold));
    }
  }
}
