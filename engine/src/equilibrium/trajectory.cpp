// A wheelset followed along a trajectory (wrc/equilibrium/trajectory.hpp).
#include "wrc/equilibrium/trajectory.hpp"

#include "wrc/core/error.hpp"

namespace wrc {

TrajectoryOptions read_trajectory_options(OptionReader& r) {
  TrajectoryOptions o;
  o.tolerance = r.number("tolerance", {"-", "normal solver's tolerance of the steps (relative)"}, o.tolerance);
  o.keep_grids = r.boolean("grids", {"-", "keep the pressure and h grids in the results"}, o.keep_grids);
  o.extrapolate = r.boolean("extrapolate", {"-", "start a step from the last two (fixed time step)"}, o.extrapolate);
  o.max_penetration = read_max_penetration(r, o.max_penetration);
  return o;
}

Trajectory::Trajectory(std::shared_ptr<const Wheelset> wheelset, const TrajectoryOptions& options)
    : wheelset_(std::move(wheelset)), options_(options) {
  if (!wheelset_) fail("trajectory: no wheelset");
  workspace_ = wheelset_->make_workspace();
  if (!(options.tolerance >= 1e-14 && options.tolerance < 1e-2))
    fail("trajectory: tolerance must be in [1e-14, 1e-2[, got {}", options.tolerance);
}

ContactResult Trajectory::contact(const Pose& pose, const std::optional<RollingRequest>& rolling, bool sensitivity) {
  ContactRequest req;
  req.jacobian = sensitivity;
  req.keep_grids = options_.keep_grids;
  req.tolerance = options_.tolerance;
  req.rolling = rolling;
  req.max_penetration = options_.max_penetration;
  workspace_->extrapolate = options_.extrapolate;
  try {
    return evaluate_contact(wheelset_->contact_model(), pose, *workspace_, req);
  } catch (const Error&) {
    // A cold start before failing: whatever the previous steps left (pressures, their displacements, the windows they
    // give) must not make a step fail that a top-level call solves. A bad pose fails again, as it should.
    workspace_->forget();
    return evaluate_contact(wheelset_->contact_model(), pose, *workspace_, req);
  }
}

WheelResult Trajectory::wheel(const WheelCase& c, const std::optional<RollingRequest>& rolling, bool sensitivity) {
  c.validate("wheel");  // as solve_wheel would, before the side indexes the approaches
  const int side = c.side;
  WheelOptions opt;
  opt.limits.normal_tolerance = options_.tolerance;
  opt.final_at_model_tolerance = false;
  opt.limits.max_penetration = options_.max_penetration;
  opt.sensitivity = sensitivity;
  // The secant's iterates are no time steps: start each from the last alone (the evaluations then keep no older
  // areas, so a later contact() step cannot extrapolate across them either).
  workspace_->extrapolate = false;
  // The start: the approach of the last step, extrapolated linearly in time with the one before when steps are
  // (extrapolate): it follows the load, where the height follows the rail.
  std::optional<double> start = last_approach_[side];
  if (start && before_approach_[side] && options_.extrapolate) start = 2 * *start - *before_approach_[side];
  // Likewise the creep forces' vertical part, which the normal problem's load leaves out.
  std::optional<WheelHint> hint = rolling ? last_hint_[side] : std::nullopt;
  if (hint && before_hint_[side] && options_.extrapolate) hint->creep = 2 * hint->creep - before_hint_[side]->creep;
  // And the tangential tractions: the step's first exact solve starts from those of the last two steps.
  std::vector<ContactWorkspace::Previous> last_tangential = workspace_->tangential[side];
  if (options_.extrapolate) workspace_->tangential_before[side] = before_tangential_[side];
  WheelResult r;
  try {
    r = solve_wheel(wheelset_->contact_model(), c, *workspace_, opt, start, rolling, hint);
  } catch (const Error&) {
    r.converged = false;
  }
  if (!r.converged) {  // a cold start before failing, as contact() (the result is then the cold solve's)
    workspace_->forget();
    r = solve_wheel(wheelset_->contact_model(), c, *workspace_, opt, std::nullopt, rolling);
  }
  before_approach_[side] = r.converged ? last_approach_[side] : std::nullopt;
  last_approach_[side] = r.converged ? std::optional<double>(r.approach) : std::nullopt;
  const bool creep_solved = r.converged && rolling;
  before_hint_[side] = creep_solved ? last_hint_[side] : std::nullopt;
  if (creep_solved) before_tangential_[side] = std::move(last_tangential);
  else before_tangential_[side].clear();
  last_hint_[side] = creep_solved ? std::optional<WheelHint>(r.hint) : std::nullopt;
  return r;
}

void Trajectory::reset() {
  workspace_->forget();
  for (auto& b : before_tangential_) b.clear();
  for (int s : {kLeft, kRight}) {
    last_approach_[s].reset(), before_approach_[s].reset();
    last_hint_[s].reset(), before_hint_[s].reset();
  }
}

}  // namespace wrc
