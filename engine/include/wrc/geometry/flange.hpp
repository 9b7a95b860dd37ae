// The flange of a wheel profile and flange climb (docs/guide/robustness.md, "Flange climb"): the one definition of
// when a wheel is past flange climb, used by the elastic results (wheelset, equilibrium) and the rigid ones
// (kinematics).
#pragma once

#include "wrc/geometry/track.hpp"

#include <string>

namespace wrc {

// The flange of a wheel profile (left-side profile frame, m; docs/design.md section 2: z = radius offset with the
// sign of a height, so the flange tip is the lowest z).
struct Flange {
  bool present = false;   // the profile reaches more than kMinFlangeHeight below its tape-circle height on the
                          // gauge side (y < 0)
  double tip_y = 0;       // the flange tip (largest radius; the one nearest the tape circle when several)
  double tip_z = 0;
  double height = 0;      // z at the tape circle - tip_z (m)
  double max_angle = 0;   // steepest slope of the flange face between the tip and the tape circle (rad)
  double steep_y = 0;     // the tip-side end of the steepest part of the face (slopes within kSteepBand of it)
  double face_y = 0;      // the face kFlangeThicknessHeight above the tape-circle level (the tip when lower):
                          // flange thickness = tape_offset + face_y (EN 15313's Sd at 10 mm)
};

inline constexpr double kMinFlangeHeight = 5e-3;        // m: a lower rise is a tread, not a flange
inline constexpr double kFlangeThicknessHeight = 10e-3; // m: where the flange thickness is measured
inline constexpr double kSteepBand = 0.0175;            // rad (1 deg): slopes this close to the steepest count as it

Flange flange_of(const Profile& wheel);

// Lateral position in the profile frame of a wheelset-frame lateral position Y of that side.
inline double profile_y(const SidePlacement& place, double Y) { return place.sign * Y - place.tape_y; }

// Why a loaded wheel is past flange climb, or "" when it is not (flange: that wheel's; no flange: never):
//  - beyond_steepest: a contact area's centre of pressure (at profile lateral position y) lies beyond the steepest
//    part of the flange face, toward the tip, where a wheel pushed further climbs;
//  - nadal: the wheel's L/V (lateral force toward the track centre over vertical force; force on the wheel, track
//    frame) exceeds Nadal's limit of the frictionless contact, tan(steepest flange angle).
std::string beyond_steepest(const Flange& flange, double y);
std::string nadal_exceeded(const Flange& flange, int side, double Fy, double Fz);
// Why a lifted wheel is off its rail: lifted (radial gap `gap` to its rail, m) by more than its flange height, so
// that its flange no longer guides it; or "".
std::string lifted_off(const Flange& flange, double gap);

}  // namespace wrc
