// Orientation checks of profiles by their shape (orientation.hpp).
#include "wrc/profile/orientation.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace wrc {
namespace {

// y where the polyline first crosses the level z = level walking from point k in direction dir (+1 / -1).
std::optional<double> crossing(const Profile& p, std::size_t k, int dir, double level) {
  for (std::size_t i = k; dir > 0 ? i + 1 < p.size() : i > 0; i = dir > 0 ? i + 1 : i - 1) {
    const std::size_t j = dir > 0 ? i + 1 : i - 1;
    if ((p.z[i] - level) * (p.z[j] - level) <= 0 && p.z[i] != p.z[j])
      return p.y[i] + (level - p.z[i]) / (p.z[j] - p.z[i]) * (p.y[j] - p.y[i]);
  }
  return std::nullopt;
}

void check_wheel(const Profile& p, std::vector<std::string>& out) {
  const auto [lo, hi] = std::minmax_element(p.z.begin(), p.z.end());
  const bool has_tape = p.y.front() <= 0 && p.y.back() >= 0;
  const double z_tape = has_tape ? interpolate_z(p, 0.0) : 0.5 * (*lo + *hi);
  const double down = z_tape - *lo, up = *hi - z_tape;
  const double y_low = p.y[static_cast<std::size_t>(lo - p.z.begin())];
  const double y_high = p.y[static_cast<std::size_t>(hi - p.z.begin())];
  if (up > 0.010 && up > 2 * down)
    out.push_back(fmt::format(
        "{}: the wheel profile looks upside down: its extreme point (the flange tip?) lies {:.1f} mm ABOVE the tape "
        "circle at y = {:.1f} mm; in the wheel frame the flange tip points down (S1002: z = -28 mm). Pass mirror_z = "
        "true if the file has z pointing down",
        p.source, up * 1e3, y_high * 1e3));
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
        "y = -55 mm). Pass mirror_y = true if the file measures toward the flange",
        p.source, down * 1e3, y_low * 1e3));
}

void check_rail(const Profile& p, std::vector<std::string>& out) {
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
          "{:.1f} mm higher; a rail head has its top as the interior highest point. Pass mirror_z = true if the file "
          "has z pointing down",
          p.source, p.y[m] * 1e3, height * 1e3));
    return;
  }
  const auto g = crossing(p, k, -1, *hi - 0.014), f = crossing(p, k, +1, *hi - 0.014);
  if (!g || !f) return;
  const double offset = p.y[k] - 0.5 * (*g + *f);
  if (offset < -0.003)
    out.push_back(fmt::format(
        "{}: the rail head's top lies {:.1f} mm toward -y (the gauge side) of the head's centre (the middle of its "
        "width 14 mm below the top): the head leans outward. A rail canted toward the track centre has its top on "
        "the field side (+y); the profile is probably mirrored (MiniProf rails measured with the track centre on +X "
        "need mirror_y = true)",
        p.source, -offset * 1e3));
}

}  // namespace

std::vector<std::string> orientation_warnings(const Profile& p) {
  std::vector<std::string> out;
  if (p.size() < 3) return out;
  if (p.kind == ProfileKind::wheel) check_wheel(p, out);
  else check_rail(p, out);
  return out;
}

}  // namespace wrc
