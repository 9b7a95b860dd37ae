// Reference normal solver: the paper's active-set iteration with a dense Cholesky solve (section 3), the factor kept
// from one iteration to the next where the sets share its leading columns (dense_factor.hpp).
#include "dense_factor.hpp"
#include "normal_internal.hpp"

#include "wrc/halfspace/influence.hpp"
#include "wrc/core/error.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace wrc::halfspace {
namespace {

// u = 2 D p on the whole grid, p non-zero on `active` only.
std::vector<double> displacement(const InfluenceTable& table, double factor, const Grid& grid,
                                 const std::vector<int>& active, const std::vector<double>& p) {
  std::vector<double> u(grid.size(), 0.0);
  for (int k = 0; k < grid.size(); ++k) {
    const int ik = k % grid.nx, jk = k / grid.nx;
    double s = 0;
    for (int l : active) s += table(ik - l % grid.nx, jk - l / grid.nx) * p[l];
    u[k] = factor * s;
  }
  return u;
}

}  // namespace

NormalSolution solve_normal_dense(const Material& material, const Grid& grid, std::span<const double> h,
                                  const NormalLoad& load, const NormalOptions& options) {
  validate_normal_input(material, grid, h, load, options, "solve_normal_dense");
  const bool force_control = load.control == NormalLoad::Control::force;
  const int n = grid.size();
  const double hmax = *std::max_element(h.begin(), h.end());
  if ((force_control && load.force == 0) || (!force_control && hmax <= 0)) return detail::zero_solution(grid, h, load);

  const double factor = material.pair_compliance();  // 2 D = factor * I
  const InfluenceTable table(grid.dx, grid.dy, grid.nx, grid.ny);
  const double dA = grid.element_area();
  const int max_iterations = options.max_iterations > 0 ? options.max_iterations : 200;

  const auto paper_start = [&](std::vector<char>& set) {
    for (int k = 0; k < n; ++k) set[k] = h[k] > 0;  // the paper's start: {h > 0}
    if (std::find(set.begin(), set.end(), 1) == set.end())  // prescribed force, bodies apart: deepest element
      set[std::max_element(h.begin(), h.end()) - h.begin()] = 1;
  };
  std::vector<char> in(n, 0);
  bool warm = false;  // started from options.initial_pressure's support
  if (!options.initial_pressure.empty())
    for (int k = 0; k < n; ++k) warm |= (in[k] = options.initial_pressure[k] > 0);
  if (!warm) paper_start(in);

  NormalSolution s;
  s.grid = grid;
  s.load = load;
  s.pressure.assign(n, 0.0);
  std::vector<int> active;
  std::vector<std::vector<int>> visited;  // the active set of each iteration
  detail::DenseActiveFactor block(table, factor, grid, h, "solve_normal_dense");
  for (int it = 1;; ++it) {
    if (it > max_iterations)
      fail("solve_normal_dense: the active set did not settle in {} iterations ({} x {} grid)", max_iterations,
           grid.nx, grid.ny);
    active.clear();
    for (int k = 0; k < n; ++k)
      if (in[k]) active.push_back(k);
    if (active.empty() && warm) {  // a warm start's whole support turned tensile (it lay beside the contact)
      warm = false;
      paper_start(in);
      for (int k = 0; k < n; ++k)
        if (in[k]) active.push_back(k);
    }
    if (active.empty())
      fail("solve_normal_dense: the active set became empty (internal error for h with max {} m)", hmax);
    // Each set determines the next: one met before would repeat the same iterations up to max_iterations.
    const auto seen = std::find(visited.begin(), visited.end(), active);
    if (seen != visited.end())
      fail("solve_normal_dense: the active set cycles: iteration {} has the {} elements of iteration {} ({} x {} grid); "
           "use the fast solver (solver = \"fast\")", it, active.size(), seen - visited.begin() + 1, grid.nx, grid.ny);
    visited.push_back(active);
    const int m = static_cast<int>(active.size());
    block.factorise(in);
    const std::vector<int>& order = block.order();  // the set in the factor's order
    Eigen::VectorXd rhs(m);
    for (int a = 0; a < m; ++a) rhs[a] = h[order[a]];
    Eigen::VectorXd pa = block.solve(rhs);
    double approach = 0;
    if (force_control) {  // p = K^-1 (h + approach g), sum w p dA = F (g: the gap weights)
      Eigen::VectorXd w(m), g(m);
      for (int a = 0; a < m; ++a) w[a] = load.weight(order[a]), g[a] = load.gap_weight(order[a]);
      const Eigen::VectorXd v = block.solve(g);
      approach = (load.force / dA - w.dot(pa)) / w.dot(v);
      pa += approach * v;
    }
    std::fill(s.pressure.begin(), s.pressure.end(), 0.0);
    bool dropped = false;
    for (int a = 0; a < m; ++a) {
      if (pa[a] < 0) {  // tensile: leaves the contact set
        in[order[a]] = 0;
        dropped = true;
      } else {
        s.pressure[order[a]] = pa[a];
      }
    }
    if (dropped) continue;
    // CONTACT's check: an element outside the set with a negative deformed gap was wrongly removed (or,
    // for a prescribed force, not yet reached by the approach): re-add it.
    const std::vector<double> u = displacement(table, factor, grid, active, s.pressure);
    const double scale = hmax + approach;
    bool added = false;
    for (int k = 0; k < n; ++k)
      if (!in[k] && u[k] - h[k] - approach * load.gap_weight(k) < -1e-12 * scale) {
        in[k] = 1;
        added = true;
      }
    if (added) continue;
    s.approach = force_control ? approach : 0.0;
    s.iterations = it;
    detail::finish_solution(s, u, h);
    return s;
  }
}

NormalResponse normal_response_dense(const Material& material, const NormalSolution& solution,
                                     std::span<const double> dh) {
  validate(material, "normal_response_dense");
  detail::validate_response_input(solution, dh, "normal_response_dense");
  const Grid& grid = solution.grid;
  NormalResponse r;
  r.pressure.assign(grid.size(), 0.0);
  std::vector<char> in(grid.size(), 0);
  for (int k = 0; k < grid.size(); ++k) in[k] = solution.pressure[k] > 0;
  if (std::find(in.begin(), in.end(), 1) == in.end()) {
    detail::finish_response(r, grid);
    return r;
  }
  const double factor = material.pair_compliance();
  const InfluenceTable table(grid.dx, grid.dy, grid.nx, grid.ny);
  detail::DenseActiveFactor block(table, factor, grid, {}, "normal_response_dense");
  block.factorise(in);
  const std::vector<int>& active = block.order();
  const int m = static_cast<int>(active.size());
  Eigen::VectorXd rhs(m);
  for (int a = 0; a < m; ++a) rhs[a] = dh[active[a]];
  Eigen::VectorXd dp = block.solve(rhs);
  if (solution.load.control == NormalLoad::Control::force) {  // sum w dp = 0: the approach moves instead
    Eigen::VectorXd w(m), g(m);
    for (int a = 0; a < m; ++a) w[a] = solution.load.weight(active[a]), g[a] = solution.load.gap_weight(active[a]);
    const Eigen::VectorXd v = block.solve(g);
    r.approach = -w.dot(dp) / w.dot(v);
    dp += r.approach * v;
  }
  for (int a = 0; a < m; ++a) r.pressure[active[a]] = dp[a];
  r.iterations = 1;
  detail::finish_response(r, grid);
  return r;
}

}  // namespace wrc::halfspace
