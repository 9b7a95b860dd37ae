// A wheelset followed along a trajectory (wheelset/trajectory.hpp).
#include "wrc/equilibrium/trajectory.hpp"

namespace wrc {

Trajectory::Trajectory(const Wheelset& wheelset, const TrajectoryOptions& options)
    : wheelset_(wheelset), options_(options), workspace_(wheelset.make_workspace()) {
  if (!(options.tolerance >= 1e-14 && options.tolerance < 1e-2))
    fail("trajectory: tolerance must be in [1e-14, 1e-2[, got {}", options.tolerance);
}

ContactResult Trajectory::contact(const Pose& pose) {
  ContactRequest req;
  req.keep_grids = options_.keep_grids;
  req.tolerance = options_.tolerance;
  return evaluate_contact(wheelset_.contact_model(), pose, *workspace_, req);
}

WheelResult Trajectory::wheel(int side, double y, double yaw, double roll, double Fz) {
  EquilibriumOptions opt;
  opt.normal_tolerance = options_.tolerance;
  opt.final_at_model_tolerance = false;
  WheelResult r = solve_wheel(wheelset_.contact_model(), side, y, yaw, roll, Fz, *workspace_, opt, last_z_[side]);
  if (r.converged) last_z_[side] = r.z;
  return r;
}

void Trajectory::reset() {
  workspace_->forget();
  last_z_[kLeft].reset();
  last_z_[kRight].reset();
}

}  // namespace wrc
