// One call layer for every front end (docs/design.md section 7): one request type per operation that Lua (ws:contact
// {...}), the C API (wrc_contact(...)) and later Python perform. A front end converts its arguments into an
// OptionTable (the C API puts the numbers it takes positionally -- y, z, Fz, ... -- into the table under the names
// Lua uses), reads the request from it (X::read: every key of the operation, with its unit and help), runs it and
// describes the result into its own FieldSink. A front end writes no default and no check of its own: the defaults are
// the options structs' members, the checks their validate() (which the engine's solvers call themselves). A request's
// validate() makes those checks (with the engine's messages) and its own; run() calls it first. A caller may call it
// alone, e.g. to check keyword arguments before a long call.
#pragma once

#include "wrc/core/error.hpp"
#include "wrc/core/options.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/equilibrium/trajectory.hpp"
#include "wrc/geometry/strategy_check.hpp"
#include "wrc/halfspace/subsurface.hpp"
#include "wrc/kinematics/conicity.hpp"
#include "wrc/kinematics/table.hpp"
#include "wrc/profile/measures.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wrc::api {

// Throws the "unknown key" error of `table`'s first key that is neither among `documented` (an operation's keys, as
// a documenting reader records them) nor read by `partial` (the reader that failed); returns when there is none.
void unknown_key_first(const OptionTable& table, const std::string& context, const OptionReader& partial,
                       const std::vector<OptionInfo>& documented);

// Reads request X from `table` (the reader's messages name `context`, e.g. "wrc_contact") and rejects keys it does
// not know. A misspelt key is reported before any other error of the reading: it is often the cause ('yaht' given,
// so 'yhat' is missing), and a message about the key it hid would not name it.
template <class X>
X read(const OptionTable& table, std::string context) {
  OptionReader r(table, context);
  try {
    X x = X::read(r);
    r.finish();
    return x;
  } catch (const Error&) {
    std::vector<OptionInfo> documented;
    OptionReader all = OptionReader::documenting(context, documented);
    X::read(all);
    unknown_key_first(table, context, r, documented);
    throw;
  }
}

// What a failed pose solve does: raise an error (Lua, Python) or give the result with converged = false. The C API
// reports it by its status (WRC_NOT_CONVERGED, with the result) and takes no on_failure.
struct OnFailure {
  bool returns = false;  // on_failure = "return"
  void read(OptionReader& r);
};

// ws:contact{...}, wrc_contact: the contact at a prescribed pose, frictionless or rolling.
struct ContactCall {
  Pose pose;
  ContactRequest request;  // grids, sensitivity, max_penetration, the rolling keys
  bool brute = false;      // search = "brute": every rail line against every cone (a check of the strategy)
  static ContactCall read(OptionReader& r);
  void validate() const;
  ContactResult run(const Wheelset& wheelset, ContactWorkspace& ws) const;
};

// ws:wheel{...}, wrc_wheel: one wheel with its vertical force prescribed.
struct WheelCall {
  WheelCase wheel;
  WheelOptions options;
  std::optional<RollingRequest> rolling;
  OnFailure on_failure;
  static WheelCall read(OptionReader& r);
  void validate() const;
  WheelResult run(const Wheelset& wheelset, ContactWorkspace& ws) const;
};

// ws:equilibrium{...}, wrc_equilibrium: the elastic equilibrium under the load Q.
struct EquilibriumCall {
  EquilibriumCase equilibrium;
  NewtonOptions options;
  std::vector<Start> starts;  // start = {z =, roll =}: tried first
  ContactRequest request;     // grids
  OnFailure on_failure;
  static EquilibriumCall read(OptionReader& r);
  void validate() const;  // also: a start's z and roll finite
  EquilibriumResult run(const Wheelset& wheelset, ContactWorkspace& ws) const;
};

// ws:rigid{...}, wrc_rigid_contact, wrc_rigid: the rigid contact at (y, yaw).
struct RigidCall {
  double y = 0, yaw = 0;  // m, rad
  RigidOptions options;
  static RigidCall read(OptionReader& r);
  RigidResult run(const Wheelset& wheelset) const;
};

// A long call's progress line on stderr: asked for (true, false) or left to the front end (Lua: when stderr is a
// terminal; C: none).
struct ProgressAsked {
  std::optional<bool> asked;
  void read(OptionReader& r);
  bool on(bool front_end_default) const { return asked.value_or(front_end_default); }
};

// ws:geometry_table{...}, wrc_geometry_table: the rigid contact over a range of y.
struct GeometryTableCall {
  GeometryTableOptions options;  // the front end sets options.progress and options.notice from `progress`
  ProgressAsked progress;
  static GeometryTableCall read(OptionReader& r);
  GeometryTable run(const Wheelset& wheelset) const;
};

// ws:conicity{...}, wrc_wheelset_conicity: the equivalent conicity from the wheelset's own Δr table.
struct WheelsetConicityCall {
  WheelsetConicityOptions options;
  static WheelsetConicityCall read(OptionReader& r);
  WheelsetConicity run(const Wheelset& wheelset) const;
};

// wrc.conicity(table, options), wrc_conicity: the equivalent conicity of a Δr table. Its keys are in two tables:
// the Δr table (y, dr, flange) and the options; read(r) reads both from one (the documentation's form).
struct ConicityCall {
  DeltaRFunction dr;
  ConicityOptions options;
  static ConicityCall read(OptionReader& table, OptionReader& options);
  static ConicityCall read(OptionReader& r) { return read(r, r); }
  ConicityResult run() const;
};

// p:flange_measures{...}, wrc_profile_flange_measures: EN 15313's Sh, Sd, qR.
struct FlangeMeasuresCall {
  double tape_offset = kTapeOffset;  // m
  static FlangeMeasuresCall read(OptionReader& r);
  FlangeMeasures run(const Profile& wheel) const;
};

// ws:trajectory{...}, wrc_trajectory_new: a trajectory's options.
struct TrajectoryCall {
  TrajectoryOptions options;
  static TrajectoryCall read(OptionReader& r);
  std::unique_ptr<Trajectory> run(std::shared_ptr<const Wheelset> wheelset) const;
};

// tr:contact{...}, wrc_trajectory_contact(_with): one step at a prescribed pose.
struct TrajectoryContactCall {
  Pose pose;
  std::optional<RollingRequest> rolling;
  bool sensitivity = false;  // each wheel's Jacobian (ContactRequest::sensitivity)
  static TrajectoryContactCall read(OptionReader& r);
  ContactResult run(Trajectory& trajectory) const;
};

// tr:wheel{...}, wrc_trajectory_wheel(_with): one step of a wheel with Fz given.
struct TrajectoryWheelCall {
  WheelCase wheel;
  std::optional<RollingRequest> rolling;
  bool sensitivity = false;  // the wheel's Jacobians (WheelOptions::sensitivity)
  static TrajectoryWheelCall read(OptionReader& r);
  void validate() const;
  WheelResult run(Trajectory& trajectory) const;
};

// ws:sweep{...}: equilibria over y (and yaw), chunks of them when asked.
struct SweepCall {
  SweepPlan plan;           // y (required), yaw, chain
  std::vector<int> chunks;  // 0-based; every chunk of the plan when not given (chunks = {k, ...} is 1-based)
  SweepOptions options;     // the front end sets options.progress, notice and single_thread
  ProgressAsked progress;
  static SweepCall read(OptionReader& r);
  void validate() const;
  SweepResult run(const Wheelset& wheelset, const std::function<std::unique_ptr<ContactWorkspace>()>& workspace) const;
};

// What the stresses below a contact area take from its result (the front end reads them from the area's fields:
// grid, pressure, px, py, nu): the grid (m), the pressure (Pa), the tractions on the wheel (Pa; empty: frictionless)
// and Poisson's ratio.
struct PatchLoad {
  halfspace::Grid grid;
  std::vector<double> pressure, px, py;
  double nu = 0;
};

// p:subsurface{...}, wrc_subsurface: the stresses below a contact area at the depths z (halfspace/subsurface.hpp:
// z, method, body, fields, shear_yield, shakedown_map).
struct SubsurfaceCall {
  halfspace::SubsurfaceRequest request;
  static SubsurfaceCall read(OptionReader& r);
  // Throws wrc::Error naming what is wrong (an invalid load or request: compute_subsurface).
  halfspace::SubsurfaceResult run(const PatchLoad& load) const;
};

// The cases of ws:sweep and ws:sweep_plan: y (required), yaw (default 0), chain.
SweepPlan read_sweep_plan(OptionReader& r);

// ws:check_strategy{...}: the strategy against brute force on random poses.
struct StrategyCheckCall {
  StrategyCheckOptions options;  // the front end sets options.progress
  ProgressAsked progress;
  static StrategyCheckCall read(OptionReader& r);
};

}  // namespace wrc::api
