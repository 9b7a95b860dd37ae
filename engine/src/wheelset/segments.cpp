// The located segments of a contact area (segments.hpp): their arcs, weights and normals, the plane through them,
// the grid's index spans and its cap.
#include "segments.hpp"

#include "wrc/core/error.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace wrc::areas {
namespace {

// Lateral spacing of rail line r: half the distance between its neighbours (one-sided at the ends).
double line_spacing(const RailLines& rail, int r) {
  const int n = rail.count();
  const int a = std::max(0, r - 1), b = std::min(n - 1, r + 1);
  const double d = std::hypot(rail.y[b] - rail.y[a], rail.z[b] - rail.z[a]);
  return b - a == 2 ? 0.5 * d : d;
}

}  // namespace

// Radius of the wheel's section along a rail line at a wheelset-frame lateral position: the paper's radius /
// cos(conicity) of the rolling direction, divided by cos^2(yaw) because a yawed wheel meets the line at the yaw
// angle (normal curvature cos^2 of the rolling one; the profile's own bend along a yawed line is added by
// section_correction where a segment has one). Without it a yawed cylinder's h is too deep by 1/cos^2(yaw): 1 % of
// force at 0.1 rad. The floor on cos keeps it finite on the steepest flange faces.
double arc_radius(const WheelSurfacePoint& s, double yaw) {
  const double c = std::cos(yaw);
  return s.radius / (std::max(s.normal_r, 0.05) * c * c);
}

namespace {

// Under yaw a rail line runs across the wheel's profile: its wheelset-frame lateral position moves by x sin(yaw)
// along it (0.7 mm over a 40 mm segment at 1 deg). The arc models the rim's circle through the segment's exact ends
// with one normal, but not the profile's bend between the ends' radii nor the turning of the wheel's normal along the
// line; on a steep curved face both are large, because the radius's curvature in Y is the profile's divided by cos^3
// of the conicity: at the S1002 flange root (67-70 deg) at yaw 1 deg the arc alone is up to 20 % too deep. h's
// definition there, n_r (r(Y) - distance to the axle), is the arc's n_ref (r_lin - distance) (r_lin: the radius
// linear between the ends', n_ref: the normal's radial part the arc's radius holds) plus
//   n_r (r - r_lin) + (n_r / n_ref - 1) arc,
// the correction, exact at the profile points the segment passes under (the cones' kinks): knots there, linear in
// between, zero at the ends. On a cylinder or within one cone it is zero; at yaw 0 the line stays at one Y: no knot.
void section_correction(const WheelCones& w, const Segment& s, const WheelSurfacePoint& t, const WheelSurfacePoint& l,
                        double Yt, double Yl, SegmentInfo& info) {
  const double lo = std::min(Yt, Yl), hi = std::max(Yt, Yl);
  const double n_ref = 2 / (1 / std::max(t.normal_r, 0.05) + 1 / std::max(l.normal_r, 0.05));  // as arc_radius
  // The profile points strictly between the ends' lateral positions (the points 1 .. n - 1 ascend in y).
  const auto first = w.y.begin() + 1, last = w.y.begin() + w.cone_count();
  const auto v0 = std::upper_bound(first, last, lo), v1 = std::lower_bound(v0, last, hi);
  info.knots.reserve(static_cast<std::size_t>(v1 - v0));
  for (int v = static_cast<int>(v0 - w.y.begin()); v < static_cast<int>(v1 - w.y.begin()); ++v) {
    const double u = (w.y[v] - Yt) / (Yl - Yt), x = s.x_t + u * (s.x_l - s.x_t);
    if (!(x > s.x_t && x < s.x_l)) continue;
    const auto k = static_cast<std::size_t>(v);
    const double nr = std::max(w.vertex_nr.size() == w.y.size() ? w.vertex_nr[k] : wheel_vertex_normal(w, v).y(), 0.05);
    info.knots.push_back({x, nr * (-w.z[k] - (t.radius + u * (l.radius - t.radius))) + (nr / n_ref - 1) * info.arc(x)});
  }
  if (Yl < Yt) std::reverse(info.knots.begin(), info.knots.end());  // Y falls along the line: found by descending x
}

}  // namespace

double SegmentInfo::correction(double x) const {
  if (knots.empty() || !(x > xm - 0.5 * L && x < xm + 0.5 * L)) return 0;
  const auto after = std::upper_bound(knots.begin(), knots.end(), x, [](double v, const Knot& k) { return v < k.x; });
  return knot_lerp(static_cast<std::size_t>(after - knots.begin()), x);
}

// Interval by interval between the knots (x ascends), so that each inner loop is the arc plus a straight line.
void LineProfile::corrected_heights(const SegmentInfo& s, const double* x, std::size_t n, double* out) {
  const double drop = s.R - s.rim;
  std::size_t i = 0;
  const auto run = [&](double end, double xa, double ha, double slope) {
    for (; i < n && x[i] < end; ++i)
      out[i] = std::max(out[i], arc_height(s.R, x[i] - s.xm) - drop + (ha + slope * (x[i] - xa)));
  };
  const double xt = s.xm - 0.5 * s.L, xl = s.xm + 0.5 * s.L;
  const std::size_t m = s.knots.size();
  for (; i < n && !(x[i] > xt); ++i) out[i] = std::max(out[i], arc_height(s.R, x[i] - s.xm) - drop);
  for (std::size_t k = 0; k <= m; ++k) {
    const double xa = k == 0 ? xt : s.knots[k - 1].x, ha = k == 0 ? 0.0 : s.knots[k - 1].h;
    const double xb = k == m ? xl : s.knots[k].x, hb = k == m ? 0.0 : s.knots[k].h;
    run(xb, xa, ha, (hb - ha) / (xb - xa));
  }
  for (; i < n; ++i) out[i] = std::max(out[i], arc_height(s.R, x[i] - s.xm) - drop);
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
    const WheelSurfacePoint t = wheel_surface_at(w, Yt), l = Yl == Yt ? t : wheel_surface_at(w, Yl);
    const double Rt = arc_radius(t, yaw);
    info.R = 0.5 * (Rt + (Yl == Yt ? Rt : arc_radius(l, yaw)));  // equal at yaw 0
    info.rim = info.R - std::sqrt(std::max(0.0, info.R * info.R - 0.25 * info.L * info.L));
    if (Yl != Yt) section_correction(w, s, t, l, Yt, Yl, info);
    info.sagitta = std::max(0.0, info.rim + info.correction(info.xm));
    info.weight = (2.0 / 3.0) * info.L * info.sagitta * line_spacing(g.side[side].rail, s.line);
    info.normal = wheel_inward_normal(w, f, info.mid);
    out.push_back(std::move(info));
  }
}

namespace {

// The plane through the segments' weighted mid-point with their weighted normals normal(k) (k: the segment's index).
template <class Normal>
Plane weighted_plane(const std::vector<SegmentInfo>& infos, const Patch& fallback, const Normal& normal) {
  Plane pl;
  double W = 0;
  Eigen::Vector3d O = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < infos.size(); ++k) {
    const SegmentInfo& s = infos[k];
    W += s.weight;
    O += s.weight * s.mid;
    if (s.weight > 0) n += s.weight * normal(k);
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

}  // namespace

Plane plane_of(const std::vector<SegmentInfo>& infos, const Patch& fallback) {
  return weighted_plane(infos, fallback, [&](std::size_t k) { return infos[k].normal; });
}

Plane foot_plane_of(const WheelCones& wheel, const PoseFrame& frame, const std::vector<SegmentInfo>& infos,
                    const std::vector<WheelNormalFoot>& feet, const Patch& fallback) {
  return weighted_plane(infos, fallback,
                        [&](std::size_t k) { return wheel_foot_normal(wheel, frame, infos[k].mid, feet[k]); });
}

std::vector<WheelNormalFoot> mid_feet(const WheelCones& wheel, const PoseFrame& frame,
                                      const std::vector<SegmentInfo>& infos) {
  std::vector<WheelNormalFoot> feet;
  feet.reserve(infos.size());
  for (const auto& s : infos) feet.push_back(wheel_normal_foot(wheel, frame, s.mid));
  return feet;
}

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

namespace {

// normal_depth's bend for a line whose radial depth (turned onto the normal) is `radial` at wheelset-frame lateral
// position Y: for a line inside the wheel, fitted to the exact depth there (exact(): wheel_normal_depth, asked for
// only then), so that h is exact at the line's deepest point whatever the profile does between the point's radial and
// normal feet (on S1002 a curvature jump lies between them at the flange root); for a line that barely reaches the
// wheel or stays outside it (the margin: only the sign of its h counts, and the exact search would go as far as the
// gap), the profile's own kappa tan^2(delta) / 2 (curvature from the smooth normal's turning dtheta/dY n_r,
// tan(delta) = n_y / n_r, n_r floored as in arc_radius).
template <class ExactDepth>
double depth_bend(const WheelCones& wheel, double Y, double radial, const ExactDepth& exact) {
  if (radial > 1e-6) {
    const double d = exact();
    return std::clamp((radial - d) / (radial * radial), -0.25 / radial, 0.25 / radial);
  }
  const WheelSurfacePoint s = wheel_surface_at(wheel, Y);
  const double nr = std::max(s.normal_r, 0.05);
  return 0.5 * wheel_normal_turning(wheel, Y) * s.normal_y * s.normal_y / nr;
}

// The same at the wheelset-frame point q, its exact depth searched.
double depth_bend(const WheelCones& wheel, const Eigen::Vector3d& q, double radial) {
  return depth_bend(wheel, q.y(), radial, [&] { return wheel_normal_depth(wheel, q.y(), std::hypot(q.x(), q.z())); });
}

}  // namespace

// Under yaw a line runs across the profile (0.7 mm over a 40 mm segment at 1 deg; at the S1002 flange root across the
// rounding, whose curvature and slope change along it), so the bend fitted at the deepest point alone left elements
// elsewhere on the line up to 2.6 % of the deepest h off their exact depth. What changes along the line is the lateral
// position: the bend is the deepest point's plus, at 1/8 and 1/4 of the segment's length on both sides, the change of
// the bend fitted at the deepest point's depth from the mid-point's lateral position to theirs; linear between them,
// held beyond: 0.7 % (at 1/4 alone 1.3 %, with 3/8 too 0.6 %). The samples' own depths would add the
// bend's dependence on the depth, which the vertical load's prediction does not see (its error at the flange root
// 7e-4 instead of 6e-5), and samples at the profile points the line passes under would appear and vanish at the
// segment's ends: at fixed fractions of the segment they move continuously with the pose, and symmetrically about its
// middle (a yawed cylinder's h stays symmetric). At yaw 0 the changes are zero: h is as it was.
constexpr double kBendTravel = 0.1e-3;  // m

void fit_bend(const WheelCones& wheel, const PoseFrame& frame, const SegmentInfo& s, const WheelNormalFoot& foot,
              LineProfile& lp) {
  const double Y_mid = frame.to_wheelset(s.mid).y();
  lp.bend = depth_bend(wheel, Y_mid, s.sagitta, [&] { return foot.depth; });
  lp.bends = {};
  // The bend at lateral position Y for the depth of the deepest point, fitted at the meridian point of that depth.
  const auto at = [&](double Y) {
    const WheelSurfacePoint p = wheel_surface_at(wheel, Y);
    return depth_bend(wheel, {0.0, Y, s.sagitta / std::max(p.normal_r, 0.05) - p.radius}, s.sagitta);
  };
  constexpr std::array<double, 5> f{-0.25, -0.125, 0.0, 0.125, 0.25};
  std::array<double, f.size()> Y{};
  Y[2] = Y_mid;
  const double dY = frame.to_wheelset({s.xm + f[4] * s.L, s.y, s.z}).y() - Y[2];  // Y is linear in x
  // Phased in over a lateral travel (4 dY) of 0.1 .. 0.2 mm: below it the bend changes little along the line (every
  // element within 0.9 % of the deepest h on the S1002 rounding at 0.1 deg without the samples, 0.7 % with them), and
  // their searches would cost a trajectory at small yaw 4 % of its instructions.
  const double w = std::clamp(std::abs(4 * dY) / kBendTravel - 1, 0.0, 1.0);
  if (w == 0) return;
  for (std::size_t k = 0; k < f.size(); ++k) Y[k] = Y[2] + f[k] / f[4] * dY;
  const double mid = at(Y[2]);
  for (std::size_t k = 0; k < f.size(); ++k)
    lp.bends.push_back({s.xm + f[k] * s.L, lp.bend + (k == 2 ? 0.0 : w * (at(Y[k]) - mid))});
}

// Interval by interval between each segment's knots and between the bend's samples (x ascends, as bent_heights), each x
// in the formulas a single x meets (SegmentInfo::height: the arc plus the correction, knot_lerp inside the segment; the
// line between two samples, held beyond them), so the same numbers bit for bit without a search per x.
void LineProfile::walked_heights(const double* x, std::size_t n, double* out, double* slope) const {
  if (arcs.empty()) {
    for (std::size_t i = 0; i < n; ++i) out[i] = radial(x[i]);
  } else {
    std::fill_n(out, n, -INFINITY);
    for (const SegmentInfo* s : arcs) {
      const double xt = s->xm - 0.5 * s->L, xl = s->xm + 0.5 * s->L;  // as correction's
      const std::size_t m = s->knots.size();
      std::size_t i = 0;
      if (m > 0) {
        for (; i < n && !(x[i] > xt); ++i) out[i] = std::max(out[i], s->arc(x[i]) + 0.0);  // correction 0
        for (std::size_t k = 0; k <= m; ++k) {
          const double end = k < m ? std::min(s->knots[k].x, xl) : xl;
          for (; i < n && x[i] < end; ++i) out[i] = std::max(out[i], s->arc(x[i]) + s->knot_lerp(k, x[i]));
        }
      }
      for (; i < n; ++i) out[i] = std::max(out[i], s->arc(x[i]) + 0.0);
    }
  }
  std::size_t i = 0;
  const auto run = [&](double end, double ha, double hb, double xa, double xb) {  // the bend ha .. hb over xa .. xb
    for (; i < n && x[i] < end; ++i) {
      const double bi = xa == xb ? ha : ha + (hb - ha) * (x[i] - xa) / (xb - xa);
      slope[i] = normal_depth_slope(out[i], bi);
      out[i] = normal_depth(out[i], bi);
    }
  };
  const SegmentInfo::Knot* b = bends.begin();
  const std::size_t m = bends.size();
  if (m == 0) return run(INFINITY, bend, bend, 0, 0);
  run(b[0].x, b[0].h, b[0].h, 0, 0);
  for (std::size_t k = 1; k < m; ++k) run(b[k].x, b[k - 1].h, b[k].h, b[k - 1].x, b[k].x);
  run(INFINITY, b[m - 1].h, b[m - 1].h, 0, 0);
}

// Interval by interval between the samples (x ascends), so that each inner loop is a straight line.
void LineProfile::bent_heights(const double* x, std::size_t n, double* out, double* slope) const {
  const SegmentInfo::Knot* b = bends.begin();
  const std::size_t m = bends.size();
  std::size_t i = 0;
  const auto run = [&](double end, double xa, double ba, double db) {
    for (; i < n && x[i] < end; ++i) {
      const double bi = ba + db * (x[i] - xa);
      if (slope) slope[i] = normal_depth_slope(out[i], bi);
      out[i] = normal_depth(out[i], bi);
    }
  };
  run(b[0].x, b[0].x, b[0].h, 0.0);
  for (std::size_t k = 1; k < m; ++k) run(b[k].x, b[k - 1].x, b[k - 1].h, (b[k].h - b[k - 1].h) / (b[k].x - b[k - 1].x));
  run(INFINITY, b[m - 1].x, b[m - 1].h, 0.0);
}

LineApproach arc_through_deepest(const WheelCones& wheel, const LocationState& st, double y, double z, LineProfile& lp) {
  const LineApproach a = line_approach(wheel, st.frame(), y, z);
  const WheelSurfacePoint sp = wheel_surface_at(wheel, a.Y);
  lp.R = arc_radius(sp, st.pose().yaw);
  lp.apex = std::min(a.overlap, 0.0) * sp.normal_r;  // a line without a segment is not inside
  lp.x_apex = a.x;
  lp.bend = depth_bend(wheel, st.frame().to_wheelset({a.x, y, z}), lp.apex);
  return a;
}

// The potential contact area of a pose exceeds max_elements: either the grid is too fine for the cap or the pose is
// far deeper than any elastic approach (a solve that lost its way, an unreachable load).
void too_many_elements(const ContactOptions& opt, const std::vector<SegmentInfo>& all, int side,
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

}  // namespace wrc::areas
