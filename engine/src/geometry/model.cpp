// Building the discretised geometry (model.hpp) and the profile operations of the strategies.
#include "wrc/geometry/model.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {

// ---------------------------------------------------------------------------------------------------------------
// RangeExtrema

void RangeExtrema::build(const std::vector<double>& v) {
  const int n = static_cast<int>(v.size());
  table_.clear();
  offset_.clear();
  offset_.push_back(0);
  for (double x : v) table_.push_back({x, x});
  for (int k = 1; (1 << k) <= n; ++k) {
    const int prev = offset_.back(), len = n - (1 << k) + 1, half = 1 << (k - 1);
    offset_.push_back(static_cast<int>(table_.size()));
    for (int i = 0; i < len; ++i) {
      const MinMax a = table_[prev + i], b = table_[prev + i + half];
      table_.push_back({std::min(a.min, b.min), std::max(a.max, b.max)});
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Cone, WheelCones

double Cone::radius_at(double Y) const {
  const double r0 = -z0, r1 = -z1;
  if (y1 == y0) return std::max(r0, r1);
  const double a = std::clamp((Y - y0) / (y1 - y0), 0.0, 1.0);
  return r0 + a * (r1 - r0);
}

double Cone::slope_angle() const { return std::atan2((-z1) - (-z0), y1 - y0); }

void Cone::meridian_normal(double& n_y, double& n_r) const {
  const double dy = y1 - y0, dr = (-z1) - (-z0), L = std::hypot(dy, dr);
  // The solid lies below the generatrix in the (y, r) half-plane, which runs toward +y: outward is the tangent
  // turned by +90 degrees.
  n_y = -dr / L;
  n_r = dy / L;
}

int WheelCones::running_cone(double Y) const {
  // Profile points are 1 .. n - 1 (0 and n are on the axle); running-surface cones 1 .. n - 2.
  const int n = cone_count();
  Y = std::clamp(Y, y[1], y[n - 1]);
  // First point with y >= Y among the profile points; the cone before it holds Y.
  const auto it = std::lower_bound(y.begin() + 1, y.begin() + n, Y);
  int c = std::clamp(static_cast<int>(it - y.begin()) - 1, 1, n - 2);
  while (c < n - 2 && y[c + 1] == y[c]) ++c;  // a flat ring holds Y only at its own y: take the cone after it
  return c;
}

int WheelCones::first_cone_reaching(double y_lo) const {
  // Cone w spans [y[w], y[w+1]]: the first w with y[w+1] >= y_lo.
  const auto it = std::lower_bound(y.begin() + 1, y.end(), y_lo);
  const int w = static_cast<int>(it - y.begin()) - 1;
  return std::clamp(w, 0, cone_count() - 1);
}

int WheelCones::last_cone_starting_before(double y_hi) const {
  // The last w with y[w] <= y_hi.
  const auto it = std::upper_bound(y.begin(), y.end() - 1, y_hi);
  const int w = static_cast<int>(it - y.begin()) - 1;
  return std::clamp(w, 0, cone_count() - 1);
}

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Enclosure of a dilated polyline solid (the coarse wheel of Fig. 3).
//
// In (u, v) coordinates with the solid BELOW the polyline (v <= envelope(u), u in [u_0, u_n]), the solid dilated
// by D is bounded above by the discs of radius D centred on the polyline. For a line v = l(u) of slope m, the top
// of such a disc centred at p rises D sqrt(1 + m^2) above l at most, over p's own height above l. So a coarse
// segment over [b0, b1] encloses the dilation there if its line lies at least
//   max_{p on the polyline, u_p in [b0 - D, b1 + D]} (v_p - l(u_p)) + D sqrt(1 + m^2)
// above l -- a maximum of a piecewise-linear function, reached at vertices or where the polyline is clipped.

struct UV {
  std::vector<double> u, v;
};

UV to_uv(const Profile& p) {
  UV r{p.y, p.z};
  if (p.kind == ProfileKind::wheel)
    for (double& v : r.v) v = -v;  // the wheel solid is above its profile: flip so that it lies below
  return r;
}

// Upper envelope of the polyline at u (max over a vertical run), u clamped to the polyline's range.
double envelope(const UV& f, double u) {
  const std::size_t n = f.u.size();
  if (u <= f.u.front()) {
    double v = f.v.front();
    for (std::size_t i = 1; i < n && f.u[i] == f.u.front(); ++i) v = std::max(v, f.v[i]);
    return v;
  }
  if (u >= f.u.back()) {
    double v = f.v.back();
    for (std::size_t i = n - 1; i-- > 0 && f.u[i] == f.u.back();) v = std::max(v, f.v[i]);
    return v;
  }
  const auto lo = std::lower_bound(f.u.begin(), f.u.end(), u) - f.u.begin();
  const auto hi = std::upper_bound(f.u.begin(), f.u.end(), u) - f.u.begin();
  double v = -std::numeric_limits<double>::infinity();
  for (auto i = lo; i < hi; ++i) v = std::max(v, f.v[i]);  // vertices exactly at u
  if (lo > 0 && hi < static_cast<long>(n)) {                // the segment across u
    const std::size_t a = static_cast<std::size_t>(lo) - 1, b = static_cast<std::size_t>(hi);
    if (lo == hi) {
      const double t = (u - f.u[a]) / (f.u[b] - f.u[a]);
      v = std::max(v, f.v[a] + t * (f.v[b] - f.v[a]));
    }
  }
  return v;
}

// Required lift of the line l(u) = v0 + m (u - b0) over [b0, b1] (see above).
double required_lift(const UV& f, double D, double b0, double b1, double v0, double m) {
  const double lo = b0 - D, hi = b1 + D;
  const std::size_t n = f.u.size();
  double need = -std::numeric_limits<double>::infinity();
  auto consider = [&](double u, double v) { need = std::max(need, v - (v0 + m * (u - b0))); };
  // First segment that can reach lo.
  std::size_t i = static_cast<std::size_t>(std::lower_bound(f.u.begin(), f.u.end(), lo) - f.u.begin());
  if (i > 0) --i;
  for (; i < n && f.u[i] <= hi; ++i) {
    if (f.u[i] >= lo) consider(f.u[i], f.v[i]);
    if (i + 1 < n) {  // clip the segment i..i+1 at lo and hi
      const double ua = f.u[i], ub = f.u[i + 1];
      for (double c : {lo, hi}) {
        if (ua < c && c < ub) consider(c, f.v[i] + (c - ua) / (ub - ua) * (f.v[i + 1] - f.v[i]));
      }
    }
  }
  return need + D * std::sqrt(1 + m * m);
}

// Top of the capsule {q : dist(q, segment p0-p1) <= D} at abscissa u (-inf outside it). The capsule's upper
// boundary is the arc of p0's disc, the segment offset by D along its upward normal, then the arc of p1's disc.
double capsule_top(double u, double u0, double v0, double u1, double v1, double D) {
  double top = -std::numeric_limits<double>::infinity();
  for (const double* p : {&u0, &u1}) {
    const double pu = *p, pv = p == &u0 ? v0 : v1, du = u - pu;
    if (std::abs(du) <= D) top = std::max(top, pv + std::sqrt(D * D - du * du));
  }
  const double du = u1 - u0, dv = v1 - v0;
  if (du > 0) {
    const double L = std::hypot(du, dv), nu = -dv / L, nv = du / L;  // upward normal
    const double a = u0 + D * nu, b = u1 + D * nu;
    if (u >= a && u <= b) top = std::max(top, v0 + D * nv + (u - a) * dv / du);
  }
  return top;
}

// The largest amount (m) by which the dilated solid of `fine` rises above the coarse polyline `coarse` (both in
// (u, v), solid below); <= 0 when enclosed; +inf if the coarse polyline does not span the dilated solid's range.
// Exact: on a coarse segment the excess over one fine segment's capsule is concave in u (the capsule is convex)
// and smooth inside, so its maximum is at an end of the coarse segment, where a disc arc has the coarse slope,
// or at an end of the offset straight part; all those candidates are evaluated.
double enclosure_excess(const UV& coarse, const UV& fine, double D) {
  const std::size_t m = coarse.u.size(), n = fine.u.size();
  if (coarse.u.front() > fine.u.front() - D || coarse.u.back() < fine.u.back() + D)
    return std::numeric_limits<double>::infinity();
  double excess = -std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j + 1 < m; ++j) {
    const double b0 = coarse.u[j], b1 = coarse.u[j + 1];
    if (!(b1 > b0)) return std::numeric_limits<double>::infinity();
    const double slope = (coarse.v[j + 1] - coarse.v[j]) / (b1 - b0);
    const double tangent = D * slope / std::sqrt(1 + slope * slope);  // disc point whose tangent has the slope
    auto line = [&](double u) { return coarse.v[j] + slope * (u - b0); };
    std::size_t i = static_cast<std::size_t>(std::lower_bound(fine.u.begin(), fine.u.end(), b0 - D) - fine.u.begin());
    if (i > 0) --i;
    for (; i < n && fine.u[i] <= b1 + D; ++i) {
      const std::size_t k = i + 1 < n ? i + 1 : i;  // the segment i..k (a single point at the end)
      const double u0 = fine.u[i], v0 = fine.v[i], u1 = fine.u[k], v1 = fine.v[k];
      const double L = std::hypot(u1 - u0, v1 - v0);
      const double nu = (L > 0 && u1 > u0) ? -(v1 - v0) / L : 0.0;
      for (double u : {b0, b1, u0 + D * nu, u1 + D * nu, u0 - tangent, u1 - tangent}) {
        if (u < b0 || u > b1) continue;
        excess = std::max(excess, capsule_top(u, u0, v0, u1, v1, D) - line(u));
      }
    }
  }
  return excess;
}

// ---------------------------------------------------------------------------------------------------------------
// Placement

void finish_wheel(WheelCones& w) {
  w.r2.resize(w.y.size());
  for (std::size_t i = 0; i < w.y.size(); ++i) w.r2[i] = w.z[i] * w.z[i];
  w.r2_range.build(w.r2);
  w.vertex_ny.resize(w.y.size());
  w.vertex_nr.resize(w.y.size());
  for (std::size_t i = 0; i < w.y.size(); ++i) {
    const Eigen::Vector2d n = wheel_vertex_normal(w, static_cast<int>(i));
    w.vertex_ny[i] = n.x(), w.vertex_nr[i] = n.y();
  }
}

// The lateral positions y of a discretised profile placed on its side (ordered by increasing y) must not decrease:
// the searches bisect them (a wheel whose y turned back sent them past its cones). A face within kVerticalRounding
// of vertical rounds to vertical. A larger turn is a fold: from the cant, or from a spline through points with a
// step or sharp corner (an interpolating cubic overshoots there by a fraction of the step, although the points are
// monotone).
void require_monotone(std::vector<double>& y, const Profile& p, int side, const char* what) {
  for (std::size_t i = 1; i < y.size(); ++i) {
    if (y[i] < y[i - 1] && y[i] > y[i - 1] - kVerticalRounding) y[i] = y[i - 1];  // a vertical face
    if (!(y[i] >= y[i - 1])) {
      const std::size_t k = side == kLeft ? i : y.size() - 1 - i;  // the point's index in the profile
      fail("wrc.wheelset: the {} {} ({}) as discretised is not monotone in y: at y = {:.4f} mm, z = {:.4f} mm (profile "
           "frame) it turns back by {:.4g} mm{}",
           side_name(side), what, p.source, p.y[k] * 1e3, p.z[k] * 1e3, (y[i - 1] - y[i]) * 1e3,
           p.spline ? fmt::format("; the profile's spline (smooth = {:g}) turns back there, as a cubic spline does "
                                  "through a step or sharp corner: load it with smooth = false (the polyline through "
                                  "its points) or a larger smoothing length", p.spline->smoothing)
                    : std::string(what) == "rail" ? "; the cant turns one of its faces over" : "");
    }
  }
}

// The wheel profile placed in the wheelset frame, ordered by increasing y, closed by two points on the axle.
WheelCones place_wheel(const Profile& p, const SidePlacement& pl, int side, const char* what) {
  const std::size_t n = p.size();
  std::vector<double> y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d q = pl.wheel(p.y[i], p.z[i]);
    const std::size_t j = side == kLeft ? i : n - 1 - i;  // mirroring reverses the order
    y[j] = q.x();
    z[j] = q.y();
    if (!(q.y() < 0))
      fail("wrc.wheelset: the {} {} ({}) point {} (s = {} m) has radius {} m; a wheel radius must be positive",
           side_name(side), what, p.source, i + 1, p.y[i], -q.y());
  }
  require_monotone(y, p, side, what);
  WheelCones w;
  w.y.reserve(n + 2);
  w.z.reserve(n + 2);
  w.y.push_back(y.front());
  w.z.push_back(0.0);
  w.y.insert(w.y.end(), y.begin(), y.end());
  w.z.insert(w.z.end(), z.begin(), z.end());
  w.y.push_back(y.back());
  w.z.push_back(0.0);
  finish_wheel(w);
  return w;
}

RailLines place_rail(const Profile& p, const SidePlacement& pl, int side) {
  const std::size_t n = p.size();
  RailLines r;
  r.y.resize(n);
  r.z.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d q = pl.rail(p.y[i], p.z[i]);
    const std::size_t j = side == kLeft ? i : n - 1 - i;
    r.y[j] = q.x();
    r.z[j] = q.y();
  }
  require_monotone(r.y, p, side, "rail");
  return r;
}

// Cells of `every` consecutive profile points (profile order), with the middle point standing for each.
struct Cells {
  std::vector<int> first, last, middle;  // profile indices
};

Cells make_cells(std::size_t n, int every) {
  Cells c;
  for (std::size_t a = 0; a < n; a += static_cast<std::size_t>(every)) {
    const std::size_t b = std::min(n - 1, a + static_cast<std::size_t>(every) - 1);
    c.first.push_back(static_cast<int>(a));
    c.last.push_back(static_cast<int>(b));
    c.middle.push_back(static_cast<int>(a + (b - a) / 2));
  }
  return c;
}

}  // namespace

double cell_dilation(const Profile& rail, int every) {
  if (every < 1) fail("cell_dilation: 'every' must be >= 1, got {}", every);
  const Cells c = make_cells(rail.size(), every);
  double D = 0;
  for (std::size_t k = 0; k < c.first.size(); ++k)
    for (int i = c.first[k]; i <= c.last[k]; ++i)
      D = std::max(D, std::hypot(rail.y[i] - rail.y[c.middle[k]], rail.z[i] - rail.z[c.middle[k]]));
  return D;
}

Profile offset_outward(const Profile& p, double distance, double step) {
  if (!(distance >= 0) || !std::isfinite(distance)) fail("offset_outward: distance must be >= 0 m, got {}", distance);
  if (!(step > 0) || !std::isfinite(step)) fail("offset_outward: step must be > 0 m, got {}", step);
  const UV f = to_uv(p);
  const double u0 = f.u.front() - distance, u1 = f.u.back() + distance;
  const double intervals = std::max(1.0, std::ceil((u1 - u0) / step - 1e-9));
  check_point_count(intervals + 1, fmt::format("offset_outward: step {:.6g} m over {:.6g} m", step, u1 - u0));
  const auto m = static_cast<std::size_t>(intervals);
  // Each coarse segment starts as the chord of the envelope, lifted until the bound of required_lift holds: then
  // every disc of the dilation lies under the lifted chord's whole line. A vertex takes the higher of the two
  // lifted chords meeting there; the coarse segment between two such vertices lies above its own lifted chord, so
  // above the dilated solid. (1 nm more against rounding in the exact check of build_geometry.)
  std::vector<double> b(m + 1), H(m + 1, -std::numeric_limits<double>::infinity());
  for (std::size_t j = 0; j <= m; ++j) b[j] = u0 + (u1 - u0) * static_cast<double>(j) / static_cast<double>(m);
  b.front() = u0;
  b.back() = u1;
  for (std::size_t j = 0; j < m; ++j) {
    const double v0 = envelope(f, b[j]), v1 = envelope(f, b[j + 1]);
    const double slope = (v1 - v0) / (b[j + 1] - b[j]);
    const double lift = required_lift(f, distance, b[j], b[j + 1], v0, slope) + 1e-9;
    H[j] = std::max(H[j], v0 + lift);
    H[j + 1] = std::max(H[j + 1], v1 + lift);
  }
  UV c{b, H};
  Profile r;
  r.kind = p.kind;
  r.name = p.name + " (coarse)";
  r.source = p.source;
  r.transforms = p.transforms;
  r.transforms.push_back(fmt::format("offset outward by {:.6g} m, points every {:.6g} m", distance, (u1 - u0) / m));
  r.y = c.u;
  r.z = c.v;
  if (p.kind == ProfileKind::wheel)
    for (double& v : r.z) v = -v;
  return r;
}

Profile resample_constant_slope(const Profile& p, double slope_step, double max_step) {
  if (!(slope_step > 0) || !std::isfinite(slope_step))
    fail("constant_slope: slope_step must be a positive angle in rad, got {}", slope_step);
  if (!(max_step > 0) || !std::isfinite(max_step)) fail("constant_slope: max_step must be > 0 m, got {}", max_step);
  const std::size_t n = p.size();
  auto seg = [&](std::size_t i) { return std::hypot(p.y[i + 1] - p.y[i], p.z[i + 1] - p.z[i]); };
  auto turn = [&](std::size_t i) {  // turning of the tangent at vertex i (rad)
    const double a0 = std::atan2(p.z[i] - p.z[i - 1], p.y[i] - p.y[i - 1]);
    const double a1 = std::atan2(p.z[i + 1] - p.z[i], p.y[i + 1] - p.y[i]);
    return std::abs(std::remainder(a1 - a0, 2 * M_PI));
  };
  std::vector<double> y{p.y.front()}, z{p.z.front()};
  double acc_turn = 0, acc_arc = 0;
  for (std::size_t i = 1; i < n; ++i) {
    acc_arc += seg(i - 1);
    if (i == n - 1) break;
    const double t = turn(i);
    if (acc_turn + t >= slope_step || acc_arc + seg(i) > max_step) {
      y.push_back(p.y[i]);
      z.push_back(p.z[i]);
      acc_turn = 0;
      acc_arc = 0;
    } else {
      acc_turn += t;
    }
  }
  y.push_back(p.y.back());
  z.push_back(p.z.back());
  Profile r;
  r.kind = p.kind;
  r.name = p.name;
  r.source = p.source;
  r.transforms = p.transforms;
  r.metadata = p.metadata;
  r.transforms.push_back(
      fmt::format("constant-slope resampling: {:.6g} rad per point, at most {:.6g} m apart", slope_step, max_step));
  r.y = std::move(y);
  r.z = std::move(z);
  return r;
}

// ---------------------------------------------------------------------------------------------------------------
// build_geometry

GeometryModel build_geometry(std::shared_ptr<const Track> track, const std::array<SideDiscretisation, 2>& sides,
                             StrategyInfo strategy) {
  if (!track) fail("build_geometry: no track");
  GeometryModel m;
  m.track = track;
  m.strategy = std::move(strategy);
  for (int s : {kLeft, kRight}) {
    const SideDiscretisation& d = sides[s];
    if (d.wheel.kind != ProfileKind::wheel)
      fail("wrc.wheelset: the {} side's discretised wheel ({}) is a {} profile", side_name(s), d.wheel.source,
           to_string(d.wheel.kind));
    if (d.rail.kind != ProfileKind::rail)
      fail("wrc.wheelset: the {} side's discretised rail ({}) is a {} profile", side_name(s), d.rail.source,
           to_string(d.rail.kind));
    if (d.wheel.size() < 2 || d.rail.size() < 1)
      fail("wrc.wheelset: the {} side's discretisation has too few points", side_name(s));
    const SidePlacement& pl = track->place[s];
    SideGeometry& g = m.side[s];
    g.wheel_name = d.wheel.name;
    g.rail_name = d.rail.name;
    g.wheel = place_wheel(d.wheel, pl, s, "wheel");
    g.rail = place_rail(d.rail, pl, s);
    g.wheel_r2_max = *std::max_element(g.wheel.r2.begin(), g.wheel.r2.end());
    g.wheel_curve = profile_curve(track->wheel[s]);
    g.rail_curve = profile_curve(track->rail[s]);
    g.flange = flange_of(track->wheel[s]);

    if (d.coarse_every > 0) {
      if (d.coarse_every < 2) fail("wrc.wheelset: coarse 'every' must be >= 2 fine lines per cell, got {}", d.coarse_every);
      CoarseLevel c;
      c.every = d.coarse_every;
      c.dilation = cell_dilation(d.rail, d.coarse_every);
      Profile coarse_wheel = d.coarse_wheel ? *d.coarse_wheel : offset_outward(d.wheel, c.dilation, d.coarse_wheel_step);
      if (coarse_wheel.kind != ProfileKind::wheel) fail("wrc.wheelset: the {} coarse wheel is not a wheel profile", side_name(s));
      const double excess = enclosure_excess(to_uv(coarse_wheel), to_uv(d.wheel), c.dilation);
      if (!(excess <= 0))
        fail("wrc.wheelset: the {} coarse wheel ({} points) does not contain the fine wheel dilated by {:.6g} m (the "
             "cells' size): it falls short by {:.3g} m; build it with wrc.geometry.offset_outward",
             side_name(s), coarse_wheel.size(), c.dilation, excess);
      c.wheel = place_wheel(coarse_wheel, pl, s, "coarse wheel");
      // Cells in profile order (so that the right side's are the mirror images of the left's), then as line indices.
      const Cells cells = make_cells(d.rail.size(), d.coarse_every);
      const int n = static_cast<int>(d.rail.size());
      const std::size_t k = cells.first.size();
      for (std::size_t i = 0; i < k; ++i) {
        const std::size_t j = s == kLeft ? i : k - 1 - i;
        const int mid = s == kLeft ? cells.middle[j] : n - 1 - cells.middle[j];
        c.lines.y.push_back(g.rail.y[mid]);
        c.lines.z.push_back(g.rail.z[mid]);
        c.cell_first.push_back(s == kLeft ? cells.first[j] : n - 1 - cells.last[j]);
        c.cell_last.push_back(s == kLeft ? cells.last[j] : n - 1 - cells.first[j]);
      }
      c.offset.assign(static_cast<std::size_t>(n), 0.0);
      for (std::size_t k2 = 0; k2 < c.cell_first.size(); ++k2)
        for (int r = c.cell_first[k2]; r <= c.cell_last[k2]; ++r)
          c.offset[r] = std::hypot(g.rail.y[r] - c.lines.y[k2], g.rail.z[r] - c.lines.z[k2]);
      g.coarse = std::move(c);
    }
  }
  return m;
}

ProfilePoint profile_point(const GeometryModel& g, int side, const Eigen::Vector3d& point, double wheel_y,
                           double radius) {
  const SideGeometry& sg = g.side[side];
  const SidePlacement& pl = g.track->place[side];
  ProfilePoint p;
  p.wheel = {pl.sign * wheel_y - pl.tape_y, pl.radius - radius};
  // The rail profile's frame: the track point mirrored onto the left side, unshifted and turned back by the cant.
  const double yc = pl.sign * point.y() - pl.rail_dy, zc = point.z() - pl.rail_dz;
  const double c = std::cos(pl.cant_angle), s = std::sin(pl.cant_angle);
  p.rail = {c * yc + s * zc, -s * yc + c * zc};
  if (sg.wheel_curve)
    p.wheel_curvature = surface_curvature(*sg.wheel_curve, ProfileKind::wheel, sg.wheel_curve->param_at_y(p.wheel.x()));
  if (sg.rail_curve) p.rail_curvature = surface_curvature(*sg.rail_curve, ProfileKind::rail, sg.rail_curve->closest(p.rail));
  return p;
}

}  // namespace wrc
