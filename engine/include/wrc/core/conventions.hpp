// The conventions every area shares, written once (docs/design.md, section 2).
//
// Sides: the LEFT rail is at +y of the track frame (x along the track, z up), the RIGHT rail at -y. Profiles are
// given as the left wheel and rail; the right side is their mirror image y -> -y, so a left-side quantity maps to
// the right side with the factor side_sign(side) on its lateral component.
#pragma once

#include "wrc/core/error.hpp"

#include <Eigen/Core>

#include <cmath>
#include <string_view>

namespace wrc {

enum Side : int { kLeft = 0, kRight = 1 };

inline const char* side_name(int side) { return side == kLeft ? "left" : "right"; }

// +1 on the left, -1 on the right: the lateral sign of the side's profile frame in the track frame.
inline double side_sign(int side) { return side == kLeft ? 1.0 : -1.0; }

// "left" -> kLeft, "right" -> kRight; anything else is an error naming `context`.
inline int parse_side(std::string_view text, std::string_view context) {
  if (text == "left") return kLeft;
  if (text == "right") return kRight;
  fail("{}: side must be \"left\" or \"right\", got \"{}\"", context, text);
}

// Contact angle (rad) of a direction n on the given side's wheel, n pointing from the rail INTO the wheel (the
// direction of the force of the rail on the wheel; track frame): the angle of n to the vertical, positive when
// n tilts toward the track centre -- on both sides, so that flange contact has a large positive angle.
inline double contact_angle(int side, const Eigen::Vector3d& n) {
  return std::atan2(-side_sign(side) * n.y(), n.z());
}

}  // namespace wrc
