#include "wrc/geometry/track.hpp"

#include "wrc/core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace wrc {

Eigen::Vector2d SidePlacement::rail(double y, double z) const {
  const double c = std::cos(cant_angle), s = std::sin(cant_angle);
  const double yc = c * y - s * z, zc = s * y + c * z;  // rotation about x: field side (+y) goes up
  return {sign * (yc + rail_dy), zc + rail_dz};
}

namespace {

void check_params(const TrackParams& p) {
  auto positive = [](double v, const char* key, double lo, double hi) {
    if (v > lo && v < hi && std::isfinite(v)) return;
    const bool mm = v / 1e3 > lo && v / 1e3 < hi;  // a length in millimetres: 1435 for the gauge
    fail("wrc.wheelset: '{}' = {} is out of range: it must lie strictly between {} and {} (m){}", key, v, lo, hi,
         mm ? fmt::format("; wrc takes metres: {} mm is {} = {:.6g}", v, key, v / 1e3) : "");
  };
  positive(p.radius, "radius", 0.05, 5.0);
  positive(p.back_to_back, "back_to_back", 0.3, 3.0);
  positive(p.gauge, "gauge", 0.3, 3.0);
  positive(p.gauge_depth, "gauge_depth", 0.0, 0.1);
  positive(p.tape_offset, "tape_offset", 0.0, 0.5);
  if (!(std::abs(p.cant) < 0.5) || !std::isfinite(p.cant))
    fail("wrc.wheelset: 'cant' = {} is out of range (|cant| < 0.5): it is the rails' inclination as a slope: 1:40 is "
         "cant = 0.025 (2.5 %; not 40, nor an angle in degrees)", p.cant);
}

// The first point of y that lies below the one before it (y.size() when none).
std::size_t fold_index(const std::vector<double>& y) {
  for (std::size_t i = 1; i < y.size(); ++i)
    if (y[i] < y[i - 1]) return i;
  return y.size();
}

// Lateral position (left-side frame) of the gauge point of a canted rail, walking from the highest point toward the
// gauge side (decreasing y): the first crossing of the level top - depth, or (innermost) the last point of the walk
// still at or above it -- the innermost gauge-face point of the band, as the profile is monotone in y.
double gauge_point_y(const std::vector<double>& y, const std::vector<double>& z, double depth,
                     TrackParams::GaugeRule rule, const std::string& source) {
  const auto top = static_cast<std::size_t>(std::max_element(z.begin(), z.end()) - z.begin());
  const double level = z[top] - depth;
  std::optional<double> found;
  for (std::size_t i = top; i > 0; --i) {
    if (z[i] > level && z[i - 1] <= level) {  // the walk leaves the band downward here
      const double a = (z[i] - level) / (z[i] - z[i - 1]);
      found = y[i] + a * (y[i - 1] - y[i]);
      if (rule == TrackParams::GaugeRule::first) return *found;
    }
  }
  if (found) return *found;
  fail("wrc.wheelset: rail profile {} does not reach {} mm below its top on the gauge side, where the gauge point "
       "lies: is it cropped above that depth, or upside down (a file with z pointing down: mirror_z = true)?", source,
       depth * 1e3);
}

// Smallest vertical gap wheel - rail over the lateral overlap of two polylines ordered by y. The gap of
// two piecewise-linear functions is smallest at a vertex of one of them.
double min_vertical_gap(const std::vector<double>& wy, const std::vector<double>& wz, const std::vector<double>& ry,
                        const std::vector<double>& rz) {
  const double lo = std::max(wy.front(), ry.front()), hi = std::min(wy.back(), ry.back());
  double g = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < wy.size(); ++i)
    if (wy[i] >= lo && wy[i] <= hi) g = std::min(g, wz[i] - interpolate(ry, rz, wy[i]));
  for (std::size_t i = 0; i < ry.size(); ++i)
    if (ry[i] >= lo && ry[i] <= hi) g = std::min(g, interpolate(wy, wz, ry[i]) - rz[i]);
  return g;
}

void place_sorted(const Profile& p, int side, bool wheel, const SidePlacement& pl, std::vector<double>& oy,
                  std::vector<double>& oz) {
  const std::size_t n = p.size();
  oy.resize(n);
  oz.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d q = wheel ? pl.wheel(p.y[i], p.z[i]) : pl.rail(p.y[i], p.z[i]);
    const std::size_t j = side == kLeft ? i : n - 1 - i;  // mirroring reverses the order
    oy[j] = q.x();
    oz[j] = q.y();
  }
}

}  // namespace

Track assemble_track(const std::array<Profile, 2>& wheels, const std::array<Profile, 2>& rails, const TrackParams& params) {
  check_params(params);
  Track t;
  t.params = params;
  t.wheel = wheels;
  t.rail = rails;
  for (int s : {kLeft, kRight}) {
    if (wheels[s].kind != ProfileKind::wheel)
      fail("wrc.wheelset: the {} wheel profile ({}) is a {} profile", side_name(s), wheels[s].source, to_string(wheels[s].kind));
    if (rails[s].kind != ProfileKind::rail)
      fail("wrc.wheelset: the {} rail profile ({}) is a {} profile", side_name(s), rails[s].source, to_string(rails[s].kind));
  }
  const double angle = std::atan(params.cant);
  for (int s : {kLeft, kRight}) {
    SidePlacement& pl = t.place[s];
    pl.tape_y = 0.5 * params.back_to_back + params.tape_offset;
    pl.radius = params.radius;
    pl.cant_angle = angle;
    // Canted rail in the left-side frame, then shifted so its gauge point lies at gauge/2.
    const Profile& r = rails[s];
    std::vector<double> cy(r.size()), cz(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Eigen::Vector2d q = pl.rail(r.y[i], r.z[i]);  // sign = +1 and no shift yet: left-side frame
      cy[i] = q.x();
      cz[i] = q.y();
    }
    // A face that the cant turns vertical (60E1's 1:20 gauge-side flank at cant 1:20) rounds to either side.
    for (std::size_t i = 1; i < cy.size(); ++i)
      if (cy[i] < cy[i - 1] && cy[i] > cy[i - 1] - kVerticalRounding) cy[i] = cy[i - 1];
    if (!std::is_sorted(cy.begin(), cy.end()))
      fail("wrc.wheelset: the {} rail profile '{}' ({}) is not monotone in y after the cant rotation (a face leans "
           "over once canted by {:.4g} rad, at y = {:+.1f} mm of the profile){}", side_name(s), r.name, r.source, angle,
           r.y[fold_index(cy)] * 1e3,
           params.cant != 0 ? ": is the rail already canted in its file (Simpack and MiniProf rails often are)? A "
                              "canted rail is used with cant = 0" : "");
    pl.rail_dy = 0.5 * params.gauge - gauge_point_y(cy, cz, params.gauge_depth, params.gauge_rule, r.source);
    pl.rail_dz = -params.radius;  // provisional: crown near the wheel's lowest point
    pl.sign = s == kLeft ? 1.0 : -1.0;
  }
  // Common vertical shift of both rails so that the first touch of the centred wheelset is at z = 0.
  double gap = std::numeric_limits<double>::infinity();
  for (int s : {kLeft, kRight}) {
    place_sorted(wheels[s], s, true, t.place[s], t.wheel_y[s], t.wheel_z[s]);
    place_sorted(rails[s], s, false, t.place[s], t.rail_y[s], t.rail_z[s]);
    if (t.wheel_y[s].back() < t.rail_y[s].front() || t.rail_y[s].back() < t.wheel_y[s].front())
      fail("wrc.wheelset: the {} wheel (y_w {:.4f} .. {:.4f} m) and rail (y {:.4f} .. {:.4f} m) do not overlap laterally",
           side_name(s), t.wheel_y[s].front(), t.wheel_y[s].back(), t.rail_y[s].front(), t.rail_y[s].back());
    gap = std::min(gap, min_vertical_gap(t.wheel_y[s], t.wheel_z[s], t.rail_y[s], t.rail_z[s]));
  }
  for (int s : {kLeft, kRight}) {
    t.place[s].rail_dz += gap;
    for (double& z : t.rail_z[s]) z += gap;
    t.gauge_point[s] = {t.place[s].sign * 0.5 * params.gauge,
                        *std::max_element(t.rail_z[s].begin(), t.rail_z[s].end()) - params.gauge_depth};
    t.rail_top[s] = t.gauge_point[s].y() + params.gauge_depth;
    t.tape_point[s] = t.place[s].wheel(0.0, interpolate_z(wheels[s], 0.0));
  }
  return t;
}

}  // namespace wrc
