// What the two pose solvers -- solve_equilibrium (newton.hpp) and solve_wheel (wheel.hpp) -- share: when a load
// counts as carried, how long they try, how deep a pose may go and how well the normal problems are solved on the way.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/wheelset/contact.hpp"

#include <string_view>

namespace wrc {

// The largest load a solve accepts (N): far beyond any wheel (1e9 N is a load out of reach, refused after a few
// evaluations), small enough that the solvers' powers of it stay finite.
inline constexpr double kMaxLoad = 1e10;
// The most iterations or evaluations a solve may be given.
inline constexpr int kMaxSolveCount = 1 << 20;

struct SolveLimits {
  // Converged: |carried - load| <= force_tolerance * load (the load: Q, or a wheel's Fz); in ]0, 0.1].
  double force_tolerance = 1e-6;
  int max_iterations = 50;   // Newton iterations (or secant steps) per attempt, [1, kMaxSolveCount]
  int max_evaluations = 400; // contact evaluations per solve (all attempts), [1, kMaxSolveCount]; then it gives up
  // An iterate whose contacts are deeper than this (m, > 0) and still carry less than the load ends the solve at once:
  // the load is out of reach; a solution deeper than this is not converged (the reason says why). The default and why:
  // kMaxPenetration (wheelset/contact.hpp). The iterates themselves may pass deeper (a Newton step overshooting).
  double max_penetration = kMaxPenetration;
  // Tolerance of the normal problems while the solver iterates (relative, in [1e-14, 1e-2[; inexact steps from warm
  // starts, a few CG iterations each); a solution found so is evaluated again at the model's tolerance before it is
  // reported (a trajectory, content with this one, turns that off: WheelOptions::final_at_model_tolerance).
  double normal_tolerance = 1e-6;
  // Throws wrc::Error "<context>: <key> = <value> <unit> must be in <range>" for the first member out of its range.
  void validate(std::string_view context) const;
};

// Reads the keys both solvers share over the defaults: force_tolerance, max_iterations, max_evaluations,
// max_penetration (m); then validates.
SolveLimits read_solve_limits(OptionReader& options);

}  // namespace wrc
