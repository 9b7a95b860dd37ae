// Smooth queries on the discretised wheel (wrc/geometry/model.hpp, wheelset frame) that the normal-contact
// stage needs away from the crossings: radius, normal and conicity at a lateral position, and the deepest
// point of a rail line relative to the wheel.
//
// Why smooth: a Newton solver differentiates forces with respect to the pose. Normals taken per cone jump by
// the profile's turning between cones (up to 8 mrad at the S1002 flange root at 0.1 mm), which would make the
// force direction a step function of the pose. Here normals are interpolated between vertex normals (the
// average of the two cones meeting at a generatrix point), so they vary continuously along the wheel.
#pragma once

#include "wrc/geometry/cone_line.hpp"
#include "wrc/geometry/model.hpp"

#include <Eigen/Core>

#include <limits>

namespace wrc {

struct WheelSurfacePoint {
  double radius = 0;    // wheel radius at the lateral position (m), linear on the cones
  double normal_y = 0;  // smooth outward meridian normal (n_y, n_r), unit; n_r = cos(conicity angle) >= 0 on
  double normal_r = 1;  // the tread and flange faces
  int cone = 0;         // the cone holding the position (not an end face)
};

// The wheel surface at wheelset-frame lateral position Y (m), clamped to the profile's lateral range.
WheelSurfacePoint wheel_surface_at(const WheelCones& wheel, double Y);
// Its radius alone (m), without the normal: cheaper.
double wheel_radius_at(const WheelCones& wheel, double Y);
// The signed distance of the meridian point (Y, rho) (wheelset-frame lateral position, distance to the axle; m) from
// the running surface's generatrix, > 0 inside the wheel (rho below the radius at Y): for a surface of revolution the
// exact 3-D depth of the point, its closest wheel point lying in its meridian plane. Searches the cones outward from
// the one holding Y only as far as one can be nearer.
double wheel_normal_depth(const WheelCones& wheel, double Y, double rho);
// The same search, with where it ends: the depth (m, as wheel_normal_depth) and the lateral position (m) of the
// point's closest generatrix point, its normal foot, at position t in [0, 1] on running-surface cone `cone`.
struct WheelNormalFoot {
  double depth = 0;
  double Y = 0;
  int cone = 0;
  double t = 0;
};
WheelNormalFoot wheel_normal_foot(const WheelCones& wheel, double Y, double rho);
// The same for the track-frame point p (at its wheelset-frame meridian point): the foot wheel_foot_normal and
// wheel_foot_normal_rate take, for a caller that needs it more than once at the same point to search it once.
WheelNormalFoot wheel_normal_foot(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& p);
// How fast the smooth normal of wheel_surface_at turns with Y there: d(atan2(n_y, n_r)) / dY (rad/m), constant on a
// cone (the normal is linear between the vertex normals). > 0 where the profile is convex (the radius falls ever
// faster away from a crown), < 0 in a throat.
double wheel_normal_turning(const WheelCones& wheel, double Y);

// The running surface's unit normal (y, radial) at generatrix point i: the mean of the normals of the non-degenerate
// cones meeting there.
Eigen::Vector2d wheel_vertex_normal(const WheelCones& wheel, int i);

// Track-frame unit normal of the wheel surface, pointing INTO the wheel (the direction of the force of the
// rail on the wheel), at the track-frame point p near the surface.
Eigen::Vector3d wheel_inward_normal(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& p);
// The same at the point's normal foot (wheel_normal_foot: its closest wheel point, in its meridian plane) instead of
// at its lateral position: the direction along which its depth d is measured. Inside a profile of curvature kappa
// and slope delta the two differ by kappa d tan(delta) (0.9 deg at 70 deg, 40 um deep in a 4 mm circle).
Eigen::Vector3d wheel_foot_normal(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& p);
// The same at p's foot found already (wheel_normal_foot(wheel, frame, p)).
Eigen::Vector3d wheel_foot_normal(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& p,
                                  const WheelNormalFoot& foot);
// wheel_foot_normal and how it turns as the point moves relative to the wheel: d(normal)/ds at p + s v (track-frame
// direction v, m; 1/m). The foot slides along the smooth surface (the normals interpolated between the vertices, of
// curvature kappa) by the point's tangential motion / (1 - kappa d), d its depth, the normal turning with the foot's
// Y (wheel_normal_turning), and the meridian plane turns about the axle. E.g. v = e_z: the wheel moving down by s.
// (wheel_foot_normal itself is the polygon's: between small jumps from cone to cone it turns 1 - kappa d as fast.)
struct WheelFootNormal {
  Eigen::Vector3d normal, rate;
};
WheelFootNormal wheel_foot_normal_rate(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& p,
                                       const Eigen::Vector3d& v);
// The same at p's foot found already (wheel_normal_foot(wheel, frame, p)).
WheelFootNormal wheel_foot_normal_rate(const WheelCones& wheel, const PoseFrame& frame, const Eigen::Vector3d& p,
                                       const WheelNormalFoot& foot, const Eigen::Vector3d& v);

// The deepest point of the rail line (y_r, z_r) (track frame, m) relative to the wheel: the maximum over x of
// overlap(x) = wheel radius at the line point's lateral position - the point's distance to the axle, which is
// > 0 inside the wheel. Exact on the discretised wheel: on each cone the overlap is concave in x, so its maximum
// is the clamped stationary point, and only the cones the line passes under within reach are visited.
struct LineApproach {
  double overlap = 0;  // radial overlap at the deepest point (m), < 0: the gap
  double x = 0;        // track-frame x of that point (m)
  double Y = 0;        // its wheelset-frame lateral position (m)
};
// With `floor`: a line whose overlap provably stays below it (its distance to the axle against the largest radius
// it passes under) returns at once with an overlap below the floor (the search of the deepest of many lines).
LineApproach line_approach(const WheelCones& wheel, const PoseFrame& frame, double y_r, double z_r,
                           double floor = -std::numeric_limits<double>::infinity());
// The overlap at the line's closest approach to the axle: a cheap lower bound of line_approach(...).overlap.
double line_overlap_at_closest(const WheelCones& wheel, const PoseFrame& frame, double y_r, double z_r);

}  // namespace wrc
