#include "wrc/geometry/wheel_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {
namespace {

// Meridian normal of the cone joining generatrix points i and i + 1 (unit, outward).
Eigen::Vector2d cone_normal(const WheelCones& w, int i) {
  double ny = 0, nr = 0;
  w.cone(i).meridian_normal(ny, nr);
  return {ny, nr};
}

}  // namespace

Eigen::Vector2d wheel_vertex_normal(const WheelCones& w, int i) {
  const int n = w.cone_count();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  // Cones i - 1 and i meet at point i; the end faces (cones 0 and n - 1) are not part of the running surface.
  if (i - 1 >= 1 && i - 1 <= n - 2) sum += cone_normal(w, i - 1);
  if (i >= 1 && i <= n - 2) sum += cone_normal(w, i);
  if (sum.squaredNorm() == 0) return {0, 1};
  return sum.normalized();
}

namespace {

Eigen::Vector2d vertex_normal(const WheelCones& w, int i) {
  const auto k = static_cast<std::size_t>(i);
  if (w.vertex_ny.size() == w.y.size()) return {w.vertex_ny[k], w.vertex_nr[k]};
  return wheel_vertex_normal(w, i);
}

// The running-surface cone holding Y (clamped to the profile) and the position t in [0, 1] on it.
int cone_holding(const WheelCones& w, double& Y, double& t) {
  const int n = w.cone_count();
  Y = std::clamp(Y, w.y[1], w.y[n - 1]);
  const int c = w.running_cone(Y);
  const double y0 = w.y[c], y1 = w.y[c + 1];
  t = y1 > y0 ? std::clamp((Y - y0) / (y1 - y0), 0.0, 1.0) : 0.0;
  return c;
}

}  // namespace

double wheel_radius_at(const WheelCones& w, double Y) {
  double t = 0;
  const int c = cone_holding(w, Y, t);
  return -(w.z[c] + t * (w.z[c + 1] - w.z[c]));
}

WheelNormalFoot wheel_normal_foot(const WheelCones& w, double Y, double rho) {
  const int n = w.cone_count();  // running-surface cones 1 .. n - 2, ascending in y
  double Yc = Y, t = 0;
  const int c = cone_holding(w, Yc, t);
  WheelNormalFoot best{INFINITY, Yc, c, t};
  const auto nearer = [&](int k) {
    const double ay = w.y[k], ar = -w.z[k], dy = w.y[k + 1] - ay, dr = -w.z[k + 1] - ar, L2 = dy * dy + dr * dr;
    const double u = L2 > 0 ? std::clamp(((Y - ay) * dy + (rho - ar) * dr) / L2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(Y - (ay + u * dy), rho - (ar + u * dr));
    if (d < best.depth) best = {d, ay + u * dy, k, u};
  };
  nearer(c);
  for (int k = c + 1; k <= n - 2 && w.y[k] - Y < best.depth; ++k) nearer(k);
  for (int k = c - 1; k >= 1 && Y - w.y[k + 1] < best.depth; --k) nearer(k);
  if (!(rho < -(w.z[c] + t * (w.z[c + 1] - w.z[c])))) best.depth = -best.depth;  // the radius at Y
  return best;
}

double wheel_normal_depth(const WheelCones& w, double Y, double rho) { return wheel_normal_foot(w, Y, rho).depth; }

double wheel_normal_turning(const WheelCones& w, double Y) {
  double t = 0;
  const int c = cone_holding(w, Y, t);
  const double dy = w.y[c + 1] - w.y[c];
  if (!(dy > 0)) return 0;
  const Eigen::Vector2d a = vertex_normal(w, c), b = vertex_normal(w, c + 1);
  return std::atan2(a.y() * b.x() - a.x() * b.y(), a.dot(b)) / dy;  // theta(b) - theta(a), theta = atan2(n_y, n_r)
}

namespace {

// The smooth meridian normal (n_y, n_r) at position t on cone c (the vertex normals' interpolation normalised) and,
// with `rate`, its derivative by Y there.
Eigen::Vector2d normal_on(const WheelCones& w, int c, double t, Eigen::Vector2d* rate = nullptr) {
  const Eigen::Vector2d a = vertex_normal(w, c), b = vertex_normal(w, c + 1), v = (1 - t) * a + t * b;
  const Eigen::Vector2d n = v.normalized();
  if (rate) {
    const double dy = w.y[c + 1] - w.y[c];
    *rate = dy > 0 ? Eigen::Vector2d((b - a - n * n.dot(b - a)) / (v.norm() * dy)) : Eigen::Vector2d::Zero();
  }
  return n;
}

}  // namespace

WheelSurfacePoint wheel_surface_at(const WheelCones& w, double Y) {
  double t = 0;
  const int c = cone_holding(w, Y, t);
  const Eigen::Vector2d nrm = normal_on(w, c, t);
  WheelSurfacePoint s;
  s.cone = c;
  s.radius = -(w.z[c] + t * (w.z[c + 1] - w.z[c]));
  s.normal_y = nrm.x();
  s.normal_r = nrm.y();
  return s;
}

namespace {

// The meridian plane of the wheelset-frame point q: its distance rho to the axle and the angle eps about the axle.
struct Meridian {
  double rho, se, ce;  // rho (m), sin eps, cos eps
};
Meridian meridian_of(const Eigen::Vector3d& q) {
  // eq. (1): q = (-Z sin eps, Y, Z cos eps) with Z = -rho, so q_x = rho sin eps, q_z = -rho cos eps.
  const double rho = std::hypot(q.x(), q.z());
  return {rho, rho > 0 ? q.x() / rho : 0.0, rho > 0 ? -q.z() / rho : 1.0};
}

// The inward normal of the wheel surface of meridian normal (n_y, n_r) in meridian plane m.
Eigen::Vector3d inward_normal_at(const PoseFrame& frame, const Meridian& m, const Eigen::Vector2d& n) {
  const Eigen::Vector3d outward(n.y() * m.se, n.x(), -n.y() * m.ce);
  return -(frame.matrix() * outward);
}

}  // namespace

Eigen::Vector3d wheel_inward_normal(const WheelCones& w, const PoseFrame& frame, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = frame.to_wheelset(p);
  const WheelSurfacePoint s = wheel_surface_at(w, q.y());
  return inward_normal_at(frame, meridian_of(q), {s.normal_y, s.normal_r});
}

WheelNormalFoot wheel_normal_foot(const WheelCones& w, const PoseFrame& frame, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = frame.to_wheelset(p);
  return wheel_normal_foot(w, q.y(), std::hypot(q.x(), q.z()));
}

Eigen::Vector3d wheel_foot_normal(const WheelCones& w, const PoseFrame& frame, const Eigen::Vector3d& p,
                                  const WheelNormalFoot& foot) {
  return inward_normal_at(frame, meridian_of(frame.to_wheelset(p)), normal_on(w, foot.cone, foot.t));
}

Eigen::Vector3d wheel_foot_normal(const WheelCones& w, const PoseFrame& frame, const Eigen::Vector3d& p) {
  return wheel_foot_normal(w, frame, p, wheel_normal_foot(w, frame, p));
}

WheelFootNormal wheel_foot_normal_rate(const WheelCones& w, const PoseFrame& frame, const Eigen::Vector3d& p,
                                       const WheelNormalFoot& foot, const Eigen::Vector3d& v) {
  const Eigen::Matrix3d A = frame.matrix();
  const Eigen::Vector3d q = frame.to_wheelset(p), dq = A.transpose() * v;
  const Meridian m = meridian_of(q);
  const double rho = m.rho, se = m.se, ce = m.ce;
  // The point's meridian coordinates move by drho and deps (q_x = rho sin eps, q_z = -rho cos eps).
  const double drho = se * dq.x() - ce * dq.z(), deps = rho > 0 ? (ce * dq.x() + se * dq.z()) / rho : 0.0;
  const int c = foot.cone;
  Eigen::Vector2d dn_dY;
  const Eigen::Vector2d n = normal_on(w, c, foot.t, &dn_dY);
  // The foot's cone, unit tangent g (ascending y), and the smooth surface's curvature there, kappa = (g . dn/dY) g_y
  // per arc length. A point d deep moves its foot along it by ds = g . (dY, drho) / (1 - kappa d). (On the polygon
  // the foot slides by the numerator alone, or stays at a vertex, and jumps from cone to cone where two feet are
  // equally near: on average the same.) kappa d stays far below 1 in a contact; the guard keeps the centre of
  // curvature out.
  const Eigen::Vector2d g = Eigen::Vector2d(w.y[c + 1] - w.y[c], w.z[c] - w.z[c + 1]).normalized();
  const double kappa = g.dot(dn_dY) * g.x();
  const double ds = g.dot(Eigen::Vector2d(dq.y(), drho)) / std::max(1 - kappa * foot.depth, 0.5);
  const Eigen::Vector2d dn = dn_dY * (g.x() * ds);
  const Eigen::Vector3d doutward(dn.y() * se + n.y() * ce * deps, dn.x(), -dn.y() * ce + n.y() * se * deps);
  return {inward_normal_at(frame, m, n), -(A * doutward)};
}

WheelFootNormal wheel_foot_normal_rate(const WheelCones& w, const PoseFrame& frame, const Eigen::Vector3d& p,
                                       const Eigen::Vector3d& v) {
  return wheel_foot_normal_rate(w, frame, p, wheel_normal_foot(w, frame, p), v);
}

LineApproach line_approach(const WheelCones& w, const PoseFrame& f, double y_r, double z_r, double floor) {
  // Wheelset-frame coordinates of the line point at x: q = a x + b (A^T applied to (x, dy, dz)).
  const double dy = y_r - f.y, dz = z_r - f.z;
  const double a1 = f.a11, a2 = f.a12, a3 = f.a13;
  const double b1 = f.a21 * dy, b2 = f.a22 * dy + f.a32 * dz, b3 = f.a23 * dy + f.a33 * dz;
  const double s2 = a1 * a1 + a3 * a3, s = std::sqrt(s2);
  const double xc = -(a1 * b1 + a3 * b3) / s2;  // closest approach to the axle
  const double dmin2 = std::max(0.0, (a1 * xc + b1) * (a1 * xc + b1) + (a3 * xc + b3) * (a3 * xc + b3));
  const double dmin = std::sqrt(dmin2);
  auto dist = [&](double x) { return std::hypot(a1 * x + b1, a3 * x + b3); };

  LineApproach best;
  best.overlap = -std::numeric_limits<double>::infinity();
  const int n = w.cone_count();
  // Beyond the wheel's lateral range there is no wheel (its end faces go down to the axle): radius 0.
  const auto outside = [&] {
    best.x = xc;
    best.Y = a2 * xc + b2;
    best.overlap = -dmin;
    return best;
  };
  if (std::abs(a2) < 1e-15) {  // no yaw: the line stays in one meridian plane
    if (b2 < w.y[1] || b2 > w.y[n - 1]) return outside();
    best.x = xc;
    best.Y = b2;
    best.overlap = wheel_radius_at(w, b2) - dmin;
    return best;
  }
  // Only where the line is closer to the axle than the wheel's radius can it be inside: the reach in x around
  // the closest approach follows from the largest radius over the lateral range the line sweeps there, which
  // shrinks the range in turn (two rounds, on the range-maximum table of the radii).
  const double ymin = w.y[1], ymax = w.y[n - 1];
  double r2max = w.r2_range.max(1, n - 1);
  double ylo = 0, yhi = -1;
  for (int round = 0; round < 3; ++round) {
    const double reach = std::sqrt(std::max(0.0, r2max - dmin2)) / s;
    const double ya = a2 * (xc - reach) + b2, yb = a2 * (xc + reach) + b2;
    ylo = std::max(std::min(ya, yb), ymin);
    yhi = std::min(std::max(ya, yb), ymax);
    if (ylo > yhi) break;
    const int p0 = std::max(1, w.first_cone_reaching(ylo)), p1 = std::min(n - 1, w.last_cone_starting_before(yhi) + 1);
    r2max = w.r2_range.max(p0, p1);
    if (std::sqrt(r2max) - dmin < floor) {  // no point of the line gets deeper than the floor
      best.x = xc;
      best.Y = a2 * xc + b2;
      best.overlap = std::sqrt(r2max) - dmin;
      return best;
    }
  }
  auto consider = [&](double x, double radius) {
    const double o = radius - dist(x);
    if (o > best.overlap) {
      best.overlap = o;
      best.x = x;
      best.Y = a2 * x + b2;
    }
  };
  if (ylo > yhi) {  // the line passes under no part of the wheel within reach
    const double Yc = a2 * xc + b2;
    if (Yc < ymin || Yc > ymax) return outside();
    consider(xc, wheel_radius_at(w, Yc));  // within the lateral range but below: the gap there
    return best;
  }
  const int c0 = std::max(1, w.first_cone_reaching(ylo)), c1 = std::min(n - 2, w.last_cone_starting_before(yhi));
  for (int c = c0; c <= c1; ++c) {
    const double y0 = w.y[c], y1 = w.y[c + 1];
    if (y1 <= y0) continue;  // flat ring: its circle is also an end of a neighbouring cone
    const double r0 = -w.z[c], k = ((-w.z[c + 1]) - r0) / (y1 - y0);  // d radius / d Y
    // Stationary point of r0 + k (a2 x + b2 - y0) - sqrt(dmin^2 + s^2 (x - xc)^2).
    const double ka = k * a2, den = s2 - ka * ka;
    double x = den > 0 ? xc + ka * dmin / (s * std::sqrt(den)) : (ka > 0 ? 1e3 : -1e3);
    const double xa = (y0 - b2) / a2, xb = (y1 - b2) / a2;
    x = std::clamp(x, std::min(xa, xb), std::max(xa, xb));
    consider(x, r0 + k * std::clamp(a2 * x + b2 - y0, 0.0, y1 - y0));
  }
  return best;
}

double line_overlap_at_closest(const WheelCones& w, const PoseFrame& f, double y_r, double z_r) {
  const double dy = y_r - f.y, dz = z_r - f.z;
  const double a1 = f.a11, a2 = f.a12, a3 = f.a13;
  const double b1 = f.a21 * dy, b2 = f.a22 * dy + f.a32 * dz, b3 = f.a23 * dy + f.a33 * dz;
  const double xc = -(a1 * b1 + a3 * b3) / (a1 * a1 + a3 * a3);
  const double Y = a2 * xc + b2, d = std::hypot(a1 * xc + b1, a3 * xc + b3);
  const int n = w.cone_count();
  if (Y < w.y[1] || Y > w.y[n - 1]) return -d;  // beyond the wheel's lateral range: no wheel there
  return wheel_radius_at(w, Y) - d;
}

}  // namespace wrc
