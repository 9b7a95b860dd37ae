// The flange of a wheel profile and the flange-climb conditions (flange.hpp).
#include "wrc/geometry/flange.hpp"

#include "wrc/core/conventions.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wrc {
namespace {

constexpr double kDeg = 180.0 / M_PI;

}  // namespace

Flange flange_of(const Profile& w) {
  Flange f;
  const double z0 = interpolate_z(w, 0.0);
  std::size_t tip = w.size();
  for (std::size_t i = 0; i < w.size() && w.y[i] <= 0; ++i)
    if (tip == w.size() || w.z[i] <= w.z[tip]) tip = i;  // the lowest z; the last of equals (nearest the tape circle)
  if (tip == w.size() || z0 - w.z[tip] <= kMinFlangeHeight) return f;
  f.present = true;
  f.tip_y = w.y[tip];
  f.tip_z = w.z[tip];
  f.height = z0 - f.tip_z;
  f.face_y = f.tip_y;
  std::size_t end = tip;  // the last point of the face: the last with y <= 0
  while (end + 1 < w.size() && w.y[end + 1] <= 0) ++end;
  std::vector<double> angle;
  for (std::size_t i = tip; i < end; ++i) angle.push_back(std::atan2(w.z[i + 1] - w.z[i], w.y[i + 1] - w.y[i]));
  if (angle.empty()) return f;
  f.max_angle = *std::max_element(angle.begin(), angle.end());
  for (std::size_t k = 0; k < angle.size(); ++k)
    if (angle[k] >= f.max_angle - kSteepBand) {
      f.steep_y = w.y[tip + k];
      break;
    }
  const double level = z0 - kFlangeThicknessHeight;
  for (std::size_t i = end; i > tip; --i)  // from the tape circle toward the tip: the first crossing of the level
    if (w.z[i - 1] <= level && w.z[i] > level) {
      f.face_y = w.y[i - 1] + (level - w.z[i - 1]) / (w.z[i] - w.z[i - 1]) * (w.y[i] - w.y[i - 1]);
      break;
    }
  return f;
}

std::string beyond_steepest(const Flange& f, double y) {
  if (!f.present || y >= f.steep_y) return "";
  return fmt::format("contact at y = {:.2f} mm on the wheel profile, beyond the steepest part of the flange face "
                     "({:.1f} deg, ends at y = {:.2f} mm; tip at {:.2f} mm): the wheel climbs its flange",
                     y * 1e3, f.max_angle * kDeg, f.steep_y * 1e3, f.tip_y * 1e3);
}

std::string nadal_exceeded(const Flange& f, int side, double Fy, double Fz) {
  if (!f.present || f.max_angle >= 0.5 * M_PI) return "";
  const double L = -side_sign(side) * Fy;  // toward the track centre: -y for the left wheel
  const double limit = std::tan(f.max_angle);
  if (Fz > 0 && L <= limit * Fz) return "";
  return fmt::format("L/V = {:.3g} exceeds Nadal's limit tan({:.1f} deg) = {:.3f} of the frictionless flange",
                     Fz > 0 ? L / Fz : INFINITY, f.max_angle * kDeg, limit);
}

std::string lifted_off(const Flange& f, double gap) {
  if (!f.present || gap <= f.height) return "";
  return fmt::format("lifted {:.1f} mm off its rail, more than its flange height ({:.1f} mm): the flange no longer "
                     "guides it (derailed)", gap * 1e3, f.height * 1e3);
}

}  // namespace wrc
