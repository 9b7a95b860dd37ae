// The area pipeline (area.cpp): one contact area from its located patches to its solution, on the surface the model
// asks for (surface.hpp) -- the surface lays out the grid and h, the pipeline solves the normal problem (warm-started
// from the workspace's last evaluation), asks the surface for the resultant and the sensitivities, and remembers the
// pressures for the next evaluation. evaluate_contact (contact.cpp) runs it per area. Internal, not installed.
#pragma once

#include "surface.hpp"
#include "vertical_load.hpp"

#include "wrc/wheelset/contact.hpp"

#include <time.h>

#include <optional>
#include <vector>

namespace wrc::areas {

inline double thread_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Adds the thread CPU time of its scope to a field of the workspace's times (when timing is on).
class PhaseTimer {
 public:
  PhaseTimer(const ContactWorkspace& ws, double& slot) : slot_(ws.timing ? &slot : nullptr) {
    if (slot_) t0_ = thread_seconds();
  }
  ~PhaseTimer() {
    if (slot_) *slot_ += thread_seconds() - t0_;
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double* slot_;
  double t0_ = 0;
};

// How the areas of one evaluation are solved.
struct AreaSolve {
  double tolerance = 0;      // > 0: the normal solver's tolerance (ContactRequest::tolerance)
  bool sensitivity = false;  // fill PatchContact::sensitivity
  std::optional<double> vertical_force;  // the predictor's VerticalLoad::force (a wheel with one area only)
  bool estimate = false;                 // VerticalLoad::estimate
};

// Lays out, solves and describes one area; its pressures are appended to `next_previous` (the warm start of the
// workspace's next evaluation of that side).
PatchContact solve_area(const AreaInput& in, const AreaSolve& how, ContactWorkspace& ws,
                        std::vector<ContactWorkspace::Previous>& next_previous);
// d(force, moment)/d(z, roll) of a solved area (its pressure grid kept): the normal problem's pressure response to
// the rigid motions of the wheelset, on its contact set (halfspace/normal.hpp).
void area_sensitivity(const ContactModel& model, const Pose& pose, PatchContact& area, ContactWorkspace& ws);
// The normal problem's part of an area's Jacobian for one pose coordinate (PoseCoordinate): the response of its
// pressure (`dp`, Pa per unit) to the wheelset's rigid motion on its contact set, the change of its normal force and
// of their moment about the centre (the centre's motion included), and dh (m per unit, per element). The response is
// solved to the relative residual `tolerance`. dh: on a conformal area the layout's own h differenced over the layouts
// at the pose -+ kLayoutStep (geometry only, no solve; the wheel's normal where a layout misses the element), and its
// rows turn with the wheel's normal (row_turning); on a plane along the wheel's own normal at every element.
inline constexpr double kLayoutStep = 1e-6;  // m or rad: moves the wheel's surface by ~1 um, where h is smooth
struct NormalColumn {
  Eigen::Vector3d dF = Eigen::Vector3d::Zero(), dM = Eigen::Vector3d::Zero();
  std::vector<double> dp, dh;
  std::vector<Eigen::Vector3d> dn;  // conformal: each row's normal turning (row_turning); empty on a plane
  Eigen::Vector2d dref = Eigen::Vector2d::Zero();  // conformal: the reference point's motion (m: x, arc length)
};
NormalColumn normal_column(const ContactModel& model, const Pose& pose, const PatchContact& area, int coordinate,
                           ContactWorkspace& ws, double tolerance);
// Separate contact regions of a solution (8-connected, each >= 0.1 % of the force).
int contact_regions(const halfspace::NormalSolution& sol);

}  // namespace wrc::areas
