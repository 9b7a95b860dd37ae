// EN 15313 flange measures (measures.hpp).
#include "wrc/profile/measures.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace wrc {
namespace {

// The lowest point of the polyline among points with y < 0, refined by the parabola through it and its neighbours.
Eigen::Vector2d flange_tip(const Profile& p, std::size_t& k) {
  k = 0;
  for (std::size_t i = 0; i < p.size() && p.y[i] < 0; ++i)
    if (p.z[i] < p.z[k]) k = i;
  if (k == 0 || k + 1 >= p.size() || p.y[k + 1] == p.y[k] || p.y[k] == p.y[k - 1]) return {p.y[k], p.z[k]};
  const double y0 = p.y[k - 1], y1 = p.y[k], y2 = p.y[k + 1], z0 = p.z[k - 1], z1 = p.z[k], z2 = p.z[k + 1];
  const double den = (y0 - y1) * (y0 - y2) * (y1 - y2);
  const double A = (y2 * (z1 - z0) + y1 * (z0 - z2) + y0 * (z2 - z1)) / den;
  const double B = (y2 * y2 * (z0 - z1) + y1 * y1 * (z2 - z0) + y0 * y0 * (z1 - z2)) / den;
  const double C = z1 - A * y1 * y1 - B * y1;
  if (!(A > 0)) return {y1, z1};
  const double yt = std::clamp(-B / (2 * A), y0, y2);
  return {yt, A * yt * yt + B * yt + C};
}

// The first crossing of the level z = level walking from point k toward +y (the flange face side).
Eigen::Vector2d face_crossing(const Profile& p, std::size_t k, double level, const char* what) {
  for (std::size_t i = k; i + 1 < p.size(); ++i)
    if ((p.z[i] - level) * (p.z[i + 1] - level) <= 0 && p.z[i] != p.z[i + 1]) {
      const double a = (level - p.z[i]) / (p.z[i + 1] - p.z[i]);
      return {p.y[i] + a * (p.y[i + 1] - p.y[i]), level};
    }
  fail("flange measures: {}: the flange face does not reach {} (z = {:.3f} mm)", p.source, what, level * 1e3);
}

}  // namespace

FlangeMeasures flange_measures(const Profile& p, double tape_offset, double sd_height, double qr_depth) {
  if (p.kind != ProfileKind::wheel) fail("flange measures: {} is a {} profile, not a wheel", p.source, to_string(p.kind));
  if (!(tape_offset > 0 && tape_offset < 0.5)) fail("flange measures: tape_offset = {} m must lie in ]0, 0.5[", tape_offset);
  if (!(p.y.front() < 0 && p.y.back() >= 0))
    fail("flange measures: {}: the profile ({:.1f} .. {:.1f} mm) must reach the flange (s < 0) and the tape circle "
         "(s = 0)", p.source, p.y.front() * 1e3, p.y.back() * 1e3);
  FlangeMeasures m;
  m.tape_offset = tape_offset;
  m.tape = {0.0, interpolate_z(p, 0.0)};
  std::size_t k = 0;
  m.tip = flange_tip(p, k);
  m.Sh = m.tape.y() - m.tip.y();
  if (!(m.Sh > sd_height + qr_depth))
    fail("flange measures: {}: no flange: the lowest point on the flange side is {:.2f} mm below the tape circle "
         "(needs more than {:.0f} mm)", p.source, m.Sh * 1e3, (sd_height + qr_depth) * 1e3);
  m.sd_point = face_crossing(p, k, m.tape.y() - sd_height, "the Sd level 10 mm above the tape circle");
  m.qr_point = face_crossing(p, k, m.tip.y() + qr_depth, "the qR level 2 mm below the flange tip");
  m.Sd = m.sd_point.x() + tape_offset;
  m.qR = m.sd_point.x() - m.qr_point.x();
  return m;
}

void describe(const FlangeMeasures& m, FieldSink& out) {
  out.number("Sh", m.Sh, {"m", "flange height: radial distance from the tape circle to the flange tip"});
  out.number("Sd", m.Sd, {"m", "flange thickness: inner face to the flange face 10 mm radially outward of the tape circle"});
  out.number("qR", m.qR, {"m", "flange slope measure: lateral distance of the Sd point and the face point 2 mm radially inward of the tip"});
  out.number("tape_offset", m.tape_offset, {"m", "the tape circle's distance from the inner face (at s = -tape_offset)"});
  const std::tuple<const char*, Eigen::Vector2d, const char*> points[] = {
      {"tape", m.tape, "the tape circle point (s = 0)"},
      {"tip", m.tip, "the flange tip (the lowest point of the flange)"},
      {"sd_point", m.sd_point, "the flange face point of Sd"},
      {"qr_point", m.qr_point, "the flange face point of qR, 2 mm radially inward of the tip"}};
  for (const auto& [key, v, meaning] : points) {
    out.begin(key, {"", meaning});
    out.number("y", v.x(), {"m", "s, lateral from the tape circle, + toward the field side (profile frame)"});
    out.number("z", v.y(), {"m", "radius offset with the sign of a height (profile frame)"});
    out.end();
  }
}

}  // namespace wrc
