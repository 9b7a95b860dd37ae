// The wheelset's pose on its track and the rotation it stands for (docs/design.md, section 2: frames and signs).
#pragma once

#include <Eigen/Core>

#include <string_view>

namespace wrc {

// Wheelset pose in the track frame: lateral y (m), vertical z (m, z < 0 pressed into the rails), roll phi
// about x (rad), yaw psi about z (rad).
struct Pose {
  double y = 0, z = 0, roll = 0, yaw = 0;
};

// The lateral displacement, yaw and roll every call that takes a pose accepts. Far beyond a wheelset on its rails (the
// flanges leave ~10 mm of play; a wheelset yaws by a few mrad, some tens in the tightest curves; it rolls by a few
// mrad, 0.01 rad lifting a wheel 7.5 mm), they hold what the geometry can still compute and refuse the usual slips of
// unit: y = 8 for 8 mm, yaw = 1 or roll = 1 for one degree.
inline constexpr double kMaxLateral = 0.1;  // m: |y| <= this
inline constexpr double kMaxYaw = 0.3;      // rad (17 deg): |yaw| <= this
inline constexpr double kMaxRoll = 0.1;     // rad (5.7 deg): |roll| <= this
// Throw wrc::Error "<context>: y = <y> m must be finite and within +-0.1 m (...)" (yaw and roll alike, in rad) unless
// the value is finite and within its limit.
void check_lateral(double y, std::string_view context);
void check_yaw(double yaw, std::string_view context);
void check_roll(double roll, std::string_view context);

// A = Rz(yaw) Rx(roll) (dimensionless), with the pose's translation; the form every line-cone test uses.
struct PoseFrame {
  double y = 0, z = 0;                                       // wheelset centre (m)
  double a11 = 1, a12 = 0, a13 = 0, a21 = 0, a22 = 1, a23 = 0, a32 = 0, a33 = 1;  // A31 = 0
  PoseFrame() = default;
  explicit PoseFrame(const Pose& p);
  Eigen::Matrix3d matrix() const;
  // Track-frame point of the wheelset-frame point p_w.
  Eigen::Vector3d to_track(const Eigen::Vector3d& p_w) const;
  // Wheelset-frame point of the track-frame point p.
  Eigen::Vector3d to_wheelset(const Eigen::Vector3d& p) const;
};

}  // namespace wrc
