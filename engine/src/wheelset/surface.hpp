// The surface a contact area is solved on (ContactOptions::surface): one plane per area (planar.cpp, the paper's) or
// the rail's surface unrolled (conformal.cpp, wrc/wheelset/conformal.hpp). The area pipeline (area.hpp) asks a surface
// for the area's grid and undeformed distance, then for what the solved pressure means on it (resultant, sensitivity,
// fields); the normal solve, its warm start and the bookkeeping around it are the pipeline's, written once. A surface
// calls no part of the pipeline. One virtual call per area and step; loops over elements stay inside a surface.
// Internal, not installed.
#pragma once

#include "segments.hpp"

#include "wrc/core/fields.hpp"
#include "wrc/halfspace/normal.hpp"
#include "wrc/wheelset/contact.hpp"

#include <Eigen/Core>

#include <vector>

namespace wrc::areas {

// One area to lay out: located patches of one wheel solved together.
struct AreaInput {
  const ContactModel& model;
  const LocationState& located;
  int side;
  const std::vector<int>& patches;           // indices into located.patches(side)
  const std::vector<SegmentInfo>& segments;  // the segments of all of them
  const Patch& first;                        // located.patches(side)[patches.front()]
};

// What a surface lays out for the area's normal problem, beside the area's h and frame (PatchContact).
struct AreaLayout {
  halfspace::Grid grid;  // the potential contact area in the surface's coordinates (m)
  // Where the warm start looks for the last evaluation's area and maps its pressures: the plane, or for the conformal
  // surface its unrolled coordinates as a plane (origin (x, s, 0), axes e_x, e_y, normal e_z).
  Plane frame;
  std::vector<double> vertical;   // per grid row: the vertical part of its normal (a vertical load's weights)
  std::vector<double> deepening;  // per grid row: dh/dz, h's growth as the wheel moves down
  // Conformal, per grid row: d(normal_y, normal_z)/da, the row normal's turning as the wheel moves down by a (1/m; the
  // wheel's normal at a line's normal foot turns as the foot slides). Empty: normals fixed.
  std::vector<Eigen::Vector2d> turning;
};

// A rigid motion of the wheelset per unit of one of its pose coordinates (Pose: y, z, roll, yaw): its centre c moves by
// `translation`, its points X by translation + rotation x (X - c).
struct RigidMotion {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
};
enum PoseCoordinate { kPoseY = 0, kPoseZ = 1, kPoseRoll = 2, kPoseYaw = 3 };
// y: e_y; z: e_z; roll: about the roll axis Rz(yaw) e_x; yaw: about e_z (the pose's rotations, docs/design.md
// section 2).
RigidMotion pose_motion(const Pose& pose, int coordinate);

class AreaSurface {
 public:
  virtual ~AreaSurface() = default;
  virtual const char* name() const = 0;  // "planar" | "conformal", the field `surface`
  // The area's grid, its h (area.h, m, > 0 inter-penetration) and its frame (area.origin, t1, t2, normal; the rows
  // of a conformal area).
  virtual AreaLayout lay_out(const AreaInput& in, PatchContact& area) const = 0;
  // What the solved pressure (area.solution) exerts on the wheel at the pose `frame`: area.normal_force, force,
  // moment (about the wheelset centre), point (centre of pressure), normal, angle, angle_min, angle_max.
  virtual void resultant(const PoseFrame& frame, PatchContact& area) const = 0;
  // The sensitivities, in two steps per rigid motion of the wheelset (pose_motion). motion: the change of h per element
  // (dh = -dX . n, the wheel's rigid motion toward the rail). response: the change of the area's normal force and its
  // moment about the centre c held where it is, for the pressure response `r` to dh (the caller adds the centre's
  // own motion, -translation x force).
  virtual void motion(const PatchContact& area, const Pose& pose, const RigidMotion& m, std::vector<double>& dh) const = 0;
  virtual void response(const PatchContact& area, const Pose& pose, const halfspace::NormalResponse& r,
                        Eigen::Vector3d& dF, Eigen::Vector3d& dM) const = 0;
  // Where element (i, j) of the area's grid is (track frame, m): on the plane, or on the rail's surface.
  virtual Eigen::Vector3d element_point(const PatchContact& area, int i, int j) const = 0;
  // The surface's own fields of an area, after the fields every area has.
  virtual void describe(const PatchContact& area, FieldSink& out) const = 0;
};

const AreaSurface& planar_surface();     // planar.cpp
const AreaSurface& conformal_surface();  // conformal.cpp
inline const AreaSurface& surface_for(ContactSurface kind) {
  return kind == ContactSurface::conformal ? conformal_surface() : planar_surface();
}
// A conformal area laid out again for the located patches `st` of another pose (the side's patches with a segment on
// the area's rows), on the area's lattice: its origin (track x, arc length S: the reference point) and h at each of
// the area's elements (m; NaN where the new grid does not reach, and everything NaN when no patch is left).
struct ConformalLayoutAt {
  Eigen::Vector2d origin;
  std::vector<double> h;
};
ConformalLayoutAt conformal_layout_at(const ContactModel& model, const LocationState& st, const PatchContact& area);
// How a conformal area's row normals (the bisectors of the rail's and the wheel's normals, wrc/wheelset/conformal.hpp)
// turn per unit of a pose coordinate (PoseCoordinate), per row: the wheel's normal at the normal foot of the row's
// centre of pressure turning with the wheel and as the point moves relative to it (wheel_foot_normal_rate), the rail's
// held. (Central differences of the polygon's foot normal, as before, were off at a few rows in a hundred: the foot
// jumps from cone to cone or rests at a vertex of a concave part within their step.)
void row_turning(const ContactModel& model, const Pose& pose, const PatchContact& area, int coordinate,
                 std::vector<Eigen::Vector3d>& dn);
// The change of a conformal area's normal force and moment about the centre when its rows' normals turn by dn.
void turning_wrench(const PatchContact& area, const Pose& pose, const std::vector<Eigen::Vector3d>& dn,
                    Eigen::Vector3d& dF, Eigen::Vector3d& dM);
// The surface a solved area was laid out on.
inline const AreaSurface& surface_of(const PatchContact& area) {
  return area.conformal ? conformal_surface() : planar_surface();
}

}  // namespace wrc::areas
