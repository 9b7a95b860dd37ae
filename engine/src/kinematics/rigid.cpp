// Rigid contact of a wheelset on its track (rigid.hpp): the gap of the rail lines, the touching pose (Newton with
// analytic derivatives, nested brackets where the contact point jumps), the contact points and the force balance.
#include "wrc/kinematics/rigid.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/roots.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {
namespace {

constexpr double kTouch = 1e-12;  // m: both overlaps within this of zero = touching

void check_case(double y, double yaw, const RigidOptions& o) {
  if (!std::isfinite(y) || std::abs(y) > 0.1) fail("rigid contact: y = {} m must be finite and within +-0.1 m", y);
  if (!std::isfinite(yaw) || std::abs(yaw) > 0.3)
    fail("rigid contact: yaw = {} rad must be finite and within +-0.3 rad", yaw);
  if (!std::isfinite(o.Q) || !(o.Q > 0)) fail("rigid contact: Q = {} N must be a positive number", o.Q);
  if (!std::isfinite(o.roll) || std::abs(o.roll) > 0.1)
    fail("rigid contact: roll = {} rad must be finite and within +-0.1 rad", o.roll);
  if (!(o.two_point_tolerance >= 0) || !(o.two_point_tolerance <= 1e-3))
    fail("rigid contact: two_point_tolerance = {} m must lie in [0, 1e-3]", o.two_point_tolerance);
}

// The wheel radius at Y and its slope dR/dY, with a cone index that walks along as the rail lines are visited in
// order (their wheelset-frame Y is nearly monotone): the rule of wheel_radius_at, in O(1) per line.
struct RadiusWalk {
  const WheelCones& w;
  int c = 1, last = 1;
  explicit RadiusWalk(const WheelCones& wheel) : w(wheel), last(wheel.cone_count() - 2) {}
  bool inside(double Y) const { return Y >= w.y[1] && Y <= w.y[last + 1]; }
  double radius(double Y, double* slope = nullptr) {
    while (c < last && Y > w.y[c + 1]) ++c;
    while (c > 1 && Y < w.y[c]) --c;
    while (c < last && w.y[c + 1] == w.y[c]) ++c;  // a flat ring holds Y only at its own y: the cone after it
    const double y0 = w.y[c], y1 = w.y[c + 1];
    const double t = y1 > y0 ? std::clamp((Y - y0) / (y1 - y0), 0.0, 1.0) : 0.0;
    if (slope) *slope = y1 > y0 ? -(w.z[c + 1] - w.z[c]) / (y1 - y0) : 0.0;
    return -(w.z[c] + t * (w.z[c + 1] - w.z[c]));
  }
};

// The overlap of every rail line's deepest point (m, > 0 inside the wheel) and its x. At zero yaw the plane x = 0
// holds the axle and every line's closest approach: the exact 2-D section, one pass; otherwise the 3-D search of
// each line (line_approach), where a line that provably stays below `floor` gets a bound below it instead.
void line_overlaps(const SideGeometry& g, const PoseFrame& f, std::vector<double>& overlap, std::vector<double>& xs,
                   double floor = -std::numeric_limits<double>::infinity()) {
  const RailLines& rail = g.rail;
  const int n = rail.count();
  overlap.resize(static_cast<std::size_t>(n));
  xs.assign(static_cast<std::size_t>(n), 0.0);
  if (f.a12 == 0) {
    RadiusWalk walk(g.wheel);
    for (int r = 0; r < n; ++r) {
      const double dy = rail.y[r] - f.y, dz = rail.z[r] - f.z;
      const double Y = f.a22 * dy + f.a32 * dz, d = std::abs(f.a23 * dy + f.a33 * dz);
      overlap[static_cast<std::size_t>(r)] = walk.inside(Y) ? walk.radius(Y) - d : -d;
    }
    return;
  }
  for (int r = 0; r < n; ++r) {
    const LineApproach a = line_approach(g.wheel, f, rail.y[r], rail.z[r], floor);
    overlap[static_cast<std::size_t>(r)] = a.overlap;
    xs[static_cast<std::size_t>(r)] = a.x;
  }
}

// The deepest line of one side and its point (track frame).
struct Deepest {
  double overlap = -std::numeric_limits<double>::infinity();
  int line = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

Deepest find_deepest(const SideGeometry& g, const PoseFrame& f) {
  const RailLines& rail = g.rail;
  Deepest best;
  if (f.a12 == 0) {  // zero yaw: the section, in one pass
    RadiusWalk walk(g.wheel);
    for (int r = 0; r < rail.count(); ++r) {
      const double dy = rail.y[r] - f.y, dz = rail.z[r] - f.z;
      const double Y = f.a22 * dy + f.a32 * dz, d = std::abs(f.a23 * dy + f.a33 * dz);
      const double o = walk.inside(Y) ? walk.radius(Y) - d : -d;
      if (o > best.overlap) {
        best.overlap = o;
        best.line = r;
      }
    }
    if (best.line >= 0) best.point = {0.0, rail.y[best.line], rail.z[best.line]};
    return best;
  }
  // With yaw: the largest overlap at the lines' closest approaches is a floor; lines that provably stay below it are
  // skipped (each full line search visits the cones it passes under).
  double floor = -std::numeric_limits<double>::infinity();
  for (int r = 0; r < rail.count(); ++r) floor = std::max(floor, line_overlap_at_closest(g.wheel, f, rail.y[r], rail.z[r]));
  double x = 0;
  for (int r = 0; r < rail.count(); ++r) {
    const LineApproach a = line_approach(g.wheel, f, rail.y[r], rail.z[r], std::max(floor, best.overlap));
    if (a.overlap > best.overlap) {
      best.overlap = a.overlap;
      best.line = r;
      x = a.x;
    }
  }
  if (best.line >= 0) best.point = {x, rail.y[best.line], rail.z[best.line]};
  return best;
}

// d(overlap)/d(z, roll) at the deepest point p of a line. The deepest point maximises the overlap along its line, so
// (envelope theorem) its x may stay fixed: overlap = R(q_y) - |(q_x, q_z)| with q = A^T (p - c).
Eigen::Vector2d overlap_gradient(const WheelCones& w, const PoseFrame& f, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d(p.x(), p.y() - f.y, p.z() - f.z);
  const Eigen::Matrix3d A = f.matrix();
  const Eigen::Vector3d q = A.transpose() * d;
  const double dist = std::hypot(q.x(), q.z());
  const int c = w.running_cone(q.y());
  const double dy = w.y[c + 1] - w.y[c];
  const double k = dy > 0 ? -(w.z[c + 1] - w.z[c]) / dy : 0.0;  // dR/dY
  const Eigen::Vector3d dq_dz = -A.row(2).transpose();             // A^T (0, 0, -1)
  // A = Rz(yaw) Rx(roll): dA/droll = Rz dRx, so dq/droll = dRx^T (Rz^T d).
  const double cy = f.a11, sy = f.a21, cr = f.a33, sr = f.a32;
  const Eigen::Vector3d u(cy * d.x() + sy * d.y(), -sy * d.x() + cy * d.y(), d.z());
  const Eigen::Vector3d dq_dr(0.0, -sr * u.y() + cr * u.z(), -cr * u.y() - sr * u.z());
  auto grad = [&](const Eigen::Vector3d& dq) { return k * dq.y() - (q.x() * dq.x() + q.z() * dq.z()) / dist; };
  return {grad(dq_dz), grad(dq_dr)};
}

// Overlaps of both wheels at (z, roll) with their Jacobian.
struct Depths {
  Eigen::Vector2d P = Eigen::Vector2d::Zero();
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
};

class RigidSolver {
 public:
  RigidSolver(const GeometryModel& g, double y, double yaw) : g_(g), y_(y), yaw_(yaw) {}

  double overlap(int side, double z, double roll) const { return find_deepest(g_.side[side], frame(z, roll)).overlap; }

  Depths depths(double z, double roll) const {
    Depths d;
    const PoseFrame f = frame(z, roll);
    for (int s : {kLeft, kRight}) {
      const Deepest b = find_deepest(g_.side[s], f);
      d.P(s) = b.overlap;
      if (b.line >= 0) d.J.row(s) = overlap_gradient(g_.side[s].wheel, f, b.point).transpose();
    }
    return d;
  }

  // Newton on (z, roll) for both overlaps = 0, steps limited (1 mm, 2 mrad) and backtracked on |P|.
  bool newton(double& z, double& roll) const {
    Depths d = depths(z, roll);
    for (int it = 0; it < 30; ++it) {
      if (!d.P.allFinite() || !(std::abs(z) <= 0.02 && std::abs(roll) <= 0.02)) return false;  // the brackets' range
      if (d.P.cwiseAbs().maxCoeff() <= kTouch) return true;
      Eigen::Vector2d dx = -d.J.fullPivLu().solve(d.P);
      if (!dx.allFinite()) return false;
      dx /= std::max({1.0, std::abs(dx(0)) / 1e-3, std::abs(dx(1)) / 2e-3});
      bool accepted = false;
      for (double t = 1; t > 1e-3 && !accepted; t *= 0.5) {
        Depths trial = depths(z + t * dx(0), roll + t * dx(1));
        if (trial.P.norm() < (1 - 1e-4 * t) * d.P.norm()) {
          z += t * dx(0);
          roll += t * dx(1);
          d = trial;
          accepted = true;
        }
      }
      if (!accepted) return false;
    }
    return false;
  }

  // The height at which one wheel touches at a held roll: Newton (the overlap falls one to one with z), then a
  // bracket over +-20 mm. Throws when the wheel does not touch within it.
  double touch_z(int side, double roll, double z) const {
    for (int it = 0; it < 8; ++it) {
      const PoseFrame f = frame(z, roll);
      const Deepest b = find_deepest(g_.side[side], f);
      if (b.line < 0) break;
      if (std::abs(b.overlap) <= kTouch) return z;
      const double slope = overlap_gradient(g_.side[side].wheel, f, b.point)(0);
      if (!(slope < -0.1)) break;
      z -= b.overlap / slope;
      if (!(std::abs(z) <= 0.02)) break;  // the bracket's range: farther, no rail under the wheel
    }
    auto f = [&](double zz) { return overlap(side, zz, roll); };
    const double a = -0.02, b = 0.02, fa = f(a), fb = f(b);
    if (!(fa > 0 && fb < 0))
      fail("rigid contact: the {} wheel does not touch its rail within z = +-20 mm at y = {} m, roll = {} rad",
           side_name(side), y_, roll);
    bool ok = false;
    return bracketed_root(f, a, b, fa, fb, kTouch, 200, ok);
  }

  // Where Newton stalls on a jump of the contact point: nested brackets. For a roll, the height at which the first
  // wheel touches; then the roll at which both do (the difference of the overlaps changes sign: the left rises).
  void nested(double& z, double& roll) const {
    auto first_touch = [&](double rr) {
      auto f = [&](double zz) { return std::max(overlap(kLeft, zz, rr), overlap(kRight, zz, rr)); };
      const double a = -0.02, b = 0.02, fa = f(a), fb = f(b);
      if (!(fa > 0 && fb < 0)) fail("rigid contact: no touching height within +-20 mm at y = {}, yaw = {}", y_, yaw_);
      bool ok = false;
      return bracketed_root(f, a, b, fa, fb, kTouch, 200, ok);
    };
    auto diff = [&](double rr) {
      const double zz = first_touch(rr);
      return overlap(kLeft, zz, rr) - overlap(kRight, zz, rr);
    };
    const double a = -0.02, b = 0.02, fa = diff(a), fb = diff(b);
    if (!(fa > 0 && fb < 0)) fail("rigid contact: no roll within +-20 mrad puts both wheels on their rails");
    bool ok = false;
    roll = bracketed_root(diff, a, b, fa, fb, kTouch, 200, ok);
    if (!ok) fail("rigid contact: the roll that puts both wheels on their rails was not found to 1e-12 m");
    z = first_touch(roll);
  }

  PoseFrame frame(double z, double roll) const { return PoseFrame(Pose{y_, z, roll, yaw_}); }

 private:
  const GeometryModel& g_;
  double y_, yaw_;
};

// The separate local minima of the gap (maxima of the overlap) within `tol` of the deepest: the deepest first, then
// by increasing gap; separate = the gap rises by more than tol above the shallower one between them.
std::vector<int> gap_minima(const std::vector<double>& o, double tol) {
  const int n = static_cast<int>(o.size());
  const double top = *std::max_element(o.begin(), o.end());
  std::vector<int> cand;
  for (int r = 0; r < n; ++r) {
    // A local maximum (plateaus give several, merged below: no valley between them).
    if ((r == 0 || o[r] >= o[r - 1]) && (r + 1 == n || o[r] >= o[r + 1]) && o[r] >= top - tol) cand.push_back(r);
  }
  std::sort(cand.begin(), cand.end(), [&](int a, int b) { return o[a] > o[b]; });
  std::vector<int> kept;
  for (int c : cand) {
    bool separate = true;
    for (int k : kept) {
      const int lo = std::min(c, k), hi = std::max(c, k);
      const double ridge = *std::min_element(o.begin() + lo, o.begin() + hi + 1);
      if (ridge > o[c] - tol) separate = false;  // no valley deeper than tol between them: the same contact
    }
    if (separate) kept.push_back(c);
  }
  return kept;
}

// Rail profile coordinates (its own frame as given) of a track-frame point of the placed rail.
Eigen::Vector2d rail_profile_point(const SidePlacement& pl, double y, double z) {
  const double yc = pl.sign * y - pl.rail_dy, zc = z - pl.rail_dz;
  const double c = std::cos(pl.cant_angle), s = std::sin(pl.cant_angle);
  return {c * yc + s * zc, -s * yc + c * zc};
}

// Contact point at line r, located between the lines by the parabola through the overlaps of r and its neighbours.
RigidContactPoint make_contact(const GeometryModel& g, int side, const PoseFrame& f, const std::vector<double>& o,
                               const std::vector<double>& xs, int r) {
  const SideGeometry& sg = g.side[side];
  const int n = sg.rail.count();
  double delta = 0;  // offset toward the next line (index units)
  if (r > 0 && r + 1 < n) {
    const double curv = o[r - 1] - 2 * o[r] + o[r + 1];
    if (curv < 0) delta = std::clamp(0.5 * (o[r - 1] - o[r + 1]) / curv, -0.5, 0.5);
  }
  const int nb = delta >= 0 ? std::min(r + 1, n - 1) : std::max(r - 1, 0);
  const double a = std::abs(delta);
  RigidContactPoint c;
  c.line = r;
  c.gap = std::max(0.0, -o[r]);
  c.point = {xs[r] + a * (xs[nb] - xs[r]), sg.rail.y[r] + a * (sg.rail.y[nb] - sg.rail.y[r]),
             sg.rail.z[r] + a * (sg.rail.z[nb] - sg.rail.z[r])};
  c.wheel_point = f.to_wheelset(c.point);
  c.rolling_radius = wheel_radius_at(sg.wheel, c.wheel_point.y());
  c.normal = wheel_inward_normal(sg.wheel, f, c.point);
  c.angle = contact_angle(side, c.normal);
  const SidePlacement& pl = g.track->place[side];
  c.wheel_profile = {pl.sign * c.wheel_point.y() - pl.tape_y, pl.radius - c.rolling_radius};
  c.rail_profile = rail_profile_point(pl, c.point.y(), c.point.z());
  if (sg.wheel_curve)
    c.wheel_curvature = surface_curvature(*sg.wheel_curve, ProfileKind::wheel, sg.wheel_curve->param_at_y(c.wheel_profile.x()));
  if (sg.rail_curve)
    c.rail_curvature = surface_curvature(*sg.rail_curve, ProfileKind::rail, sg.rail_curve->closest(c.rail_profile));
  return c;
}

// Normal forces from the vertical and roll balance: N_L n_L + N_R n_R carries Q with no moment about x.
void balance_forces(RigidResult& res) {
  const Eigen::Vector3d c(0, res.y, res.z);
  Eigen::Matrix2d A;
  for (int s : {kLeft, kRight}) {
    A(0, s) = res.wheel[s].normal.z();
    A(1, s) = (res.wheel[s].point - c).cross(res.wheel[s].normal).x();
  }
  const Eigen::Vector2d N = A.fullPivLu().solve(Eigen::Vector2d(res.Q, 0));
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
  for (int s : {kLeft, kRight}) {
    res.wheel[s].normal_force = N(s);
    const Eigen::Vector3d force = N(s) * res.wheel[s].normal;
    F += force;
    M += (res.wheel[s].point - c).cross(force);
  }
  res.Y = -F.y();
  res.My = -M.y();
  res.Mz = -M.z();
  res.converged = std::isfinite(res.Y) && N.allFinite();
  if (!res.converged) res.message = "rigid contact: the contact normals give a singular force balance";
  res.tension = res.converged && (N(0) < 0 || N(1) < 0);
}

// The deepest line's point, normal, angle and rolling radius (the fields of RigidWheel before contacts[]).
void set_deepest(const GeometryModel& g, int side, const PoseFrame& f, int line, double x, RigidWheel& w) {
  w.line = line;
  if (line < 0) return;
  const SideGeometry& sg = g.side[side];
  w.point = {x, sg.rail.y[line], sg.rail.z[line]};
  w.normal = wheel_inward_normal(sg.wheel, f, w.point);
  w.angle = contact_angle(side, w.normal);
  w.rolling_radius = wheel_surface_at(sg.wheel, f.to_wheelset(w.point).y()).radius;
}

// The wheel's deepest line and contact points at its pose, from one pass over the lines.
void describe_wheel_pose(const GeometryModel& g, int side, const Pose& pose, double tol, RigidWheel& w) {
  const PoseFrame f(pose);
  const SideGeometry& sg = g.side[side];
  std::vector<double> o, xs;
  // With yaw, lines far below the deepest need only a bound (they can be no contact point nor change the test).
  const double floor = f.a12 == 0 ? -std::numeric_limits<double>::infinity()
                                   : find_deepest(sg, f).overlap - 2 * tol - 1e-9;
  line_overlaps(sg, f, o, xs, floor);
  const int r = static_cast<int>(std::max_element(o.begin(), o.end()) - o.begin());
  w.overlap = o[static_cast<std::size_t>(r)];
  set_deepest(g, side, f, r, xs[static_cast<std::size_t>(r)], w);
  w.contacts.clear();
  for (int k : gap_minima(o, tol)) {
    for (int nb : {k - 1, k + 1})  // the neighbours exactly, for the parabola
      if (nb >= 0 && nb < sg.rail.count() && o[static_cast<std::size_t>(nb)] < floor) {
        const LineApproach a = line_approach(sg.wheel, f, sg.rail.y[nb], sg.rail.z[nb]);
        o[static_cast<std::size_t>(nb)] = a.overlap;
        xs[static_cast<std::size_t>(nb)] = a.x;
      }
    w.contacts.push_back(make_contact(g, side, f, o, xs, k));
  }
}

void solve_free(const GeometryModel& g, double y, double yaw, const RigidOptions& o, RigidResult& res) {
  const RigidSolver solver(g, y, yaw);
  double z = o.start ? (*o.start)(0) : 0.0, roll = o.start ? (*o.start)(1) : 0.0;
  bool ok = solver.newton(z, roll);
  if (!ok && o.start) {
    z = roll = 0;
    ok = solver.newton(z, roll);
  }
  if (!ok) {
    for (int s : {kLeft, kRight}) solver.touch_z(s, 0.0, 0.0);  // throws, naming the wheel, when one cannot touch
    solver.nested(z, roll);
  }
  res.z = z;
  res.roll = roll;
  for (int s : {kLeft, kRight}) {
    describe_wheel_pose(g, s, {y, z, roll, yaw}, o.two_point_tolerance, res.wheel[s]);
    res.wheel[s].z = z;
  }
  balance_forces(res);
}

void solve_fixed(const GeometryModel& g, double y, double yaw, const RigidOptions& o, RigidResult& res) {
  const RigidSolver solver(g, y, yaw);
  res.roll = o.roll;
  res.z = -std::numeric_limits<double>::infinity();
  for (int s : {kLeft, kRight}) {
    RigidWheel& w = res.wheel[s];
    try {
      w.z = solver.touch_z(s, o.roll, o.start ? (*o.start)(0) : 0.0);
    } catch (const Error&) {
      w.lifted = true;
      continue;
    }
    describe_wheel_pose(g, s, {y, w.z, o.roll, yaw}, o.two_point_tolerance, w);
    res.z = std::max(res.z, w.z);
  }
  if (res.wheel[kLeft].lifted && res.wheel[kRight].lifted) {
    res.z = 0;
    res.message = fmt::format("rigid contact: neither wheel touches its rail within z = +-20 mm at y = {} m", y);
    return;
  }
  for (int s : {kLeft, kRight})
    if (!res.wheel[s].lifted) res.wheel[s].gap = res.z - res.wheel[s].z;
  res.converged = true;
}

}  // namespace

RigidWheel deepest_point(const GeometryModel& g, int side, const Pose& pose) {
  const PoseFrame f(pose);
  const Deepest d = find_deepest(g.side[side], f);
  RigidWheel w;
  w.overlap = d.overlap;
  set_deepest(g, side, f, d.line, d.point.x(), w);
  return w;
}

RigidResult solve_rigid(const GeometryModel& g, double y, double yaw, const RigidOptions& o) {
  check_case(y, yaw, o);
  RigidResult res;
  res.roll_mode = o.roll_mode;
  res.y = y;
  res.yaw = yaw;
  res.Q = o.Q;
  try {
    if (o.roll_mode == RollMode::free) solve_free(g, y, yaw, o, res);
    else solve_fixed(g, y, yaw, o, res);
  } catch (const Error& e) {
    res.converged = false;
    res.message = e.what();
  }
  return res;
}

RigidResult solve_rigid(const GeometryModel& g, double y, double yaw, double Q) {
  RigidOptions o;
  o.Q = Q;
  return solve_rigid(g, y, yaw, o);
}

RigidOptions read_rigid_options(OptionReader& r, RigidOptions o) {
  const std::string roll = o.roll_mode == RollMode::free ? "\"free\"" : fmt::format("{}", o.roll);
  if (const OptionValue* v = r.value("roll", "number or string",
                                     {"rad", "\"free\" (both wheels touch), \"fixed\" (held at 0) or the roll held"}, roll)) {
    if (v->type == OptionValue::Type::number) {
      o.roll_mode = RollMode::fixed;
      o.roll = v->number;
    } else if (v->type == OptionValue::Type::string && (v->string == "free" || v->string == "fixed")) {
      o.roll_mode = v->string == "free" ? RollMode::free : RollMode::fixed;
    } else {
      fail("{}: 'roll' must be \"free\" (both wheels touch), \"fixed\" (held at 0) or a number (held there, rad), "
           "got {}", r.context(), v->type == OptionValue::Type::string ? "\"" + v->string + "\"" : v->type_name());
    }
  }
  o.Q = r.number("Q", {"N", "the load the normal forces carry (roll free)"}, o.Q);
  o.two_point_tolerance = r.number("two_point_tolerance", {"m", "a second gap minimum this close to 0 is a contact"},
                                   o.two_point_tolerance);
  if (auto s = r.table("start", {"-", "a start {z, roll} of the iteration"})) {
    const double z = s->need_number("z", {"m", "height to start from"});
    o.start = Eigen::Vector2d(z, s->number("roll", {"rad", "roll to start from"}, 0.0));
    s->finish();
  }
  return o;
}

void describe(const RigidContactPoint& c, FieldSink& out) {
  out.number("gap", c.gap);
  out.integer("line", c.line + 1);
  out.vec3("point", c.point);
  out.vec3("wheel_point", c.wheel_point);
  out.vec3("normal", c.normal);
  out.number("angle", c.angle);
  out.number("rolling_radius", c.rolling_radius);
  for (auto [key, v] : {std::pair{"wheel_profile", c.wheel_profile}, {"rail_profile", c.rail_profile}}) {
    out.begin(key);
    out.number("y", v.x());
    out.number("z", v.y());
    out.end();
  }
  out.number("wheel_curvature", c.wheel_curvature);
  out.number("rail_curvature", c.rail_curvature);
  if (c.wheel_curvature != 0) out.number("wheel_lateral_radius", 1 / c.wheel_curvature);
  if (c.rail_curvature != 0) out.number("rail_lateral_radius", 1 / c.rail_curvature);
}

namespace {

void describe_wheel(const RigidResult& r, const RigidWheel& w, FieldSink& out) {
  out.boolean("lifted", w.lifted);
  if (w.lifted) return;
  out.number("z", w.z);
  out.number("gap", w.gap);
  out.boolean("two_point", w.contacts.size() > 1);
  out.vec3("point", w.point);
  out.vec3("normal", w.normal);
  out.number("angle", w.angle);
  out.number("rolling_radius", w.rolling_radius);
  if (r.has_forces()) out.number("normal_force", w.normal_force);
  out.number("overlap", w.overlap);
  out.integer("line", w.line + 1);
  out.begin_list("contacts", w.contacts.size());
  for (const RigidContactPoint& c : w.contacts) {
    out.item();
    describe(c, out);
    out.end();
  }
  out.end();
}

}  // namespace

void describe(const RigidResult& r, FieldSink& out) {
  out.boolean("converged", r.converged);
  out.boolean("tension", r.tension);
  if (!r.message.empty()) out.string("error", r.message);
  out.string("roll_mode", r.roll_mode == RollMode::free ? "free" : "fixed");
  out.number("y", r.y);
  out.number("yaw", r.yaw);
  out.number("Q", r.Q);
  out.number("z", r.z);
  out.number("roll", r.roll);
  if (r.touching()) out.number("rolling_radius_difference", r.rolling_radius_difference());
  if (r.has_forces()) {
    out.number("Y", r.Y);
    out.number("My", r.My);
    out.number("Mz", r.Mz);
    out.number("Y_Q", r.Y / r.Q);
  }
  for (int s : {kLeft, kRight}) {
    out.begin(side_name(s));
    describe_wheel(r, r.wheel[s], out);
    out.end();
  }
}

}  // namespace wrc
