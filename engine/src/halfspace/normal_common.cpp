// Input validation and solution summaries shared by the dense and the fast normal solvers.
#include "normal_internal.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::halfspace {

void validate_normal_input(const Material& material, const Grid& grid, std::span<const double> h,
                           const NormalLoad& load, const NormalOptions& options, std::string_view context) {
  validate(material, context);
  validate(grid, context);
  if (h.size() != static_cast<std::size_t>(grid.size()))
    fail("{}: h has {} values for a {} x {} grid ({} elements)", context, h.size(), grid.nx, grid.ny, grid.size());
  for (std::size_t k = 0; k < h.size(); ++k)
    if (!std::isfinite(h[k]))
      fail("{}: h is not finite at element {} (i = {}, j = {}): {}", context, k, k % grid.nx, k / grid.nx, h[k]);
  if (load.control == NormalLoad::Control::force && (!std::isfinite(load.force) || load.force < 0))
    fail("{}: prescribed normal force F = {} N must be finite and >= 0", context, load.force);
  // The force's weights and the approach's gap weights: per element, finite and > 0, for a prescribed force only.
  auto check_weights = [&](const std::vector<double>& w, const char* name, const char* one) {
    if (w.empty()) return;
    if (load.control != NormalLoad::Control::force) fail("{}: {} apply to a prescribed force only", context, name);
    if (w.size() != h.size()) fail("{}: {} has {} values for {} elements", context, name, w.size(), h.size());
    for (std::size_t k = 0; k < h.size(); ++k)
      if (!std::isfinite(w[k]) || !(w[k] > 0)) fail("{}: {} {} at element {} must be finite and > 0", context, one, w[k], k);
  };
  check_weights(load.weights, "weights", "weight");
  check_weights(load.gap_weights, "gap_weights", "gap weight");
  if (!std::isfinite(options.tolerance) || !(options.tolerance > 0) || options.tolerance >= 1)
    fail("{}: tolerance {} must be in ]0, 1[", context, options.tolerance);
  if (options.max_iterations < 0) fail("{}: max_iterations {} must be >= 0", context, options.max_iterations);
  if (!options.initial_displacement.empty() && options.initial_displacement.size() != h.size())
    fail("{}: initial_displacement has {} values for {} elements", context, options.initial_displacement.size(), h.size());
  if (!options.initial_pressure.empty()) {
    if (options.initial_pressure.size() != h.size())
      fail("{}: initial_pressure has {} values for {} elements", context, options.initial_pressure.size(), h.size());
    for (std::size_t k = 0; k < h.size(); ++k)
      if (!std::isfinite(options.initial_pressure[k]))
        fail("{}: initial_pressure is not finite at element {}", context, k);
  }
}

namespace detail {

void finish_solution(NormalSolution& s, std::span<const double> u, std::span<const double> h) {
  const Grid& grid = s.grid;
  const int n = grid.size();
  const double dA = grid.element_area();
  s.gap.resize(static_cast<std::size_t>(n));
  double F = 0, mx = 0, my = 0, pmax = 0, hmax = -INFINITY;
  int count = 0, edge = 0;
  Complementarity& c = s.residual;
  c = {};
  for (int j = 0; j < grid.ny; ++j) {
    const double y = grid.y(j);
    const bool edge_row = j == 0 || j == grid.ny - 1;
    for (int i = 0; i < grid.nx; ++i) {
      const int k = grid.index(i, j);
      const double p = s.pressure[k];
      const double shift = s.approach * s.load.gap_weight(static_cast<std::size_t>(k));
      const double g = u[k] - h[k] - shift;
      hmax = std::max(hmax, h[k] + shift);
      c.negative_pressure = std::max(c.negative_pressure, -p);
      c.product = std::max(c.product, std::abs(p * g));
      if (p > 0) {
        ++count;
        edge += edge_row || i == 0 || i == grid.nx - 1;
        F += p;
        mx += p * grid.x(i);
        my += p * y;
        pmax = std::max(pmax, p);
        c.contact_gap = std::max(c.contact_gap, std::abs(g));
        s.gap[k] = 0;  // zero by definition in contact: the exact complementary pair
      } else {
        c.negative_gap = std::max(c.negative_gap, -g);
        s.gap[k] = g;
      }
    }
  }
  s.force = F * dA;
  s.cop_x = F > 0 ? mx / F : grid.x0 + 0.5 * (grid.nx - 1) * grid.dx;
  s.cop_y = F > 0 ? my / F : grid.y0 + 0.5 * (grid.ny - 1) * grid.dy;
  s.area = count * dA;
  s.max_pressure = pmax;
  s.elements_in_contact = count;
  s.edge_elements_in_contact = edge;
  c.relative = hmax > 0 ? std::max(c.contact_gap, c.negative_gap) / hmax : 0.0;
  const double all[] = {s.force, s.cop_x, s.cop_y, s.max_pressure, s.approach, c.contact_gap, c.negative_gap,
                        c.product, c.relative};
  for (double v : all)
    if (!std::isfinite(v)) fail("normal contact solve: a result is not finite (internal error; inputs were finite)");
}

NormalSolution zero_solution(const Grid& grid, std::span<const double> h, const NormalLoad& load) {
  NormalSolution s;
  s.grid = grid;
  s.load = load;
  s.pressure.assign(grid.size(), 0.0);
  // For F = 0 the approach is any value <= -max h / w: report the one at which the bodies just touch.
  if (load.control == NormalLoad::Control::force) {
    s.approach = INFINITY;
    for (std::size_t k = 0; k < h.size(); ++k) s.approach = std::min(s.approach, -h[k] / load.gap_weight(k));
  }
  const std::vector<double> u(grid.size(), 0.0);
  finish_solution(s, u, h);
  return s;
}

void finish_response(NormalResponse& r, const Grid& grid) {
  const double dA = grid.element_area();
  double F = 0, mx = 0, my = 0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double dp = r.pressure[grid.index(i, j)];
      F += dp;
      mx += dp * grid.x(i);
      my += dp * grid.y(j);
    }
  r.force = F * dA;
  r.moment_x = mx * dA;
  r.moment_y = my * dA;
  if (!std::isfinite(r.force) || !std::isfinite(r.moment_x) || !std::isfinite(r.moment_y) || !std::isfinite(r.approach))
    fail("normal contact response: a result is not finite (internal error; inputs were finite)");
}

void validate_response_input(const NormalSolution& s, std::span<const double> dh, std::string_view context) {
  validate(s.grid, context);
  if (s.pressure.size() != static_cast<std::size_t>(s.grid.size()))
    fail("{}: the solution has {} pressures for {} elements", context, s.pressure.size(), s.grid.size());
  if (dh.size() != s.pressure.size())
    fail("{}: dh has {} values for {} elements", context, dh.size(), s.pressure.size());
  for (std::size_t k = 0; k < dh.size(); ++k)
    if (!std::isfinite(dh[k])) fail("{}: dh is not finite at element {}", context, k);
}

}  // namespace detail
}  // namespace wrc::halfspace
