// A wheelset followed along a trajectory, for callers that evaluate the contact at every time step (a multibody
// code): the state keeps the last solution of each contact area and starts the next evaluation from it, instead
// of starting cold as the top-level calls do. Results then depend on the steps before (to the solver tolerance);
// reset() starts afresh.
#pragma once

#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <memory>

namespace wrc {

struct TrajectoryOptions {
  // Tolerance of the normal problems (relative gap, as NormalOptions::tolerance): at 1e-6 (the equilibrium's
  // inner tolerance) forces are within ~1e-6 of a 1e-12 solve, and a warm start from the previous step needs a few
  // CG iterations.
  double tolerance = 1e-6;
  bool keep_grids = false;  // pressure and h grids in the results
  // contact(): start each step from the linear extrapolation of the last two steps (2 p_k - p_k-1, where both were in
  // contact), as for a fixed time step; false: from the last step alone (steps of varying size or direction).
  bool extrapolate = true;
  // A step deeper than this (m) is an error (contact) or not converged (wheel), as ContactRequest::max_penetration.
  double max_penetration = kMaxPenetration;
};

// Reads {tolerance =, grids =, extrapolate =, max_penetration =} (the keys of ws:trajectory{} and wrc_trajectory_new).
TrajectoryOptions read_trajectory_options(OptionReader& options);

class Trajectory {
 public:
  explicit Trajectory(std::shared_ptr<const Wheelset> wheelset, const TrajectoryOptions& options = {});
  // Contact at a prescribed pose (as evaluate_contact), warm-started from the previous step; with `rolling`, the
  // tangential problem of every area too (creep forces, as ws:contact's rolling keys; "fastsim" for speed). A step
  // that fails warm is evaluated again cold before it throws.
  // `sensitivity`: each wheel's Jacobian too (WheelContact::jacobian; and jacobian_fz from wheel()).
  ContactResult contact(const Pose& pose, const std::optional<RollingRequest>& rolling = std::nullopt,
                        bool sensitivity = false);
  // One wheel with its vertical force prescribed (as solve_wheel, `rolling` included), from the previous steps'
  // approach; a step that fails (or throws) so is solved again from a cold start, whose result it returns.
  WheelResult wheel(const WheelCase& c, const std::optional<RollingRequest>& rolling = std::nullopt,
                    bool sensitivity = false);
  // Forget the previous steps.
  void reset();
  const TrajectoryOptions& options() const { return options_; }
  // The workspace (set its timing on to measure; benchmarks).
  ContactWorkspace& workspace() { return *workspace_; }
  const Wheelset& wheelset() const { return *wheelset_; }

 private:
  std::shared_ptr<const Wheelset> wheelset_;
  TrajectoryOptions options_;
  std::unique_ptr<ContactWorkspace> workspace_;
  // Per side, the approaches (WheelResult::approach) of the last wheel solve and the one before it.
  std::optional<double> last_approach_[2], before_approach_[2];
  // Per side, what the last two wheel solves with rolling contact tell the next (creep forces' vertical part,
  // stiffness).
  std::optional<WheelHint> last_hint_[2], before_hint_[2];
  // Per side, the exact tangential solutions that ended the step before the last (ContactWorkspace::tangential_before).
  std::vector<ContactWorkspace::Previous> before_tangential_[2];
};

}  // namespace wrc
