// How far a profile's points scatter about a smooth curve: measurement noise or coarse rounding in a profile file.
//
// Why it matters: a profile loaded without a smoothing length follows every point (the interpolating spline, or a
// polyline with smooth = false), so a scatter of a micrometre becomes a waviness of the undeformed distance at the
// points' spacing, which raises the peak pressure and breaks up the contact area while the forces stay plausible.
// On S1002 against 60E1 (one wheel, Fz = 100 kN, the largest rise of pmax over y = 0, 3 and 6.5 mm; points every
// 0.1 mm; six draws), Gaussian scatter of 1 um raised pmax by 7-40 % on a 0.5 mm grid and by 40-94 % on a 0.2 mm
// grid, 0.2 um by 1-8 % and 5-19 %, the points rounded to 1 um (a scatter of 0.29 um) by up to 6 % on either grid;
// loaded with smooth = 0.5e-3 the same points came within 2.6 % of the clean profile's pmax (0.2 um: 0.4 %), and the
// clean profile smoothed so within 0.1 %.
// (tests/scripts/profile_scatter.lua repeats a draw of 1 um on the 0.5 mm grid.)
//
// Method (each interior point's sagitta and its change from point to point):
//  - d_i, the signed distance of point i from the chord of points i-1 and i+1, is a smooth curve's sagitta
//    (kappa h^2 / 2 for the curvature kappa and the spacing h) plus the points' scatter normal to the curve;
//  - e_i = d_{i+1} - d_i takes the sagitta out but for the curvature's change over a spacing (kappa' h^3 / 2), which
//    is small everywhere but at a curvature jump (a point or two);
//  - independent scatter of standard deviation s at even spacing gives var d = 1.5 s^2 and cov(d_i, d_{i+1}) = -s^2,
//    so var e = 5 s^2, and e changes sign from one point to the next with probability acos(-0.75) / pi = 0.77 (its
//    lag-1 correlation is -0.75); so s = 1.4826 MAD(e) / sqrt(5), the median absolute deviation ignoring the few
//    points of a curvature jump;
//  - a curve sampled so coarsely that kappa' h^3 is most of e (S1002 every 2 mm: s would be 0.56 um) is told from
//    scatter by its e keeping one sign over runs of points: it changes sign at 0.17-0.24 of the points of S1002
//    sampled every 0.1-2 mm, at 0.53-0.77 with 1 um of scatter.
// Measured on S1002 with Gaussian scatter added to z: 0.3 um gave s = 0.27 and 0.34 um (points every 0.1 and 0.4
// mm), 1 um gave 0.89-1.2 um (every 0.1-1 mm). Only the scatter's part normal to the curve counts: on 60E1, whose
// head falls steeply on both sides, 1 um in z gave 0.41-0.47 um.
#pragma once

#include "wrc/profile/profile.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc {

struct PointScatter {
  double sigma = 0;         // m: the points' scatter normal to the curve (s above); 0 for fewer than kMinPoints points
  double spacing = 0;       // m: the median distance between consecutive points
  double sign_changes = 0;  // share of consecutive e_i of opposite signs (0..1)
  bool noise = false;       // sign_changes at least kNoiseSignChanges: scatter, not a coarsely sampled curve
};

// Fewer points give no estimate (the median of a dozen differences is no measure).
inline constexpr std::size_t kMinScatterPoints = 20;
// e's sign changes from point to point at this share or more: the scatter is noise (0.77 for pure noise, 0.17-0.24
// for clean S1002 samples at 0.1-2 mm).
inline constexpr double kNoiseSignChanges = 0.5;
// m: a scatter of noise from this size on is warned of: 0.2 um raised pmax by 1-8 % on a 0.5 mm grid and 5-19 % on a
// 0.2 mm grid (S1002/60E1, points every 0.1 mm); the points rounded to 1 um (0.29 um) by up to 6 %.
inline constexpr double kScatterWarning = 0.2e-6;

// The scatter of the polyline's points (y, z in m, in order along the profile), as above.
PointScatter point_scatter(const std::vector<double>& y, const std::vector<double>& z);

// The warning for a profile whose points scatter as noise by kScatterWarning or more, naming p.source and the
// remedy (a smoothing length); nothing otherwise. For profiles that follow their points: loaded without `smooth`.
// `remedy`: what to do about it, the sentence's start ("Load it" for a file, "Make it" for given points).
std::optional<std::string> scatter_warning(const Profile& p, std::string_view remedy = "Load it");
// Whether a warning is one of scatter_warning's (a profile smoothed afterwards drops it, whatever points it was of).
bool is_scatter_warning(std::string_view warning);

}  // namespace wrc
