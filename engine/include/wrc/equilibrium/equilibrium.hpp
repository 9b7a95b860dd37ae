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

#include "wrc/core/options.hpp"
#include "wrc/core/parallel.hpp"
#include "wrc/kinematics/rigid.hpp"
#include "wrc/wheelset/contact.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace wrc {

struct EquilibriumOptions {
  double force_tolerance = 1e-6;   // |sum Fz - Q| <= force_tolerance * Q
  double moment_tolerance = 1e-6;  // |sum Mx| <= moment_tolerance * Q * 1 m
  int max_iterations = 50;
  int max_evaluations = 400;       // contact evaluations per solve (all attempts), then it gives up
  double max_step_z = 0.5e-3;      // largest Newton step in z (m)
  double max_step_roll = 2e-3;     // largest Newton step in roll (rad)
  double initial_approach = 0.05e-3;  // cold start: the rigid position pressed in by this much (m)
  // solve_wheel's cold start for Fz = 100 kN (m below the touching height), scaled as Fz^(2/3) (Hertz): a little
  // deeper than a tread contact's approach (S1002/60E1: 75-115 um on the tread, 150 um at the flange root), so that
  // the first prediction's grid, which covers the rigid overlap at this approach, holds most of the contact.
  double wheel_approach = 0.08e-3;
  // An iterate whose contacts are deeper than this (m) and still carry less than the load ends the solve at once: the
  // load is out of reach; a solution deeper than this is not converged (the reason says why). The default and why:
  // kMaxPenetration (wheelset/contact.hpp). The iterates themselves may pass deeper (a Newton step overshooting).
  double max_penetration = kMaxPenetration;
  // Tolerance of the normal problems while Newton iterates (inexact steps, from warm starts: a few CG iterations
  // each); a solution found so is confirmed by an evaluation at the model's tolerance, and Newton goes on from it
  // if the residuals moved out of tolerance, so the forces reported are those evaluate_contact gives at the pose.
  double normal_tolerance = 1e-6;
  // solve_wheel: evaluate the solved pose once more at the model's own tolerance (the forces ws:contact gives
  // there); a trajectory, content with normal_tolerance, turns it off.
  bool final_at_model_tolerance = true;
  // Called at every iterate (iteration, z, roll, contact), e.g. to print the Newton history.
  std::function<void(int, double, double, const ContactResult&)> trace;
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
// bad input (non-finite y or yaw, Q <= 0).
EquilibriumResult solve_equilibrium(const ContactModel& model, double y, double yaw, double Q, ContactWorkspace& ws,
                                    const EquilibriumOptions& options = {}, const std::vector<Start>& starts = {},
                                    const ContactRequest& request = {});

// One wheel-rail pair with its vertical force prescribed (CONTACT / multibody style): the wheelset height z
// that makes that wheel's vertical contact force equal Fz at the given y, yaw and roll. With `rolling`, the
// tangential problems are solved too and Fz includes the creep forces' vertical part (the frictionless height
// starts the iteration).
struct WheelResult {
  bool converged = false;
  std::string message;
  int side = kLeft;
  double Fz = 0;             // the prescribed vertical force (N)
  double z = 0;              // solved height of the wheelset centre (m)
  double approach = 0;       // how far that is below the height at which the wheel just touches its rail (m)
  double residual = 0;       // Fz(side) - Fz (N)
  int iterations = 0;        // contact evaluations
  WheelContact wheel;        // the side's contact
};
// `start`: an approach to start from (m below the touching height; e.g. the previous time step's, which follows the
// load where the height does not); otherwise options.wheel_approach scaled to Fz. The approach is predicted by the
// wheel's normal problem solved for Fz itself (ContactRequest::vertical_force), twice from afar (the first only
// estimated on the coarse grid) and once from a close start, then confirmed (and corrected by secant steps) by
// evaluations of the pose; the result is always such an evaluation, at the model's normal tolerance. A load that the
// wheel does not carry at an approach of options.max_penetration is out of reach: not converged, with the reason.
WheelResult solve_wheel(const ContactModel& model, int side, double y, double yaw, double roll, double Fz,
                        ContactWorkspace& ws, const EquilibriumOptions& options = {},
                        std::optional<double> start = std::nullopt,
                        const std::optional<RollingRequest>& rolling = std::nullopt);

// A sweep of equilibria: for each yaw, y runs over `ys` with continuation, starting at the y closest to 0
// and marching outward on both sides. The cases are cut into chunks (plan_sweep), each solved on its own from a
// cold start, so that a case's result depends on the plan alone, never on which thread, process or machine ran
// which chunk: 1, 2 or 8 threads, or a study split into shards, give the same numbers bit for bit. Chunks run on
// `threads` worker threads (each with its own ContactWorkspace, made by `make_workspace`). A failed case is
// recorded and its chain goes on from the last converged point.
struct SweepCase {
  double y = 0, yaw = 0;
};
// A chunk solves `solve` in order: solve[0] from a cold start (no neighbour, an empty workspace), each next case by
// continuation from the previous converged ones. It reports `report` (sorted case indices); solve[0] may be the
// centre of a series that another chunk reports (the chain below the centre starts from its solution).
struct SweepChunk {
  std::vector<int> solve;
  std::vector<int> report;
};
// For each yaw (sorted by y): the case nearest y = 0 is the centre; the chain above it (centre included) and the
// chain below it (started from the centre, which it does not report) are chunks, each cut into pieces of at most
// `chain` reported cases (0: uncut), every piece after the first starting cold at its first case. Chunks are
// ordered by their first reported case; with ys sorted, each reports a contiguous range of cases.
struct SweepPlan {
  std::vector<SweepCase> cases;  // yaw major, then y as given
  std::vector<SweepChunk> chunks;
};
SweepPlan plan_sweep(const std::vector<double>& ys, const std::vector<double>& yaws, int chain = 0);

struct SweepOptions {
  int threads = 0;             // 0: the cores this process may use (available_cores)
  double Q = 200e3;            // N
  bool keep_grids = false;     // keep pressure/h grids of every case (memory)
  bool rigid = false;          // also solve the rigid reference of each case
  int chain = 0;               // reported cases per chunk at most (0: whole continuation chains); see SweepPlan
  EquilibriumOptions equilibrium;
  // With kinematics or creepages: the tangential problems of every converged case at its equilibrium pose (the
  // equilibrium itself stays frictionless); the creep forces join the wheels' forces, Y, My, Mz do not.
  std::optional<RollingRequest> rolling;
  // Called from the workers (serialised) after each reported case: cases done, cases in all, failed so far.
  Progress progress;
  // Why the sweep must run on the calling thread alone ("": it need not), e.g. a strategy bound to one Lua state.
  std::string single_thread;
  // Called once (on the calling thread) when fewer threads run than `threads` asked for, with the reason.
  std::function<void(const std::string&)> notice;
};
struct SweepResult {
  std::vector<int> index;                   // the plan's case index of each entry (ascending)
  std::vector<SweepCase> cases;             // in the order of the plan (yaw major, then y as given)
  std::vector<EquilibriumResult> elastic;   // one per case
  std::vector<std::optional<RigidResult>> rigid;
  std::vector<std::string> errors;          // per case: exception text if the case threw, else empty
  double seconds = 0;
  int threads = 1;            // worker threads used
  std::string threads_note;   // why fewer than SweepOptions::threads (when given) ran; "" otherwise
};
// All the cases of the plan_sweep(ys, yaws, options.chain).
SweepResult run_sweep(const ContactModel& model, const std::vector<double>& ys, const std::vector<double>& yaws,
                      const SweepOptions& options,
                      const std::function<std::unique_ptr<ContactWorkspace>()>& make_workspace);
// The cases reported by the chunks `chunks` (indices into plan.chunks) alone: a part of a study.
SweepResult run_sweep(const ContactModel& model, const SweepPlan& plan, const std::vector<int>& chunks,
                      const SweepOptions& options,
                      const std::function<std::unique_ptr<ContactWorkspace>()>& make_workspace);

// Options as Lua and the C API give them: force_tolerance, moment_tolerance, max_iterations, max_evaluations,
// max_penetration, trace (true: print the Newton iterates to stderr).
EquilibriumOptions read_equilibrium_options(OptionReader& options);
// A sweep's options: Q (required), threads (0: all cores), rigid, grids, chain, the equilibrium options above, and
// the rolling keys (read_rolling_request). `progress` and `notice` are left to the front end: a reader prints nothing.
SweepOptions read_sweep_options(OptionReader& options);
// Why a solve did not converge, with its last iterate (the error of a Lua call that does not return failures).
std::string failure_message(const EquilibriumResult& result);
std::string failure_message(const WheelResult& result);

// The results as fields (Lua tables, C API paths; docs/guide/equilibrium.md "Lua API"). An equilibrium: converged,
// error, flange_climb (and flange_climb_reason when true), y, yaw, Q, z, roll, Y, My, Mz, Y_Q, iterations,
// evaluations, residual = {force, moment}, left, right (as wheelset/contact.hpp describes a wheel),
// rolling_radius_difference (left - right; only when both wheels carry load), force, moment. A wheel: the side's
// wheel fields, converged, error, z, residual, iterations. (A rigid case: kinematics/rigid.hpp.)
void describe(const EquilibriumResult& result, FieldSink& out);
void describe(const WheelResult& result, FieldSink& out);
// Entry i of a sweep: `case` (its 1-based index in the plan), its equilibrium, and `rigid` (a rigid case) when the
// sweep solved it.
void describe_case(const SweepResult& sweep, std::size_t i, FieldSink& out);

}  // namespace wrc
