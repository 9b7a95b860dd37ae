// The equilibrium area (docs/design.md section 3): the Newton solve of a case (newton.hpp), one wheel with its vertical
// force given (wheel.hpp), the limits both share (limits.hpp), and sweeps of equilibria (below); the rigid reference
// they start from: kinematics/rigid.hpp. Trajectories: trajectory.hpp.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/core/parallel.hpp"
#include "wrc/equilibrium/newton.hpp"
#include "wrc/equilibrium/wheel.hpp"
#include "wrc/kinematics/rigid.hpp"
#include "wrc/wheelset/contact.hpp"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wrc {

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
  bool keep_rows = false;      // without the grids: keep each area's per-row results (wear_passage) all the same
  bool rigid = false;          // also solve the rigid reference of each case
  int chain = 0;               // reported cases per chunk at most (0: whole continuation chains); see SweepPlan
  NewtonOptions equilibrium;   // of every case
  // With kinematics or creepages: the tangential problems of every converged case at its equilibrium pose (the
  // equilibrium itself stays frictionless); the creep forces join the wheels' forces, Y, My, Mz do not.
  std::optional<RollingRequest> rolling;
  // Called from the workers (serialised) after each reported case: cases done, cases in all, failed so far.
  Progress progress;
  // Per case of the plan (yaw major, then y as given; empty: none), a start tried before the chain's: e.g. the case's
  // own equilibrium on profiles worn a little less (a wear loop). A chunk's first case then needs no cold start.
  // The chain's last Jacobian goes with it. Results depend on the plan and these starts, never on the threads.
  std::vector<std::optional<Start>> starts;
  // Per case of the plan (empty, or null entries: none): the normal pressures and (with `rolling`) exact tangential
  // solutions the case's solves start from (e.g. its own on profiles worn a little less) instead of the chain's
  // previous case's. A start changes a result only within the solvers' tolerances.
  std::vector<std::shared_ptr<const ContactStart>> contact_starts;
  // Keep each converged case's ContactStart (SweepResult::contact_starts), to start a later sweep's.
  bool keep_starts = false;
  // Why the sweep must run on the calling thread alone ("": it need not), e.g. a strategy bound to one Lua state.
  std::string single_thread;
  // Called once (on the calling thread) when fewer threads run than `threads` asked for, with the reason.
  std::function<void(const std::string&)> notice;
  // The front end's stop (Ctrl-C): once it turns true no case begins (those being solved finish) and run_sweep
  // throws wrc::Error saying how many cases were solved, so that no partial sweep is taken for a whole one.
  const std::atomic<bool>* stop = nullptr;
};
struct SweepResult {
  std::vector<int> index;                   // the plan's case index of each entry (ascending)
  std::vector<SweepCase> cases;             // in the order of the plan (yaw major, then y as given)
  std::vector<EquilibriumResult> elastic;   // one per case
  std::vector<std::optional<RigidResult>> rigid;
  std::vector<std::string> errors;          // per case: exception text if the case threw, else empty
  // Per case with SweepOptions::keep_starts (else empty): what its solves leave to start a later one (null: failed).
  std::vector<std::shared_ptr<const ContactStart>> contact_starts;
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

// A sweep's options: Q (required), threads (0: all cores), rigid, grids, chain, the Newton options
// (read_newton_options), and the rolling keys (read_rolling_request). `progress` and `notice` are left to the front
// end: a reader prints nothing.
SweepOptions read_sweep_options(OptionReader& options);

// Entry i of a sweep: `case` (its 1-based index in the plan), its equilibrium, and `rigid` (a rigid case) when the
// sweep solved it.
void describe_case(const SweepResult& sweep, std::size_t i, FieldSink& out);

}  // namespace wrc
