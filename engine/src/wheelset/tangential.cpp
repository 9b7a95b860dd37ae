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
#include <numbers>

namespace wrc {

const char* method_name(RollingMethod m) { return m == RollingMethod::exact ? "exact" : "fastsim"; }

double FrictionProfile::at(double v) const {
  if (v <= y.front()) return mu.front();
  if (v >= y.back()) return mu.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(y.begin(), y.end(), v) - y.begin());
  const double t = (v - y[k - 1]) / (y[k] - y[k - 1]);
  return (1 - t) * mu[k - 1] + t * mu[k];
}

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

// The wheelset's velocity field: v(X) = vc + Omega x (X - c); `axle` the wheelset's axle (unit).
struct VelocityField {
  Eigen::Vector3d c, vc, omega, axle;
  Eigen::Vector3d at(const Eigen::Vector3d& X) const { return vc + omega.cross(X - c); }
};

VelocityField velocity_field(const Kinematics& k, double r0, const Pose& pose) {
  const PoseFrame frame(pose);
  const Eigen::Vector3d axle = frame.matrix().col(1);
  const double omega = k.omega.value_or(k.V / r0);
  return {Eigen::Vector3d(0, pose.y, pose.z), Eigen::Vector3d(k.V, k.vy, 0),
          omega * axle + k.yaw_rate * Eigen::Vector3d::UnitZ(), axle};
}

// The tangential problem of an area: its pressure, the creepages at the plane's origin and, from kinematics, the
// per-element difference of the rigid slip at the elements' contact points from the creepages' linear field (in the
// workspace's scratch grids, 0 outside the contact); with `rigid`, also the rigid slip itself (the result's, 0 outside
// the contact), as halfspace::rigid_slip sums it.
struct AreaSlip {
  halfspace::Creepages creepages;
  std::span<const double> extra_x, extra_y;
  std::vector<double> rigid_x, rigid_y;
  double V = 1;
};

// Where an element of the area is and its tangent frame: on a plane, the plane's frame everywhere and the point in
// the plane; on a conformal area (wheelset/conformal.hpp), row j's frame (e_x, t2(j), n(j)) and the point on the
// rail's surface. `contact_point` moves the point along n to where the slip is taken: onto the wheel's undeformed
// surface, or midway between the undeformed surfaces (h: their overlap) (SlipReference).
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

// The slip velocity along the contact surface's rolling direction at X: v's component along t1 tilted toward n by
// half the slope, relative to t1, of the wheel's circumference through X (the rail is straight along t1). Both
// surfaces' material moves along the deformed contact surface, which lies between the two undeformed ones (one
// material: midway); v . t1 alone would add the wheel's own curvature term x^2 / (2 r^2) to xi at a distance x from
// the axle's plane (up to 8e-5 on a 12 mm long patch at r = 0.46 m), a slip the rolling wheel does not have.
// With tilt = tn / (2 |tw|), tn = tw . n: (v . t1 |tw| + tn v . n / 2) / sqrt(|tw|^2 + tn^2 / 4), one division
// instead of two (it runs over every contact element, twice per time step of a wheel with friction).
// `tw`: axle x (X - c), the wheel's circumferential direction at X (unnormalised).
// `tw_t1`, `v_t1`: tw . t1 and v . t1, which on a conformal row (t1 = e_x) are the vectors' x without the products.
[[gnu::always_inline]] inline double rolling_slip(const Eigen::Vector3d& tw, double tw_t1, const Eigen::Vector3d& v,
                                                  double v_t1, const Eigen::Vector3d& n) {
  const double norm2 = tw.squaredNorm(), tn = tw_t1 < 0 ? -tw.dot(n) : tw.dot(n);
  if (!(norm2 > 0)) return v_t1;
  return (v_t1 * std::sqrt(norm2) + 0.5 * tn * v.dot(n)) / std::sqrt(norm2 + 0.25 * tn * tn);
}
[[gnu::always_inline]] inline double rolling_slip(const Eigen::Vector3d& tw, const Eigen::Vector3d& v,
                                                  const ElementFrame& f) {
  return rolling_slip(tw, tw.dot(f.t1), v, v.dot(f.t1), f.n);
}
[[gnu::always_inline]] inline double rolling_slip(const VelocityField& field, const Eigen::Vector3d& X,
                                                  const Eigen::Vector3d& v, const ElementFrame& f) {
  return rolling_slip(field.axle.cross(X - field.c), v, f);
}

// rolling_slip's change (the frame held) for changes dv of v, dr of X - c and d_axle of the axle.
double rolling_slip_change(const VelocityField& field, const Eigen::Vector3d& X, const Eigen::Vector3d& v,
                           const ElementFrame& f, const Eigen::Vector3d& dv, const Eigen::Vector3d& dr,
                           const Eigen::Vector3d& d_axle) {
  Eigen::Vector3d tw = field.axle.cross(X - field.c), dtw = d_axle.cross(X - field.c) + field.axle.cross(dr);
  if (tw.dot(f.t1) < 0) tw = -tw, dtw = -dtw;
  const double norm = tw.norm();
  if (!(norm > 0)) return dv.dot(f.t1);
  const double tilt = 0.5 * tw.dot(f.n) / norm;
  const double dtilt = 0.5 * (dtw.dot(f.n) / norm - tw.dot(f.n) * tw.dot(dtw) / (norm * norm * norm));
  const double root = std::sqrt(1 + tilt * tilt), s = (v.dot(f.t1) + tilt * v.dot(f.n)) / root;
  return (dv.dot(f.t1) + tilt * dv.dot(f.n) + dtilt * v.dot(f.n)) / root - s * tilt * dtilt / (root * root);
}

AreaSlip area_slip(const ContactModel& model, const Pose& pose, const PatchContact& pc, const RollingRequest& rq,
                   ContactWorkspace& ws, bool rigid = false) {
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
  const Eigen::Vector3d X0 = geo.contact_point(i0, j0, h0), v0 = field.at(X0);
  a.creepages = {rolling_slip(field, X0, v0, f0) / speed, v0.dot(f0.t2) / speed, field.omega.dot(f0.n) / speed};
  const auto n = static_cast<std::size_t>(g.size());
  ws.extra_x.resize(n);  // every element written below
  ws.extra_y.resize(n);
  a.extra_x = ws.extra_x, a.extra_y = ws.extra_y;
  if (rigid) a.rigid_x.assign(n, 0.0), a.rigid_y.assign(n, 0.0);
  const halfspace::Creepages c = a.creepages;  // (a copy: the grids' stores cannot alias it, nor g's below)
  const double inv_speed = 1 / speed, x0 = g.x0, dx = g.dx;
  for (int j = 0; j < g.ny; ++j) {
    const ElementFrame f = geo.frame(j);
    const double row_x = c.xi - c.phi * g.y(j);  // the creepages' field along x, the same along the row
    // On a conformal area a row's contact points are affine in the element's index and h (along the row's normal),
    // and so are v and axle x (X - c): per element two sums instead of the point and two cross products.
    Eigen::Vector3d v0 = Eigen::Vector3d::Zero(), vi = v0, vh = v0, t0 = v0, ti = v0, th = v0;
    if (pc.conformal) {
      const Eigen::Vector3d X0 = geo.contact_point(0, j, 0.0);
      const Eigen::Vector3d Xi = geo.contact_point(1, j, 0.0) - X0, Xh = geo.contact_point(0, j, 1.0) - X0;
      v0 = field.at(X0), vi = field.omega.cross(Xi), vh = field.omega.cross(Xh);
      t0 = field.axle.cross(X0 - field.c), ti = field.axle.cross(Xi), th = field.axle.cross(Xh);
    }
    const std::size_t row = static_cast<std::size_t>(g.index(0, j));
    const double* p = pc.solution.pressure.data() + row;
    const double* hs = pc.h.data() + row;
    double *ex = ws.extra_x.data() + row, *ey = ws.extra_y.data() + row;
    for (int i = 0; i < g.nx; ++i) {
      if (!(p[i] > 0)) {  // the slip matters on the contact only
        ex[i] = ey[i] = 0;
        continue;
      }
      double sx, sy;
      if (pc.conformal) {
        const double h = hs[i];
        const Eigen::Vector3d v = v0 + i * vi + h * vh;
        const Eigen::Vector3d tw = t0 + i * ti + h * th;
        sx = rolling_slip(tw, tw.x(), v, v.x(), f.n), sy = v.dot(f.t2);
      } else {
        const Eigen::Vector3d X = geo.contact_point(i, j, hs[i]), v = field.at(X);
        sx = rolling_slip(field, X, v, f), sy = v.dot(f.t2);
      }
      const double row_y = c.eta + c.phi * (x0 + i * dx);  // g.x(i)
      ex[i] = sx * inv_speed - row_x;
      ey[i] = sy * inv_speed - row_y;
      if (!rigid) continue;
      // halfspace::rigid_slip's sums (the reference point at the grid's origin), without its pass over the grid
      a.rigid_x[row + static_cast<std::size_t>(i)] = row_x + ex[i];
      a.rigid_y[row + static_cast<std::size_t>(i)] = row_y + ey[i];
    }
  }
  return a;
}

// The lateral coordinate of a track-frame point in its rail profile's own frame (the inverse of SidePlacement::rail).
double rail_profile_y(const SidePlacement& place, const Eigen::Vector3d& X) {
  const double yc = place.sign * X.y() - place.rail_dy, zc = X.z() - place.rail_dz;
  return std::cos(place.cant_angle) * yc + std::sin(place.cant_angle) * zc;
}

// The friction law's factor at every contact element of an area from its rail's friction profile: mu(0) there over
// the law's own (1 outside the contact).
std::vector<double> profile_scale(const ContactModel& model, const Pose& pose, const PatchContact& pc,
                                  const FrictionProfile& profile, double mu0) {
  const AreaGeometry geo(model, pose, pc, SlipReference::deformed);
  const SidePlacement& place = model.geometry().track->place[static_cast<std::size_t>(pc.side)];
  const halfspace::Grid& g = pc.solution.grid;
  std::vector<double> scale(static_cast<std::size_t>(g.size()), 1.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto q = static_cast<std::size_t>(g.index(i, j));
      if (pc.solution.pressure[q] > 0)
        scale[q] = profile.at(rail_profile_y(place, geo.contact_point(i, j, pc.h[q]))) / mu0;
    }
  return scale;
}

// The creep force (track frame) and its moment about c of the tangential tractions: on a plane fx t1 + fy t2 at the
// origin plus mz n; on a conformal area each element's traction px e_x + py t2(j) at its point on the rail's surface
// (as the pressure acts there along n(j)), summed per row.
template <class Tractions>  // TangentialSolution or TangentialDerivative
void creep_wrench(const PatchContact& pc, const Tractions& s, const Eigen::Vector3d& c,
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

namespace {

// The tangential problem of an area (its friction scale apart).
halfspace::TangentialProblem area_problem(const PatchContact& pc, const AreaSlip& slip, const RollingRequest& rq) {
  halfspace::TangentialProblem pb;
  pb.grid = pc.solution.grid;
  pb.pressure = pc.solution.pressure;
  pb.creepages = slip.creepages;
  pb.extra_x = slip.extra_x;
  pb.extra_y = slip.extra_y;
  pb.direction = slip.V > 0 ? 1 : -1;
  pb.friction = rq.friction;
  pb.speed = std::abs(slip.V);
  if (!pc.region_label.empty()) pb.regions = pc.region_ellipses, pb.region_label = pc.region_label;  // found with p
  return pb;
}

// With kinematics, the change of the rigid slip for a pose coordinate, as TangentialChange has it (creepages at the
// reference point, the extra slip per element; the reference point's motion ch.ref_x, ref_y given): the velocity field
// v = vc + Omega x (X - c) changes with the centre c (translation T), the axle's direction (rotation W: dOmega =
// omega W x axle) and the contact points, which move along n by -dh / 2 (deformed; -dh undeformed) as the wheel's
// surface approaches. The frames are the rows' (conformal: on the rail, which does not move; planar: the plane, held
// as the normal sensitivities hold it).
void kinematic_change(const ContactModel& model, const Pose& pose, const PatchContact& pc, const Kinematics& k,
                      const halfspace::Creepages& creepages, const areas::NormalColumn& normal, int coordinate,
                      halfspace::TangentialChange& ch) {
  const AreaGeometry geo(model, pose, pc, k.slip_reference);
  const VelocityField field = velocity_field(k, model.geometry().track->params.radius, pose);
  const areas::RigidMotion m = areas::pose_motion(pose, coordinate);
  const double omega = k.omega.value_or(k.V / model.geometry().track->params.radius), speed = std::abs(k.V);
  const Eigen::Vector3d axle = PoseFrame(pose).matrix().col(1), d_omega = omega * m.rotation.cross(axle);
  const double below = k.slip_reference == SlipReference::undeformed ? 1.0 : 0.5;
  const halfspace::Grid& g = pc.solution.grid;
  const int j0 = std::clamp(static_cast<int>(std::lround(-g.y0 / g.dy)), 0, g.ny - 1);
  // The spin's change from Omega's (the frame held); xi and eta 0: the extra slip takes the rest of each element's.
  halfspace::Creepages& d = ch.creepages;
  d = {0.0, 0.0, d_omega.dot(geo.frame(j0).n) / speed};
  ch.extra_x.assign(static_cast<std::size_t>(g.size()), 0.0);
  ch.extra_y.assign(ch.extra_x.size(), 0.0);
  for (int j = 0; j < g.ny; ++j) {
    const ElementFrame f = geo.frame(j);
    for (int i = 0; i < g.nx; ++i) {
      const auto q = static_cast<std::size_t>(g.index(i, j));
      if (!(pc.solution.pressure[q] > 0)) continue;
      const Eigen::Vector3d X = geo.contact_point(i, j, pc.h[q]), dX = -below * normal.dh[q] * f.n;
      const Eigen::Vector3d dv = d_omega.cross(X - field.c) - field.omega.cross(m.translation) + field.omega.cross(dX);
      // the element's rigid slip changes by (rolling_slip's change, dv . t2) / |V|; the creepages' field takes its part
      const double ds = rolling_slip_change(field, X, field.at(X), f, dv, dX - m.translation, m.rotation.cross(axle));
      ch.extra_x[q] = ds / speed - (d.xi - d.phi * g.y(j) + creepages.phi * ch.ref_y);
      ch.extra_y[q] = dv.dot(f.t2) / speed - (d.eta + d.phi * g.x(i) - creepages.phi * ch.ref_x);
    }
  }
}

}  // namespace

Jacobian rolling_jacobian(const ContactModel& model, const Pose& pose, const PatchContact& pc, const RollingRequest& rq,
                          const std::array<areas::NormalColumn, 4>& normal, const std::array<Eigen::Vector2d, 4>& dref,
                          ContactWorkspace& ws) {
  Jacobian J = Jacobian::Zero();
  if (!pc.rolling || !(pc.solution.force > 0)) return J;
  const PatchRolling& r = *pc.rolling;
  if (r.solution.px.empty() || pc.solution.pressure.empty())
    fail("contact sensitivity: the {} wheel's area has no traction grid (kept grids are needed)", side_name(pc.side));
  const AreaSlip slip = area_slip(model, pose, pc, rq, ws);
  halfspace::TangentialProblem pb = area_problem(pc, slip, rq);
  pb.friction_scale = r.friction_scale;
  std::vector<halfspace::TangentialChange> changes(7);
  changes[0].creepages.xi = 1;
  changes[1].creepages.eta = 1;
  changes[2].creepages.phi = 1;
  for (int c = 0; c < 4; ++c) {
    const auto cs = static_cast<std::size_t>(c);
    halfspace::TangentialChange& ch = changes[3 + cs];
    ch.pressure = normal[cs].dp;
    ch.ref_x = dref[cs].x();
    ch.ref_y = dref[cs].y();
    if (rq.kinematics) kinematic_change(model, pose, pc, *rq.kinematics, slip.creepages, normal[cs], c, ch);
  }
  const std::vector<halfspace::TangentialDerivative> d =
      r.method == RollingMethod::fastsim
          ? halfspace::linearise_fastsim(model.material(), pb, r.solution, changes)
          : model.rolling_solver().linearise(pb, r.solution, changes, ws.rolling, kJacobianSolveTolerance);
  const Eigen::Vector3d c(0, pose.y, pose.z);
  for (int col = 0; col < 7; ++col) {
    Eigen::Vector3d dF, dM;
    creep_wrench(pc, d[static_cast<std::size_t>(col)], c, dF, dM);
    if (col >= 3) dM -= areas::pose_motion(pose, col - 3).translation.cross(r.force);  // the centre moves
    J.block<3, 1>(0, col) = dF;
    J.block<3, 1>(3, col) = dM;
  }
  return J;
}

void solve_area_rolling(const ContactModel& model, const Pose& pose, PatchContact& pc, const RollingRequest& rq,
                        ContactWorkspace& ws, std::vector<ContactWorkspace::Previous>& next) {
  if (pc.rolling) {  // replace an earlier solution
    pc.force -= pc.rolling->force;
    pc.moment -= pc.rolling->moment;
    pc.rolling.reset();
  }
  if (pc.solution.pressure.empty() || pc.h.empty())
    fail("rolling contact: the {} wheel's area has no pressure grid (kept grids are needed)", side_name(pc.side));
  AreaSlip slip = area_slip(model, pose, pc, rq, ws, true);
  halfspace::TangentialProblem pb = area_problem(pc, slip, rq);
  PatchRolling r;
  if (const auto& profile = rq.friction_profile[static_cast<std::size_t>(pc.side)]) {
    r.friction_scale = profile_scale(model, pose, pc, *profile, rq.friction.static_coefficient);
    pb.friction_scale = r.friction_scale;
  }
  r.method = rq.method;
  r.friction = rq.friction;
  r.V = slip.V;
  r.creepage = slip.creepages;
  if (rq.method == RollingMethod::fastsim) {
    // (the pressure a normal solution's, the extra slip from checked kinematics on a checked pose: their sizes alone)
    r.solution = std::move(ws.fastsim_grids);  // (every element is written: stale values do not matter)
    halfspace::solve_fastsim(model.material(), pb, r.solution, halfspace::ProblemCheck::sizes);
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
  if (!slip.rigid_x.empty()) {  // kinematics: area_slip summed it
    r.rigid_x = std::move(slip.rigid_x);
    r.rigid_y = std::move(slip.rigid_y);
  } else {
    halfspace::rigid_slip(pb, r.rigid_x, r.rigid_y);
    for (std::size_t k = 0; k < r.rigid_x.size(); ++k)
      if (!(pb.pressure[k] > 0)) r.rigid_x[k] = r.rigid_y[k] = 0;
  }
  r.fx = s.fx;
  r.fy = s.fy;
  r.mz = s.mz;
  creep_wrench(pc, s, Eigen::Vector3d(0, pose.y, pose.z), r.force, r.moment);
  r.adhesion = s.adhesion_fraction();
  r.power = std::abs(slip.V) * s.power_per_speed;
  pc.force += r.force;
  pc.moment += r.moment;
  pc.rolling = std::move(r);
  pc.rolling->damage = damage::compute_damage(area_fields(pc), rq.damage, damage::FieldCheck::sizes);
}

void recycle_tangential(ContactResult& result, ContactWorkspace& ws) {
  for (WheelContact& wc : result.wheel)
    for (PatchContact& pc : wc.patches)
      if (pc.rolling && pc.rolling->method == RollingMethod::fastsim && !pc.rolling->solution.px.empty()) {
        ws.fastsim_grids = std::move(pc.rolling->solution);
        return;
      }
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

void drop_grids(PatchRolling& r, bool keep_rows) {
  r.solution.px = {};
  r.solution.py = {};
  r.solution.sx = {};
  r.solution.sy = {};
  r.solution.state = {};
  r.rigid_x = {};
  r.rigid_y = {};
  damage::drop_grids(r.damage, keep_rows);
  r.friction_scale = {};
}

void describe(const PatchRolling& r, FieldSink& out) {
  out.string("method", method_name(r.method), {"", "tangential solver: exact or fastsim (with rolling keys)"});
  out.begin("mu", {"", "the friction coefficients"});
  out.number("static", r.friction.static_coefficient,
             {"-", "static coefficient: |traction| <= mu p in adhesion (a falling law: mu(0))"});
  out.number("kinetic", r.friction.kinetic_coefficient,
             {"-", "kinetic coefficient: |traction| = mu p in slip (a falling law: mu at large slip velocity)"});
  out.end();
  out.string("friction_law", halfspace::law_name(r.friction.law),
             {"", "coulomb, or the law falling with the slip velocity: polach, linear, rational, exponential"});
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
  out.integer("creep_products", r.solution.products, {"-", "products with the influence matrix on the area's grid "
                                                            "(exact solver; a nested start's coarser grids not counted)"});
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
  std::vector<double> mu0(vx.size(), 0.0);  // the law's mu(0) per element, from a friction profile
  for (std::size_t k = 0; k < mu0.size(); ++k)
    if (s.state[k] != halfspace::kExterior)
      mu0[k] = r.friction.static_coefficient * (r.friction_scale.empty() ? 1.0 : r.friction_scale[k]);
  out.grid("mu_map", mu0.data(), nx, ny, {"-", "the friction law's mu(0) at each element in contact (0 outside)"});
}

void describe(const CreepTotals& c, FieldSink& out) {
  if (!c.solved) return;
  out.vec3("creep_force", c.force, {"N", "the areas' creep forces summed (track frame; with rolling keys)"});
  out.vec3("creep_moment", c.moment, {"N m", "their moment about the wheelset centre (track axes)"});
  out.number("power", c.power, {"W", "frictional power summed over the areas"});
  out.number("axle_torque", c.axle_torque, {"N m", "the creep moment's component along the axle (> 0 drives the "
                                                    "wheelset's spin forward; free_rolling: ~0 for both wheels)"});
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
    for (const char* key : {"omega", "free_rolling", "vy", "yaw_rate", "slip_reference"})
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
  k.free_rolling = r.boolean("free_rolling", {"-", "find omega: the one at which the creep forces of both wheels "
                                                   "have no moment about the axle (no traction or braking torque)"},
                             false);
  if (!r.documenting() && k.free_rolling && k.omega)
    fail("{}: free_rolling finds omega; give omega or free_rolling = true, not both", r.context());
  k.vy = r.number("vy", {"m/s", "lateral velocity of the wheelset centre"}, k.vy);
  k.yaw_rate = r.number("yaw_rate", {"rad/s", "yaw rate of the wheelset"}, k.yaw_rate);
  if (r.choice("slip_reference", {"undeformed", "deformed"},
               {"-", "where the rigid slip is taken: on the wheel's undeformed surface (undeformed, the default, "
                     "CONTACT's convention) or midway between the undeformed surfaces (deformed)"})
          .value_or("undeformed") == "deformed")
    k.slip_reference = SlipReference::deformed;
  q.kinematics = k;
  q.V = k.V;
  if (!r.documenting()) check_speed(r, q.V);
}

// Named parameter sets of Polach's law (docs/guide/rolling.md gives them with their sources).
struct FrictionPreset {
  const char* name;
  double mu0, A, B;  // -, -, s/m
};
constexpr FrictionPreset kFrictionPresets[] = {
    {"polach_dry", 0.55, 0.40, 0.60},       // Polach 2005, Wear 258, dry rail
    {"polach_wet", 0.30, 0.40, 0.20},       // Polach 2005, wet rail
    {"contact_example", 0.36, 0.38, 0.70},  // CONTACT's user guide, creep curve example (mu_stat, A, B)
};

void check_coefficient(const OptionReader& r, const char* key, double v) {
  if (!(v >= halfspace::kFrictionMin && v <= halfspace::kFrictionMax))
    fail("{}: the friction coefficient {} = {} must be in [{:g}, {:g}] (wheel on rail: 0.05 .. 0.6)", r.context(), key,
         v, halfspace::kFrictionMin, halfspace::kFrictionMax);
}

// friction = {law = "polach", mu0 =, A =, B =} or {law = "linear" | "rational" | "exponential", mu_inf =, m1 =, s1 =,
// m2 =, s2 =} or {preset = ...}.
halfspace::Friction read_law(OptionReader& t) {
  using halfspace::FrictionLaw;
  const auto preset = t.choice("preset", {"polach_dry", "polach_wet", "contact_example"},
                               {"-", "a named parameter set of Polach's law (instead of law and its coefficients)"});
  const auto law = t.choice("law", {"polach", "linear", "rational", "exponential"},
                            {"-", "friction falling with the slip velocity w: Polach's law or CONTACT's L = 2, 3, 4"});
  const auto mu0 = t.number("mu0", {"-", "polach: mu at zero slip velocity"});
  const auto A = t.number("A", {"-", "polach: mu(infinity) / mu0, in [0, 1]"});
  const auto B = t.number("B", {"s/m", "polach: the exponential decay rate, > 0"});
  const auto mu_inf = t.number("mu_inf", {"-", "linear, rational, exponential: mu at large slip velocity (CONTACT FKIN)"});
  const auto m1 = t.number("m1", {"-", "linear, rational, exponential: the first term's size at w = 0, >= 0"});
  const auto s1 = t.number("s1", {"m/s", "the first term's velocity (CONTACT SABSH1, here m/s)"});
  const auto m2 = t.number("m2", {"-", "the second term's size at w = 0, >= 0 (default 0)"});
  const auto s2 = t.number("s2", {"m/s", "the second term's velocity (CONTACT SABSH2, m/s)"});
  if (t.documenting()) return {};
  if (preset) {
    if (law || mu0 || A || B || mu_inf || m1 || s1 || m2 || s2)
      fail("{}: 'preset' gives the whole law; no 'law' or coefficients with it", t.context());
    for (const FrictionPreset& p : kFrictionPresets)
      if (*preset == p.name) return halfspace::Friction::polach(p.mu0, p.A, p.B);
  }
  if (!law) fail("{}: 'law' (polach, linear, rational, exponential) or 'preset' is required", t.context());
  const auto need = [&](const std::optional<double>& v, const char* key) {
    if (!v) fail("{}: the {} law needs '{}'", t.context(), *law, key);
    return *v;
  };
  if (*law == "polach") {
    for (const char* key : {"mu_inf", "m1", "s1", "m2", "s2"})
      if (t.has(key)) fail("{}: '{}' is not a coefficient of the polach law (mu0, A, B)", t.context(), key);
    const double m = need(mu0, "mu0"), a = need(A, "A"), b = need(B, "B");
    check_coefficient(t, "mu0", m);
    if (!(a >= 0 && a <= 1)) fail("{}: A = {} must be in [0, 1] (mu falls from mu0 to A mu0)", t.context(), a);
    if (!(b > 0)) fail("{}: B = {} s/m must be > 0", t.context(), b);
    if (a * m < halfspace::kFrictionMin) check_coefficient(t, "A mu0", a * m);
    return halfspace::Friction::polach(m, a, b);
  }
  for (const char* key : {"mu0", "A", "B"})
    if (t.has(key)) fail("{}: '{}' is a coefficient of the polach law, not of the {} law", t.context(), key, *law);
  const double mi = need(mu_inf, "mu_inf");
  check_coefficient(t, "mu_inf", mi);
  const std::array<double, 2> terms{m1.value_or(0), m2.value_or(0)};
  const std::array<std::optional<double>, 2> vel{s1, s2};
  for (std::size_t i = 0; i < 2; ++i) {
    if (!(terms[i] >= 0)) fail("{}: m{} = {} must be >= 0 (friction falls with slip)", t.context(), i + 1, terms[i]);
    if (terms[i] > 0 && !vel[i]) fail("{}: m{} > 0 needs its velocity s{} (m/s)", t.context(), i + 1, i + 1);
    if (vel[i] && !(*vel[i] > 0)) fail("{}: s{} = {} m/s must be > 0", t.context(), i + 1, *vel[i]);
  }
  const FrictionLaw kind = *law == "linear" ? FrictionLaw::linear
                           : *law == "rational" ? FrictionLaw::rational
                                                : FrictionLaw::exponential;
  halfspace::Friction f = halfspace::Friction::falling(kind, mi, terms, {s1.value_or(1), s2.value_or(1)});
  check_coefficient(t, "mu_inf + m1 + m2", f.static_coefficient);
  return f;
}

// friction_profile = {y = {...}, mu = {...}} (both rails) or {left = {...}, right = {...}}.
FrictionProfile read_profile(OptionReader& t) {
  FrictionProfile p;
  const auto y = t.numbers("y", {"m", "the rail profile's lateral coordinate (its file's frame), increasing"});
  const auto mu = t.numbers("mu", {"-", "mu(0) of the friction law at each y (linear between, constant beyond)"});
  if (t.documenting()) return p;
  if (!y || !mu) fail("{}: a friction profile needs 'y' (m) and 'mu', lists of equal length", t.context());
  if (y->size() != mu->size() || y->empty())
    fail("{}: 'y' has {} values and 'mu' {}: expected equal, non-empty lists", t.context(), y->size(), mu->size());
  for (std::size_t i = 0; i < y->size(); ++i) {
    if (!(std::abs((*y)[i]) <= kFrictionProfileTo))
      fail("{}: {} (= {} m) lies beyond +-{:g} m of the rail profile's origin, wider than any rail head (60E1: -36 .. "
           "+37 mm): is it in mm? y is in metres", t.context(), value_at(i, "y"), (*y)[i], kFrictionProfileTo);
    if (i > 0 && !((*y)[i] > (*y)[i - 1]))
      fail("{}: {} (= {} m) does not increase from the one before ({} m)", t.context(), value_at(i, "y"), (*y)[i],
           (*y)[i - 1]);
    if (!((*mu)[i] >= halfspace::kFrictionMin && (*mu)[i] <= halfspace::kFrictionMax))
      fail("{}: {} (= {}) must be in [{:g}, {:g}]", t.context(), value_at(i, "mu"), (*mu)[i], halfspace::kFrictionMin,
           halfspace::kFrictionMax);
  }
  p.y = std::move(*y);
  p.mu = std::move(*mu);
  return p;
}

void read_friction_profile(OptionReader& r, RollingRequest& q) {
  auto t = r.table("friction_profile", {"-", "mu across the rail's profile: {y =, mu =} or per wheel {left =, right =}"});
  if (!t) return;
  const bool sides = t->documenting() || t->has("left") || t->has("right");
  if (sides) {
    for (int side : {kLeft, kRight})
      if (auto s = t->table(side_name(side), {"-", "this wheel's rail: {y =, mu =}"})) {
        q.friction_profile[static_cast<std::size_t>(side)] = read_profile(*s);
        s->finish();
      }
  }
  if (!sides || t->documenting()) {
    const FrictionProfile p = read_profile(*t);
    if (!t->documenting()) q.friction_profile = {p, p};
  }
  t->finish();
}

halfspace::Friction read_friction(OptionReader& r) {
  const auto mu = r.number("mu", {"-", "friction coefficient (static = kinetic)"});
  const auto mus = r.number("mu_static", {"-", "static friction coefficient (with mu_kinetic)"});
  const auto muk = r.number("mu_kinetic", {"-", "kinetic friction coefficient (default: mu_static)"});
  halfspace::Friction f;
  if (auto t = r.table("friction", {"-", "friction falling with the slip velocity: {law =, ...} or {preset =}"})) {
    if (!r.documenting() && (mu || mus || muk))
      fail("{}: 'friction' gives the friction law; 'mu', 'mu_static', 'mu_kinetic' cannot be given with it",
           r.context());
    f = read_law(*t);
    t->finish();
    if (!r.documenting()) return f;
  }
  if (r.documenting()) return f;
  if (!mu && !mus)
    fail("{}: the friction coefficient 'mu' (or 'mu_static' and 'mu_kinetic', or a 'friction' law) is required",
         r.context());
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

// yaw_rate, vy, and omega against pure rolling on r0 (m).
void check_kinematics(const std::optional<Kinematics>& kinematics, std::string_view context, double r0) {
  if (!kinematics) return;
  const Kinematics& k = *kinematics;
  check_plausible(context, "yaw_rate", k.yaw_rate, kYawRate);
  check_plausible(context, "vy", k.vy, kLateralVelocity);
  if (!k.omega) return;
  if (!(r0 > 0)) fail("{}: omega cannot be checked against pure rolling without the nominal radius (r0 = {} m)", context, r0);
  const double rolling = k.V / r0, ratio = *k.omega / rolling;
  if (ratio >= 0 && ratio <= kMaxSpinRatio) return;
  fail("{}: omega = {:.6g} rad/s is {:.3g} times the {:.4g} rad/s of pure rolling at V = {:.4g} m/s on r0 = {:.4g} m: "
       "the longitudinal creepage would be {:.3g}, beyond a locked wheel (1) and a wheel spinning at twice the speed "
       "(-1). Is omega in another unit? wrc takes rad/s ({:.4g} rad/s is {:.4g} rpm); {}",
       context, *k.omega, ratio, rolling, k.V, r0, 1 - ratio, rolling, rolling * 60 / (2 * std::numbers::pi),
       kUncheckedHint);
}

}  // namespace

void RollingRequest::validate(std::string_view context, bool plausible, double r0) const {
  if (!plausible) return;
  check_plausible(context, "V", kinematics ? kinematics->V : V, kTrainSpeed);
  check_kinematics(kinematics, context, r0);
  check_plausible(context, friction.law == halfspace::FrictionLaw::coulomb ? "mu" : "mu(0)",
                  friction.static_coefficient, kFrictionCoefficient);
  for (const auto& side : friction_profile)
    if (side)
      for (double mu : side->mu) check_plausible(context, "friction_profile's mu", mu, kFrictionCoefficient);
  if (creepage) {
    check_plausible(context, "xi", creepage->xi, kCreepage);
    check_plausible(context, "eta", creepage->eta, kCreepage);
    check_plausible(context, "phi", creepage->phi, kSpinCreepage);
  }
  if (friction.law == halfspace::FrictionLaw::polach)  // s_1 = ln 2 / B (halfspace::Friction::polach)
    check_plausible(context, "B", std::numbers::ln2 / friction.velocity[0], kPolachDecay);
  if (friction.law == halfspace::FrictionLaw::coulomb || friction.law == halfspace::FrictionLaw::polach) return;
  for (std::size_t i = 0; i < 2; ++i)
    if (friction.term[i] > 0)
      check_plausible(context, i == 0 ? "s1" : "s2", friction.velocity[i], kFrictionVelocity);
}

std::optional<RollingRequest> read_rolling_request(OptionReader& r) {
  bool any = r.documenting() || r.has("creepage");
  for (const char* key : {"V", "omega", "free_rolling", "vy", "yaw_rate", "slip_reference"}) any |= r.has(key);
  for (const char* key : {"mu", "mu_static", "mu_kinetic", "friction", "friction_profile", "method", "rolling_tolerance",
                          "wear", "fatigue"})
    if (r.has(key) && !any)
      fail("{}: '{}' is given but neither V (the wheelset's kinematics) nor creepage: {} needs one of them",
           r.context(), key, std::string_view(key) == "wear" || std::string_view(key) == "fatigue" ? "rolling contact" : "friction");
  if (!any) return std::nullopt;
  RollingRequest q;
  read_slip(r, q);
  q.friction = read_friction(r);
  if (!r.documenting() && q.friction.slip_dependent() && q.creepage && !r.has("V"))
    fail("{}: the {} friction law depends on the slip velocity: give V (m/s) with the creepages", r.context(),
         halfspace::law_name(q.friction.law));
  read_friction_profile(r, q);
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
