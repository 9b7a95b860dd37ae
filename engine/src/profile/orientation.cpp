// Orientation checks of profiles by their shape (orientation.hpp).
#include "wrc/profile/orientation.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace wrc {
namespace {

// The lean test of a rail head. The head's width is taken this far below its top, where the head of a 60E1 (EN
// 13674-1) is nearly at its full 72 mm; its top lies this far toward the field side of the middle of that width on a
// head canted 1:40 toward the track centre (60E1: 6.9 mm, by its R300 crown), toward the gauge side when mirrored.
constexpr double kHeadDepth = 0.014;   // m
constexpr double kLeanOffset = 0.003;  // m
// The head's tilt: the angle that, undone, leaves the head most nearly symmetric, the middles of its width at every
// mm from 1 to kHeadDepth below its top on one vertical line. A 60E1 head canted 1:40 and mirrored is found tilted
// 1:40 outward and symmetric so within 0.01 mm (tests/scripts/profile_orientation_files.lua); a worn gauge face
// moves the deeper middles, which no tilt puts back in line with the crown's, or only with an inward tilt (the
// crown's middle then follows the worn head's). The tilt must be outward beyond 1:100 (well below the cant of any
// track: 1:40, 1:30, 1:20), and symmetric within kSymmetry, to settle that a head leaning outward is mirrored.
constexpr double kMaxTilt = 0.1, kTiltStep = 0.0005;  // searched over +-1:10
constexpr double kMinTilt = 0.01;
constexpr double kSymmetry = 0.3e-3;  // m

// y where the polyline first crosses the level z = level walking from point k in direction dir (+1 / -1).
std::optional<double> crossing(const std::vector<double>& y, const std::vector<double>& z, std::size_t k, int dir,
                               double level) {
  for (std::size_t i = k; dir > 0 ? i + 1 < y.size() : i > 0; i = dir > 0 ? i + 1 : i - 1) {
    const std::size_t j = dir > 0 ? i + 1 : i - 1;
    if ((z[i] - level) * (z[j] - level) <= 0 && z[i] != z[j])
      return y[i] + (level - z[i]) / (z[j] - z[i]) * (y[j] - y[i]);
  }
  return std::nullopt;
}
std::optional<double> crossing(const Profile& p, std::size_t k, int dir, double level) {
  return crossing(p.y, p.z, k, dir, level);
}

// How far the middles of the head's width, every mm from 1 mm to kHeadDepth below its top, lie from one vertical
// line (their range) once the points are turned by -tilt (radians, positive counter-clockwise: toward the track
// centre); infinity where the head does not reach that deep on both sides.
double asymmetry(const Profile& p, double tilt) {
  const double c = std::cos(tilt), s = std::sin(tilt);
  std::vector<double> y(p.size()), z(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) y[i] = c * p.y[i] + s * p.z[i], z[i] = -s * p.y[i] + c * p.z[i];
  const std::size_t k = static_cast<std::size_t>(std::max_element(z.begin(), z.end()) - z.begin());
  double lo = INFINITY, hi = -INFINITY;
  for (int mm = 1; mm <= static_cast<int>(std::lround(kHeadDepth * 1e3)); ++mm) {
    const auto g = crossing(y, z, k, -1, z[k] - mm * 1e-3), f = crossing(y, z, k, +1, z[k] - mm * 1e-3);
    if (!g || !f) return INFINITY;
    lo = std::min(lo, 0.5 * (*g + *f)), hi = std::max(hi, 0.5 * (*g + *f));
  }
  return hi - lo;
}

// The tilt (radians, positive toward the track centre) that leaves the head most nearly symmetric, and how nearly.
std::pair<double, double> head_tilt(const Profile& p) {
  std::pair<double, double> best{0.0, INFINITY};
  for (double t = -kMaxTilt; t <= kMaxTilt + 0.5 * kTiltStep; t += kTiltStep)
    if (const double a = asymmetry(p, t); a < best.second) best = {t, a};
  return best;
}

// How to turn the profile round: the default option, or the steps that reversed that direction on the way in.
std::string undo(const std::vector<std::string>& steps, const char* axis, const std::string& otherwise) {
  if (steps.empty()) return otherwise;
  std::string list;
  for (const std::string& s : steps) list += (list.empty() ? "" : "; and ") + s;
  return fmt::format("Its {} direction was reversed on the way in by {}", axis, list);
}

void check_wheel(const Profile& p, const Reversals& rev, std::vector<std::string>& out) {
  const auto [lo, hi] = std::minmax_element(p.z.begin(), p.z.end());
  const bool has_tape = p.y.front() <= 0 && p.y.back() >= 0;
  const double z_tape = has_tape ? interpolate_z(p, 0.0) : 0.5 * (*lo + *hi);
  const double down = z_tape - *lo, up = *hi - z_tape;
  const double y_low = p.y[static_cast<std::size_t>(lo - p.z.begin())];
  const double y_high = p.y[static_cast<std::size_t>(hi - p.z.begin())];
  if (up > 0.010 && up > 2 * down)
    out.push_back(fmt::format(
        "{}: the wheel profile looks upside down: its extreme point (the flange tip?) lies {:.1f} mm ABOVE the tape "
        "circle at y = {:.1f} mm; in the wheel frame the flange tip points down (S1002: z = -28 mm). {}",
        p.source, up * 1e3, y_high * 1e3,
        undo(rev.z, "vertical", "Pass mirror_z = true if the file has z pointing down")));
  else if (down > 0.010 && y_low > 0 && y_low - p.y.front() < 0.5 * (p.y.back() - p.y.front()))
    out.push_back(fmt::format(
        "{}: the wheel profile's origin is not at the tape circle: its flange (lowest point, {:.1f} mm below the "
        "height at y = 0) lies toward its gauge-side end, as a wheel's does, but at y = +{:.1f} mm; in the wheel frame "
        "y is measured from the tape circle, 70 mm from the flange back (S1002's flange at y = -55 mm). Is y measured "
        "from the flange back (MiniProf's X)? Pass shift = {{y = {:.4f}}} to put the first point at -70 mm",
        p.source, down * 1e3, y_low * 1e3, -0.070 - p.y.front()));
  else if (down > 0.010 && y_low > 0)
    out.push_back(fmt::format(
        "{}: the wheel profile looks mirrored: its flange (lowest point, {:.1f} mm below the tape circle) lies at "
        "y = +{:.1f} mm, on the field side; in the wheel frame the flange is toward -y (the track centre; S1002: "
        "y = -55 mm). {}",
        p.source, down * 1e3, y_low * 1e3,
        undo(rev.y, "lateral", "Pass mirror_y = true if the file measures toward the flange")));
}

void check_rail(const Profile& p, const Reversals& rev, std::vector<std::string>& out) {
  const auto hi = std::max_element(p.z.begin(), p.z.end());
  const auto lo = std::min_element(p.z.begin(), p.z.end());
  const std::size_t k = static_cast<std::size_t>(hi - p.z.begin());
  const double height = *hi - *lo;
  if (height < 0.005) return;  // too flat to say
  const double drop_first = *hi - p.z.front(), drop_last = *hi - p.z.back();
  if (drop_first < 0.25 * height && drop_last < 0.25 * height) {
    // Both ends near the top: with an interior lowest point the head hangs down.
    const std::size_t m = static_cast<std::size_t>(lo - p.z.begin());
    if (m > 0 && m + 1 < p.size())
      out.push_back(fmt::format(
          "{}: the rail profile looks upside down: its lowest point (y = {:.1f} mm) is interior and its ends are "
          "{:.1f} mm higher; a rail head has its top as the interior highest point. {}",
          p.source, p.y[m] * 1e3, height * 1e3,
          undo(rev.z, "vertical", "Pass mirror_z = true if the file has z pointing down")));
    return;
  }
  const auto g = crossing(p, k, -1, *hi - kHeadDepth), f = crossing(p, k, +1, *hi - kHeadDepth);
  if (!g || !f) return;
  const double offset = p.y[k] - 0.5 * (*g + *f);
  if (offset >= -kLeanOffset) return;
  const std::string fix = undo(rev.y, "lateral", "Pass mirror_y = true (MiniProf rails are measured with the track "
                                                  "centre on +X)");
  const auto [tilt, spread] = head_tilt(p);
  if (tilt < -kMinTilt && spread < kSymmetry)
    fail("{}: the rail profile is mirrored: its head leans outward, toward -y (the gauge side), by two measures: its "
         "top lies {:.1f} mm toward -y of the head's centre (the middle of its width {:.0f} mm below the top), and the "
         "head is a symmetric one tilted outward by 1:{:.0f} (turned back by that angle, the middles of its width from "
         "1 to {:.0f} mm below the top lie within {:.2f} mm of one vertical line): a rail canted toward the track "
         "centre, seen from the other side. {}",
         p.source, -offset * 1e3, kHeadDepth * 1e3, -1 / tilt, kHeadDepth * 1e3, spread * 1e3, fix);
  out.push_back(fmt::format(
      "{}: the rail head's top lies {:.1f} mm toward -y (the gauge side) of the head's centre (the middle of its "
      "width {:.0f} mm below the top): the head leans outward. A rail canted toward the track centre has its top on "
      "the field side (+y); the profile is probably mirrored, unless it is a worn high rail whose worn gauge face has "
      "moved the head's centre (the head is no symmetric one tilted outward, which would settle it). {}",
      p.source, -offset * 1e3, kHeadDepth * 1e3, fix));
}

}  // namespace

std::vector<std::string> orientation_warnings(const Profile& p, const Reversals& reversed) {
  std::vector<std::string> out;
  if (p.size() < 3) return out;
  if (p.kind == ProfileKind::wheel) check_wheel(p, reversed, out);
  else check_rail(p, reversed, out);
  return out;
}

}  // namespace wrc
