// Static, frictionless wheelset on the track (paper section 4, docs/design.md section 3).
//
// Elastic equilibrium: lateral position y, yaw and the vertical load Q at the centre are given; the height z
// and the roll are solved (Newton-Raphson) so that the contact forces carry Q and have no moment about x:
//   sum Fz - Q = 0,   sum Mx = 0   (moments about the wheelset centre, track axes).
// The lateral force Y and the moments My, Mz that an external support must apply at the centre to hold the
// wheelset there are reported: Y = -sum Fy, My = -sum My, Mz = -sum Mz.
//
// The Jacobian comes from the sensitivities of the normal problems (wheelset/contact.hpp): each area's
// pressure response to the rigid motion of the wheel surface, on its contact set (forward differences while a
// wheel is lifted), and is corrected by Broyden updates between steps. Steps are limited and backtracked on the
// residual norm (|R_F|/Q)^2 + (|R_M|/(Q 1 m))^2.
//
// Rigid reference: the same (y, yaw) with undeformable bodies: z and roll such that both wheels just touch
// (kinematic constraint), the contact points where they touch, and the normal forces and Y that balance Q
// (solve_rigid, wrc/kinematics/rigid.hpp).
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/equilibrium/limits.hpp"
#include "wrc/kinematics/rigid.hpp"
#include "wrc/wheelset/contact.hpp"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc {

// What an equilibrium is asked for.
struct EquilibriumCase {
  double y = 0;    // lateral position of the centre (m), within +-kMaxLateral (geometry/pose.hpp)
  double yaw = 0;  // rad, within +-kMaxYaw
  double Q = 0;    // vertical load at the centre (N), in ]0, kMaxLoad]
  // Throws wrc::Error "<context>: <key> = <value> <unit> must be ..." for the first value out of its range;
  // `plausible`: also for a Q no railway wheelset carries (kWheelsetLoad, wheelset/plausibility.hpp).
  void validate(std::string_view context, bool plausible = false) const;
};

// The Newton solver's settings.
struct NewtonOptions {
  SolveLimits limits;              // force_tolerance (of Q), iterations, evaluations, max_penetration, normal_tolerance
  double moment_tolerance = 1e-6;  // |sum Mx| <= moment_tolerance * Q * 1 m; in ]0, 0.1]
  double max_step_z = 0.5e-3;      // largest Newton step in z (m), in ]0, 0.01]
  double max_step_roll = 2e-3;     // largest Newton step in roll (rad), in ]0, 0.1]
  double initial_approach = 0.05e-3;  // cold start: the rigid position pressed in by this much (m), in [0, 0.01]
  // Called at every iterate (iteration, z, roll, contact), e.g. to print the Newton history.
  std::function<void(int, double, double, const ContactResult&)> trace;
  // Throws wrc::Error naming the first member out of its range (its key, value, unit and range).
  void validate(std::string_view context) const;
};

struct EquilibriumResult {
  bool converged = false;
  std::string message;       // why it did not converge (empty when it did)
  double y = 0, yaw = 0, Q = 0;
  double z = 0, roll = 0;    // solution (or last iterate) (m, rad)
  double Y = 0, My = 0, Mz = 0;  // balancing lateral force (N) and moments (N m) at the centre
  double residual_force = 0;     // sum Fz - Q (N)
  double residual_moment = 0;    // sum Mx (N m)
  int iterations = 0;            // Newton iterations
  int evaluations = 0;           // contact evaluations (including line-search trials)
  int jacobians = 0;             // Jacobians computed (the others were reused)
  // The last Jacobian d(sum Fz - Q, sum Mx)/d(z, roll) (Broyden-updated), and whether it belongs to a wheel lifted:
  // a start for a neighbouring case (a sweep hands it on).
  std::optional<Eigen::Matrix2d> jacobian;
  bool jacobian_lifted = false;
  ContactResult contact;         // at the solution
  // "<side> wheel: why" when a wheel is past flange climb (contact beyond the steepest part of its flange, Nadal's
  // limit exceeded, or lifted off its rail by more than its flange height; wheelset/plausibility.hpp); "" if not.
  std::string flange_climb;
};

// A start (z, roll), e.g. the previous point of a sweep.
struct Start {
  double z = 0, roll = 0;
  // d(sum Fz, sum Mx)/d(z, roll) near the start (e.g. the previous case's), used while the start has a wheel
  // lifted or not as it had (jacobian_lifted), and while it serves.
  std::optional<Eigen::Matrix2d> jacobian;
  bool jacobian_lifted = false;
};

// Solves the elastic equilibrium (frictionless: request.rolling is ignored; add_rolling gives the creep forces at the
// solution's pose). Tries Newton from each of `starts` in order (neighbouring solutions of a
// sweep), then from the rigid position pressed in by initial_approach, then by continuation in y from the
// centred wheelset, then by nested bracketing. Never throws for lack of convergence: `converged` is false and
// `message` says why each attempt stopped, with the last iterate in z, roll and contact. Throws wrc::Error on
// bad input (the case's and the options' validate(), first).
EquilibriumResult solve_equilibrium(const ContactModel& model, const EquilibriumCase& c, ContactWorkspace& ws,
                                    const NewtonOptions& options = {}, const std::vector<Start>& starts = {},
                                    const ContactRequest& request = {});

// Reads y (required), yaw (default 0) and Q (required) of ws:equilibrium{} into a case (validated by the solver).
EquilibriumCase read_equilibrium_case(OptionReader& options);
// The Newton options as Lua and the C API give them: force_tolerance, max_iterations, max_evaluations,
// max_penetration (read_solve_limits), moment_tolerance, trace (true: print the Newton iterates to stderr); validated.
NewtonOptions read_newton_options(OptionReader& options);
// Why a solve did not converge, with its last iterate (the error of a Lua call that does not return failures).
std::string failure_message(const EquilibriumResult& result);

// The result as fields (Lua tables, C API paths; docs/guide/equilibrium.md): converged, error, flange_climb (and
// flange_climb_reason when true), y, yaw, Q, z, roll, Y, My, Mz, Y_Q, iterations, evaluations, residual = {force,
// moment}, left, right (as wheelset/contact.hpp describes a wheel), rolling_radius_difference (left - right; only when
// both wheels carry load), force, moment.
void describe(const EquilibriumResult& result, FieldSink& out);

}  // namespace wrc
