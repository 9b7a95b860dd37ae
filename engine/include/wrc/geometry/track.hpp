// Track assembly (docs/design.md, section 2): places the left/right wheel profiles in the wheelset frame and
// the rail profiles in the track frame, so that the centred, unrotated wheelset at z = 0 just touches.
#pragma once

#include "wrc/core/conventions.hpp"
#include "wrc/profile/measures.hpp"
#include "wrc/profile/profile.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace wrc {

struct TrackParams {
  double radius = 0.45;        // wheel nominal radius r0 at the tape circle (m)
  double back_to_back = 1.360; // flange-back distance (m)
  double tape_offset = kTapeOffset;  // tape circle from the flange back (m): left tape circle at y_w = 0.750
  double gauge = 1.435;        // between the gauge points (m)
  double gauge_depth = 0.014;  // gauge points this far below the top of each rail (m)
  // Which point of the gauge face is the gauge point. Both look at the rail as it lies in the track (after the cant;
  // a canted file, used with cant = 0, the same way), below its highest point, walking toward the gauge side:
  //  - first: the first point gauge_depth below the top (the crossing of that level met first);
  //  - innermost: the innermost gauge-face point from the top down to gauge_depth below it (EN 13848-1's measuring
  //    band; differs from `first` only where the gauge face crosses the level more than once, e.g. a worn lip).
  enum class GaugeRule { first, innermost } gauge_rule = GaugeRule::first;
  double cant = 1.0 / 40.0;    // rail inclination (tan of the angle); the head tilts toward the track centre
};

// Rigid placement of one side. Profile points are given in the left-side frame (+y toward the field
// side); the right side is the mirror image (y -> -y).
struct SidePlacement {
  double sign = 1;        // +1 left, -1 right
  double tape_y = 0.75;   // |y_w| of the tape circle (m)
  double radius = 0.45;   // r0 (m)
  double cant_angle = 0;  // rail rotation (rad) = atan(cant), field side up
  double rail_dy = 0;     // left-side lateral shift of the canted rail (m, before mirroring)
  double rail_dz = 0;     // vertical shift of the canted rail (m)

  // Wheel point (s, zs) -> (y_w, z_w) in the wheelset frame; z_w = -(r0 - zs) is the circle's lowest
  // point, the generatrix of eq. (1).
  Eigen::Vector2d wheel(double s, double zs) const { return {sign * (tape_y + s), zs - radius}; }
  // Rail point (y, z) of the profile frame -> (y, z) of the track frame.
  Eigen::Vector2d rail(double y, double z) const;
};

struct Track {
  TrackParams params;
  std::array<Profile, 2> wheel, rail;       // as given (left-side frame), indexed by Side
  std::array<SidePlacement, 2> place;
  // The given profiles placed, ordered by increasing y: wheel in the wheelset frame (y_w, z_w),
  // rail in the track frame.
  std::array<std::vector<double>, 2> wheel_y, wheel_z, rail_y, rail_z;
  std::array<Eigen::Vector2d, 2> gauge_point;  // track frame (m)
  std::array<Eigen::Vector2d, 2> tape_point;   // wheelset frame (m): tape circle's lowest point
  std::array<double, 2> rail_top;              // z of each placed rail's highest point (m)
};

// A canted rail face that comes out vertical may lean back by rounding: up to this much (m) it is taken as vertical.
inline constexpr double kVerticalRounding = 1e-9;

// Assembles the track. Throws wrc::Error when a profile has the wrong kind, the rail does not reach
// gauge_depth below its top on the gauge side, a parameter is out of range, or wheel and rail do not
// overlap laterally.
Track assemble_track(const std::array<Profile, 2>& wheels, const std::array<Profile, 2>& rails,
                     const TrackParams& params);

}  // namespace wrc
