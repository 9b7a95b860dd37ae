// Rolling contact with friction on the wheelset's contact areas (wheelset/tangential.hpp): the rigid slip of every
// element from the wheelset's kinematics, the tangential solve of an area (exact or FASTSIM), its results and the
// options that ask for it.
#include "tangential_step.hpp"
#include "warm_start.hpp"

#include "wrc/core/error.hpp"
#include "wrc/wheelset/plausibility.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace wrc {

const char* method_name(RollingMethod m) { return m == RollingMethod::exact ? "exact" : "fastsim"; }

namespace {

// The offset along n from the plane point X0 to the wheel's surface (m): the root of (distance to the axle) -
// (wheel radius at the lateral position), by Newton with a difference derivative; a few micrometres to a fraction
// of a millimetre on a contact patch.
double wheel_offset(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& X0,
                    const Eigen::Vector3d& n) {
  const auto f = [&](double zeta) {
    const Eigen::Vector3d P = frame.to_wheelset(X0 + zeta * n);
    return std::hypot(P.x(), P.z()) - wheel_radius_at(wheel, P.y());
  };
  double zeta = 0, fz = f(0);
  for (int it = 0; it < 6 && std::abs(fz) > 1e-12; ++it) {
    const double h = 1e-7, d = (f(zeta + h) - fz) / h;
    if (!(std::abs(d) > 1e-3)) break;  // n nearly tangent to the wheel: keep the plane point
    zeta -= fz / d;
    fz = f(zeta);
  }
  return zeta;
}

// The wheelset's velocity field: v(X) = vc + Omega x (X - c).
struct VelocityField {
  Eigen::Vector3d c, vc, omega;
  Eigen::Vector3d at(const Eigen::Vector3d& X) const { return vc + omega.cross(X - c); }
};

VelocityField velocity_field(const Kinematics& k, double r0, const Pose& pose) {
  const PoseFrame frame(pose);
  const Eigen::Vector3d axle = frame.matrix().col(1);
  const double omega = k.omega.value_or(k.V / r0);
  return {Eigen::Vector3d(0, pose.y, pose.z), Eigen::Vector3d(k.V, k.vy, 0),
          omega * axle + k.yaw_rate * Eigen::Vector3d::UnitZ()};
}

// The tangential problem of an area: its pressure, the creepages at the plane's origin and, from kinematics, the
// per-element difference of the rigid slip at the elements' contact points from the creepages' linear field.
struct AreaSlip {
  halfspace::Creepages creepages;
  std::vector<double> extra_x, extra_y;
  double V = 1;
};

// Where an element of the area is and its tangent frame: on a plane, the plane's frame everywhere and the point in
// the plane; on a conformal area (wheelset/conformal.hpp), row j's frame (e_x, t2(j), n(j)) and the point on the
// rail's surface. `contact_point` moves the point along n to where the slip is taken: midway between the undeformed
// surfaces (h: their overlap), or onto the wheel's undeformed surface (SlipReference).
struct ElementFrame {
  Eigen::Vector3d t1, t2, n;
};

class AreaGeometry {
 public:
  AreaGeometry(const ContactModel& model, const Pose& pose, const PatchContact& pc, SlipReference reference)
      : pc_(pc), wheel_(model.geometry().side[pc.side].wheel), frame_(pose),
        below_rail_(reference == SlipReference::undeformed ? 1.0 : 0.5) {}
  ElementFrame frame(int j) const {
    if (!pc_.conformal) return {pc_.t1, pc_.t2, pc_.normal};
    return {Eigen::Vector3d::UnitX(), pc_.conformal->t2(j), pc_.conformal->normal(j)};
  }
  Eigen::Vector3d contact_point(int i, int j, double h) const {
    const halfspace::Grid& g = pc_.solution.grid;
    if (pc_.conformal) {  // on the rail's surface: the wheel's is h below it along the row's normal
      const ConformalSurface& s = *pc_.conformal;
      const int r = std::clamp(j, 0, s.rows() - 1);  // (the reference point is on the grid; kept on it regardless)
      return s.point(r, s.x0 + g.x(i)) - below_rail_ * h * s.normal(r);
    }
    Eigen::Vector3d X = pc_.origin;
    X += g.x(i) * pc_.t1;
    X += g.y(j) * pc_.t2;
    X += (wheel_offset(wheel_, frame_, X, pc_.normal) + (1 - below_rail_) * h) * pc_.normal;  // from the wheel's surface
    return X;
  }

 private:
  const PatchContact& pc_;
  const WheelCones& wheel_;
  PoseFrame frame_;
  double below_rail_;  // the slip point's depth below the rail's surface along n, as a share of h
};

AreaSlip area_slip(const ContactModel& model, const Pose& pose, const PatchContact& pc, const RollingRequest& rq) {
  AreaSlip a;
  if (rq.creepage) {
    a.creepages = *rq.creepage;
    a.V = rq.V;
    return a;
  }
  const Kinematics& k = *rq.kinematics;
  a.V = k.V;
  const AreaGeometry geo(model, pose, pc, k.slip_reference);
  const VelocityField field = velocity_field(k, model.geometry().track->params.radius, pose);
  const halfspace::Grid& g = pc.solution.grid;
  const double speed = std::abs(k.V);
  // The reference point: the grid's origin (the plane's origin; on a conformal area the origin on the surface, at a
  // row), with h of the element there (the grid is aligned with it).
  const int i0 = static_cast<int>(std::lround(-g.x0 / g.dx)), j0 = static_cast<int>(std::lround(-g.y0 / g.dy));
  const bool inside = i0 >= 0 && j0 >= 0 && i0 < g.nx && j0 < g.ny;
  const double h0 = inside ? pc.h[static_cast<std::size_t>(g.index(i0, j0))] : 0.0;
  const ElementFrame f0 = geo.frame(std::clamp(j0, 0, g.ny - 1));
  const Eigen::Vector3d v0 = field.at(geo.contact_point(i0, j0, h0));
  a.creepages = {v0.dot(f0.t1) / speed, v0.dot(f0.t2) / speed, field.omega.dot(f0.n) / speed};
  a.extra_x.assign(static_cast<std::size_t>(g.size()), 0.0);
  a.extra_y.assign(a.extra_x.size(), 0.0);
  for (int j = 0; j < g.ny; ++j) {
    const ElementFrame f = geo.frame(j);
    for (int i = 0; i < g.nx; ++i) {
      const auto q = static_cast<std::size_t>(g.index(i, j));
      if (!(pc.solution.pressure[q] > 0)) continue;  // the slip matters on the contact only
      const Eigen::Vector3d v = field.at(geo.contact_point(i, j, pc.h[q]));
      a.extra_x[q] = v.dot(f.t1) / speed - (a.creepages.xi - a.creepages.phi * g.y(j));
      a.extra_y[q] = v.dot(f.t2) / speed - (a.creepages.eta + a.creepages.phi * g.x(i));
    }
  }
  return a;
}

// The creep force (track frame) and its moment about c of the tangential tractions: on a plane fx t1 + fy t2 at the
// origin plus mz n; on a conformal area each element's traction px e_x + py t2(j) at its point on the rail's surface
// (as the pressure acts there along n(j)), summed per row.
void creep_wrench(const PatchContact& pc, const halfspace::TangentialSolution& s, const Eigen::Vector3d& c,
                  Eigen::Vector3d& force, Eigen::Vector3d& moment) {
  if (!pc.conformal) {
    force = s.fx * pc.t1 + s.fy * pc.t2;
    moment = (pc.origin - c).cross(force) + s.mz * pc.normal;
    return;
  }
  const ConformalSurface& surf = *pc.conformal;
  const halfspace::Grid& g = s.grid;
  const double dA = g.element_area();
  force.setZero();
  moment.setZero();
  for (int j = 0; j < g.ny; ++j) {
    double fx = 0, fy = 0, qy = 0;  // row sums: sum px dA, sum py dA, sum py x dA (x: track x)
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, j));
      fx += s.px[k] * dA;
      fy += s.py[k] * dA;
      qy += s.py[k] * (surf.x0 + g.x(i)) * dA;
    }
    if (fx == 0 && fy == 0) continue;
    const Eigen::Vector3d t2 = surf.t2(j), F = fx * Eigen::Vector3d::UnitX() + fy * t2;
    force += F;
    moment += (surf.point(j, 0.0) - c).cross(F) + Eigen::Vector3d::UnitX().cross(t2) * qy;
  }
}

}  // namespace

void solve_area_rolling(const ContactModel& model, const Pose& pose, PatchContact& pc, const RollingRequest& rq,
                        ContactWorkspace& ws, std::vector<ContactWorkspace::Previous>& next) {
  if (pc.rolling) {  // replace an earlier solution
    pc.force -= pc.rolling->force;
    pc.moment -= pc.rolling->moment;
    pc.rolling.reset();
  }
  if (pc.solution.pressure.empty() || pc.h.empty())
    fail("rolling contact: the {} wheel's area has no pressure grid (kept grids are needed)", side_name(pc.side));
  const AreaSlip slip = area_slip(model, pose, pc, rq);
  halfspace::TangentialProblem pb;
  pb.grid = pc.solution.grid;
  pb.pressure = pc.solution.pressure;
  pb.creepages = slip.creepages;
  pb.extra_x = slip.extra_x;
  pb.extra_y = slip.extra_y;
  pb.direction = slip.V > 0 ? 1 : -1;
  pb.friction = rq.friction;
  PatchRolling r;
  r.method = rq.method;
  r.friction = rq.friction;
  r.V = slip.V;
  r.creepage = slip.creepages;
  if (rq.method == RollingMethod::fastsim) {
    r.solution = halfspace::solve_fastsim(model.material(), pb);
  } else {
    halfspace::TangentialOptions opt;
    opt.tolerance = rq.tolerance;
    const areas::Plane frame = areas::area_frame(pc);
    std::vector<double> sx, sy;
    std::vector<unsigned char> split;
    if (areas::tangential_start(ws, pc.side, frame, pb.grid, sx, sy, split)) {
      opt.initial_x = sx;
      opt.initial_y = sy;
      opt.initial_state = split;
    }
    r.solution = model.rolling_solver().solve(pb, ws.rolling, opt);
    const halfspace::TangentialSolution& s = r.solution;
    next.push_back({frame.O, frame.t1, frame.t2, frame.n, s.grid, pc.solution.pressure, {}, s.px, s.py, s.state});
  }
  const halfspace::TangentialSolution& s = r.solution;
  halfspace::rigid_slip(pb, r.rigid_x, r.rigid_y);
  for (std::size_t k = 0; k < r.rigid_x.size(); ++k)
    if (!(pb.pressure[k] > 0)) r.rigid_x[k] = r.rigid_y[k] = 0;
  r.fx = s.fx;
  r.fy = s.fy;
  r.mz = s.mz;
  creep_wrench(pc, s, Eigen::Vector3d(0, pose.y, pose.z), r.force, r.moment);
  r.adhesion = s.adhesion_fraction();
  r.power = std::abs(slip.V) * s.power_per_speed;
  pc.force += r.force;
  pc.moment += r.moment;
  pc.rolling = std::move(r);
  pc.rolling->damage = damage::compute_damage(area_fields(pc), rq.damage);
}

damage::AreaFields area_fields(const PatchContact& area) {
  if (!area.rolling) fail("damage: the area has no tangential solution (give the call V and mu, or creepage and mu)");
  const PatchRolling& r = *area.rolling;
  const halfspace::TangentialSolution& s = r.solution;
  if (area.solution.pressure.empty() || s.px.empty())
    fail("damage: the area's grids were not kept (grids = false); the indices need the pressure and traction grids");
  return {s.grid, area.solution.pressure, s.px, s.py, s.sx, s.sy, r.V, r.creepage, r.fx, r.fy, r.mz};
}

void add_creep(CreepTotals& total, const PatchContact& pc) {
  if (!pc.rolling) return;
  total.solved = true;
  total.force += pc.rolling->force;
  total.moment += pc.rolling->moment;
  total.power += pc.rolling->power;
}

void add_creep(CreepTotals& total, const CreepTotals& part) {
  if (!part.solved) return;
  total.solved = true;
  total.force += part.force;
  total.moment += part.moment;
  total.power += part.power;
}

void drop_grids(PatchRolling& r) {
  r.solution.px = {};
  r.solution.py = {};
  r.solution.sx = {};
  r.solution.sy = {};
  r.solution.state = {};
  r.rigid_x = {};
  r.rigid_y = {};
  damage::drop_grids(r.damage);
}

void describe(const PatchRolling& r, FieldSink& out) {
  out.string("method", method_name(r.method), {"", "tangential solver: exact or fastsim (with rolling keys)"});
  out.begin("mu", {"", "the friction coefficients"});
  out.number("static", r.friction.static_coefficient, {"-", "static coefficient: |traction| <= mu p in adhesion"});
  out.number("kinetic", r.friction.kinetic_coefficient, {"-", "kinetic coefficient: |traction| = mu p in slip"});
  out.end();
  out.number("V", r.V, {"m/s", "forward speed, which scales the slip velocities and the power (with creepage alone: 1)"});
  out.begin("creepage", {"", "the creepages at the area's reference point (frame.origin)"});
  out.number("xi", r.creepage.xi, {"-", "longitudinal creepage along t1, > 0 braking (wheel surface slower than the rail's)"});
  out.number("eta", r.creepage.eta, {"-", "lateral creepage along t2"});
  out.number("phi", r.creepage.phi, {"1/m", "spin creepage about the normal"});
  out.end();
  out.number("Fx", r.fx, {"N", "tangential force on the wheel along t1 (braking: < 0)"});
  out.number("Fy", r.fy, {"N", "tangential force on the wheel along t2"});
  out.number("Mz", r.mz, {"N m", "moment of the tangential tractions about the reference point, along the normal"});
  out.vec3("creep_force", r.force, {"N", "the area's creep force on the wheel (track frame)"});
  out.vec3("creep_moment", r.moment, {"N m", "moment of the area's tangential tractions about the wheelset centre"});
  out.number("adhesion", r.adhesion, {"-", "fraction of the contact area in adhesion"});
  out.number("power", r.power, {"W", "frictional power of the area, >= 0"});
  out.integer("creep_iterations", r.solution.iterations, {"-", "iterations of the tangential solver"});
  damage::describe(r.damage, out);
  const halfspace::TangentialSolution& s = r.solution;
  if (s.px.empty()) return;
  const int nx = s.grid.nx, ny = s.grid.ny;
  const double speed = std::abs(r.V);
  std::vector<double> vx(s.sx.size()), vy(vx.size()), map(vx.size()), density(vx.size()), wx(vx.size()), wy(vx.size());
  for (std::size_t k = 0; k < vx.size(); ++k) {
    vx[k] = speed * s.sx[k];
    vy[k] = speed * s.sy[k];
    map[k] = s.state[k];
    density[k] = -speed * (s.px[k] * s.sx[k] + s.py[k] * s.sy[k]);
    wx[k] = speed * r.rigid_x[k];
    wy[k] = speed * r.rigid_y[k];
  }
  out.grid("px", s.px.data(), nx, ny, {"Pa", "tangential traction on the wheel along t1 (with grids)"});
  out.grid("py", s.py.data(), nx, ny, {"Pa", "tangential traction on the wheel along t2 (conformal: the row's t2)"});
  out.grid("slip_x", vx.data(), nx, ny, {"m/s", "slip velocity of the wheel relative to the rail along t1"});
  out.grid("slip_y", vy.data(), nx, ny, {"m/s", "slip velocity of the wheel relative to the rail along t2"});
  out.grid("adhesion_map", map.data(), nx, ny, {"-", "element state: 0 outside the contact, 1 adhesion, 2 slip"});
  out.grid("power_density", density.data(), nx, ny, {"W/m^2", "frictional power density, -(traction . slip) >= 0"});
  out.grid("rigid_slip_x", wx.data(), nx, ny, {"m/s", "rigid slip velocity along t1 of the elements in contact (0 outside)"});
  out.grid("rigid_slip_y", wy.data(), nx, ny, {"m/s", "rigid slip velocity along t2 of the elements in contact (0 outside)"});
}

void describe(const CreepTotals& c, FieldSink& out) {
  if (!c.solved) return;
  out.vec3("creep_force", c.force, {"N", "the areas' creep forces summed (track frame; with rolling keys)"});
  out.vec3("creep_moment", c.moment, {"N m", "their moment about the wheelset centre (track axes)"});
  out.number("power", c.power, {"W", "frictional power summed over the areas"});
}

namespace {

const OptionDoc kV{"m/s", "forward speed of the wheelset centre (rolling: required with the kinematics; with creepage "
                          "it scales slip velocities and power, default 1)"};

void check_speed(const OptionReader& r, double V) {
  if (V == 0)
    fail("{}: V = 0: the creepages are slip velocities divided by the rolling speed V, undefined at V = 0", r.context());
}

// The creepages prescribed, or the kinematics; sets q.V. A documenting reader goes through both.
void read_slip(OptionReader& r, RollingRequest& q) {
  if (auto t = r.table("creepage", {"-", "creepages prescribed at every area's reference point: {xi, eta, phi}"})) {
    for (const char* key : {"omega", "vy", "yaw_rate", "slip_reference"})
      if (!r.documenting() && r.has(key))
        fail("{}: 'creepage' prescribes the creepages; '{}' (kinematics) cannot be given with it", r.context(), key);
    halfspace::Creepages c;
    c.xi = t->number("xi", {"-", "longitudinal creepage"}, c.xi);
    c.eta = t->number("eta", {"-", "lateral creepage"}, c.eta);
    c.phi = t->number("phi", {"1/m", "spin creepage"}, c.phi);
    q.creepage = c;
    t->finish();
    if (!r.documenting()) {
      q.V = r.number("V", kV, q.V);
      return check_speed(r, q.V);
    }
  }
  if (!r.documenting() && !r.has("V")) fail("{}: the kinematics need the forward speed V (m/s)", r.context());
  Kinematics k;
  k.V = r.documenting() ? r.number("V", kV).value_or(0) : r.need_number("V", kV);
  k.omega = r.number("omega", {"rad/s", "axle angular velocity (default: V / r0, pure rolling)"});
  k.vy = r.number("vy", {"m/s", "lateral velocity of the wheelset centre"}, k.vy);
  k.yaw_rate = r.number("yaw_rate", {"rad/s", "yaw rate of the wheelset"}, k.yaw_rate);
  if (r.choice("slip_reference", {"deformed", "undeformed"},
               {"-", "where the rigid slip is taken: midway between the undeformed surfaces (deformed) or on the "
                     "wheel's undeformed surface (undeformed, CONTACT's convention)"})
          .value_or("deformed") == "undeformed")
    k.slip_reference = SlipReference::undeformed;
  q.kinematics = k;
  q.V = k.V;
  if (!r.documenting()) check_speed(r, q.V);
}

halfspace::Friction read_friction(OptionReader& r) {
  const auto mu = r.number("mu", {"-", "friction coefficient (static = kinetic)"});
  const auto mus = r.number("mu_static", {"-", "static friction coefficient (with mu_kinetic)"});
  const auto muk = r.number("mu_kinetic", {"-", "kinetic friction coefficient (default: mu_static)"});
  halfspace::Friction f;
  if (r.documenting()) return f;
  if (!mu && !mus) fail("{}: the friction coefficient 'mu' (or 'mu_static' and 'mu_kinetic') is required", r.context());
  f.static_coefficient = mus.value_or(mu.value_or(0));
  f.kinetic_coefficient = muk.value_or(mu.value_or(f.static_coefficient));
  for (auto [name, v] : {std::pair{"mu_static", f.static_coefficient}, {"mu_kinetic", f.kinetic_coefficient}})
    if (!(v >= halfspace::kFrictionMin && v <= halfspace::kFrictionMax))
      fail("{}: the friction coefficient {} = {} must be in [{:g}, {:g}] (wheel on rail: 0.05 .. 0.6)", r.context(),
           mu && !mus ? "mu" : name, v, halfspace::kFrictionMin, halfspace::kFrictionMax);
  if (f.kinetic_coefficient > f.static_coefficient)
    fail("{}: mu_kinetic = {} exceeds mu_static = {}", r.context(), f.kinetic_coefficient, f.static_coefficient);
  return f;
}

}  // namespace

void RollingRequest::validate(std::string_view context, bool plausible) const {
  if (plausible) check_plausible(context, "V", kinematics ? kinematics->V : V, kTrainSpeed);
}

std::optional<RollingRequest> read_rolling_request(OptionReader& r) {
  bool any = r.documenting() || r.has("creepage");
  for (const char* key : {"V", "omega", "vy", "yaw_rate", "slip_reference"}) any |= r.has(key);
  for (const char* key : {"mu", "mu_static", "mu_kinetic", "method", "rolling_tolerance", "wear", "fatigue"})
    if (r.has(key) && !any)
      fail("{}: '{}' is given but neither V (the wheelset's kinematics) nor creepage: {} needs one of them",
           r.context(), key, std::string_view(key) == "wear" || std::string_view(key) == "fatigue" ? "rolling contact" : "friction");
  if (!any) return std::nullopt;
  RollingRequest q;
  read_slip(r, q);
  q.friction = read_friction(r);
  const bool fastsim = q.method == RollingMethod::fastsim;
  q.method = r.choice("method", {"exact", "fastsim"}, {"-", "tangential solver: exact, or FASTSIM"},
                      fastsim ? "fastsim" : "exact") == "fastsim"
                 ? RollingMethod::fastsim
                 : RollingMethod::exact;
  q.tolerance = r.number("rolling_tolerance", {"-", "the exact tangential solver's tolerance (relative)"}, q.tolerance);
  if (!r.documenting() && !(q.tolerance > 0 && q.tolerance <= 0.1))
    fail("{}: rolling_tolerance = {} must be in ]0, 0.1]", r.context(), q.tolerance);
  q.damage = damage::read_damage_options(r);
  return q;
}

}  // namespace wrc
