// The numeric kernels of a wear loop (examples/wear_evolution.lua, docs/guide/wear.md): where contact rows fall on a
// profile, their worn areas deposited onto the profile's points as depths, an area-preserving smoothing of the
// depths, the profile moved along its normals, and the area between two profiles. A profile here is a polyline (y, z)
// in its own frame (docs/design.md, section 2); "arc" is its cumulative arc length from the first point (m).
//
// Depths live on the points: point i owns the cell of arc between the midpoints of its two segments (half a segment at
// either end), and its depth d_i (m) stands for the worn area d_i c_i (m^2, c_i the cell's length). The deposit and the
// smoothing conserve sum d_i c_i exactly; moving every point by d_i along its normal removes that area to first order
// in d / (radius of curvature) (the trapezoids between the old and the new polyline).
#pragma once

#include "wrc/profile/profile.hpp"

#include <span>
#include <vector>

namespace wrc::damage {

// The cumulative arc length (m) at each point of the polyline; throws wrc::Error on sizes that differ or < 2 points.
std::vector<double> arc_length(std::span<const double> y, std::span<const double> z);

// The cell length c_i (m) of each point: (arc_{i+1} - arc_{i-1}) / 2, half a segment at the ends.
std::vector<double> cell_lengths(std::span<const double> arc);

// The nearest point of the polyline to each of the points (py, pz): its arc length (m) and the distance (m).
struct Projection {
  std::vector<double> arc, distance;
};
Projection project_onto(std::span<const double> y, std::span<const double> z, std::span<const double> py,
                        std::span<const double> pz);

// Worn strips deposited onto the points: strip k covers the arc [centre_k - width_k / 2, centre_k + width_k / 2]
// (m) with its worn area area_k (m^2, or any unit of depth times length) spread uniformly; point i gets
// d_i = (the strips' area over its cell) / c_i. `outside` is the area of the strips beyond the polyline's ends (lost).
struct Deposit {
  std::vector<double> depth;
  double outside = 0;
};
Deposit deposit_strips(std::span<const double> arc, std::span<const double> centre, std::span<const double> width,
                       std::span<const double> area);

// Area-preserving smoothing: each point's area d_j c_j spread over the points by a Gaussian of standard deviation
// `length` (m, > 0) in arc, cut at 3 `length`, its weights normalised per source point, so that sum d_i c_i is kept
// exactly (also at the ends); a depth of one sign keeps its sign. length = 0 returns the depths unchanged.
std::vector<double> smooth_depths(std::span<const double> arc, std::span<const double> depth, double length);

// The unit normal (ny, nz) at each point pointing into the body's material: a wheel's toward its axle (the +z side of
// its profile frame, where the radius r0 - z shrinks), a rail's into the head (the -z side); at a point between two
// segments the normalised mean of theirs. Either order of the points.
struct Normals {
  std::vector<double> ny, nz;
};
Normals inward_normals(std::span<const double> y, std::span<const double> z, ProfileKind kind);

// The polyline with each point moved by depth_i (m, >= 0 removes material) along its inward normal.
struct Polyline {
  std::vector<double> y, z;
};
Polyline move_along_normals(std::span<const double> y, std::span<const double> z, std::span<const double> depth,
                            ProfileKind kind);

// The area (m^2, >= 0) between two polylines of the same number of points, point i of one moved to point i of the
// other: the sum of the quadrilaterals (a_i, a_{i+1}, b_{i+1}, b_i), each by the shoelace formula, taken with its sign
// (material removed and added cancel) and the sum's magnitude returned.
double area_between(std::span<const double> ya, std::span<const double> za, std::span<const double> yb,
                    std::span<const double> zb);

}  // namespace wrc::damage
