// Wheel profile measures of EN 15313 (as UIC 510-2 defines them), on a wheel profile in its frame (docs/design.md,
// section 2: y = s from the tape circle, + toward the field side; z = radius offset with the sign of a height, so
// the flange tip is the lowest point). The tape circle (measuring circle) is at s = 0, `tape_offset` (70 mm) from
// the inner face of the wheel (the flange back), which therefore lies at s = -tape_offset whether or not the
// profile reaches it.
//
//   Sh  flange height: radial distance from the tape circle to the flange tip (the lowest point of the flange).
//   Sd  flange thickness: lateral distance from the inner face to the flange face at Sd_height (10 mm) radially
//       outward of the tape circle (z = z_tape - 10 mm), the point met first walking from the tip toward the tread.
//   qR  flange slope measure: lateral distance between that Sd point and the flange face point qR_depth (2 mm)
//       radially inward of the tip (z = z_tip + 2 mm), on the same face.
//
// Nominal S1002 (EN 13715 "h28 e32.5"): Sh = 28 mm, Sd = 32.5 mm, qR = 10.79 mm (the R20 flange face at 26 mm).
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/profile/profile.hpp"

#include <Eigen/Core>

namespace wrc {

// The tape circle's distance from the inner face of the wheel (m; EN 15313: 70 mm): the one default of the flange
// measures and of the track's placement of the wheels (TrackParams::tape_offset).
inline constexpr double kTapeOffset = 0.070;

struct FlangeMeasures {
  double Sh = 0, Sd = 0, qR = 0;            // m
  double tape_offset = kTapeOffset;         // inner face at s = -tape_offset (m)
  Eigen::Vector2d tape = Eigen::Vector2d::Zero();      // the tape circle point (s = 0, z) (m, profile frame)
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();       // flange tip (m)
  Eigen::Vector2d sd_point = Eigen::Vector2d::Zero();  // flange face point of Sd (m)
  Eigen::Vector2d qr_point = Eigen::Vector2d::Zero();  // flange face point 2 mm below the tip (m)
};

// Throws wrc::Error when the profile is not a wheel, does not reach the tape circle, has no flange (tip less than
// Sd_height + 2 mm below the tape circle) or its flange face does not reach the measuring levels.
FlangeMeasures flange_measures(const Profile& wheel, double tape_offset = kTapeOffset, double sd_height = 0.010,
                               double qr_depth = 0.002);

// Sh, Sd, qR (m), tape_offset, tape, tip, sd_point, qr_point ({y =, z =}, m).
void describe(const FlangeMeasures& m, FieldSink& out);

}  // namespace wrc
