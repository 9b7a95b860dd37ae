// The area pipeline (area.hpp): lay out on the surface, solve the normal problem, resultant, sensitivities, memory.
#include "area.hpp"

#include "warm_start.hpp"

#include "wrc/core/error.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace wrc::areas {
namespace {

// The located patches of a group and their segments, copied (the result must not depend on the workspace).
void copy_located(const AreaInput& in, PatchContact& pc) {
  const auto& patches = in.located.patches(in.side);
  const auto& segs = in.located.segments(in.side);
  for (int p : in.patches) {
    Patch patch = patches[static_cast<std::size_t>(p)];
    const int first = static_cast<int>(pc.segments.size());
    pc.segments.insert(pc.segments.end(), segs.begin() + patch.first_segment,
                       segs.begin() + patch.first_segment + patch.segment_count);
    patch.longest += first - patch.first_segment;
    patch.first_segment = first;
    pc.located.push_back(patch);
  }
}

// The load of an area: its penetration, or the predictor's vertical force with the rows' vertical normal parts n_z as
// weights. The vertical force is sum n_z p dA, and a vertical approach a deepens h by a times `deepening` (to first
// order; on a plane n_z itself; on the curved surface the z part of the wheel's normal, along which h is measured,
// up to a few per mille from the row's bisector normal at the flange root): the solution is the pose's penetration
// problem with h + a deepening, a the multiplier. Rows less upright than kVerticalWeightMin: the penetration.
halfspace::NormalLoad area_load(const AreaSolve& how, const halfspace::Grid& grid, const std::vector<double>& vertical,
                                const std::vector<double>& deepening, const std::vector<double>& gain) {
  if (!how.vertical_force) return halfspace::NormalLoad::penetration();
  // Per element, its row's value (gap weights only where the deepening differs from the weights: the curved surface,
  // or h's normal_depth slope h_gain on a curved steep face).
  const bool curved = std::any_of(gain.begin(), gain.end(), [](double g) { return g != 1.0; });
  const bool own_gap = deepening != vertical || curved;
  auto per_element = [&](const std::vector<double>& rows) {
    std::vector<double> e(static_cast<std::size_t>(grid.size()));
    for (int j = 0; j < grid.ny; ++j)
      std::fill_n(e.begin() + grid.index(0, j), grid.nx, rows[static_cast<std::size_t>(j)]);
    return e;
  };
  for (int j = 0; j < grid.ny; ++j)
    if (!(vertical[static_cast<std::size_t>(j)] >= kVerticalWeightMin) ||
        !(deepening[static_cast<std::size_t>(j)] >= kVerticalWeightMin))
      return halfspace::NormalLoad::penetration();
  halfspace::NormalLoad load = halfspace::NormalLoad::normal_force(*how.vertical_force, per_element(vertical));
  if (own_gap) {
    load.gap_weights = per_element(deepening);
    if (curved)
      for (std::size_t e = 0; e < load.gap_weights.size(); ++e) load.gap_weights[e] *= gain[e];
  }
  return load;
}

// The normal problem of one area on its layout, at the evaluation's tolerance, warm-started from `from` if given, else
// from the workspace's last evaluation of that side (extrapolated with the one before when the workspace extrapolates).
halfspace::NormalSolution solve_normal(const ContactModel& model, const AreaSolve& how, int side, const AreaLayout& l,
                                       const std::vector<double>& h, const std::vector<double>& gain,
                                       ContactWorkspace& ws, std::span<const double> from = {}) {
  PhaseTimer t(ws, ws.times.solve);
  const ContactOptions& opt = model.options();
  halfspace::NormalOptions nopt = opt.normal;
  if (how.tolerance > 0) nopt.tolerance = how.tolerance;
  nopt.estimate = how.estimate;
  std::vector<double> start, displacement;
  if (!from.empty()) {
    nopt.initial_pressure = from;
  } else if (warm_start(ws, side, l.frame, l.grid, start, displacement)) {
    nopt.initial_pressure = start;
    nopt.initial_displacement = displacement;
  }
  const halfspace::NormalLoad load = area_load(how, l.grid, l.vertical, l.deepening, gain);
  return opt.dense ? halfspace::solve_normal_dense(model.material(), l.grid, h, load, nopt)
                   : model.solver().solve(l.grid, h, load, ws.normal, nopt);
}

// A prediction's rows turned to the approach a it predicts. Its vertical force there is sum n_z(a) p dA, the rows'
// normals turning with the approach (AreaLayout::turning, dn/da: the wheel's normal foot slides), which the solve's
// fixed weights n_z miss by a sum dn_z/da p dA: to first order the predicted approach is off by the relative
// sum dn_z/da p dA / k, k the area's vertical stiffness (6.6e-4 at the S1002 flange root). So the rows are turned to
// n + a dn/da, normalised (the prediction's result then holds the rows of the approach it predicts), and the area is
// solved again for the force with their n_z as weights, from the first solution (a few CG iterations): its approach
// a' then misses the exact one by the second order, (a' - a) dn_z/da against n_z. Skipped (false) for an estimate,
// without turning, and where a sum dn_z/da p dA is below a tenth of the solve's tolerance times the force.
bool turn_rows(const AreaSolve& how, double tolerance, AreaLayout& l, PatchContact& pc) {
  const halfspace::NormalSolution& sol = pc.solution;
  if (!how.vertical_force || how.estimate || l.turning.empty() || !pc.conformal ||
      sol.load.control != halfspace::NormalLoad::Control::force)
    return false;
  const halfspace::Grid& g = sol.grid;
  const double a = sol.approach;
  double term = 0;
  for (int j = 0; j < g.ny; ++j) {
    double P = 0;
    for (int i = 0; i < g.nx; ++i) P += sol.pressure[static_cast<std::size_t>(g.index(i, j))];
    term += a * l.turning[static_cast<std::size_t>(j)].y() * P * g.element_area();
  }
  if (!(std::abs(term) > 0.1 * tolerance * *how.vertical_force)) return false;
  ConformalSurface& surf = *pc.conformal;
  for (std::size_t j = 0; j < l.turning.size(); ++j) {
    const Eigen::Vector2d n = (Eigen::Vector2d(surf.normal_y[j], surf.normal_z[j]) + a * l.turning[j]).normalized();
    surf.normal_y[j] = n.x();
    surf.normal_z[j] = l.vertical[j] = n.y();
  }
  return true;
}

}  // namespace

namespace {

// The contact regions of a solution carrying >= 0.1 % of its force, and FASTSIM's ellipse of the one carrying the
// most (halfspace/ellipse.hpp): one pass over the contact. `all`, `label`: every region's ellipse and each element's
// region, as equivalent_ellipses gives them.
struct Regions {
  int count = 0;
  std::optional<halfspace::EquivalentEllipse> largest;
  std::vector<halfspace::EquivalentEllipse> all;
  std::vector<int> label;
  halfspace::RegionSpan span;  // the smallest spans, each way, of the regions that matter (PatchContact::span_*)
};
// A region's pressure matters to the area's pmax and area when it holds the peak or carries this share of the force.
constexpr double kSpanForceShare = 0.1;
Regions find_regions(const halfspace::NormalSolution& sol) {
  Regions r;
  if (sol.pressure.empty() || !(sol.force > 0)) return r;
  r.all = halfspace::equivalent_ellipses(sol.grid, sol.pressure, r.label);
  auto peak = std::find(sol.pressure.begin(), sol.pressure.end(), sol.max_pressure);  // stops there: cheaper
  if (peak == sol.pressure.end()) peak = std::max_element(sol.pressure.begin(), sol.pressure.end());
  const int peak_region = r.label[static_cast<std::size_t>(peak - sol.pressure.begin())];
  std::vector<int> judged;  // the regions whose spans judge the area's (at most 1 + 1 / kSpanForceShare)
  for (std::size_t k = 0; k < r.all.size(); ++k) {
    const halfspace::EquivalentEllipse& e = r.all[k];
    r.count += e.force >= 1e-3 * sol.force;
    if (static_cast<int>(k) == peak_region || e.force >= kSpanForceShare * sol.force)
      judged.push_back(static_cast<int>(k));
    if (!r.largest || e.force > r.largest->force) r.largest = e;
  }
  if (r.count == 0) return r;
  r.span = {sol.grid.nx, sol.grid.ny};
  for (const halfspace::RegionSpan& s : halfspace::region_spans(sol.grid, r.label, judged))
    r.span = {std::min(r.span.x, s.x), std::min(r.span.y, s.y)};
  return r;
}

}  // namespace

int contact_regions(const halfspace::NormalSolution& sol) { return find_regions(sol).count; }

namespace {
// The area's contact ellipses (PatchContact::ellipses) at its centre of pressure.
void add_ellipses(const ContactModel& model, double wheel_y, PatchContact& pc) {
  const ProfilePoint pp = profile_point(model.geometry(), pc.side, pc.point, wheel_y, pc.rolling_radius);
  pc.ellipses = halfspace::hertz_ellipses(
      halfspace::wheel_rail_curvature(pc.rolling_radius, pc.angle, pp.wheel_curvature, pp.rail_curvature),
      pc.normal_force, model.material());
}
}  // namespace

PatchContact solve_area(const AreaInput& in, const AreaSolve& how, ContactWorkspace& ws,
                        std::vector<ContactWorkspace::Previous>& next_previous) {
  const AreaSurface& surface = surface_for(in.model.options().surface);
  PatchContact pc;
  pc.side = in.side;
  pc.nu = in.model.material().nu;
  pc.nominal = in.first.point;
  pc.nominal_angle = contact_angle(in.side, -in.first.normal);  // Patch::normal points out of the wheel
  AreaLayout layout;
  {
    PhaseTimer t(ws, ws.times.geometry);
    layout = surface.lay_out(in, pc);
  }
  pc.solution = solve_normal(in.model, how, in.side, layout, pc.h, pc.h_gain, ws);
  int iterations = 0;  // of a first solve, which turn_rows corrects
  if (turn_rows(how, how.tolerance > 0 ? how.tolerance : in.model.options().normal.tolerance, layout, pc)) {
    iterations = pc.solution.iterations + pc.solution.coarse_iterations;
    const std::vector<double> first = std::move(pc.solution.pressure);
    pc.solution = solve_normal(in.model, how, in.side, layout, pc.h, pc.h_gain, ws, first);
  }
  {
    PhaseTimer t(ws, ws.times.results);
    const PoseFrame& f = in.located.frame();
    copy_located(in, pc);
    surface.resultant(f, pc);
    pc.penetration = *std::max_element(pc.h.begin(), pc.h.end());
    Regions regions = find_regions(pc.solution);
    pc.regions = regions.count;
    pc.span_x = regions.span.x;
    pc.span_y = regions.span.y;
    pc.region_ellipses = std::move(regions.all);
    pc.region_label = std::move(regions.label);
    const double wheel_y = f.to_wheelset(pc.point).y();
    pc.rolling_radius = wheel_surface_at(in.model.geometry().side[in.side].wheel, wheel_y).radius;
    add_ellipses(in.model, wheel_y, pc);
    pc.ellipses.ellipse = regions.largest;
    ++ws.times.areas;
    ws.times.elements += layout.grid.size();
    ws.times.iterations += iterations + pc.solution.iterations + pc.solution.coarse_iterations;
  }
  if (how.sensitivity) {
    PhaseTimer t(ws, ws.times.sensitivity);
    area_sensitivity(in.model, in.located.pose(), pc, ws);
  }
  const Plane& k = layout.frame;
  next_previous.push_back({k.O, k.t1, k.t2, k.n, pc.solution.grid, pc.solution.pressure,
                           std::move(pc.solution.displacement), {}, {}, {}});
  return pc;
}

RigidMotion pose_motion(const Pose& pose, int coordinate) {
  RigidMotion m;
  switch (coordinate) {
    case kPoseY: m.translation = Eigen::Vector3d::UnitY(); break;
    case kPoseZ: m.translation = Eigen::Vector3d::UnitZ(); break;
    case kPoseRoll: m.rotation = Eigen::Vector3d(std::cos(pose.yaw), std::sin(pose.yaw), 0); break;
    case kPoseYaw: m.rotation = Eigen::Vector3d::UnitZ(); break;
    default: fail("pose_motion: coordinate {} is not 0 (y), 1 (z), 2 (roll) or 3 (yaw)", coordinate);
  }
  return m;
}

namespace {
// The area's normal force and its moment (the creep force taken out when the area rolls).
Eigen::Vector3d normal_part(const PatchContact& pc) {
  return pc.rolling ? Eigen::Vector3d(pc.force - pc.rolling->force) : pc.force;
}

// dh of a rigid motion along the wheel's own normal at every element: the wheel's surface there (a surface of
// revolution about the axle) moves by dX = T + W x (X - c) and the gap along the direction h is measured in (the
// plane's normal; on the curved surface the wheel's normal) closes by dX . n_w / (n_w . n_h).
void wheel_motion(const ContactModel& model, const Pose& pose, const PatchContact& pc, const RigidMotion& m,
                  std::vector<double>& dh) {
  const AreaSurface& surface = surface_of(pc);
  const WheelCones& wheel = model.geometry().side[static_cast<std::size_t>(pc.side)].wheel;
  const PoseFrame frame(pose);
  const Eigen::Vector3d c(0, pose.y, pose.z);
  const halfspace::Grid& g = pc.solution.grid;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Eigen::Vector3d X = surface.element_point(pc, i, j), n = wheel_inward_normal(wheel, frame, X);
      const double along = pc.conformal ? 1.0 : n.dot(pc.normal);
      const auto e = static_cast<std::size_t>(g.index(i, j));
      dh[e] = -(m.translation + m.rotation.cross(X - c)).dot(n) / along * pc.h_gain[e];
    }
}

// A conformal area's h and origin differenced over its layouts at the pose -+ kLayoutStep in one coordinate (the
// geometry alone: relocated, laid out on the same lattice, no solve): dh where both layouts reach the element (the
// others keep `dh`), and the origin's motion.
void layout_motion(const ContactModel& model, const Pose& pose, const PatchContact& pc, int coordinate,
                   ContactWorkspace& ws, std::vector<double>& dh, Eigen::Vector2d& dref) {
  ConformalLayoutAt at[2];
  for (int k = 0; k < 2; ++k) {
    Pose p = pose;
    double* coordinates[4] = {&p.y, &p.z, &p.roll, &p.yaw};
    *coordinates[coordinate] += (k == 0 ? -1 : 1) * kLayoutStep;
    at[k] = conformal_layout_at(model, ws.locator.locate(p), pc);
  }
  for (std::size_t q = 0; q < dh.size(); ++q)
    if (std::isfinite(at[0].h[q]) && std::isfinite(at[1].h[q])) dh[q] = (at[1].h[q] - at[0].h[q]) / (2 * kLayoutStep);
  dref.setZero();
  if (at[0].origin.allFinite() && at[1].origin.allFinite()) dref = (at[1].origin - at[0].origin) / (2 * kLayoutStep);
}

// The normal response to dh: the change of the normal force and of its moment about the centre (moving by T).
NormalColumn respond(const ContactModel& model, const Pose& pose, const PatchContact& pc,
                     const halfspace::NormalSolution& sol, const RigidMotion& m, std::vector<double> dh,
                     ContactWorkspace& ws, double tolerance) {
  NormalColumn col;
  halfspace::NormalResponse r = model.options().dense
                                    ? halfspace::normal_response_dense(model.material(), sol, dh)
                                    : model.solver().response(sol, dh, ws.normal, tolerance);
  surface_of(pc).response(pc, pose, r, col.dF, col.dM);
  col.dM -= m.translation.cross(normal_part(pc));  // the centre moves
  col.dp = std::move(r.pressure);
  col.dh = std::move(dh);
  return col;
}

// The rows' motion of the Newton steps' sensitivities (surface.hpp).
NormalColumn column_of(const ContactModel& model, const Pose& pose, const PatchContact& pc,
                       const halfspace::NormalSolution& sol, int coordinate, ContactWorkspace& ws, double tolerance) {
  std::vector<double> dh(static_cast<std::size_t>(sol.grid.size()), 0.0);
  if (!(sol.force > 0)) return {.dp = dh, .dh = dh, .dn = {}};
  if (sol.pressure.empty()) fail("contact sensitivity: the area's pressure grid was not kept");
  const RigidMotion m = pose_motion(pose, coordinate);
  surface_of(pc).motion(pc, pose, m, dh);
  return respond(model, pose, pc, sol, m, std::move(dh), ws, tolerance);
}
}  // namespace

NormalColumn normal_column(const ContactModel& model, const Pose& pose, const PatchContact& pc, int coordinate,
                           ContactWorkspace& ws, double tolerance) {
  const halfspace::NormalSolution& sol = pc.solution;
  std::vector<double> dh(static_cast<std::size_t>(sol.grid.size()), 0.0);
  if (!(sol.force > 0)) return {.dp = dh, .dh = dh, .dn = {}};
  if (sol.pressure.empty()) fail("contact sensitivity: the area's pressure grid was not kept");
  const RigidMotion m = pose_motion(pose, coordinate);
  wheel_motion(model, pose, pc, m, dh);
  Eigen::Vector2d dref = Eigen::Vector2d::Zero();
  if (pc.conformal) layout_motion(model, pose, pc, coordinate, ws, dh, dref);
  NormalColumn col = respond(model, pose, pc, sol, m, std::move(dh), ws, tolerance);
  col.dref = dref;
  if (pc.conformal) {
    row_turning(model, pose, pc, coordinate, col.dn);
    Eigen::Vector3d dF, dM;
    turning_wrench(pc, pose, col.dn, dF, dM);
    col.dF += dF;
    col.dM += dM;
  }
  return col;
}

void area_sensitivity(const ContactModel& model, const Pose& pose, PatchContact& pc, ContactWorkspace& ws) {
  pc.sensitivity.setZero();
  for (int col = 0; col < 2; ++col) {
    // A Jacobian for Newton steps needs a few digits: at 1e-2 the response agrees with a 1e-8 one to ~1e-5.
    const NormalColumn c = column_of(model, pose, pc, pc.solution, col == 0 ? kPoseZ : kPoseRoll, ws, 1e-2);
    pc.sensitivity.block<3, 1>(0, col) = c.dF;
    pc.sensitivity.block<3, 1>(3, col) = c.dM;
  }
}

double vertical_stiffness(const ContactModel& model, const Pose& pose, const PatchContact& pc, ContactWorkspace& ws) {
  if (!(pc.solution.force > 0) || pc.solution.pressure.empty()) return 0;
  halfspace::NormalSolution sol = pc.solution;
  sol.load = {};  // the response of the pressure at its approach (a predictor's solution holds its force instead)
  return -column_of(model, pose, pc, sol, kPoseZ, ws, 1e-2).dF.z();  // the approach moves the wheel down
}

}  // namespace wrc::areas
