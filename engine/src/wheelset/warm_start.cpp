// Warm starts of the normal problems (warm_start.hpp): the last evaluation's pressures mapped onto a new grid.
#include "warm_start.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>

namespace wrc::areas {
namespace {

// The last evaluation's area of the same side in (nearly) the same plane, or none.
const ContactWorkspace::Previous* previous_area(const std::vector<ContactWorkspace::Previous>& previous, const Plane& pl) {
  const ContactWorkspace::Previous* best = nullptr;
  double best_d = 5e-3;  // m: farther origins belong to another area
  for (const auto& p : previous) {
    if (p.normal.dot(pl.n) < std::cos(0.05) || p.pressure.empty()) continue;
    const double d = (p.origin - pl.O).norm();
    if (d < best_d) {
      best_d = d;
      best = &p;
    }
  }
  return best;
}

// Fractional element indices (u, v) on an old area's grid of the points of a new plane: linear in the new plane's
// coordinates (x, y), so a whole grid is mapped with two multiply-adds per element.
struct OldGridMap {
  const ContactWorkspace::Previous* old;
  double u0, ux, uy, v0, vx, vy;
  OldGridMap(const ContactWorkspace::Previous& p, const Plane& pl) : old(&p) {
    const halfspace::Grid& g = p.grid;
    const Eigen::Vector3d d = pl.O - p.origin;
    u0 = (d.dot(p.t1) - g.x0) / g.dx, ux = pl.t1.dot(p.t1) / g.dx, uy = pl.t2.dot(p.t1) / g.dx;
    v0 = (d.dot(p.t2) - g.y0) / g.dy, vx = pl.t1.dot(p.t2) / g.dy, vy = pl.t2.dot(p.t2) / g.dy;
  }
  // The old element nearest to (x, y) of the new plane (indices; may be off the old grid).
  std::pair<int, int> nearest(double x, double y) const {
    return {static_cast<int>(std::lround(u0 + ux * x + uy * y)), static_cast<int>(std::lround(v0 + vx * x + vy * y))};
  }
  // The old pressure at (x, y) of the new plane (bilinear), or nothing where the nearest old element was not in
  // contact: interpolation alone smears the contact edge outward, and each element started in contact that is not
  // costs the CG a clipping step (as prolong does).
  std::optional<double> pressure_at(double x, double y) const {
    const halfspace::Grid& g = old->grid;
    const double fu = u0 + ux * x + uy * y, fv = v0 + vx * x + vy * y;
    const int iu = static_cast<int>(std::floor(fu)), iv = static_cast<int>(std::floor(fv));
    if (iu < 0 || iv < 0 || iu + 1 >= g.nx || iv + 1 >= g.ny) return std::nullopt;
    const double a = fu - iu, b = fv - iv;
    auto P = [&](int di, int dj) { return old->pressure[static_cast<std::size_t>(g.index(iu + di, iv + dj))]; };
    if (!(P(a < 0.5 ? 0 : 1, b < 0.5 ? 0 : 1) > 0)) return std::nullopt;
    return (1 - a) * (1 - b) * P(0, 0) + a * (1 - b) * P(1, 0) + (1 - a) * b * P(0, 1) + a * b * P(1, 1);
  }
  // pressure_at every element of a grid of the new plane (0 where it gives nothing) into out (zeroed). When the
  // planes share their axes and the grids their element size (the conformal path always, a plane that did not turn),
  // every element sits at one fractional offset (a, b) from the old elements: constant weights, row by row.
  // u_out (optional): the old displacements on the new grid where the new elements are old ones (the grids shifted by
  // whole elements, the conformal path's lattice), NaN elsewhere; all NaN otherwise.
  void fill(const halfspace::Grid& grid, double* out, std::vector<double>* u_out = nullptr) const {
    const halfspace::Grid& g = old->grid;
    const bool shifted = uy == 0 && vx == 0 && std::abs(ux * grid.dx - 1) < 1e-12 && std::abs(vy * grid.dy - 1) < 1e-12;
    if (u_out) u_out->assign(static_cast<std::size_t>(grid.size()), NAN);
    if (!shifted) {
      for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i)
          if (const auto p = pressure_at(grid.x(i), grid.y(j))) out[grid.index(i, j)] = *p;
      return;
    }
    const double fu = u0 + ux * grid.x(0), fv = v0 + vy * grid.y(0);
    const int iu = static_cast<int>(std::floor(fu)), iv = static_cast<int>(std::floor(fv));
    const double a = fu - iu, b = fv - iv;
    if (u_out) shift_displacement(grid, fu, fv, u_out);
    const double w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b, w11 = a * b;
    const int i_lo = std::max(0, -iu), i_hi = std::min(grid.nx - 1, g.nx - 2 - iu);
    for (int j = 0; j < grid.ny; ++j) {
      const int jv = iv + j;
      if (jv < 0 || jv + 1 >= g.ny) continue;
      const double* r0 = old->pressure.data() + g.index(0, jv);  // old rows jv and jv + 1, from column 0
      const double* r1 = r0 + g.nx;
      const double* nearest = b < 0.5 ? r0 : r1;
      const int ni = a < 0.5 ? 0 : 1;
      double* o = out + grid.index(0, j);
      for (int i = i_lo; i <= i_hi; ++i) {
        const int k = iu + i;
        o[i] = nearest[k + ni] > 0 ? w00 * r0[k] + w10 * r0[k + 1] + w01 * r1[k] + w11 * r1[k + 1] : 0.0;
      }
    }
  }
  // The old displacements at whole-element offsets (fu, fv: the new element (0, 0) in old element units), when
  // within 1e-9 of whole: the pressures' copies then match them (to that fraction).
  void shift_displacement(const halfspace::Grid& grid, double fu, double fv, std::vector<double>* u_out) const {
    const halfspace::Grid& g = old->grid;
    const double ru = std::round(fu), rv = std::round(fv);
    if (old->displacement.size() != static_cast<std::size_t>(g.size()) || std::abs(fu - ru) > 1e-9 ||
        std::abs(fv - rv) > 1e-9)
      return;
    const int du = static_cast<int>(ru), dv = static_cast<int>(rv);
    for (int j = 0; j < grid.ny; ++j) {
      const int jv = dv + j;
      if (jv < 0 || jv >= g.ny) continue;
      for (int i = std::max(0, -du); i < grid.nx && du + i < g.nx; ++i) {
        const auto k = static_cast<std::size_t>(grid.index(i, j)), l = static_cast<std::size_t>(g.index(du + i, jv));
        (*u_out)[k] = old->displacement[l];
      }
    }
  }
};

}  // namespace

Plane area_frame(const PatchContact& pc) {
  if (!pc.conformal) return {pc.origin, pc.normal, pc.t1, pc.t2};
  return {Eigen::Vector3d(pc.conformal->x0, pc.conformal->s0, 0), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
          Eigen::Vector3d::UnitY()};
}

bool tangential_start(const ContactWorkspace& ws, int side, const Plane& pl, const halfspace::Grid& grid,
                      std::vector<double>& px, std::vector<double>& py, std::vector<unsigned char>& state) {
  const auto* last = ws.warm_start ? previous_area(ws.tangential[side], pl) : nullptr;
  if (!last || last->state.size() != last->pressure.size()) return false;
  const auto* before = previous_area(ws.tangential_before[side], pl);
  if (before && before->state.size() != before->pressure.size()) before = nullptr;
  const OldGridMap map(*last, pl), then(before ? *before : *last, pl);
  const halfspace::Grid& g = last->grid;
  const auto n = static_cast<std::size_t>(grid.size());
  px.assign(n, 0.0);
  py.assign(n, 0.0);
  state.assign(n, halfspace::kSlip);
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const auto [iu, iv] = map.nearest(grid.x(i), grid.y(j));
      if (iu < 0 || iv < 0 || iu >= g.nx || iv >= g.ny) continue;
      const auto o = static_cast<std::size_t>(g.index(iu, iv)), k = static_cast<std::size_t>(grid.index(i, j));
      if (last->state[o] == halfspace::kExterior) continue;
      px[k] = last->px[o], py[k] = last->py[o], state[k] = last->state[o];
      if (!before) continue;
      const auto [bu, bv] = then.nearest(grid.x(i), grid.y(j));
      const halfspace::Grid& bg = before->grid;
      if (bu < 0 || bv < 0 || bu >= bg.nx || bv >= bg.ny) continue;
      const auto b = static_cast<std::size_t>(bg.index(bu, bv));
      if (before->state[b] != halfspace::kExterior)  // in contact both times: linear in time
        px[k] = 2 * px[k] - before->px[b], py[k] = 2 * py[k] - before->py[b];
    }
  return true;
}

bool warm_start(const ContactWorkspace& ws, int side, const Plane& pl, const halfspace::Grid& grid,
                std::vector<double>& start, std::vector<double>& displacement) {
  const auto* last = ws.warm_start ? previous_area(ws.previous[side], pl) : nullptr;
  if (!last) return false;
  const auto* before = ws.extrapolate ? previous_area(ws.before[side], pl) : nullptr;
  const OldGridMap now(*last, pl), then(before ? *before : *last, pl);
  start.assign(static_cast<std::size_t>(grid.size()), 0.0);
  if (!before) {
    now.fill(grid, start.data(), &displacement);
    // The old displacements hold the whole old pressure's: reusable only if the new grid carries all of it.
    const double carried = std::accumulate(start.begin(), start.end(), 0.0);
    const double all = std::accumulate(last->pressure.begin(), last->pressure.end(), 0.0);
    if (!(std::abs(carried - all) <= 1e-12 * all)) displacement.clear();
    return true;
  }
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.x(i), y = grid.y(j);
      const auto p = now.pressure_at(x, y);
      if (!p) continue;
      const auto q = before ? then.pressure_at(x, y) : std::nullopt;
      start[static_cast<std::size_t>(grid.index(i, j))] = q ? std::max(0.0, 2 * *p - *q) : *p;
    }
  return true;
}

}  // namespace wrc::areas
