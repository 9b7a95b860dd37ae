// Conformal contact (docs/design.md section 3, "Conformal contact"): a contact area solved on a curved surface, as
// CONTACT's conformal mode does, instead of on one plane. Chosen per wheelset: ContactOptions::surface.
//
// Why: between the tread and the flange the wheel's surface turns by tens of degrees inside one patch. On a plane,
// all of the pressure acts along one normal and the lateral force depends on how that plane is chosen; on the
// curved surface each element's pressure acts along its own normal.
//
// The geometry (engine/src/wheelset/conformal.cpp):
//  - Reference surface: the rail's surface. The rail is a set of lines parallel to x (an extrusion of its profile),
//    so its surface is exactly x-extruded: the curve across the patch is the rail profile through the placed rail
//    points, the potential contact area lies on it, and unrolling it is exact (no stretching).
//  - Parameters: x (track x, m) along the track and s (m), the arc length along the rail profile (the chords between
//    consecutive rail points, counted from the side's first rail line). The grid is regular in (x, s), its element
//    centres on the rail's fixed lattice (x and s - ContactModel::rail_lattice_origin integer multiples of the
//    element), so they do not slide with the pose; the normal solver and its half-space influence coefficients are
//    those of the planar path, applied on the unrolled surface (the standard approximation of the conformal mode; a
//    kernel corrected for the surface's turning would enter there).
//  - Local frame per grid row (one s): t1 = e_x; n = the normal of the surface midway between wheel and rail, where
//    two bodies of one material meet when pressed together (each deforms by half the overlap): at each rail line
//    the bisector of the rail's normal (across its neighbouring lines) and the wheel's inward normal at the line's
//    deepest point (where the wheel's surface is parallel to the line, so it has no x component), linear in s
//    between lines and normalised; t2 = n x t1 (across the track, toward increasing s).
//  - Undeformed distance h(x, s): along each rail line the depth of the line inside the wheel measured along the
//    wheel's normal -- the arcs of the planar path (the segment's sagitta, radius r / (cos(conicity) cos^2(yaw))
//    along x; the exact normal gap at the deepest point of a line without a segment) -- linear in s between lines.
//    Along the row's normal the depth is longer by 1 / cos of half the angle between the undeformed surfaces, i.e.
//    of half the gap's slope: a few degrees at most where there is pressure, a relative 1e-3.
//  - Forces: element (i, j) carries p dA along n_j (dA = dx ds); the area's force and moment about the wheelset
//    centre are the sums over the elements at their points (x_i, y(s_j), z(s_j)) on the rail surface. Since every
//    n_j is perpendicular to x, a frictionless area has no longitudinal force: a straight rail cannot push along
//    itself (the energy does not change when the wheel moves along x).
//  - Not modelled: the wheel's curvature along x enters h only (as on the plane); the coupling of elements through
//    the half-space is that of a flat surface (exact for small turning, the standard approximation otherwise).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace wrc {

enum class ContactSurface { planar, conformal };
const char* surface_name(ContactSurface surface);  // "planar" | "conformal"

// The curved potential contact area of a conformal area: the area's grid (PatchContact::solution.grid) is laid out
// on the rail's surface unrolled. Element (i, j) is at track x = x0 + grid.x(i) and arc length s0 + grid.y(j); row j
// holds the rail-surface points (x, y[j], z[j]) and all its elements share the frame t1 = e_x, t2(j), normal(j).
// What a tangential solver needs per element: its position, its tangent plane (slip in t1, t2(j)) and its normal
// (the spin omega . normal(j) varies across the patch).
struct ConformalSurface {
  double x0 = 0;                          // track x of grid x = 0 (m)
  double s0 = 0;                          // arc length of grid y = 0 along the rail profile, from its first line (m)
  std::vector<double> y, z;               // per row: the reference point (track frame, m)
  std::vector<double> normal_y, normal_z; // per row: unit normal from the rail into the wheel (x component 0)
  int rows() const { return static_cast<int>(y.size()); }
  Eigen::Vector3d normal(int j) const { return {0.0, normal_y[j], normal_z[j]}; }
  Eigen::Vector3d t2(int j) const { return {0.0, normal_z[j], -normal_y[j]}; }  // normal(j) x e_x
  Eigen::Vector3d point(int j, double x) const { return {x, y[j], z[j]}; }     // x: track x (m)
};

}  // namespace wrc
