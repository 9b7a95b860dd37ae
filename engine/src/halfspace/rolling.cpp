// The steady-rolling solver's driver (rolling.hpp): validation, cropping, the nested start, and the solution's
// summaries. The Newton-GMRES core is in rolling_newton.cpp.
#include "rolling_internal.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::halfspace {

void validate(const TangentialProblem& pb, std::string_view context, ProblemCheck check) {
  validate(pb.grid, context);
  const auto n = static_cast<std::size_t>(pb.grid.size());
  if (pb.pressure.size() != n)
    fail("{}: pressure has {} values for a {} x {} grid ({} elements)", context, pb.pressure.size(), pb.grid.nx,
         pb.grid.ny, n);
  const bool values = check == ProblemCheck::values;
  for (std::size_t k = 0; values && k < n; ++k)
    if (!std::isfinite(pb.pressure[k]) || pb.pressure[k] < 0)
      fail("{}: pressure at element {} (i = {}, j = {}) is {} Pa, expected a finite value >= 0", context, k,
           k % pb.grid.nx, k / pb.grid.nx, pb.pressure[k]);
  const Creepages& c = pb.creepages;
  if (!std::isfinite(c.xi) || !std::isfinite(c.eta) || !std::isfinite(c.phi))
    fail("{}: creepages xi = {}, eta = {}, phi = {} 1/m must be finite", context, c.xi, c.eta, c.phi);
  if (!std::isfinite(pb.ref_x) || !std::isfinite(pb.ref_y))
    fail("{}: reference point ({}, {}) m must be finite", context, pb.ref_x, pb.ref_y);
  if (pb.extra_x.size() != pb.extra_y.size() || (!pb.extra_x.empty() && pb.extra_x.size() != n))
    fail("{}: the extra rigid slip has {} and {} values for {} elements", context, pb.extra_x.size(),
         pb.extra_y.size(), n);
  for (std::size_t k = 0; values && k < pb.extra_x.size(); ++k)
    if (!std::isfinite(pb.extra_x[k]) || !std::isfinite(pb.extra_y[k]))
      fail("{}: the extra rigid slip is not finite at element {}", context, k);
  validate(pb.friction, context);
  if (pb.friction.slip_dependent() && !(pb.speed > 0 && std::isfinite(pb.speed)))
    fail("{}: the {} friction law depends on the slip velocity: the rolling speed is {} m/s, expected > 0", context,
         law_name(pb.friction.law), pb.speed);
  if (!pb.friction_scale.empty() && pb.friction_scale.size() != n)
    fail("{}: the friction scale has {} values for {} elements", context, pb.friction_scale.size(), n);
  for (std::size_t k = 0; k < pb.friction_scale.size(); ++k)
    if (!(pb.friction_scale[k] > 0 && std::isfinite(pb.friction_scale[k])))
      fail("{}: the friction scale at element {} (i = {}, j = {}) is {}, expected a finite value > 0", context, k,
           k % pb.grid.nx, k / pb.grid.nx, pb.friction_scale[k]);
  if (pb.direction != 1 && pb.direction != -1)
    fail("{}: rolling direction {} must be +1 (toward +x) or -1", context, pb.direction);
  if (pb.regions.empty() != pb.region_label.empty() || (!pb.region_label.empty() && pb.region_label.size() != n))
    fail("{}: {} contact regions with {} region labels for {} elements (both or neither)", context,
         pb.regions.size(), pb.region_label.size(), n);
}

void rigid_slip(const TangentialProblem& pb, std::vector<double>& wx, std::vector<double>& wy) {
  const Grid& g = pb.grid;
  wx.resize(static_cast<std::size_t>(g.size()));
  wy.resize(wx.size());
  const Creepages& c = pb.creepages;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, j));
      wx[k] = c.xi - c.phi * (g.y(j) - pb.ref_y) + (pb.extra_x.empty() ? 0.0 : pb.extra_x[k]);
      wy[k] = c.eta + c.phi * (g.x(i) - pb.ref_x) + (pb.extra_y.empty() ? 0.0 : pb.extra_y[k]);
    }
}

namespace detail {

Level make_level(const Field& f, const Friction& friction, int direction, double speed) {
  Level L;
  L.direction = direction;
  L.friction = friction;
  L.speed = speed;
  const Grid& g = f.grid;
  int i0 = g.nx, i1 = -1, j0 = g.ny, j1 = -1;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (f.pressure[static_cast<std::size_t>(g.index(i, j))] > 0)
        i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  if (i1 < 0) return L;
  // The contact's bounding box and the column upstream of it (the displacement there enters the upwind difference).
  L.i0 = direction > 0 ? i0 : i0 - 1;
  L.j0 = j0;
  Grid& c = L.field.grid;
  c = g;
  c.nx = i1 - i0 + 2;
  c.ny = j1 - j0 + 1;
  c.x0 = g.x(L.i0);
  c.y0 = g.y(j0);
  const auto n = static_cast<std::size_t>(c.size());
  L.field.pressure.assign(n, 0.0);
  L.field.wx.assign(n, 0.0);
  L.field.wy.assign(n, 0.0);
  if (!f.scale.empty()) L.field.scale.assign(n, 1.0);
  std::vector<int> element(n, -1);
  for (int j = 0; j < c.ny; ++j)
    for (int step = 0; step < c.nx; ++step) {  // marching order: from the upstream end of the row
      const int i = direction > 0 ? c.nx - 1 - step : step, gi = i + L.i0, gj = j + L.j0;
      if (gi < 0 || gi >= g.nx) continue;
      const auto from = static_cast<std::size_t>(g.index(gi, gj));
      const auto to = static_cast<std::size_t>(c.index(i, j));
      L.field.pressure[to] = f.pressure[from];
      L.field.wx[to] = f.wx[from];
      L.field.wy[to] = f.wy[from];
      if (!f.scale.empty()) L.field.scale[to] = f.scale[from];
      if (!(f.pressure[from] > 0)) continue;
      element[to] = L.size();
      L.cell.push_back(static_cast<int>(to));
      const double gp = (f.scale.empty() ? 1.0 : f.scale[from]) * f.pressure[from];
      L.gs.push_back(friction.static_coefficient * gp);
      if (L.falling()) {
        L.gp.push_back(gp);
        L.gk.push_back(friction.at(speed * std::hypot(f.wx[from], f.wy[from])) * gp);
      } else {
        L.gk.push_back(friction.kinetic_coefficient * gp);
      }
      L.wx.push_back(f.wx[from]);
      L.wy.push_back(f.wy[from]);
      L.scale = std::max(L.scale, std::hypot(f.wx[from], f.wy[from]));
    }
  L.up.resize(L.cell.size());
  for (int k = 0; k < L.size(); ++k) L.up[static_cast<std::size_t>(k)] = element[static_cast<std::size_t>(L.cell[static_cast<std::size_t>(k)] + direction)];
  return L;
}

Field coarsen(const Level& L) {
  const Grid& f = L.field.grid;
  Field c;
  c.grid = f;
  c.grid.nx = (f.nx + 1) / 2;
  c.grid.ny = (f.ny + 1) / 2;
  c.grid.dx = 2 * f.dx;
  c.grid.dy = 2 * f.dy;
  c.grid.x0 = f.x0 + 0.5 * f.dx;
  c.grid.y0 = f.y0 + 0.5 * f.dy;
  const auto n = static_cast<std::size_t>(c.grid.size());
  c.pressure.assign(n, 0.0);
  c.wx.assign(n, 0.0);
  c.wy.assign(n, 0.0);
  const bool scaled = !L.field.scale.empty();
  if (scaled) c.scale.assign(n, 0.0);
  std::vector<double> cells(n, 0.0), contacts(n, 0.0);
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i) {
      const auto q = static_cast<std::size_t>(c.grid.index(i / 2, j / 2));
      const auto k = static_cast<std::size_t>(f.index(i, j));
      cells[q] += 1;
      c.pressure[q] += L.field.pressure[k];
      if (L.field.pressure[k] > 0) {
        contacts[q] += 1;
        c.wx[q] += L.field.wx[k];
        c.wy[q] += L.field.wy[k];
        if (scaled) c.scale[q] += L.field.scale[k];
      }
    }
  for (std::size_t q = 0; q < n; ++q) {
    c.pressure[q] /= cells[q];
    if (contacts[q] > 0) c.wx[q] /= contacts[q], c.wy[q] /= contacts[q];
    if (scaled) c.scale[q] = contacts[q] > 0 ? c.scale[q] / contacts[q] : 1.0;
  }
  return c;
}

namespace {

// Puts an element's start traction on the bound when it reaches it (slip), else keeps it (adhesion).
void clip_start(const Level& L, LevelState& st, int k, bool slip) {
  const auto q = static_cast<std::size_t>(k);
  double& px = st.px[q];
  double& py = st.py[q];
  double mag = std::hypot(px, py);
  if (!slip && mag <= L.gs[q]) {
    st.state[q] = kAdhesion;
    return;
  }
  if (!(mag > 0)) {  // no direction yet: against the rigid slip
    px = -L.wx[q], py = -L.wy[q];
    mag = std::hypot(px, py);
    if (!(mag > 0)) px = 1, py = 0, mag = 1;
  }
  st.state[q] = kSlip;
  px *= L.gk[q] / mag;
  py *= L.gk[q] / mag;
}

LevelState empty_state(const Level& L) {
  LevelState st;
  st.px.assign(L.cell.size(), 0.0);
  st.py.assign(L.cell.size(), 0.0);
  st.state.assign(L.cell.size(), kAdhesion);
  return st;
}

}  // namespace

LevelState prolong(const Level& C, const LevelState& cs, const Level& L) {
  const Grid& cg = C.field.grid;
  std::vector<double> px(static_cast<std::size_t>(cg.size()), 0.0), py(px.size());
  std::vector<unsigned char> state(px.size(), kExterior);
  for (int k = 0; k < C.size(); ++k) {
    const auto c = static_cast<std::size_t>(C.cell[static_cast<std::size_t>(k)]);
    px[c] = cs.px[static_cast<std::size_t>(k)];
    py[c] = cs.py[static_cast<std::size_t>(k)];
    state[c] = cs.state[static_cast<std::size_t>(k)];
  }
  const auto at = [&](const std::vector<double>& v, int i, int j) {
    return (i < 0 || j < 0 || i >= cg.nx || j >= cg.ny) ? 0.0 : v[static_cast<std::size_t>(cg.index(i, j))];
  };
  LevelState st = empty_state(L);
  const Grid& fg = L.field.grid;
  for (int k = 0; k < L.size(); ++k) {
    const int cell = L.cell[static_cast<std::size_t>(k)], i = cell % fg.nx, j = cell / fg.nx;
    const double fu = (fg.x(i) - cg.x0) / cg.dx, fv = (fg.y(j) - cg.y0) / cg.dy;
    const int iu = static_cast<int>(std::floor(fu)), iv = static_cast<int>(std::floor(fv));
    const double a = fu - iu, b = fv - iv;
    const auto bilinear = [&](const std::vector<double>& v) {
      return (1 - a) * (1 - b) * at(v, iu, iv) + a * (1 - b) * at(v, iu + 1, iv) + (1 - a) * b * at(v, iu, iv + 1) +
             a * b * at(v, iu + 1, iv + 1);
    };
    st.px[static_cast<std::size_t>(k)] = bilinear(px);
    st.py[static_cast<std::size_t>(k)] = bilinear(py);
    const int ni = std::clamp(static_cast<int>(std::lround(fu)), 0, cg.nx - 1);
    const int nj = std::clamp(static_cast<int>(std::lround(fv)), 0, cg.ny - 1);
    clip_start(L, st, k, state[static_cast<std::size_t>(cg.index(ni, nj))] == kSlip);
  }
  return st;
}

LevelState start_from(const Level& L, std::span<const double> px, std::span<const double> py,
                      std::span<const unsigned char> state) {
  LevelState st = empty_state(L);
  for (int k = 0; k < L.size(); ++k) {
    const auto c = static_cast<std::size_t>(L.cell[static_cast<std::size_t>(k)]);
    st.px[static_cast<std::size_t>(k)] = px[c];
    st.py[static_cast<std::size_t>(k)] = py[c];
    const bool slip = state.empty() ? std::hypot(px[c], py[c]) >= (1 - 1e-9) * L.gk[static_cast<std::size_t>(k)]
                                    : state[c] == kSlip;  // at the bound: slipping
    clip_start(L, st, k, slip);
  }
  return st;
}

}  // namespace detail

namespace {

using detail::Field;
using detail::Level;
using detail::LevelState;

// Solves a level, started from the solution on a grid twice as coarse when it is large enough.
LevelState solve_level(const Level& L, const Material& material, const ShearCache& cache, RollingWorkspace& ws,
                       const TangentialOptions& opt, bool& converged) {
  LevelState st;
  if (opt.nested && L.size() > opt.coarse_limit) {
    const Level C = detail::make_level(detail::coarsen(L), L.friction, L.direction, L.speed);
    TangentialOptions copt = opt;
    copt.tolerance = std::max(opt.tolerance, 1e-4);  // a start: the fine grid finishes the job
    bool coarse_converged = false;
    const LevelState cs = solve_level(C, material, cache, ws, copt, coarse_converged);
    st = detail::prolong(C, cs, L);
    st.coarse_linear = cs.linear + cs.coarse_linear;
  } else {
    st.px.assign(L.cell.size(), 0.0);
    st.py.assign(L.cell.size(), 0.0);
    st.state.assign(L.cell.size(), kAdhesion);
  }
  const auto linear = cache.get(L.field.grid, ShearSpectrum::Kind::linear);
  const auto periodic = cache.get(L.field.grid, ShearSpectrum::Kind::periodic);
  converged = detail::newton(L, material, *linear, *periodic, ws, opt, st);
  return st;
}

}  // namespace

void detail::summarise(TangentialSolution& s, double ref_x, double ref_y) {
  const Grid& g = s.grid;
  const double dA = g.element_area();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, j));
      if (s.state[k] == kExterior) continue;
      s.contact_area += dA;
      if (s.state[k] == kAdhesion) s.adhesion_area += dA;
      s.fx += s.px[k] * dA;
      s.fy += s.py[k] * dA;
      s.mz += ((g.x(i) - ref_x) * s.py[k] - (g.y(j) - ref_y) * s.px[k]) * dA;
      s.power_per_speed -= (s.px[k] * s.sx[k] + s.py[k] * s.sy[k]) * dA;
    }
  for (double v : {s.fx, s.fy, s.mz, s.power_per_speed})
    if (!std::isfinite(v)) fail("tangential solve: a result is not finite (internal error; inputs were finite)");
}

TangentialSolution detail::empty_solution(const Grid& grid) {
  TangentialSolution s;
  s.grid = grid;
  const auto n = static_cast<std::size_t>(grid.size());
  for (auto* v : {&s.px, &s.py, &s.sx, &s.sy}) v->assign(n, 0.0);
  s.state.assign(n, kExterior);
  return s;
}

RollingSolver::RollingSolver(const Material& material, FftPlanning planning) : cache_(material, planning) {}

TangentialSolution RollingSolver::solve(const TangentialProblem& pb, const TangentialOptions& options) const {
  RollingWorkspace ws;
  return solve(pb, ws, options);
}

namespace {

// The problem's own grid as a level: its pressure, rigid slip and friction scale (solve and linearise alike).
Level top_level(const TangentialProblem& pb) {
  Field top;
  top.grid = pb.grid;
  top.pressure.assign(pb.pressure.begin(), pb.pressure.end());
  rigid_slip(pb, top.wx, top.wy);
  top.scale.assign(pb.friction_scale.begin(), pb.friction_scale.end());
  return detail::make_level(top, pb.friction, pb.direction, pb.speed);
}

// The element of the problem's grid that contact element k of the level is.
std::size_t grid_index(const Level& L, const Grid& grid, int k) {
  const int c = L.cell[static_cast<std::size_t>(k)];
  return static_cast<std::size_t>(grid.index(c % L.field.grid.nx + L.i0, c / L.field.grid.nx + L.j0));
}

// Solves the level from the warm start (tractions on the problem's grid) or from the nested coarse solution.
LevelState solve_top(const Level& L, const Grid& grid, const Material& material, const ShearCache& cache,
                     RollingWorkspace& ws, const TangentialOptions& opt) {
  bool converged = true;
  LevelState st;
  if (!opt.initial_x.empty()) {
    std::vector<double> ix(static_cast<std::size_t>(L.field.grid.size()), 0.0), iy(ix.size());
    std::vector<unsigned char> is(opt.initial_state.empty() ? 0 : ix.size(), kExterior);
    for (int k = 0; k < L.size(); ++k) {
      const auto c = static_cast<std::size_t>(L.cell[static_cast<std::size_t>(k)]);
      const std::size_t g = grid_index(L, grid, k);
      ix[c] = opt.initial_x[g];
      iy[c] = opt.initial_y[g];
      if (!is.empty()) is[c] = opt.initial_state[g];
    }
    st = detail::start_from(L, ix, iy, is);
    const auto linear = cache.get(L.field.grid, ShearSpectrum::Kind::linear);
    const auto periodic = cache.get(L.field.grid, ShearSpectrum::Kind::periodic);
    converged = detail::newton(L, material, *linear, *periodic, ws, opt, st, true);
  } else {
    st = solve_level(L, material, cache, ws, opt, converged);
  }
  if (!converged)
    fail("RollingSolver::solve: no convergence in {} Newton iterations on {} contact elements (residual {:.3g} of "
         "the rigid slip, tolerance {:.3g}): the adhesion / slip split keeps changing",
         opt.max_iterations, L.size(), st.residual, opt.tolerance);
  return st;
}

}  // namespace

TangentialSolution RollingSolver::solve(const TangentialProblem& pb, RollingWorkspace& ws,
                                        const TangentialOptions& opt) const {
  validate(pb, "RollingSolver::solve");
  if (!(opt.tolerance > 0 && opt.tolerance < 1)) fail("RollingSolver::solve: tolerance {} must be in ]0, 1[", opt.tolerance);
  if (opt.initial_x.size() != opt.initial_y.size() ||
      (!opt.initial_x.empty() && opt.initial_x.size() != pb.pressure.size()))
    fail("RollingSolver::solve: the warm start has {} and {} values for {} elements", opt.initial_x.size(),
         opt.initial_y.size(), pb.pressure.size());
  if (!opt.initial_state.empty() && opt.initial_state.size() != opt.initial_x.size())
    fail("RollingSolver::solve: the warm start's split has {} values for {} elements (and needs its tractions)",
         opt.initial_state.size(), pb.pressure.size());
  const Level L = top_level(pb);
  const bool slipping = L.size() > 0 && L.scale > 0;  // without rigid slip: no traction, all in adhesion
  LevelState st;
  if (slipping) st = solve_top(L, pb.grid, material(), cache_, ws, opt);
  else st.px.assign(L.cell.size(), 0.0), st.py.assign(L.cell.size(), 0.0), st.state.assign(L.cell.size(), kAdhesion);
  std::vector<double> sx(L.cell.size(), 0.0), sy(L.cell.size(), 0.0);
  if (slipping && st.slip.size() == 2 * L.cell.size()) {
    for (std::size_t k = 0; k < L.cell.size(); ++k) sx[k] = st.slip[2 * k], sy[k] = st.slip[2 * k + 1];
  } else if (slipping) {
    detail::slip_of(L, *cache_.get(L.field.grid, ShearSpectrum::Kind::linear), ws, st, sx, sy);
  }
  TangentialSolution out = detail::empty_solution(pb.grid);
  for (int k = 0; k < L.size(); ++k) {
    const auto q = static_cast<std::size_t>(k), f = grid_index(L, pb.grid, k);
    out.px[f] = st.px[q];
    out.py[f] = st.py[q];
    out.state[f] = st.state[q];
    if (st.state[q] == kSlip) out.sx[f] = sx[q], out.sy[f] = sy[q];  // adhesion: s = 0 within the tolerance
  }
  out.residual = st.residual;
  out.iterations = st.iterations;
  out.linear_iterations = st.linear;
  out.coarse_iterations = st.coarse_linear;
  out.products = st.products;
  ++ws.totals.solves;
  ws.totals.iterations += out.iterations;
  ws.totals.linear_iterations += out.linear_iterations;
  ws.totals.products += out.products;
  detail::summarise(out, pb.ref_x, pb.ref_y);
  return out;
}


void detail::check_linearisation(const TangentialProblem& pb, const TangentialSolution& sol,
                                 std::span<const TangentialChange> changes, std::string_view context) {
  validate(pb, context);
  if (pb.friction.slip_dependent())
    fail("{}: the {} friction law falls with the slip velocity: its solution is not linearised (constant friction "
         "only)", context, law_name(pb.friction.law));
  const auto n = static_cast<std::size_t>(pb.grid.size());
  if (sol.grid.nx != pb.grid.nx || sol.grid.ny != pb.grid.ny || sol.px.size() != n || sol.py.size() != n ||
      sol.state.size() != n)
    fail("{}: the solution's grids ({} x {}, {} values) do not fit the problem's {} x {} grid", context, sol.grid.nx,
         sol.grid.ny, sol.px.size(), pb.grid.nx, pb.grid.ny);
  for (std::size_t k = 0; k < n; ++k)
    if ((sol.state[k] != kExterior) != (pb.pressure[k] > 0))
      fail("{}: the solution's contact differs from the problem's at element {} (not its solution)", context, k);
  for (const TangentialChange& c : changes)
    for (const std::vector<double>* v : {&c.extra_x, &c.extra_y, &c.pressure})
      if (!v->empty() && v->size() != n)
        fail("{}: a change has {} values for {} elements", context, v->size(), n);
}

void detail::summarise(TangentialDerivative& d, const TangentialProblem& pb, const TangentialSolution& sol,
                       const TangentialChange& c) {
  const Grid& g = d.grid;
  const double dA = g.element_area();
  double fx = 0, fy = 0, mz = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, j));
      fx += d.px[k];
      fy += d.py[k];
      mz += (g.x(i) - pb.ref_x) * d.py[k] - (g.y(j) - pb.ref_y) * d.px[k];
    }
  d.fx = fx * dA;
  d.fy = fy * dA;
  d.mz = mz * dA - c.ref_x * sol.fy + c.ref_y * sol.fx;  // the moment's point moves with the reference point
}

std::vector<TangentialDerivative> RollingSolver::linearise(const TangentialProblem& pb, const TangentialSolution& sol,
                                                           std::span<const TangentialChange> changes,
                                                           RollingWorkspace& ws, double tolerance) const {
  detail::check_linearisation(pb, sol, changes, "RollingSolver::linearise");
  const Level L = top_level(pb);
  LevelState st;
  for (int k = 0; k < L.size(); ++k) {
    const std::size_t f = grid_index(L, pb.grid, k);
    st.px.push_back(sol.px[f]);
    st.py.push_back(sol.py[f]);
    st.state.push_back(sol.state[f]);
  }
  std::shared_ptr<const ShearSpectrum> linear, periodic;
  if (L.size() > 0) {
    linear = cache_.get(L.field.grid, ShearSpectrum::Kind::linear);
    periodic = cache_.get(L.field.grid, ShearSpectrum::Kind::periodic);
  }
  std::vector<TangentialDerivative> out;
  std::vector<double> dw(2 * st.px.size()), dg(st.px.size()), dp;
  for (const TangentialChange& c : changes) {
    TangentialDerivative& d = out.emplace_back();
    d.grid = pb.grid;
    d.px.assign(pb.pressure.size(), 0.0);
    d.py.assign(pb.pressure.size(), 0.0);
    const Creepages& w = c.creepages;
    const double phi = pb.creepages.phi;
    for (int k = 0; k < L.size(); ++k) {
      const std::size_t f = grid_index(L, pb.grid, k);
      const double x = pb.grid.x(static_cast<int>(f) % pb.grid.nx) - pb.ref_x;
      const double y = pb.grid.y(static_cast<int>(f) / pb.grid.nx) - pb.ref_y;
      // w = (xi - phi (y - ref_y), eta + phi (x - ref_x)) + extra, differentiated
      dw[2 * k] = w.xi - w.phi * y + phi * c.ref_y + (c.extra_x.empty() ? 0.0 : c.extra_x[f]);
      dw[2 * k + 1] = w.eta + w.phi * x - phi * c.ref_x + (c.extra_y.empty() ? 0.0 : c.extra_y[f]);
      dg[static_cast<std::size_t>(k)] =
          c.pressure.empty() ? 0.0 : L.gk[static_cast<std::size_t>(k)] * c.pressure[f] / pb.pressure[f];
    }
    if (L.size() > 0) d.iterations = detail::linearise(L, material(), *linear, *periodic, ws, st, dw, dg, tolerance, dp);
    for (int k = 0; k < L.size(); ++k) {
      const std::size_t f = grid_index(L, pb.grid, k);
      d.px[f] = dp[2 * static_cast<std::size_t>(k)];
      d.py[f] = dp[2 * static_cast<std::size_t>(k) + 1];
    }
    detail::summarise(d, pb, sol, c);
  }
  return out;
}

}  // namespace wrc::halfspace
