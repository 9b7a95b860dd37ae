// The contact of a wheelset pose (wrc/wheelset/contact.hpp): locate the patches, group them into areas, solve each area
// (the area pipeline, area.hpp), add up the wheels' totals; the model, the workspace, the options and the fields.
#include "wrc/wheelset/contact.hpp"

#include "area.hpp"
#include "free_rolling.hpp"
#include "tangential_step.hpp"
#include "vertical_load.hpp"

#include "wrc/halfspace/interaction.hpp"
#include "wrc/geometry/wheel_surface.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/union_find.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
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

void validate_element(double element, std::string_view context) {
  if (!(element >= kElementMin && element <= kElementMax))
    fail("{}: the element size grid = {:.6g} m must be in [{}, {}] m ({} um .. {} mm)", context, element, kElementMin,
         kElementMax, kElementMin * 1e6, kElementMax * 1e3);
}

ContactModel::ContactModel(std::shared_ptr<const GeometryModel> geometry, const halfspace::Material& material,
                           const ContactOptions& options)
    : geometry_(std::move(geometry)), options_(options), solver_(material), rolling_(material) {
  if (!geometry_) fail("contact model: no geometry");
  if (geometry_->track)
    for (int s : {kLeft, kRight}) flange_[static_cast<std::size_t>(s)] = geometry_->side[s].flange;
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
  validate_element(options.element, "contact model");
  if (options.max_elements < 1) fail("contact model: max_elements = {} must be >= 1", options.max_elements);
  if (options.margin < 1 || options.margin > 100)
    fail("contact model: margin must be 1..100 elements, got {}", options.margin);
  if (!(options.merge_tolerance > 0) || !std::isfinite(options.merge_tolerance))
    fail("contact model: merge_tolerance must be > 0, got {}", options.merge_tolerance);
  if (!(options.normal.tolerance >= 1e-14 && options.normal.tolerance < 1e-2))
    fail("contact model: the normal solver's tolerance must be in [1e-14, 1e-2[, got {}", options.normal.tolerance);
  // The angle between two normals is at most pi: a larger value is no stronger, and most likely degrees.
  if (const double a = merge_angle_of(options); !(a >= 0 && a <= std::numbers::pi))
    fail("contact model: merge_angle = {} must be in [0, pi] rad (the angle between two contact normals){}", a,
         a > std::numbers::pi ? fmt::format("; {} degrees would be {:.4g} rad", a, a * std::numbers::pi / 180) : "");
}

ContactWorkspace::ContactWorkspace(const ContactModel& model) : locator(model.geometry_ptr()) {}

ContactWorkspace::ContactWorkspace(const ContactModel& model, std::unique_ptr<PoseSearch> search)
    : locator(model.geometry_ptr(), std::move(search)) {}

namespace areas {
namespace {

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

// The areas of one wheel that are solved together: patches whose separate solutions would interact (and whose
// planes are close enough for one plane to serve them), as groups of patch indices.
std::vector<std::vector<int>> area_groups(const ContactModel& model, const std::vector<std::vector<SegmentInfo>>& infos,
                                          const std::vector<Plane>& planes) {
  const ContactOptions& opt = model.options();
  const double merge_angle = merge_angle_of(opt);
  const int np = static_cast<int>(infos.size());
  UnionFind sets;
  sets.reset(np);
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) {
      if (std::acos(std::clamp(planes[a].n.dot(planes[b].n), -1.0, 1.0)) > merge_angle) continue;
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

// A wheel deeper in its rail than max_penetration (ContactRequest): a mistaken pose, or the option is to be raised.
[[noreturn]] void too_deep(const Pose& pose, int side, double depth, double limit) {
  fail("contact: at y = {:.4f} mm, z = {:.4f} mm, roll = {:.4f} mrad, yaw = {:.4f} mrad the {} wheel and its rail "
       "inter-penetrate {:.4g} mm deep (undeformed profiles), more than max_penetration = {:.4g} mm: wheel-rail "
       "contacts at realistic loads are 0.05-0.3 mm deep and beyond ~1 mm the half-space model no longer holds; check "
       "the pose (z in m, 0 where the centred wheelset first touches, < 0 pressed in) or raise the option "
       "max_penetration",
       pose.y * 1e3, pose.z * 1e3, pose.roll * 1e3, pose.yaw * 1e3, side_name(side), depth * 1e3, limit * 1e3);
}

// Why a loaded wheel is past flange climb (plausibility.hpp), or "".
std::string flange_climb(const ContactModel& model, const PoseFrame& f, int side, const WheelContact& wc) {
  const Flange& flange = model.flange(side);
  const SidePlacement& place = model.geometry().track->place[side];
  for (const PatchContact& pc : wc.patches)
    if (pc.normal_force > 0)
      if (std::string why = beyond_steepest(flange, profile_y(place, f.to_wheelset(pc.point).y())); !why.empty())
        return why;
  return nadal_exceeded(flange, side, wc.force.y(), wc.force.z());
}

// The located patches of one wheel, their segments and the groups of patches solved as one area each.
struct WheelAreas {
  std::vector<std::vector<SegmentInfo>> segments;  // per patch
  std::vector<std::vector<int>> groups;            // patch indices
};

WheelAreas group_areas(const ContactModel& model, const LocationState& st, int side, double max_penetration,
                       ContactWorkspace& ws) {
  PhaseTimer t(ws, ws.times.geometry);
  const auto& patches = st.patches(side);
  WheelAreas a;
  a.segments.resize(patches.size());
  std::vector<Plane> planes;
  double depth = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    collect_segments(model.geometry(), st, side, patches[p], a.segments[p]);
    for (const SegmentInfo& s : a.segments[p]) depth = std::max(depth, s.sagitta);
    planes.push_back(plane_of(a.segments[p], patches[p]));
  }
  if (depth > max_penetration) too_deep(st.pose(), side, depth, max_penetration);
  a.groups = area_groups(model, a.segments, planes);
  return a;
}

// A solved area joins its wheel's totals.
void add_area(WheelContact& wc, PatchContact&& pc) {
  add_creep(wc.creep, pc);
  wc.force += pc.force;
  wc.moment += pc.moment;
  wc.sensitivity += pc.sensitivity;
  wc.patches.push_back(std::move(pc));
}

bool free_rolling(const RollingRequest& request) { return request.kinematics && request.kinematics->free_rolling; }

// The creep moments about the axle and the spin the areas were solved at.
void finish_creep(const ContactModel& model, ContactResult& result, const RollingRequest& request) {
  const Eigen::Vector3d axle = PoseFrame(result.pose).matrix().col(1);
  for (WheelContact& wc : result.wheel) wc.creep.axle_torque = wc.creep.moment.dot(axle);
  result.creep.axle_torque = result.creep.moment.dot(axle);
  result.omega.reset();
  if (const auto& k = request.kinematics)
    result.omega = k->omega.value_or(k->V / model.geometry().track->params.radius);
}

// The areas of one wheel through the pipeline, their tangential problems when `roll_areas`, the wheel's totals; the
// workspace remembers the areas for the next evaluation.
WheelContact wheel_contact(const ContactModel& model, const LocationState& st, int side, ContactWorkspace& ws,
                           const ContactRequest& request, const VerticalLoad* load, bool roll_areas) {
  WheelAreas located = group_areas(model, st, side, request.max_penetration, ws);
  AreaSolve how;
  how.tolerance = request.tolerance;
  how.sensitivity = request.sensitivity;
  if (load && located.groups.size() == 1) how.vertical_force = load->force;  // a single area only
  how.estimate = load && load->estimate;
  WheelContact wc;
  std::vector<ContactWorkspace::Previous> next_previous, next_tangential;
  for (const std::vector<int>& group : located.groups) {
    std::vector<SegmentInfo> all;
    for (int p : group)  // each patch is in one group: its segments (and their knots) are moved, not copied
      all.insert(all.end(), std::make_move_iterator(located.segments[p].begin()),
                 std::make_move_iterator(located.segments[p].end()));
    const AreaInput in{model, st, side, group, all, st.patches(side)[static_cast<std::size_t>(group.front())]};
    PatchContact pc = solve_area(in, how, ws, next_previous);
    if (roll_areas) solve_area_rolling(model, st.pose(), pc, *request.rolling, ws, next_tangential);
    add_area(wc, std::move(pc));
  }
  if (roll_areas) {  // as the normal problem's areas: the one before kept for the next step's extrapolation
    ws.tangential_before[side].clear();
    if (ws.extrapolate) ws.tangential_before[side] = std::move(ws.tangential[side]);
    ws.tangential[side] = std::move(next_tangential);
  }
  ws.before[side] = ws.extrapolate ? std::move(ws.previous[side]) : std::vector<ContactWorkspace::Previous>{};
  ws.previous[side] = std::move(next_previous);
  double rr = 0, N = 0;
  for (const PatchContact& pc : wc.patches) {
    rr += pc.rolling_radius * pc.normal_force;
    N += pc.normal_force;
  }
  wc.rolling_radius = N > 0 ? rr / N : 0.0;
  wc.angle = N > 0 ? contact_angle(side, wc.force) : 0.0;
  if (N > 0) wc.flange_climb = flange_climb(model, st.frame(), side, wc);
  return wc;
}

// evaluate_contact, with the predictor's load when given: locate, then each wheel's areas.
ContactResult evaluate(const ContactModel& model, const Pose& pose, ContactWorkspace& ws, const ContactRequest& request,
                       const VerticalLoad* load) {
  request.validate(model.options().check_magnitudes, model.geometry().track->params.radius);
  const LocationState& st = [&]() -> const LocationState& {
    PhaseTimer t(ws, ws.times.locate);
    return ws.locator.locate(pose);
  }();
  ++ws.times.evaluations;
  // Free rolling finds its spin once both wheels' normal problems are solved; otherwise each area rolls when solved.
  const bool free_spin = request.rolling && free_rolling(*request.rolling);
  const bool roll_areas = request.rolling && !free_spin;
  ContactResult res;
  res.pose = pose;
  for (int side : {kLeft, kRight}) {
    if (request.only_side >= 0 && request.only_side != side) continue;
    WheelContact& wc = res.wheel[side];
    wc = wheel_contact(model, st, side, ws, request, load, roll_areas);
    res.force += wc.force;
    res.moment += wc.moment;
    res.sensitivity += wc.sensitivity;
    add_creep(res.creep, wc.creep);
  }
  if (free_spin) solve_free_rolling(model, res, *request.rolling, ws);
  else if (roll_areas) finish_creep(model, res, *request.rolling);
  if (request.jacobian) add_jacobian(model, res, request.rolling, ws);
  if (!request.keep_grids) drop_grids(res);
  return res;
}

}  // namespace

ContactResult evaluate_vertical_load(const ContactModel& model, const Pose& pose, ContactWorkspace& ws,
                                     const ContactRequest& request, const VerticalLoad& load) {
  if (!std::isfinite(load.force) || !(load.force > 0))
    fail("contact: a vertical load of {} N must be a positive number", load.force);
  if (request.only_side < 0 || request.sensitivity || request.jacobian || request.rolling)
    fail("contact: a vertical force is prescribed to one wheel (only_side), without sensitivities or rolling");
  return evaluate(model, pose, ws, request, &load);
}

}  // namespace areas

using namespace areas;

void ContactWorkspace::forget() {
  for (auto& p : previous) p.clear();
  for (auto& p : before) p.clear();
  for (auto& p : tangential) p.clear();
  for (auto& p : tangential_before) p.clear();
  spin.reset();
}

double read_max_penetration(OptionReader& r, double fallback) {
  const double v = r.number("max_penetration", {"m", "deepest inter-penetration of a wheel accepted"}, fallback);
  if (r.documenting()) return v;
  if (!(v > 0) || !std::isfinite(v)) fail("{}: max_penetration = {} m must be a positive number", r.context(), v);
  return v;
}

bool read_sensitivity(OptionReader& r) {
  return r.boolean("sensitivity", {"-", "each wheel's jacobian by the creepages and the pose (ws:wheel: and "
                                        "jacobian_fz, Fz held); ws:contact: also d(force, moment)/d(z, roll) of "
                                        "both wheels"}, false);
}

ContactRequest read_contact_request(OptionReader& r) {
  ContactRequest req;
  req.keep_grids = r.boolean("grids", {"-", "keep the pressure and h grids in the result"}, req.keep_grids);
  req.sensitivity = req.jacobian = read_sensitivity(r);
  req.max_penetration = read_max_penetration(r, req.max_penetration);
  req.rolling = read_rolling_request(r);
  return req;
}

void ContactRequest::validate(bool plausible, double r0) const {
  if (rolling) rolling->validate("contact", plausible, r0);
  if (rolling && free_rolling(*rolling) && (only_side != -1 || jacobian))
    fail("contact: free_rolling balances the axle torque of both wheels at one omega: not with {}", only_side != -1
         ? "only_side (one wheel)" : "sensitivity (the Jacobian would hold omega fixed; give the omega it found)");
  if (!(max_penetration > 0)) fail("contact: max_penetration = {} m must be > 0", max_penetration);
  if (!(tolerance >= 0 && tolerance <= 1e-2))
    fail("contact: tolerance = {} must be in [0, 1e-2] (relative; 0: the model's)", tolerance);
  if (only_side != -1 && only_side != kLeft && only_side != kRight)
    fail("contact: only_side = {} must be -1 (both wheels), {} (left) or {} (right)", only_side, +kLeft, +kRight);
}

ContactResult evaluate_contact(const ContactModel& model, const Pose& pose, ContactWorkspace& ws,
                               const ContactRequest& request) {
  return areas::evaluate(model, pose, ws, request, nullptr);
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
  if (free_rolling(request)) return solve_free_rolling(model, result, request, ws);
  result.force.setZero();
  result.moment.setZero();
  result.creep = {};
  for (WheelContact& wc : result.wheel) {
    wc.force.setZero();
    wc.moment.setZero();
    wc.creep = {};
    std::vector<ContactWorkspace::Previous> next;
    for (PatchContact& pc : wc.patches) {
      solve_area_rolling(model, result.pose, pc, request, ws, next);
      add_creep(wc.creep, pc);
      wc.force += pc.force;
      wc.moment += pc.moment;
    }
    const int side = &wc == &result.wheel[kLeft] ? kLeft : kRight;
    if (!wc.patches.empty()) ws.tangential[side] = std::move(next), ws.tangential_before[side].clear();
    wc.angle = wc.patches.empty() ? 0.0 : contact_angle(side, wc.force);
    result.force += wc.force;
    result.moment += wc.moment;
    add_creep(result.creep, wc.creep);
  }
  finish_creep(model, result, request);
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

void drop_grids(ContactResult& result, bool keep_rows) {
  for (WheelContact& wc : result.wheel)
    for (PatchContact& pc : wc.patches) {
      pc.h = {};
      pc.h_gain = {};
      pc.region_ellipses = {};
      pc.region_label = {};
      pc.solution.pressure = {};
      pc.solution.gap = {};
      pc.solution.displacement = {};  // moved to the workspace already; kept empty whatever the path
      if (pc.rolling) drop_grids(*pc.rolling, keep_rows);
    }
}

std::string resolution_note(const WheelContact& wc) {
  for (std::size_t k = 0; k < wc.patches.size(); ++k) {
    const PatchContact& pc = wc.patches[k];
    if (resolved(pc)) continue;
    const halfspace::Grid& g = pc.solution.grid;
    // m: its width the narrower way, at least (its outermost elements' centres lie inside it; one element: its size)
    const double wide = std::min(std::max(pc.span_x - 1, 1) * g.dx, std::max(pc.span_y - 1, 1) * g.dy);
    return fmt::format(
        "the {} wheel's contact area {} spans only {} x {} elements (along t1 x t2, of its regions that hold its "
        "peak or 10 % of its force) of {:.3g} mm: its peak pressure ({:.0f} MPa) and area are not resolved by the "
        "grid (Hertzian contacts spanning 1-3 elements: pmax up to 74 % off); grid = {:.2g}e-3 or finer spans it "
        "with about {} elements",
        side_name(pc.side), k + 1, pc.span_x, pc.span_y, g.dx * 1e3, pc.solution.max_pressure / 1e6,
        wide / (2 * kMinSpan) * 1e3, 2 * kMinSpan);
  }
  return "";
}

std::string resolution_note(const ContactResult& r) {
  for (const WheelContact& wc : r.wheel)
    if (std::string note = resolution_note(wc); !note.empty()) return note;
  return "";
}

// ---- results as fields ----

void describe(const PatchContact& pc, FieldSink& out) {
  out.object_type(kPatchType);
  if (!pc.located.empty()) describe_patch_fields(pc.located.front(), out);
  else out.string("side", side_name(pc.side), {"", "the wheel of the area: left or right"});
  out.begin_list("segments", pc.segments.size(), {"", "the inter-penetration segments of the area's rail lines"});
  for (const Segment& s : pc.segments) {
    out.item();
    describe(s, out);
    out.end();
  }
  out.end();
  const halfspace::NormalSolution& s = pc.solution;
  out.integer("merged", static_cast<long long>(pc.located.size()),
              {"-", "inter-penetration patches solved together as this area"});
  out.number("normal_force", pc.normal_force,
             {"N", "normal force of the area (conformal: the magnitude of its pressure's resultant)"});
  out.number("pressure_integral", s.force,  // sum p dA: the normal force, or more where the normals turn
             {"N", "sum of p dA: the normal force on a plane, more than normal_force where the normals turn"});
  out.vec3("force", pc.force,
           {"N", "force of the rail on the wheel through this area, creep force included (track frame)"});
  out.vec3("moment", pc.moment, {"N m", "moment of the area's tractions about the wheelset centre (track axes)"});
  out.vec3("point", pc.point, {"m", "centre of pressure (track frame)"});
  out.vec3("normal", pc.normal,
           {"-", "unit normal from the rail into the wheel (track frame; conformal: direction of the normal "
                 "resultant)"});
  out.number("angle", pc.angle, {"rad", "contact angle of the normal, > 0 tilted toward the track centre"});
  const AreaSurface& surface = surface_of(pc);
  out.string("surface", surface.name(), {"", "the potential contact area: planar (a plane) or conformal (curved)"});
  out.number("angle_min", pc.angle_min,
             {"rad", "smallest contact angle of the directions the pressure acts in (planar: angle)"});
  out.number("angle_max", pc.angle_max,
             {"rad", "largest contact angle of the directions the pressure acts in (planar: angle)"});
  out.number("nominal_angle", pc.nominal_angle,
             {"rad", "contact angle of the wheel's normal at the paper's nominal point"});
  out.number("area", s.area, {"m^2", "contact area: elements in contact times the element area"});
  out.number("pmax", s.max_pressure, {"Pa", "peak pressure"});
  out.integer("elements", s.elements_in_contact, {"-", "elements in contact (p > 0)"});
  out.integer("regions", pc.regions,
              {"-", "separate contact regions of the area (p > 0, 8-connected, each >= 0.1 % of the force)"});
  out.begin("span", {"",
                     "how many elements the contact spans: the narrowest of its regions that hold the peak "
                     "pressure or carry 10 % of the force"});
  out.integer("x", pc.span_x, {"-", "the most elements in contact in one grid row (along t1)"});
  out.integer("y", pc.span_y, {"-", "the most elements in contact in one grid column (along t2)"});
  out.end();
  out.boolean("resolved", resolved(pc),
              {"",
               "span.x and span.y at least 4 (or no pressure): pmax resolved by the grid (a Hertzian contact "
               "spanning 4-5 elements: pmax within 3.3 %, its area within 52 %; 1-3 elements: pmax up to 74 % off)"});
  out.number("penetration", pc.penetration, {"m", "deepest undeformed inter-penetration of the area (max h)"});
  out.number("rolling_radius", pc.rolling_radius, {"m", "wheel radius at the centre of pressure"});
  out.number("nu", pc.nu, {"-", "Poisson's ratio of the bodies: what the stresses below the area take (p:subsurface)"});
  describe(pc.ellipses, out);
  out.integer("iterations", s.iterations,
              {"-", "iterations of the normal solver (CG, or active set for the dense one)"});
  out.number("complementarity", s.residual.relative,
             {"-", "relative residual of the normal solution: max |gap| in contact or max overlap outside / "
                   "max(h + approach)"});
  // The contact plane: grid coordinates (u, v) are at origin + u t1 + v t2.
  out.begin("frame", {"", "the contact plane (conformal: the local frame at the grid's origin): grid (u, v) at "
                          "origin + u t1 + v t2"});
  out.vec3("origin", pc.origin, {"m", "origin of the frame, the area's reference point (track frame)"});
  out.vec3("t1", pc.t1, {"-", "unit rolling direction, the grid's x axis (track frame)"});
  out.vec3("t2", pc.t2, {"-", "unit lateral direction n x t1, the grid's y axis (track frame)"});
  out.end();
  out.begin("grid", {"", "the potential contact area's grid of square elements"});
  out.integer("nx", s.grid.nx, {"-", "elements along t1"});
  out.integer("ny", s.grid.ny, {"-", "elements along t2 (conformal: along the rail profile)"});
  out.number("dx", s.grid.dx, {"m", "element size along t1"});
  out.number("dy", s.grid.dy, {"m", "element size along t2"});
  out.number("x0", s.grid.x0, {"m", "u of the first element's centre (from the frame's origin)"});
  out.number("y0", s.grid.y0, {"m", "v of the first element's centre (from the frame's origin)"});
  out.end();
  if (!s.pressure.empty())
    out.grid("pressure", s.pressure.data(), s.grid.nx, s.grid.ny,
             {"Pa", "normal pressure per element, >= 0 (with grids)"});
  if (!pc.h.empty())
    out.grid("h", pc.h.data(), s.grid.nx, s.grid.ny,
             {"m", "undeformed distance per element, > 0 where the profiles inter-penetrate (with grids)"});
  if (pc.rolling) describe(*pc.rolling, out);
  surface.describe(pc, out);
}

void describe(const WheelContact& wc, FieldSink& out) {
  out.boolean("lifted", !(wc.force.z() > 0), {"", "the wheel carries no load (vertical force <= 0)"});
  out.boolean("flange_climb", !wc.flange_climb.empty(),
              {"", "the wheel is past flange climb (beyond the flange's steepest part, Nadal's limit, or lifted off)"});
  if (!wc.flange_climb.empty())
    out.string("flange_climb_reason", wc.flange_climb, {"", "why the wheel is past flange climb (only when it is)"});
  out.vec3("force", wc.force, {"N", "force of the rail on the wheel, creep forces included (track frame)"});
  out.vec3("moment", wc.moment, {"N m", "moment of the wheel's contact forces about the wheelset centre (track axes)"});
  if (wc.force.z() > 0) {  // a lifted wheel has no contact angle nor rolling radius: absent, never 0
    out.number("angle", wc.angle, {"rad", "contact angle of the wheel's resultant force, > 0 toward the track centre"});
    out.number("rolling_radius", wc.rolling_radius,
               {"m", "normal-force weighted mean of the areas' rolling radii (only when the wheel carries load)"});
  }
  if (const std::string note = resolution_note(wc); !note.empty())
    out.string("resolution_note", note,
               {"", "what of the wheel's contact the grid does not resolve, and the grid that would (only then)"});
  describe(wc.creep, out);
  if (wc.jacobian) describe_jacobian("jacobian", *wc.jacobian, false, out);
  if (wc.jacobian_fz) describe_jacobian("jacobian_fz", *wc.jacobian_fz, true, out);
  out.begin_list("patches", wc.patches.size(), {"", "the wheel's contact areas"});
  for (const PatchContact& pc : wc.patches) {
    out.item();
    describe(pc, out);
    out.end();
  }
  out.end();
}

void describe_sensitivity(const Sensitivity& S, FieldSink& out) {
  out.begin("sensitivity",
            {"", "derivatives of (Fx, Fy, Fz, Mx, My, Mz), both wheels, by the pose (only when asked for)"});
  for (int col = 0; col < 2; ++col) {
    const double v[6] = {S(0, col), S(1, col), S(2, col), S(3, col), S(4, col), S(5, col)};
    if (col == 0) out.numbers("z", v, 6, {"N/m, N m/m", "d(Fx, Fy, Fz, Mx, My, Mz)/dz of the normal problem"});
    else out.numbers("roll", v, 6, {"N/rad, N m/rad", "d(Fx, Fy, Fz, Mx, My, Mz)/droll of the normal problem"});
  }
  out.end();
}

void describe(const Pose& p, FieldSink& out) {
  out.begin("pose", {"", "the wheelset's pose (docs/design.md section 2)"});
  out.number("y", p.y, {"m", "lateral position of the wheelset centre, + toward the left rail"});
  out.number("z", p.z, {"m", "height of the centre: 0 the centred wheelset just touches, < 0 pressed into the rails"});
  out.number("roll", p.roll, {"rad", "roll about x, > 0 lifts the left wheel"});
  out.number("yaw", p.yaw, {"rad", "yaw about z, > 0 counter-clockwise seen from above"});
  out.end();
}

void describe_spin(const ContactResult& c, FieldSink& out) {
  if (!c.omega) return;
  out.number("omega", *c.omega, {"rad/s", "the axle's angular velocity the creep forces were solved at (kinematics: "
                                          "omega, V / r0, or the free-rolling one)"});
  if (c.spin_evaluations > 0)
    out.integer("spin_evaluations", c.spin_evaluations, {"-", "free_rolling: the tangential solves of both wheels its "
                                                              "search for omega took"});
}

void describe(const ContactResult& c, FieldSink& out, bool sensitivity) {
  if (sensitivity) describe_sensitivity(c.sensitivity, out);
  for (int s : {kLeft, kRight}) {
    out.begin(side_name(s), {"", "the contact of the wheel on that side (left: +y)"});
    describe(c.wheel[s], out);
    out.end();
  }
  out.vec3("force", c.force, {"N", "contact forces of both wheels summed (track frame)"});
  out.vec3("moment", c.moment, {"N m", "their moment about the wheelset centre (track axes)"});
  describe(c.creep, out);
  describe_spin(c, out);
  describe(c.pose, out);
}

}  // namespace wrc
