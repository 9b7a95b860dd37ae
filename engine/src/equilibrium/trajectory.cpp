// A wheelset followed along a trajectory (wheelset/trajectory.hpp).
#include "wrc/equilibrium/trajectory.hpp"

namespace wrc {

TrajectoryOptions read_trajectory_options(OptionReader& r) {
  TrajectoryOptions o;
  o.tolerance = r.number("tolerance", o.tolerance);
  o.keep_grids = r.boolean("grids").value_or(o.keep_grids);
  o.extrapolate = r.boolean("extrapolate").value_or(o.extrapolate);
  return o;
}

Trajectory::Trajectory(std::shared_ptr<const Wheelset> wheelset, const TrajectoryOptions& options)
    : wheelset_(std::move(wheelset)), options_(options) {
  if (!wheelset_) fail("trajectory: no wheelset");
  workspace_ = wheelset_->make_workspace();
  if (!(options.tolerance >= 1e-14 && options.tolerance < 1e-2))
    fail("trajectory: tolerance must be in [1e-14, 1e-2[, got {}", options.tolerance);
}

ContactResult Trajectory::contact(const Pose& pose) {
  ContactRequest req;
  req.keep_grids = options_.keep_grids;
  req.tolerance = options_.tolerance;
  workspace_->extrapolate = options_.extrapolate;
  return evaluate_contact(wheelset_->contact_model(), pose, *workspace_, req);
}

WheelResult Trajectory::wheel(int side, double y, double yaw, double roll, double Fz) {
  EquilibriumOptions opt;
  opt.normal_tolerance = options_.tolerance;
  opt.final_at_model_tolerance = false;
  // The secant's iterates are no time steps: start each from the last alone.
  workspace_->extrapolate = false;
  workspace_->before[side].clear();
  WheelResult r = solve_wheel(wheelset_->contact_model(), side, y, yaw, roll, Fz, *workspace_, opt, last_z_[side]);
  if (r.converged) last_z_[side] = r.z;
  return r;
}

void Trajectory::reset() {
  workspace_->forget();
  last_z_[kLeft].reset();
  last_z_[kRight].reset();
}

}  // namespace wrc
