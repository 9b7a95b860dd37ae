// Profiles as smooth curves: a parametric cubic spline (y(t), z(t)) through or near a profile's points, with the
// parameter t the chord length of the points (m). Used for the lateral curvature radii of profiles at a contact
// point (meaningless on a polyline) and, when a profile is loaded with `smooth = ...`, for resampling it into
// cones and lines.
//
// Smoothing (Reinsch 1967, in the penalised form of Green & Silverman): each coordinate f(t) is replaced by the
// natural cubic spline g minimising
//     sum_i w_i (f_i - g(t_i))^2 + l^4 * integral g''(t)^2 dt,       w_i = the point's share of t (trapezoid, m)
// with the smoothing length l (m). Weighting by the spacing makes it a property of the curve, not of the point
// density: for densely sampled data it is the filter G(k) = F(k) / (1 + (l k)^4) of wavenumber k (rad/m), so
// waviness of wavelength 2 pi l along the profile is halved, shorter waviness (measurement noise) removed, longer
// shapes kept. l = 0 gives the interpolating natural cubic spline through the points.
#pragma once

#include "wrc/profile/profile.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace wrc {

struct ProfileSpline {
  std::vector<double> t;       // knots: chord-length parameter (m), increasing
  std::vector<double> y, z;    // curve at the knots (m)
  std::vector<double> yy, zz;  // second derivatives d2y/dt2, d2z/dt2 at the knots (1/m); 0 at the ends (natural)
  double smoothing = 0;        // the smoothing length l (m) it was fitted with
  int y_order = 0;             // +1: knot y non-decreasing, -1: non-increasing, 0: neither (set by fit and map)

  struct Point {
    Eigen::Vector2d p, d1, d2;  // (y, z) (m), first (-) and second (1/m) derivatives in t
  };
  // The curve at t (clamped to the knots).
  Point at(double t) const;
  // Signed curvature (1/m) at t with the tangent oriented toward +y (toward +z on a vertical run): positive where
  // the curve turns counter-clockwise in the (y, z) plane.
  double curvature(double t) const;
  // The parameter of the curve point closest to q (m).
  double closest(const Eigen::Vector2d& q) const;
  // A parameter where y(t) = yq, searched between the knots whose y bracket yq (the first such pair along t);
  // clamped to the curve's ends when yq lies beyond them.
  double param_at_y(double yq) const;
};

// Fits the spline to the points (y, z) (at least 3, distinct consecutive points), smoothing length l >= 0 (m).
// Throws wrc::Error naming `context` on bad input.
ProfileSpline fit_profile_spline(const std::vector<double>& y, const std::vector<double>& z, double smoothing_length,
                                 const std::string& context);

// The profile replaced by its smoothing spline: its points moved onto the spline at their own parameters, the spline
// kept in p.spline (resampling then evaluates it), a note in p.transforms. Throws when the smoothed points fold back.
Profile smooth_profile(const Profile& p, double smoothing_length);

// The curve of a profile: its spline when it has one, else the interpolating cubic spline through its points.
std::shared_ptr<const ProfileSpline> profile_curve(const Profile& p);

// Lateral curvature (1/m) of the profile's curve at the parameter t, signed as Hertz needs it: > 0 where the surface
// is convex (bulges out of its body toward the other body: a rail crown, a wheel tread curving up toward the
// field side), < 0 where concave (a wheel's flange root). Wheel bodies lie above their profile (toward +z of the
// profile frame), rails below.
double surface_curvature(const ProfileSpline& curve, ProfileKind kind, double t);

// The lateral curvature (1/m, signed as surface_curvature) of the profile's curve at lateral position y (m) of its
// frame: the first point of the curve at that y.
double profile_curvature(const Profile& p, double y);

// The spline mapped by y -> sy * y + dy, z -> sz * z + dz (sy, sz = +-1: mirrors), as p:transform maps a profile.
ProfileSpline mapped_spline(const ProfileSpline& s, double sy, double dy, double sz, double dz);

}  // namespace wrc
