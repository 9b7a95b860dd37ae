// The pose's rotation A = Rz(yaw) Rx(roll) and its translation, the limits of y, yaw and roll (pose.hpp).
#include "wrc/geometry/pose.hpp"

#include "wrc/core/error.hpp"

#include <cmath>

namespace wrc {

void check_lateral(double y, std::string_view context) {
  if (!std::isfinite(y) || std::abs(y) > kMaxLateral)
    fail("{}: y = {} m must be finite and within +-{:g} m (the lateral displacement in metres: mm given?)", context, y,
         kMaxLateral);
}

void check_yaw(double yaw, std::string_view context) {
  if (!std::isfinite(yaw) || std::abs(yaw) > kMaxYaw)
    fail("{}: yaw = {} rad must be finite and within +-{:g} rad (degrees given?)", context, yaw, kMaxYaw);
}

void check_roll(double roll, std::string_view context) {
  if (!std::isfinite(roll) || std::abs(roll) > kMaxRoll)
    fail("{}: roll = {} rad must be finite and within +-{:g} rad (degrees given?)", context, roll, kMaxRoll);
}

PoseFrame::PoseFrame(const Pose& p) : y(p.y), z(p.z) {
  const double cf = std::cos(p.roll), sf = std::sin(p.roll), cp = std::cos(p.yaw), sp = std::sin(p.yaw);
  // A = Rz(psi) Rx(phi) = [[cp, -sp cf, sp sf], [sp, cp cf, -cp sf], [0, sf, cf]]
  a11 = cp;
  a12 = -sp * cf;
  a13 = sp * sf;
  a21 = sp;
  a22 = cp * cf;
  a23 = -cp * sf;
  a32 = sf;
  a33 = cf;
}

Eigen::Matrix3d PoseFrame::matrix() const {
  Eigen::Matrix3d A;
  A << a11, a12, a13, a21, a22, a23, 0.0, a32, a33;
  return A;
}

Eigen::Vector3d PoseFrame::to_track(const Eigen::Vector3d& p) const {
  return Eigen::Vector3d(0.0, y, z) + matrix() * p;
}

Eigen::Vector3d PoseFrame::to_wheelset(const Eigen::Vector3d& p) const {
  return matrix().transpose() * (p - Eigen::Vector3d(0.0, y, z));
}

}  // namespace wrc
