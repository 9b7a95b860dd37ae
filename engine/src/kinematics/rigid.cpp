// Rigid contact of a wheelset on its track (rigid.hpp): the gap of the rail lines, the touching pose (Newton with
// analytic derivatives, nested brackets where the contact point jumps), the contact points and the force balance.
#include "wrc/kinematics/rigid.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/roots.hpp"
#include "wrc/geometry/pose.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace wrc {
namespace {

constexpr double kTouch = 1e-12;  // m: both overlaps within this of zero = touching

void check_case(double y, double yaw, const RigidOptions& o) {
  check_lateral(y, "rigid contact");
  check_yaw(yaw, "rigid contact");
  if (!std::isfinite(o.Q) || !(o.Q > 0)) fail("rigid contact: Q = {} N must be a positive number", o.Q);
  check_roll(o.roll, "rigid contact");
  if (!(o.two_point_tolerance >= 0) || !(o.two_point_tolerance <= 1e-3))
    fail("rigid contact: two_point_tolerance = {} m must lie in [0, 1e-3]", o.two_point_tolerance);
  if (!std::isfinite(o.hertz_load) || !(o.hertz_load > 0))
    fail("rigid contact: hertz_load = {} N must be a positive number", o.hertz_load);
  if (o.material) halfspace::validate(*o.material, "rigid contact");
}

// Every contact point's Hertz ellipse and Kalker's coefficients for the options' load and material.
void add_ellipses(const RigidOptions& o, RigidResult& res) {
  if (!o.material) return;
  for (RigidWheel& w : res.wheel)
    for (RigidContactPoint& c : w.contacts)
      c.ellipses = halfspace::hertz_ellipses(
          halfspace::wheel_rail_curvature(c.rolling_radius, c.angle, c.wheel_curvature, c.rail_curvature),
          o.hertz_load, *o.material);
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

// A bracket [a, b] = [-w, w] with f(a) > 0 > f(b): w = `first`, then `reach` when the first does not hold a root.
struct Bracket {
  double a, b, fa, fb;
  bool found;
};

template <class F>
Bracket widening_bracket(F&& f, double first, double reach) {
  Bracket k{-first, first, f(-first), f(first), false};
  k.found = k.fa > 0 && k.fb < 0;
  if (k.found || !(reach > first)) return k;
  k = {-reach, reach, f(-reach), f(reach), false};
  k.found = k.fa > 0 && k.fb < 0;
  return k;
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

  // The height at which one wheel touches at a held roll: Newton (the overlap falls one to one with z), then the
  // brackets of touch_height. Throws when the wheel does not touch within them.
  double touch_z(int side, double roll, double z) const {
    for (int it = 0; it < 8; ++it) {
      const PoseFrame f = frame(z, roll);
      const Deepest b = find_deepest(g_.side[side], f);
      if (b.line < 0) break;
      if (std::abs(b.overlap) <= kTouch) return z;
      const double slope = overlap_gradient(g_.side[side].wheel, f, b.point)(0);
      if (!(slope < -0.1)) break;
      z -= b.overlap / slope;
      if (!(std::abs(z) <= kTouchWindow)) break;  // the first bracket's range: farther, the brackets decide
    }
    return touch_height(g_, side, y_, yaw_, roll, "rigid contact");
  }

  // Where Newton stalls on a jump of the contact point: nested brackets. For a roll, the height at which the first
  // wheel touches; then the roll at which both do (the difference of the overlaps changes sign: the left rises).
  void nested(double& z, double& roll) const {
    auto first_touch = [&](double rr) {
      auto f = [&](double zz) { return std::max(overlap(kLeft, zz, rr), overlap(kRight, zz, rr)); };
      const Bracket b = widening_bracket(f, kTouchWindow, touch_reach(g_, rr));
      if (!b.found)
        fail("rigid contact: no touching height within +-{:.0f} mm at y = {}, yaw = {}", b.a * -1e3, y_, yaw_);
      bool ok = false;
      return bracketed_root(f, b.a, b.b, b.fa, b.fb, kTouch, 200, ok);
    };
    auto diff = [&](double rr) {
      const double zz = first_touch(rr);
      return overlap(kLeft, zz, rr) - overlap(kRight, zz, rr);
    };
    const Bracket r = widening_bracket(diff, kTouchRollWindow, touch_roll_reach(g_));
    const double a = r.a, b = r.b, fa = r.fa, fb = r.fb;
    if (!r.found)
      fail("rigid contact: no roll within +-{:.0f} mrad puts both wheels on their rails", r.b * 1e3);
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
  const ProfilePoint pp = profile_point(g, side, c.point, c.wheel_point.y(), c.rolling_radius);
  c.wheel_profile = pp.wheel;
  c.rail_profile = pp.rail;
  c.wheel_curvature = pp.wheel_curvature;
  c.rail_curvature = pp.rail_curvature;
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

// The flange-climb flags of a solved result (geometry/flange.hpp), the conditions of the elastic results applied to
// the rigid contact points: a touching point beyond the steepest part of the flange, L/V beyond Nadal's limit with
// the balance's normal forces, a wheel lifted above its rail by more than its flange height.
void flag_flange_climb(const GeometryModel& g, RigidResult& res) {
  if (!res.converged) return;
  for (int s : {kLeft, kRight}) {
    RigidWheel& w = res.wheel[s];
    const Flange& flange = g.side[s].flange;
    for (const RigidContactPoint& c : w.contacts)
      if (w.flange_climb.empty()) w.flange_climb = beyond_steepest(flange, c.wheel_profile.x());
    if (w.flange_climb.empty() && res.has_forces() && !res.tension && !w.contacts.empty()) {
      const Eigen::Vector3d F = w.normal_force * w.normal;
      if (w.normal_force > 0) w.flange_climb = nadal_exceeded(flange, s, F.y(), F.z());
    }
    if (w.flange_climb.empty() && !w.lifted) w.flange_climb = lifted_off(flange, w.gap);
    if (!w.flange_climb.empty() && res.flange_climb.empty())
      res.flange_climb = fmt::format("{} wheel: {}", side_name(s), w.flange_climb);
  }
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
    res.message = fmt::format("rigid contact: neither wheel touches its rail within z = +-{:.0f} mm at y = {} m",
                              touch_reach(g, o.roll) * 1e3, y);
    return;
  }
  for (int s : {kLeft, kRight})
    if (!res.wheel[s].lifted) res.wheel[s].gap = res.z - res.wheel[s].z;
  res.converged = true;
}

}  // namespace

double touch_reach(const GeometryModel& g, double roll) {
  double reach = 0;
  for (int s : {kLeft, kRight}) {
    const Profile &w = g.track->wheel[s], &r = g.track->rail[s];
    const auto [wlo, whi] = std::minmax_element(w.z.begin(), w.z.end());
    const auto [rlo, rhi] = std::minmax_element(r.z.begin(), r.z.end());
    const auto [ylo, yhi] = std::minmax_element(w.y.begin(), w.y.end());
    const double lateral = g.track->place[s].tape_y + std::max(std::abs(*ylo), std::abs(*yhi));
    reach = std::max(reach, (*whi - *wlo) + (*rhi - *rlo) + std::abs(std::sin(roll)) * lateral);
  }
  return reach + 1e-3;
}

double touch_roll_reach(const GeometryModel& g) {
  const double span = g.track->place[kLeft].tape_y + g.track->place[kRight].tape_y;
  return std::max(kTouchRollWindow, std::min(0.1, touch_reach(g, 0.0) / span));
}

double touch_height(const GeometryModel& g, int side, double y, double yaw, double roll, std::string_view context) {
  auto pen = [&](double z) { return deepest_point(g, side, {y, z, roll, yaw}).overlap; };
  const Bracket b = widening_bracket(pen, kTouchWindow, touch_reach(g, roll));
  if (!b.found)
    fail("{}: the {} wheel does not touch its rail within z = +-{:.0f} mm (as far as the profiles reach) at y = {} m, "
         "roll = {} rad: no rail under it", context, side_name(side), b.b * 1e3, y, roll);
  bool ok = false;
  return bracketed_root(pen, b.a, b.b, b.fa, b.fb, kTouch, 200, ok);
}

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
    flag_flange_climb(g, res);
    add_ellipses(o, res);
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
           "got {}", r.context(), v->type == OptionValue::Type::string ? "\"" + v->string + "\"" : r.type_name(*v));
    }
  }
  o.Q = r.number("Q", {"N", "the load the normal forces carry (roll free)"}, o.Q);
  o.hertz_load = r.number("hertz_load", {"N", "the normal load of every contact point's Hertz ellipse (hertz, kalker)"},
                          o.hertz_load);
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
  out.number("gap", c.gap, {"m", "gap of the point: 0 at the touching point, <= two_point_tolerance at a second one"});
  out.integer("line", c.line + 1, {"-", "rail line of the gap's minimum (1-based)"});
  out.vec3("point", c.point, {"m", "the contact point (track frame)"});
  out.vec3("wheel_point", c.wheel_point, {"m", "the contact point in the wheelset frame"});
  out.vec3("normal", c.normal, {"-", "the wheel's unit normal there, into the wheel (track frame)"});
  out.number("angle", c.angle, {"rad", "contact angle, > 0 tilted toward the track centre"});
  out.number("rolling_radius", c.rolling_radius, {"m", "wheel radius at the point"});
  const std::tuple<const char*, Eigen::Vector2d, const char*> profiles[] = {
      {"wheel_profile", c.wheel_profile, "the point on the wheel profile as loaded: y = s from the tape circle, z"},
      {"rail_profile", c.rail_profile, "the point on the rail profile as loaded (before cant and placement)"}};
  for (const auto& [key, v, meaning] : profiles) {
    out.begin(key, {"", meaning});
    out.number("y", v.x(), {"m", "lateral coordinate in the profile's frame, + toward the field side"});
    out.number("z", v.y(), {"m", "vertical coordinate in the profile's frame"});
    out.end();
  }
  out.number("wheel_curvature", c.wheel_curvature, {"1/m", "lateral curvature of the wheel profile there (> 0 convex)"});
  out.number("rail_curvature", c.rail_curvature, {"1/m", "lateral curvature of the rail profile there (> 0 convex)"});
  if (c.wheel_curvature != 0)
    out.number("wheel_lateral_radius", 1 / c.wheel_curvature, {"m", "1 / wheel_curvature (only when not 0)"});
  if (c.rail_curvature != 0)
    out.number("rail_lateral_radius", 1 / c.rail_curvature, {"m", "1 / rail_curvature (only when not 0)"});
  describe(c.ellipses, out);
}

namespace {

void describe_wheel(const RigidResult& r, const RigidWheel& w, FieldSink& out) {
  out.boolean("lifted", w.lifted, {"", "no rail under the wheel: no contact point (the wheel's other fields absent)"});
  out.boolean("flange_climb", !w.flange_climb.empty(),
              {"", "the wheel is past flange climb (beyond the flange's steepest part, Nadal's limit, or lifted off), as elastic results say"});
  if (!w.flange_climb.empty())
    out.string("flange_climb_reason", w.flange_climb, {"", "why it is past flange climb (only when it is)"});
  if (w.lifted) return;
  out.number("z", w.z, {"m", "height of the wheelset centre at which this wheel touches"});
  out.number("gap", w.gap, {"m", "roll fixed: the wheel's clearance when the wheelset rests at its z"});
  out.boolean("two_point", w.contacts.size() > 1, {"", "the wheel has a second contact point"});
  out.vec3("point", w.point, {"m", "contact point on the deepest rail line (track frame)"});
  out.vec3("normal", w.normal, {"-", "unit normal there, into the wheel (track frame)"});
  out.number("angle", w.angle, {"rad", "contact angle, > 0 tilted toward the track centre"});
  out.number("rolling_radius", w.rolling_radius, {"m", "wheel radius at the contact point"});
  if (r.has_forces())
    out.number("normal_force", w.normal_force, {"N", "normal force from the force balance (roll free and converged)"});
  out.number("overlap", w.overlap, {"m", "radial overlap at the deepest point (0 at the solution)"});
  out.integer("line", w.line + 1, {"-", "the deepest rail line (1-based)"});
  out.begin_list("contacts", w.contacts.size(),
                 {"", "the contact points between the lines: the touching point first, then by increasing gap"});
  for (const RigidContactPoint& c : w.contacts) {
    out.item();
    describe(c, out);
    out.end();
  }
  out.end();
}

}  // namespace

void describe(const RigidResult& r, FieldSink& out) {
  out.boolean("converged", r.converged, {"", "both wheels touch (the kinematic constraint holds)"});
  out.boolean("tension", r.tension,
              {"", "a wheel would need a pulling normal force to carry Q with no roll moment: no equilibrium"});
  out.boolean("flange_climb", !r.flange_climb.empty(),
              {"", "a wheel is past flange climb (beyond the flange's steepest part, Nadal's limit, or lifted off), as elastic results say"});
  if (!r.flange_climb.empty())
    out.string("flange_climb_reason", r.flange_climb, {"", "why it is past flange climb (only when it is)"});
  if (!r.message.empty()) out.string("error", r.message, {"", "why there is no solution (only then)"});
  out.string("roll_mode", r.roll_mode == RollMode::free ? "free" : "fixed",
             {"", "free (roll solved: both wheels touch) or fixed (roll held)"});
  out.number("y", r.y, {"m", "lateral position of the wheelset centre, + toward the left rail"});
  out.number("yaw", r.yaw, {"rad", "yaw, > 0 counter-clockwise seen from above"});
  out.number("Q", r.Q, {"N", "vertical load the normal forces carry (roll free)"});
  out.number("z", r.z, {"m", "height of the centre at which the wheelset rests on the rails"});
  out.number("roll", r.roll, {"rad", "roll, > 0 lifts the left wheel"});
  if (r.touching())
    out.number("rolling_radius_difference", r.rolling_radius_difference(),
               {"m", "left minus right rolling radius at the touching points (when both touch)"});
  if (r.has_forces()) {
    out.number("Y", r.Y, {"N", "lateral force a support at the centre applies, -sum Fy (roll free and converged)"});
    out.number("My", r.My, {"N m", "moment about y the support applies, -sum My (roll free and converged)"});
    out.number("Mz", r.Mz, {"N m", "moment about z the support applies, -sum Mz (roll free and converged)"});
    out.number("Y_Q", r.Y / r.Q, {"-", "Y / Q (roll free and converged)"});
  }
  for (int s : {kLeft, kRight}) {
    out.begin(side_name(s), {"", "the rigid contact of the wheel on that side (left: +y)"});
    describe_wheel(r, r.wheel[s], out);
    out.end();
  }
}

}  // namespace wrc
