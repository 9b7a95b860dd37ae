// Patches -> potential contact areas -> normal problems -> forces (wheelset/contact.hpp).
#include "wrc/wheelset/contact.hpp"

#include "contact_internal.hpp"
#include "tangential_step.hpp"

#include "wrc/halfspace/interaction.hpp"
#include "wrc/geometry/wheel_surface.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/union_find.hpp"

#include <Eigen/Geometry>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

namespace wrc {

namespace {

// The arc length (along the chords of `rail`, whose lines' arc lengths are S) of the rail's point nearest to P.
double nearest_arc(const RailLines& rail, const std::vector<double>& S, const Eigen::Vector2d& P) {
  double best = INFINITY, arc = 0;
  for (int r = 0; r < rail.count(); ++r) {
    const Eigen::Vector2d A(rail.y[r], rail.z[r]);
    Eigen::Vector2d d = Eigen::Vector2d::Zero();
    if (r + 1 < rail.count()) d = Eigen::Vector2d(rail.y[r + 1], rail.z[r + 1]) - A;
    const double t = d.squaredNorm() > 0 ? std::clamp((P - A).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const double dist = (A + t * d - P).squaredNorm();
    if (dist < best) best = dist, arc = S[static_cast<std::size_t>(r)] + t * d.norm();
  }
  return arc;
}

}  // namespace

ContactModel::ContactModel(std::shared_ptr<const GeometryModel> geometry, const halfspace::Material& material,
                           const ContactOptions& options)
    : geometry_(std::move(geometry)), options_(options), solver_(material), rolling_(material) {
  if (!geometry_) fail("contact model: no geometry");
  if (geometry_->track)
    for (int s : {kLeft, kRight}) flange_[static_cast<std::size_t>(s)] = flange_of(geometry_->track->wheel[s]);
  for (int s : {kLeft, kRight}) {
    const RailLines& rail = geometry_->side[s].rail;
    std::vector<double>& S = rail_arc_[static_cast<std::size_t>(s)];
    S.assign(static_cast<std::size_t>(rail.count()), 0.0);
    for (int r = 1; r < rail.count(); ++r) {
      const auto k = static_cast<std::size_t>(r);
      S[k] = S[k - 1] + std::hypot(rail.y[r] - rail.y[r - 1], rail.z[r] - rail.z[r - 1]);
    }
    if (geometry_->track)
      rail_lattice_[static_cast<std::size_t>(s)] = nearest_arc(rail, S, geometry_->track->place[s].rail(0.0, 0.0));
  }
  halfspace::validate(material, "contact model");
  if (!(options.element >= kElementMin && options.element <= kElementMax))
    fail("contact model: the element size grid = {:.6g} m must be in [{}, {}] m ({} um .. {} mm)", options.element,
         kElementMin, kElementMax, kElementMin * 1e6, kElementMax * 1e3);
  if (options.max_elements < 1) fail("contact model: max_elements = {} must be >= 1", options.max_elements);
  if (options.margin < 1 || options.margin > 100) fail("contact model: margin must be 1..100 elements, got {}", options.margin);
  if (!(options.merge_tolerance > 0) || !std::isfinite(options.merge_tolerance))
    fail("contact model: merge_tolerance must be > 0, got {}", options.merge_tolerance);
  if (!(options.normal.tolerance >= 1e-14 && options.normal.tolerance < 1e-2))
    fail("contact model: the normal solver's tolerance must be in [1e-14, 1e-2[, got {}", options.normal.tolerance);
  if (!(options.merge_angle >= 0) || !std::isfinite(options.merge_angle))
    fail("contact model: merge_angle must be >= 0 rad, got {}", options.merge_angle);
}

ContactWorkspace::ContactWorkspace(const ContactModel& model) : locator(model.geometry_ptr()) {}

ContactWorkspace::ContactWorkspace(const ContactModel& model, std::unique_ptr<PoseSearch> search)
    : locator(model.geometry_ptr(), std::move(search)) {}

namespace contact_detail {

// Lateral spacing of rail line r: half the distance between its neighbours (one-sided at the ends).
double line_spacing(const RailLines& rail, int r) {
  const int n = rail.count();
  const int a = std::max(0, r - 1), b = std::min(n - 1, r + 1);
  const double d = std::hypot(rail.y[b] - rail.y[a], rail.z[b] - rail.z[a]);
  return b - a == 2 ? 0.5 * d : d;
}

// Radius of the wheel's section along a rail line at a wheelset-frame lateral position: the paper's radius /
// cos(conicity) of the rolling direction, divided by cos^2(yaw) because a yawed wheel meets the line at the yaw
// angle (normal curvature cos^2 of the rolling one; the lateral profile curvature's sin^2 share is left out,
// as the paper leaves the yaw out). Without it a yawed cylinder's h is too deep by 1/cos^2(yaw): 1 % of force
// at 0.1 rad. The floor on cos keeps it finite on the steepest flange faces.
double arc_radius(const WheelSurfacePoint& s, double yaw) {
  const double c = std::cos(yaw);
  return s.radius / (std::max(s.normal_r, 0.05) * c * c);
}

void collect_segments(const GeometryModel& g, const LocationState& st, int side, const Patch& p,
                      std::vector<SegmentInfo>& out) {
  const PoseFrame& f = st.frame();
  const WheelCones& w = g.side[side].wheel;
  const auto& segs = st.segments(side);
  for (int k = p.first_segment; k < p.first_segment + p.segment_count; ++k) {
    const Segment& s = segs[k];
    SegmentInfo info;
    info.line = s.line;
    info.y = s.y;
    info.z = s.z;
    info.L = s.length();
    info.xm = 0.5 * (s.x_t + s.x_l);
    info.mid = {info.xm, s.y, s.z};
    const double Yt = f.to_wheelset({s.x_t, s.y, s.z}).y(), Yl = f.to_wheelset({s.x_l, s.y, s.z}).y();
    const double yaw = st.pose().yaw;
    const double Rt = arc_radius(wheel_surface_at(w, Yt), yaw);
    info.R = 0.5 * (Rt + (Yl == Yt ? Rt : arc_radius(wheel_surface_at(w, Yl), yaw)));  // equal at yaw 0
    info.sagitta = info.R - std::sqrt(std::max(0.0, info.R * info.R - 0.25 * info.L * info.L));
    info.weight = (2.0 / 3.0) * info.L * info.sagitta * line_spacing(g.side[side].rail, s.line);
    info.normal = wheel_inward_normal(w, f, info.mid);
    out.push_back(info);
  }
}

Plane plane_of(const std::vector<SegmentInfo>& infos, const Patch& fallback) {
  Plane pl;
  double W = 0;
  Eigen::Vector3d O = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
  for (const auto& s : infos) {
    W += s.weight;
    O += s.weight * s.mid;
    n += s.weight * s.normal;
  }
  if (W > 0 && n.norm() > 0) {
    pl.O = O / W;
    pl.n = n.normalized();
  } else {  // only tangencies: the paper's nominal point
    pl.O = fallback.point;
    pl.n = -fallback.normal;
  }
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX() - pl.n.x() * pl.n;
  if (t1.norm() < 1e-6) t1 = Eigen::Vector3d::UnitY() - pl.n.y() * pl.n;  // a normal along x: not for wheels
  pl.t1 = t1.normalized();
  pl.t2 = pl.n.cross(pl.t1);
  return pl;
}

// The rectangle of a plane's coordinates (u along t1, v along t2) that holds the segments' end points.
struct Bounds {
  double umin = INFINITY, umax = -INFINITY, vmin = INFINITY, vmax = -INFINITY;
};
Bounds projected_bounds(const std::vector<SegmentInfo>& infos, const Plane& pl) {
  Bounds b;
  for (const auto& s : infos)
    for (double x : {s.xm - 0.5 * s.L, s.xm + 0.5 * s.L}) {
      const Eigen::Vector3d d = Eigen::Vector3d(x, s.y, s.z) - pl.O;
      b.umin = std::min(b.umin, d.dot(pl.t1));
      b.umax = std::max(b.umax, d.dot(pl.t1));
      b.vmin = std::min(b.vmin, d.dot(pl.t2));
      b.vmax = std::max(b.vmax, d.dot(pl.t2));
    }
  return b;
}

// Footprint of a patch for the interaction criterion, in the frame of `ref`.
halfspace::PatchFootprint footprint(const std::vector<SegmentInfo>& infos, const Plane& own, const Plane& ref,
                                  double element) {
  const auto [umin, umax, vmin, vmax] = projected_bounds(infos, own);
  double depth = 0;
  for (const auto& s : infos) depth = std::max(depth, s.sagitta);
  halfspace::PatchFootprint fp;
  const Eigen::Vector3d c = own.O - ref.O;
  fp.x = c.dot(ref.t1);
  fp.y = c.dot(ref.t2);
  fp.half_length = std::max(0.5 * (umax - umin), 0.5 * element);
  fp.half_width = std::max(0.5 * (vmax - vmin), 0.5 * element);
  fp.penetration = std::max(depth, 1e-12);
  return fp;
}

// d(force, moment)/d(z, roll) of a solved area. Rigid perturbations of the wheelset move its surface point X by
// dz e_z + droll a x (X - c), with a the roll axis Rz(yaw) e_x and c the centre; h grows by the motion toward
// the rail, -dX . n, which is linear in the plane coordinates. The pressure response on the contact set
// (normal.hpp) gives dN and the first moments, hence dF = n dN and dM. The plane is held fixed: exact to first
// order for the elastic stiffness, which dominates while the contact does not slide along a curved profile.
void area_sensitivity(const ContactModel& model, const Pose& pose, PatchContact& pc, ContactWorkspace& ws) {
  if (pc.conformal) return conformal_sensitivity(model, pose, pc, ws);
  const halfspace::NormalSolution& sol = pc.solution;
  pc.sensitivity.setZero();
  if (!(sol.force > 0)) return;
  if (sol.pressure.empty()) fail("contact sensitivity: the area's pressure grid was not kept");
  const halfspace::Grid& grid = sol.grid;
  const Eigen::Vector3d c(0, pose.y, pose.z), a(std::cos(pose.yaw), std::sin(pose.yaw), 0);
  const Eigen::Vector3d& n = pc.normal;
  const Eigen::Vector3d oc = (pc.origin - c).cross(n), t1n = pc.t1.cross(n), t2n = pc.t2.cross(n);
  const double k0 = a.dot(oc), ku = a.dot(t1n), kv = a.dot(t2n);
  std::vector<double> dh(static_cast<std::size_t>(grid.size()));
  for (int col = 0; col < 2; ++col) {
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        dh[static_cast<std::size_t>(grid.index(i, j))] = col == 0 ? -n.z() : -(k0 + ku * grid.x(i) + kv * grid.y(j));
    // A Jacobian for Newton steps needs a few digits: at 1e-2 the response agrees with a 1e-8 one to ~1e-5.
    const halfspace::NormalResponse r = model.options().dense
                                          ? halfspace::normal_response_dense(model.material(), sol, dh)
                                          : model.solver().response(sol, dh, ws.normal, 1e-2);
    Eigen::Vector3d dM = oc * r.force + t1n * r.moment_x + t2n * r.moment_y;
    if (col == 0) dM -= Eigen::Vector3d::UnitZ().cross(n) * sol.force;  // the centre moves with z
    pc.sensitivity.block<3, 1>(0, col) = n * r.force;
    pc.sensitivity.block<3, 1>(3, col) = dM;
  }
}

// Separate contact regions of a solution: 8-connected components of {p > 0} carrying >= 0.1 % of the force. The
// contact is cut into runs (maximal intervals of a row in contact); runs of neighbouring rows whose columns touch or
// overlap diagonally are one region.
int contact_regions(const halfspace::NormalSolution& sol) {
  const halfspace::Grid& g = sol.grid;
  if (sol.pressure.empty() || !(sol.force > 0)) return 0;
  struct Run {
    int i0, i1;    // columns
    double force;  // N
  };
  std::vector<Run> runs;
  std::vector<std::size_t> row_start(static_cast<std::size_t>(g.ny) + 1, 0);
  const double dA = g.element_area();
  for (int j = 0; j < g.ny; ++j) {
    row_start[static_cast<std::size_t>(j)] = runs.size();
    const double* p = sol.pressure.data() + static_cast<std::size_t>(g.index(0, j));
    for (int i = 0; i < g.nx;) {
      if (!(p[i] > 0)) {
        ++i;
        continue;
      }
      Run r{i, i, 0.0};
      for (; i < g.nx && p[i] > 0; ++i) r.force += p[i] * dA;
      r.i1 = i - 1;
      runs.push_back(r);
    }
  }
  row_start[static_cast<std::size_t>(g.ny)] = runs.size();
  UnionFind sets;
  sets.reset(static_cast<int>(runs.size()));
  for (std::size_t j = 1; j < static_cast<std::size_t>(g.ny); ++j)
    for (std::size_t a = row_start[j - 1]; a < row_start[j]; ++a)
      for (std::size_t b = row_start[j]; b < row_start[j + 1]; ++b)
        if (runs[b].i0 <= runs[a].i1 + 1 && runs[b].i1 >= runs[a].i0 - 1)
          sets.unite(static_cast<int>(a), static_cast<int>(b));
  std::vector<double> force(runs.size(), 0.0);
  const auto root = [&](std::size_t r) { return static_cast<std::size_t>(sets.find(static_cast<int>(r))); };
  for (std::size_t r = 0; r < runs.size(); ++r) force[root(r)] += runs[r].force;
  int regions = 0;
  for (std::size_t r = 0; r < runs.size(); ++r) regions += root(r) == r && force[r] >= 1e-3 * sol.force;
  return regions;
}

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

// Start pressures for an area in the plane pl from the workspace's last evaluation of that side: the old pressure at
// each new element centre (bilinear), extrapolated linearly in time with the evaluation before it where both were in
// contact and the workspace extrapolates. Without extrapolation, on a grid that is the old one shifted by whole
// elements and carries all of the old pressure, also the old displacements (NaN where the grids do not overlap;
// else empty). False when there is no old area (or warm starts are off).
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

// The load of an area: its penetration, or the request's vertical force with the rows' vertical normal parts n_z as
// weights. The vertical force is sum n_z p dA, and a vertical approach a deepens h by a times `deepening` (to first
// order; on a plane n_z itself; on the curved surface the z part of the wheel's normal, along which h is measured,
// up to a few per mille from the row's bisector normal at the flange root): the solution is the pose's penetration
// problem with h + a deepening, a the multiplier. Rows less upright than kVerticalWeightMin: the penetration.
halfspace::NormalLoad area_load(const ContactRequest& request, const halfspace::Grid& grid,
                              const std::vector<double>& vertical, const std::vector<double>& deepening) {
  if (!request.vertical_force) return halfspace::NormalLoad::penetration();
  // Per element, its row's value (gap weights only where the deepening differs from the weights: the curved surface).
  const bool own_gap = deepening != vertical;
  auto per_element = [&](const std::vector<double>& rows) {
    std::vector<double> e(static_cast<std::size_t>(grid.size()));
    for (int j = 0; j < grid.ny; ++j) std::fill_n(e.begin() + grid.index(0, j), grid.nx, rows[static_cast<std::size_t>(j)]);
    return e;
  };
  for (int j = 0; j < grid.ny; ++j)
    if (!(vertical[static_cast<std::size_t>(j)] >= kVerticalWeightMin) ||
        !(deepening[static_cast<std::size_t>(j)] >= kVerticalWeightMin))
      return halfspace::NormalLoad::penetration();
  halfspace::NormalLoad load = halfspace::NormalLoad::normal_force(*request.vertical_force, per_element(vertical));
  if (own_gap) load.gap_weights = per_element(deepening);
  return load;
}

}  // namespace

halfspace::NormalSolution solve_area_normal(const ContactModel& model, const ContactRequest& request, int side,
                                          const Plane& pl, const halfspace::Grid& grid, const std::vector<double>& h,
                                          const std::vector<double>& vertical, const std::vector<double>& deepening,
                                          ContactWorkspace& ws) {
  PhaseTimer t(ws, ws.times.solve);
  const ContactOptions& opt = model.options();
  halfspace::NormalOptions nopt = opt.normal;
  if (request.tolerance > 0) nopt.tolerance = request.tolerance;
  nopt.estimate = request.estimate;
  std::vector<double> start, displacement;
  if (warm_start(ws, side, pl, grid, start, displacement)) {
    nopt.initial_pressure = start;
    nopt.initial_displacement = displacement;
  }
  const halfspace::NormalLoad load = area_load(request, grid, vertical, deepening);
  return opt.dense ? halfspace::solve_normal_dense(model.material(), grid, h, load, nopt)
                   : model.solver().solve(grid, h, load, ws.normal, nopt);
}

// The potential contact area of a pose exceeds max_elements: either the grid is too fine for the cap or the pose is
// far deeper than any elastic approach (a solve that lost its way, an unreachable load).
[[noreturn]] void too_many_elements(const ContactOptions& opt, const std::vector<SegmentInfo>& all, int side,
                                    const Pose& pose, double nx, double ny) {
  double depth = 0;
  for (const auto& s : all) depth = std::max(depth, s.sagitta);
  const double n = nx * ny;
  const std::string area = fmt::format(
      "the {} wheel's potential contact area at y = {:.4f} mm, z = {:.4f} mm, roll = {:.4f} mrad, yaw = {:.4f} mrad "
      "needs {:.0f} x {:.0f} = {:.0f} elements (about {:.0f} MB), more than max_elements = {}", side_name(side),
      pose.y * 1e3, pose.z * 1e3, pose.roll * 1e3, pose.yaw * 1e3, nx, ny, n, n * kBytesPerElement / 1e6,
      opt.max_elements);
  if (depth > 1e-3)
    fail("contact: {}: the pose is far too deep ({:.2f} mm of inter-penetration; elastic approaches are a fraction of "
         "a mm)", area, depth * 1e3);
  fail("contact: {}: the grid ({:.4g} mm) is too fine for the cap; raise max_elements (about {:.0f} bytes per "
       "element) or use a coarser grid", area, opt.element * 1e3, kBytesPerElement);
}

halfspace::Grid span_grid(const ContactOptions& opt, const IndexSpan& x, const IndexSpan& y,
                        const std::vector<SegmentInfo>& all, int side, const Pose& pose) {
  if (!(x.count * y.count <= opt.max_elements)) too_many_elements(opt, all, side, pose, x.count, y.count);
  halfspace::Grid grid;
  grid.nx = static_cast<int>(x.count);  // each at most max_elements (an int) now
  grid.ny = static_cast<int>(y.count);
  grid.dx = grid.dy = opt.element;
  grid.x0 = x.first * opt.element;
  grid.y0 = y.first * opt.element;
  return grid;
}

// The potential contact area: a grid aligned with the plane origin covering the projected segments plus the margin.
halfspace::Grid area_grid(const ContactOptions& opt, const std::vector<SegmentInfo>& all, const Plane& pl, int side,
                        const Pose& pose) {
  const auto [umin, umax, vmin, vmax] = projected_bounds(all, pl);
  return span_grid(opt, index_span(umin, umax, opt.element, opt.margin), index_span(vmin, vmax, opt.element, opt.margin),
                   all, side, pose);
}

// The rail lines across the grid's lateral range (one beyond each side when the rail has it), projected on the
// plane and ordered across it, each with its h(x): the arcs of its segments, or the arc through its deepest point.
std::vector<LineProfile> line_profiles(const GeometryModel& g, const LocationState& st, int side,
                                       const std::vector<SegmentInfo>& all, const Plane& pl, const halfspace::Grid& grid) {
  const WheelCones& wheel = g.side[side].wheel;
  const RailLines& rail = g.side[side].rail;
  int rmin = rail.count(), rmax = -1;
  for (const auto& s : all) {
    rmin = std::min(rmin, s.line);
    rmax = std::max(rmax, s.line);
  }
  auto v_of = [&](int r) { return (Eigen::Vector3d(0, rail.y[r], rail.z[r]) - pl.O).dot(pl.t2); };
  int rlo = rmin, rhi = rmax;
  while (rlo > 0 && v_of(rlo) > grid.y0) --rlo;
  while (rhi < rail.count() - 1 && v_of(rhi) < grid.y(grid.ny - 1)) ++rhi;
  std::vector<LineProfile> lines(static_cast<std::size_t>(rhi - rlo + 1));
  for (int r = rlo; r <= rhi; ++r) {
    LineProfile& lp = lines[static_cast<std::size_t>(r - rlo)];
    const Eigen::Vector3d d(0, rail.y[r], rail.z[r]);
    lp.v = (d - pl.O).dot(pl.t2);
    lp.u0 = (d - pl.O).dot(pl.t1);
  }
  for (const auto& s : all) lines[static_cast<std::size_t>(s.line - rlo)].arcs.push_back(&s);
  for (int r = rlo; r <= rhi; ++r) {
    LineProfile& lp = lines[static_cast<std::size_t>(r - rlo)];
    if (!lp.arcs.empty()) continue;
    const LineApproach a = line_approach(wheel, st.frame(), rail.y[r], rail.z[r]);
    const WheelSurfacePoint sp = wheel_surface_at(wheel, a.Y);
    lp.R = arc_radius(sp, st.pose().yaw);
    lp.apex = std::min(a.overlap, 0.0) * sp.normal_r;  // a line without a segment is not inside
    lp.x_apex = a.x;
  }
  // The projected lines must be ordered across the plane (they are, unless the plane is far off the rail).
  std::stable_sort(lines.begin(), lines.end(), [](const LineProfile& a, const LineProfile& b) { return a.v < b.v; });
  return lines;
}

// h at the element centres: along each projected line its arcs, linear in v between the two lines bracketing
// the element.
std::vector<double> undeformed_distance(const std::vector<LineProfile>& lines, const Plane& pl, const halfspace::Grid& grid) {
  std::vector<double> vs(lines.size());
  for (std::size_t k = 0; k < lines.size(); ++k) vs[k] = lines[k].v;
  const double t1x = pl.t1.x();  // u = x t1x + u0 along a line
  std::vector<double> h(static_cast<std::size_t>(grid.size()), 0.0);
  for (int j = 0; j < grid.ny; ++j) {
    const double v = grid.y(j);
    const auto it = std::upper_bound(vs.begin(), vs.end(), v);
    std::size_t b = static_cast<std::size_t>(it - vs.begin());
    const std::size_t a = b == 0 ? 0 : b - 1;
    b = std::min(b, vs.size() - 1);
    const LineProfile& la = lines[a];
    const LineProfile& lb = lines[b];
    const double t = (a == b || lb.v == la.v) ? 0.0 : std::clamp((v - la.v) / (lb.v - la.v), 0.0, 1.0);
    for (int i = 0; i < grid.nx; ++i) {
      const double u = grid.x(i);
      const double ha = la.height((u - la.u0) / t1x);
      const double hb = t > 0 ? lb.height((u - lb.u0) / t1x) : 0.0;
      h[static_cast<std::size_t>(grid.index(i, j))] = (1 - t) * ha + t * hb;
    }
  }
  return h;
}

// The located patches of a group and their segments, copied (the result must not depend on the workspace).
void copy_located(const LocationState& st, int side, const std::vector<int>& group, PatchContact& pc) {
  const auto& patches = st.patches(side);
  const auto& segs = st.segments(side);
  for (int p : group) {
    Patch patch = patches[static_cast<std::size_t>(p)];
    const int first = static_cast<int>(pc.segments.size());
    pc.segments.insert(pc.segments.end(), segs.begin() + patch.first_segment,
                       segs.begin() + patch.first_segment + patch.segment_count);
    patch.longest += first - patch.first_segment;
    patch.first_segment = first;
    pc.located.push_back(patch);
  }
}

// Forces, moments and the measures of a solved area.
void area_results(const WheelCones& wheel, const PoseFrame& f, PatchContact& pc) {
  const halfspace::NormalSolution& sol = pc.solution;
  pc.penetration = *std::max_element(pc.h.begin(), pc.h.end());
  pc.regions = contact_regions(sol);
  const Eigen::Vector3d c(0, f.y, f.z);
  pc.normal_force = sol.force;
  pc.force = sol.force * pc.normal;
  pc.point = pc.origin + sol.cop_x * pc.t1 + sol.cop_y * pc.t2;
  pc.moment = (pc.point - c).cross(pc.force);
  pc.angle = contact_angle(pc.side, pc.normal);
  pc.angle_min = pc.angle_max = pc.angle;  // one plane: the pressure acts along one normal
  pc.rolling_radius = wheel_surface_at(wheel, f.to_wheelset(pc.point).y()).radius;
}

PatchContact solve_area(const ContactModel& model, const LocationState& st, int side, const std::vector<int>& group,
                        const std::vector<std::vector<SegmentInfo>>& infos, ContactWorkspace& ws,
                        const ContactRequest& request, std::vector<ContactWorkspace::Previous>& next_previous) {
  const GeometryModel& g = model.geometry();
  const ContactOptions& opt = model.options();
  std::vector<SegmentInfo> all;
  for (int p : group) all.insert(all.end(), infos[p].begin(), infos[p].end());
  const Patch& first = st.patches(side)[static_cast<std::size_t>(group.front())];
  if (opt.surface == ContactSurface::conformal) {  // the curved surface (conformal.cpp)
    PatchContact pc = solve_conformal_area(model, st, side, all, first, ws, request, next_previous);
    copy_located(st, side, group, pc);
    return pc;
  }
  const Plane pl = plane_of(all, first);

  PatchContact pc;
  pc.side = side;
  halfspace::Grid grid;
  {
    PhaseTimer t(ws, ws.times.geometry);
    pc.origin = pl.O;
    pc.normal = pl.n;
    pc.t1 = pl.t1;
    pc.t2 = pl.t2;
    pc.nominal = first.point;
    pc.nominal_angle = contact_angle(side, -first.normal);  // Patch::normal points out of the wheel
    grid = area_grid(opt, all, pl, side, st.pose());
    pc.h = undeformed_distance(line_profiles(g, st, side, all, pl, grid), pl, grid);
  }
  const std::vector<double> vertical(static_cast<std::size_t>(grid.ny), pl.n.z());
  pc.solution = solve_area_normal(model, request, side, pl, grid, pc.h, vertical, vertical, ws);
  {
    PhaseTimer t(ws, ws.times.results);
    copy_located(st, side, group, pc);
    area_results(g.side[side].wheel, st.frame(), pc);
    ++ws.times.areas;
    ws.times.elements += grid.size();
    ws.times.iterations += pc.solution.iterations + pc.solution.coarse_iterations;
  }
  if (request.sensitivity) {
    PhaseTimer t(ws, ws.times.sensitivity);
    area_sensitivity(model, st.pose(), pc, ws);
  }
  next_previous.push_back({pl.O, pl.t1, pl.t2, pl.n, pc.solution.grid, pc.solution.pressure,
                           std::move(pc.solution.displacement)});
  return pc;
}

// The areas of one wheel that are solved together: patches whose separate solutions would interact (and whose
// planes are close enough for one plane to serve them), as groups of patch indices.
std::vector<std::vector<int>> area_groups(const ContactModel& model, const std::vector<std::vector<SegmentInfo>>& infos,
                                          const std::vector<Plane>& planes) {
  const ContactOptions& opt = model.options();
  const int np = static_cast<int>(infos.size());
  UnionFind sets;
  sets.reset(np);
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) {
      if (std::acos(std::clamp(planes[a].n.dot(planes[b].n), -1.0, 1.0)) > opt.merge_angle) continue;
      const auto fa = footprint(infos[a], planes[a], planes[a], opt.element);
      const auto fb = footprint(infos[b], planes[b], planes[a], opt.element);
      if (halfspace::patches_interact(model.material(), fa, fb, opt.merge_tolerance)) sets.unite(a, b);
    }
  std::map<int, std::vector<int>> groups;
  for (int p = 0; p < np; ++p) groups[sets.find(p)].push_back(p);
  std::vector<std::vector<int>> out;
  for (auto& [root, group] : groups) out.push_back(std::move(group));
  return out;
}

// A wheel deeper in its rail than max_penetration (ContactRequest): the pose is a mistake, or the option must be raised.
[[noreturn]] void too_deep(const Pose& pose, int side, double depth, double limit) {
  fail("contact: at y = {:.4f} mm, z = {:.4f} mm, roll = {:.4f} mrad, yaw = {:.4f} mrad the {} wheel and its rail "
       "inter-penetrate {:.4g} mm deep (undeformed profiles), more than max_penetration = {:.4g} mm: wheel-rail contacts "
       "at realistic loads are 0.05-0.3 mm deep and beyond ~1 mm the half-space model no longer holds; check the pose "
       "(z in m, 0 where the centred wheelset first touches, < 0 pressed in) or raise the option max_penetration",
       pose.y * 1e3, pose.z * 1e3, pose.roll * 1e3, pose.yaw * 1e3, side_name(side), depth * 1e3, limit * 1e3);
}

// Why a loaded wheel is past flange climb (plausibility.hpp), or "".
std::string flange_climb(const ContactModel& model, const PoseFrame& f, int side, const WheelContact& wc) {
  const Flange& flange = model.flange(side);
  const SidePlacement& place = model.geometry().track->place[side];
  for (const PatchContact& pc : wc.patches)
    if (pc.normal_force > 0)
      if (std::string why = beyond_steepest(flange, profile_y(place, f.to_wheelset(pc.point).y())); !why.empty()) return why;
  return nadal_exceeded(flange, side, wc.force.y(), wc.force.z());
}

WheelContact solve_wheel_areas(const ContactModel& model, const LocationState& st, int side, ContactWorkspace& ws,
                               const ContactRequest& request) {
  const auto& patches = st.patches(side);
  const std::size_t np = patches.size();
  std::vector<std::vector<SegmentInfo>> infos(np);
  std::vector<Plane> planes;
  std::vector<std::vector<int>> groups;
  {
    PhaseTimer t(ws, ws.times.geometry);
    double depth = 0;
    for (std::size_t p = 0; p < np; ++p) {
      collect_segments(model.geometry(), st, side, patches[p], infos[p]);
      for (const SegmentInfo& s : infos[p]) depth = std::max(depth, s.sagitta);
      planes.push_back(plane_of(infos[p], patches[p]));
    }
    if (depth > request.max_penetration) too_deep(st.pose(), side, depth, request.max_penetration);
    groups = area_groups(model, infos, planes);
  }
  WheelContact wc;
  double rr = 0, N = 0;
  std::vector<ContactWorkspace::Previous> next_previous;
  ContactRequest one_area = request;  // a vertical force can be prescribed to a single area only
  if (groups.size() != 1) one_area.vertical_force.reset();
  for (const auto& group : groups) {
    PatchContact pc = solve_area(model, st, side, group, infos, ws, one_area, next_previous);
    if (request.rolling) solve_area_rolling(model, st.pose(), pc, *request.rolling, ws);
    add_creep(wc.creep, pc);
    wc.force += pc.force;
    wc.moment += pc.moment;
    wc.sensitivity += pc.sensitivity;
    rr += pc.rolling_radius * pc.normal_force;
    N += pc.normal_force;
    wc.patches.push_back(std::move(pc));
  }
  ws.before[side] = ws.extrapolate ? std::move(ws.previous[side]) : std::vector<ContactWorkspace::Previous>{};
  ws.previous[side] = std::move(next_previous);
  wc.rolling_radius = N > 0 ? rr / N : 0.0;
  wc.angle = N > 0 ? contact_angle(side, wc.force) : 0.0;
  if (N > 0) wc.flange_climb = flange_climb(model, st.frame(), side, wc);
  return wc;
}

}  // namespace contact_detail

using namespace contact_detail;

void ContactWorkspace::forget() {
  for (auto& p : previous) p.clear();
  for (auto& p : before) p.clear();
}

double read_max_penetration(OptionReader& r, double fallback) {
  const double v = r.number("max_penetration", fallback);
  if (!(v > 0) || !std::isfinite(v)) fail("{}: max_penetration = {} m must be a positive number", r.context(), v);
  return v;
}

ContactRequest read_contact_request(OptionReader& r) {
  ContactRequest req;
  req.keep_grids = r.boolean("grids").value_or(req.keep_grids);
  req.sensitivity = r.boolean("sensitivity").value_or(req.sensitivity);
  req.max_penetration = read_max_penetration(r, req.max_penetration);
  req.rolling = read_rolling_request(r);
  return req;
}

ContactResult evaluate_contact(const ContactModel& model, const Pose& pose, ContactWorkspace& ws,
                               const ContactRequest& request) {
  if (request.vertical_force) {
    if (!std::isfinite(*request.vertical_force) || !(*request.vertical_force > 0))
      fail("contact: vertical_force = {} N must be a positive number", *request.vertical_force);
    if (request.only_side < 0 || request.sensitivity || request.rolling)
      fail("contact: a vertical force is prescribed to one wheel (only_side), without sensitivities or rolling");
  }
  if (!(request.max_penetration > 0)) fail("contact: max_penetration = {} m must be > 0", request.max_penetration);
  const LocationState& st = [&]() -> const LocationState& {
    PhaseTimer t(ws, ws.times.locate);
    return ws.locator.locate(pose);
  }();
  ++ws.times.evaluations;
  ContactResult res;
  res.pose = pose;
  for (int side : {kLeft, kRight}) {
    if (request.only_side >= 0 && request.only_side != side) continue;
    WheelContact& wc = res.wheel[side];
    wc = solve_wheel_areas(model, st, side, ws, request);
    res.force += wc.force;
    res.moment += wc.moment;
    res.sensitivity += wc.sensitivity;
    add_creep(res.creep, wc.creep);
  }
  if (!request.keep_grids) drop_grids(res);
  return res;
}

double largest_potential_area(const ContactModel& model, const LocationState& st) {
  const ContactOptions& opt = model.options();
  double largest = 0;
  for (int side : {kLeft, kRight})
    for (const Patch& p : st.patches(side)) {
      std::vector<SegmentInfo> infos;
      collect_segments(model.geometry(), st, side, p, infos);
      const auto [umin, umax, vmin, vmax] = projected_bounds(infos, plane_of(infos, p));
      const double n = index_span(umin, umax, opt.element, opt.margin).count *
                       index_span(vmin, vmax, opt.element, opt.margin).count;
      largest = std::max(largest, n);
    }
  return largest;
}

void add_rolling(const ContactModel& model, ContactResult& result, const RollingRequest& request,
                 ContactWorkspace& ws) {
  result.force.setZero();
  result.moment.setZero();
  result.creep = {};
  for (WheelContact& wc : result.wheel) {
    wc.force.setZero();
    wc.moment.setZero();
    wc.creep = {};
    for (PatchContact& pc : wc.patches) {
      solve_area_rolling(model, result.pose, pc, request, ws);
      add_creep(wc.creep, pc);
      wc.force += pc.force;
      wc.moment += pc.moment;
    }
    const int side = &wc == &result.wheel[kLeft] ? kLeft : kRight;
    wc.angle = wc.patches.empty() ? 0.0 : contact_angle(side, wc.force);
    result.force += wc.force;
    result.moment += wc.moment;
    add_creep(result.creep, wc.creep);
  }
}

void add_sensitivity(const ContactModel& model, ContactResult& result, ContactWorkspace& ws) {
  result.sensitivity.setZero();
  for (WheelContact& wc : result.wheel) {
    wc.sensitivity.setZero();
    for (PatchContact& pc : wc.patches) {
      PhaseTimer t(ws, ws.times.sensitivity);
      area_sensitivity(model, result.pose, pc, ws);
      wc.sensitivity += pc.sensitivity;
    }
    result.sensitivity += wc.sensitivity;
  }
}

void drop_grids(ContactResult& result) {
  for (WheelContact& wc : result.wheel)
    for (PatchContact& pc : wc.patches) {
      pc.h = {};
      pc.solution.pressure = {};
      pc.solution.gap = {};
      pc.solution.displacement = {};  // moved to the workspace already; kept empty whatever the path
      if (pc.rolling) drop_grids(*pc.rolling);
    }
}

// ---- results as fields ----

void describe(const PatchContact& pc, FieldSink& out) {
  if (!pc.located.empty()) describe_patch_fields(pc.located.front(), out);
  else out.string("side", side_name(pc.side));
  out.begin_list("segments", pc.segments.size());
  for (const Segment& s : pc.segments) {
    out.item();
    describe(s, out);
    out.end();
  }
  out.end();
  const halfspace::NormalSolution& s = pc.solution;
  out.integer("merged", static_cast<long long>(pc.located.size()));
  out.number("normal_force", pc.normal_force);
  out.number("pressure_integral", s.force);  // sum p dA: the normal force, or more where the normals turn
  out.vec3("force", pc.force);
  out.vec3("moment", pc.moment);
  out.vec3("point", pc.point);
  out.vec3("normal", pc.normal);
  out.number("angle", pc.angle);
  out.string("surface", pc.conformal ? "conformal" : "planar");
  out.number("angle_min", pc.angle_min);
  out.number("angle_max", pc.angle_max);
  out.number("nominal_angle", pc.nominal_angle);
  out.number("area", s.area);
  out.number("pmax", s.max_pressure);
  out.integer("elements", s.elements_in_contact);
  out.integer("regions", pc.regions);
  out.number("penetration", pc.penetration);
  out.number("rolling_radius", pc.rolling_radius);
  out.integer("iterations", s.iterations);
  out.number("complementarity", s.residual.relative);
  out.begin("frame");  // the contact plane: grid coordinates (u, v) are at origin + u t1 + v t2
  out.vec3("origin", pc.origin);
  out.vec3("t1", pc.t1);
  out.vec3("t2", pc.t2);
  out.end();
  out.begin("grid");
  out.integer("nx", s.grid.nx);
  out.integer("ny", s.grid.ny);
  out.number("dx", s.grid.dx);
  out.number("dy", s.grid.dy);
  out.number("x0", s.grid.x0);
  out.number("y0", s.grid.y0);
  out.end();
  if (!s.pressure.empty()) out.grid("pressure", s.pressure.data(), s.grid.nx, s.grid.ny);
  if (!pc.h.empty()) out.grid("h", pc.h.data(), s.grid.nx, s.grid.ny);
  if (pc.rolling) describe(*pc.rolling, out);
  if (pc.conformal) describe_conformal(pc, out);
}

void describe(const WheelContact& wc, FieldSink& out) {
  out.boolean("lifted", !(wc.force.z() > 0));  // the wheel carries no load
  out.boolean("flange_climb", !wc.flange_climb.empty());
  if (!wc.flange_climb.empty()) out.string("flange_climb_reason", wc.flange_climb);
  out.vec3("force", wc.force);
  out.vec3("moment", wc.moment);
  out.number("angle", wc.angle);
  out.number("rolling_radius", wc.rolling_radius);
  describe(wc.creep, out);
  out.begin_list("patches", wc.patches.size());
  for (const PatchContact& pc : wc.patches) {
    out.item();
    describe(pc, out);
    out.end();
  }
  out.end();
}

void describe_sensitivity(const Sensitivity& S, FieldSink& out) {
  out.begin("sensitivity");
  for (int col = 0; col < 2; ++col) {
    const double v[6] = {S(0, col), S(1, col), S(2, col), S(3, col), S(4, col), S(5, col)};
    out.numbers(col == 0 ? "z" : "roll", v, 6);
  }
  out.end();
}

void describe(const Pose& p, FieldSink& out) {
  out.begin("pose");
  out.number("y", p.y);
  out.number("z", p.z);
  out.number("roll", p.roll);
  out.number("yaw", p.yaw);
  out.end();
}

void describe(const ContactResult& c, FieldSink& out, bool sensitivity) {
  if (sensitivity) describe_sensitivity(c.sensitivity, out);
  for (int s : {kLeft, kRight}) {
    out.begin(side_name(s));
    describe(c.wheel[s], out);
    out.end();
  }
  out.vec3("force", c.force);
  out.vec3("moment", c.moment);
  describe(c.creep, out);
  describe(c.pose, out);
}

}  // namespace wrc
