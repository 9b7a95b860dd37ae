// Closed-form intersection of one wheel cone with one rail line (Baeza et al. 2018, eq. 1 and A.1-A.7).
//
// Frames (docs/design.md, section 2): a wheelset-frame point p_w is at (0, y, z) + A p_w in the track frame, with
// A = Rz(yaw) Rx(roll), so A31 = 0 as the appendix requires. A wheel cone joins the generatrix points
// (y_w, z_w) and (y_w1, z_w1) of the wheelset frame, z = -radius (z <= 0): rotating the point (0, Y, Z) by
// eps about the wheelset y axis sweeps the circle of radius |Z| (eq. 1). A rail line is parallel to x through
// (y_r, z_r) of the track frame. Eq. (1) then reads, with Y = y_w + alpha (y_w1 - y_w), Z = z_w + alpha (z_w1 - z_w):
//   (x, y_r, z_r) = (0, y, z) + A (-Z sin eps, Y, Z cos eps).
//
// Sign of A.5 (checked symbolically and numerically, see cone_line.cpp and tests/geometry/test_cone_line.cpp):
// eliminating alpha from rows 2 and 3 of eq. (1) gives R cos(eps) - S sin(eps) + T = 0 with R, S, T exactly as
// printed in A.1-A.3, whose roots are eps = 2 atan((-S +- sqrt(d)) / (R - T)). The printed A.5,
// eps = 2 atan((S + sqrt(d)) / (R - T)), solves R cos + S sin + T = 0 instead: under the conventions above it
// returns -eps, i.e. x of the wrong sign of the sin(eps) term in A.7 whenever yaw != 0 (S is proportional to
// A21 = sin(yaw); with zero yaw S = 0 and both forms agree). A.4, A.6 and A.7 agree with eq. (1) as printed.
#pragma once

#include "wrc/geometry/pose.hpp"

#include <Eigen/Core>

namespace wrc {

// One solution of eq. (1) for a cone and a line.
struct ConeLineRoot {
  double x = 0;        // longitudinal coordinate of the crossing (track frame, m), A.7
  double alpha = 0;    // position on the generatrix (0 at point w, 1 at point w+1)
  double cos_eps = 1;  // angular position eps of the crossing around the wheel (eq. 1)
  double sin_eps = 0;
};

// The terms of A.1-A.4 for one cone and line (m^2 scale); exposed for tests and plots.
struct ConeLineTerms {
  double R = 0, S = 0, T = 0, d = 0;
};
ConeLineTerms cone_line_terms(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1,
                              double z_w1);

// Intersections of the line through (y_r, z_r) with the cone (y_w, z_w)-(y_w1, z_w1): both roots of A.5 (the two
// signs of sqrt(d)), kept when d >= 0 and alpha is in ]0, 1] (the paper's conditions; half-open so that a
// crossing through the circle shared by cones w-1 and w is counted once, on cone w-1). `alpha_slack` >= 0 widens
// the interval to ]-slack, 1 + slack] (used by the line assembly to see crossings that rounding put just past a
// shared circle; see location.cpp). Writes up to two roots to `out` in increasing x and returns their number.
//
// Degenerate cases, each handled explicitly:
//  - d < 0: no crossing. d = 0 (tangency): both roots are returned, at the same x.
//  - R = S = T = 0: the eliminant vanishes for every eps (the line lies in the plane of a flat ring, or passes
//    through the cone's apex): no isolated crossing, 0 roots; the neighbouring cones carry the crossings.
//  - R - T = 0: one root is eps = pi (top of the wheel), the other finite (A.5 written in a division-free form).
//  - Cylinder (z_w = z_w1) and zero roll: the alpha equation of row 3 (A.6) degenerates; alpha is taken from the
//    better-conditioned of rows 2 and 3 of eq. (1) (the larger alpha coefficient).
//  - Flat ring (y_w = y_w1): T = 0; handled by the same formulae.
//  - Both alpha equations degenerate (the generatrix at that eps is parallel to the line): no crossing at that
//    eps (either none exists or the line lies along the generatrix, touching the surface without entering it).
//  - Zero yaw: S = 0, the roots are +-eps with the same alpha.
int cone_line_intersections(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1,
                            double z_w1, ConeLineRoot out[2], double alpha_slack = 0.0);

// A bound on how far rounding may have moved `root`'s alpha (a root of the same cone and line): ~1e-13 for a line that
// crosses the wheel at a clear angle, up to 1e-8 and more for one that grazes a shared circle (near a tangency the
// roots are ill-conditioned), where a fixed band made one cone of the circle report the crossing and its neighbour not.
// For the line assembly's band at the shared circles (search.cpp); not on the hot path.
double cone_line_alpha_error(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1,
                             double z_w1, const ConeLineRoot& root);

}  // namespace wrc
