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
};

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
  // The sensitivities, in two steps per column (0: the wheelset moving by dz = 1 m, 1: rolling by 1 rad). motion: the
  // change of h per element (dh = -dX . n, the wheel's rigid motion toward the rail). response: the change of the
  // area's force and moment about the centre (the centre moving with z included) for the pressure response `r` to dh.
  virtual void motion(const PatchContact& area, const Pose& pose, int column, std::vector<double>& dh) const = 0;
  virtual void response(const PatchContact& area, const Pose& pose, int column, const halfspace::NormalResponse& r,
                        Eigen::Vector3d& dF, Eigen::Vector3d& dM) const = 0;
  // The surface's own fields of an area, after the fields every area has.
  virtual void describe(const PatchContact& area, FieldSink& out) const = 0;
};

const AreaSurface& planar_surface();     // planar.cpp
const AreaSurface& conformal_surface();  // conformal.cpp
inline const AreaSurface& surface_for(ContactSurface kind) {
  return kind == ContactSurface::conformal ? conformal_surface() : planar_surface();
}
// The surface a solved area was laid out on.
inline const AreaSurface& surface_of(const PatchContact& area) {
  return area.conformal ? conformal_surface() : planar_surface();
}

}  // namespace wrc::areas
