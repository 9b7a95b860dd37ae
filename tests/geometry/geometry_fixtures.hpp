// Synthetic wheel and rail profiles for the geometry tests (the real S1002/60E1 are Lua definitions, tested
// through tests/scripts/strategy_*.lua). All in the left-side profile frame, metres.
#pragma once

#include "wrc/geometry/location.hpp"
#include "wrc/geometry/model.hpp"
#include "wrc/geometry/track.hpp"
#include "wrc/profile/profile.hpp"

#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace wrc::test {

// A wheel like S1002 in shape: 1/40 tread, a 28 mm flange (sin^2 hump) with a steep face, s in [-0.070, 0.060].
inline Profile synthetic_wheel(double step) {
  std::vector<double> y, z;
  const int n = static_cast<int>(std::round(0.130 / step));
  for (int i = 0; i <= n; ++i) {
    const double s = -0.070 + 0.130 * i / n;
    double zs = s / 40;
    if (s < -0.030) {
      const double t = std::sin(M_PI * (s + 0.070) / 0.040);
      zs -= 0.028 * t * t;
    }
    y.push_back(s);
    z.push_back(zs);
  }
  return make_profile(ProfileKind::wheel, y, z, "synthetic wheel", "test");
}

// A rail head: R300 crown, a tighter shoulder beyond |y| = 20 mm.
inline Profile synthetic_rail(double step) {
  std::vector<double> y, z;
  const int n = static_cast<int>(std::round(0.076 / step));
  for (int i = 0; i <= n; ++i) {
    const double v = -0.038 + 0.076 * i / n;
    const double e = std::max(0.0, std::abs(v) - 0.020);
    y.push_back(v);
    z.push_back(-v * v / 0.6 - 40 * e * e);
  }
  return make_profile(ProfileKind::rail, y, z, "synthetic rail", "test");
}

// The awkward pair (see tests/scripts/strategy_awkward.lua for the same idea on the Lua side): a wheel with a
// hollow tread, an exact cylinder, a vertical step (flat ring) and a vertical flange back; a rail with two crowns.
inline Profile awkward_wheel() {
  std::vector<double> y{-0.070, -0.070, -0.066, -0.060, -0.052, -0.045, -0.040, -0.035, -0.030, -0.020, -0.010,
                        0.000, 0.004, 0.004, 0.010, 0.020, 0.030, 0.040, 0.050, 0.060};
  std::vector<double> z{-0.010, -0.022, -0.028, -0.027, -0.020, -0.010, -0.004, -0.0015, -0.0008, -0.0002,
                        -0.0006, -0.0006, -0.0006, 0.0002, 0.0003, 0.0006, 0.0010, 0.0018, 0.0030, 0.0045};
  return make_profile(ProfileKind::wheel, y, z, "awkward wheel", "test");
}

inline Profile awkward_rail(double step) {
  std::vector<double> y, z;
  const int n = static_cast<int>(std::round(0.076 / step));
  for (int i = 0; i <= n; ++i) {
    const double v = -0.038 + 0.076 * i / n;
    // Two crowns at -8 mm and +9 mm with a 0.15 mm dip between, steep shoulders.
    const double c1 = -(v + 0.008) * (v + 0.008) / 0.16, c2 = -(v - 0.009) * (v - 0.009) / 0.16 - 0.00002;
    const double e = std::max(0.0, std::abs(v) - 0.022);
    y.push_back(v);
    z.push_back(std::max(c1, c2) - 40 * e * e);
  }
  return make_profile(ProfileKind::rail, y, z, "awkward rail", "test");
}

inline std::shared_ptr<const Track> make_track(const Profile& wheel, const Profile& rail) {
  return std::make_shared<const Track>(assemble_track({wheel, wheel}, {rail, rail}, TrackParams{}));
}

inline GeometryModel make_model(const Profile& wheel, const Profile& rail, int coarse_every = 0,
                                double coarse_step = 2e-3) {
  auto track = make_track(wheel, rail);
  SideDiscretisation d;
  d.wheel = wheel;
  d.rail = rail;
  d.coarse_every = coarse_every;
  d.coarse_wheel_step = coarse_step;
  return build_geometry(track, {d, d});
}

// A random pose: |y| <= 10 mm, |yaw| <= 30 mrad, |roll| <= 10 mrad, with z set so that the deepest penetration
// (found by a fine vertical-gap scan of the two placed profiles at the pose's y and roll, yaw ignored) is
// `depth` -- approximately: yaw changes the depth a little, which does not matter for the comparisons.
inline Pose random_pose(std::mt19937_64& rng, const Track& t, double depth) {
  std::uniform_real_distribution<double> U(-1, 1);
  Pose p;
  p.y = 0.010 * U(rng);
  p.yaw = 0.030 * U(rng);
  p.roll = 0.010 * U(rng);
  // Smallest vertical gap over both sides at z = 0 with this y and roll (rigid 2-D section at x = 0).
  const PoseFrame f(Pose{p.y, 0, p.roll, 0});
  double gap = 1e9;
  for (int s : {kLeft, kRight}) {
    const auto& wy = t.wheel_y[s];
    const auto& wz = t.wheel_z[s];
    const auto& ry = t.rail_y[s];
    const auto& rz = t.rail_z[s];
    for (std::size_t i = 0; i < wy.size(); ++i) {
      const Eigen::Vector3d q = f.to_track({0, wy[i], wz[i]});
      // rail height at q.y
      auto it = std::lower_bound(ry.begin(), ry.end(), q.y());
      if (it == ry.begin() || it == ry.end()) continue;
      const std::size_t k = static_cast<std::size_t>(it - ry.begin());
      const double a = (q.y() - ry[k - 1]) / (ry[k] - ry[k - 1]);
      gap = std::min(gap, q.z() - (rz[k - 1] + a * (rz[k] - rz[k - 1])));
    }
  }
  p.z = -gap - depth;
  return p;
}

inline double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> U(std::log(lo), std::log(hi));
  return std::exp(U(rng));
}

}  // namespace wrc::test
