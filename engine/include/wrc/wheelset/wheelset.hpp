// The wheelset model (docs/design.md, section 4): profiles placed on the track, discretised by a location
// strategy, with the material and the normal-contact options -- made once by build_wheelset and then shared,
// read-only, by every thread. Per-thread state lives in a ContactWorkspace (wheelset/contact.hpp) made by
// make_workspace(): the model/data split of MuJoCo.
//
// The operations are engine functions on the model (contact_model()): evaluate_contact (wheelset/contact.hpp),
// solve_wheel (equilibrium/wheel.hpp), solve_equilibrium (equilibrium/newton.hpp), run_sweep
// (equilibrium/equilibrium.hpp), solve_rigid (kinematics/rigid.hpp), and locate below.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/geometry/strategy.hpp"
#include "wrc/wheelset/contact.hpp"
#include "wrc/geometry/strategy_check.hpp"

#include <array>
#include <atomic>
#include <memory>
#include <optional>
#include <string>

namespace wrc {

// Every parameter of a wheelset with its default: the one definition of the defaults, used by wrc.wheelset{} in
// Lua, by the C API and by C++ callers.
struct WheelsetParams {
  TrackParams track;              // radius, back_to_back, tape_offset, gauge, gauge point, cant (geometry/track.hpp)
  halfspace::Material material;   // E, nu of both bodies (halfspace/material.hpp)
  ContactOptions contact;         // grid, margin, max_elements, tolerance, merging, solver, surface (contact.hpp)
  // The location strategy: "accurate" (the profiles every 0.1 mm along the arc, coarse pre-search, topology walk).
  // The constant-slope wheel of "fast" stripes the pressure of near-conformal contacts (S1002/60E1 at y = 0), and
  // the search is a small part of an evaluation beside the normal problems.
  std::string strategy = "accurate";
  // Random poses located with the strategy and with brute force when the wheelset is built (0: none): an error names
  // the first pose that differs (geometry/strategy_check.hpp; range |y| <= 10 mm, |yaw| <= 30 mrad, |roll| <= 10 mrad,
  // 1 um .. 1 mm deep). Opt-in: ~50 ms of brute force per pose at the paper's 0.1 mm discretisation.
  int check_strategy = 0;
  // The set-up's plausibility for a railway wheelset, checked when it is built (wheelset/plausibility.hpp: sizes and
  // shapes of the profiles for their kind, flanges against the gauge). false: for geometries that are no railway
  // wheel on a rail on purpose (a pin in a hole, a Hertz test body).
  bool check_setup = true;
};

// Reads wrc.wheelset{}'s keys over the defaults: radius, back_to_back, tape_offset, gauge, gauge_depth, cant, E,
// nu, grid, margin, max_elements, tolerance, merge_tolerance, merge_angle, solver ("fast" | "dense"), surface
// ("planar" | "conformal"), strategy (a name), check_strategy, check_setup. Range
// checks happen when the wheelset is built. Does not finish() the reader (the caller may read more keys).
WheelsetParams read_wheelset_params(OptionReader& options);
// The parameters as fields (wrc.defaults, ws.params).
void describe(const WheelsetParams& params, FieldSink& out);

// The four profiles, indexed by Side, each in its own left-side frame (the right side is mirrored when placed).
struct WheelsetProfiles {
  std::array<Profile, 2> wheel, rail;
};
// Reads them from `wheel` / `rail` (both sides) or `left_wheel`, `right_wheel`, `left_rail`, `right_rail`
// (objects of type kProfileTypeName).
WheelsetProfiles read_wheelset_profiles(OptionReader& options);
// Reads a pose {y, z, roll, yaw} (m, rad; each 0 when absent).
Pose read_pose(OptionReader& options);

class Wheelset {
 public:
  // `stop`: the front end's (Ctrl-C), for the strategy check of params.check_strategy (StrategyCheckOptions::stop).
  Wheelset(const WheelsetProfiles& profiles, const WheelsetParams& params,
           std::shared_ptr<const LocationStrategy> strategy, const std::atomic<bool>* stop = nullptr);
  const WheelsetParams& params() const { return params_; }
  const Track& track() const { return *track_; }
  const GeometryModel& geometry() const { return *geometry_; }
  const ContactModel& contact_model() const { return *contact_; }
  const std::shared_ptr<const GeometryModel>& geometry_ptr() const { return geometry_; }
  const std::shared_ptr<const ContactModel>& contact_model_ptr() const { return contact_; }
  const LocationStrategy& strategy() const { return *strategy_; }
  // The check of params.check_strategy, when it ran (it passed: a difference is an error of the constructor).
  const std::optional<StrategyCheckResult>& strategy_check() const { return strategy_check_; }
  // A workspace for the calling thread, with the strategy's search for that thread.
  std::unique_ptr<ContactWorkspace> make_workspace() const;
  // A workspace using `search` (not owned; it must outlive the workspace), e.g. a search bound to a Lua state.
  std::unique_ptr<ContactWorkspace> make_workspace_with(PoseSearch& search) const;

 private:
  WheelsetParams params_;
  std::shared_ptr<const LocationStrategy> strategy_;
  std::shared_ptr<const Track> track_;
  std::shared_ptr<const GeometryModel> geometry_;
  std::shared_ptr<const ContactModel> contact_;
  std::optional<StrategyCheckResult> strategy_check_;
};

// Places the profiles, discretises them with `strategy` and builds the contact model. Throws wrc::Error naming
// what is wrong (a parameter out of range, a profile of the wrong kind, profiles that do not meet, ...).
std::shared_ptr<const Wheelset> build_wheelset(const WheelsetProfiles& profiles, const WheelsetParams& params,
                                               std::shared_ptr<const LocationStrategy> strategy,
                                               const std::atomic<bool>* stop = nullptr);
// The same with the built-in strategy params.strategy names (native_strategy).
std::shared_ptr<const Wheelset> build_wheelset(const WheelsetProfiles& profiles, const WheelsetParams& params = {});

// The inter-penetration areas at a pose, as a value (ws:locate).
struct SideLocation {
  std::vector<Patch> patches;      // Patch::first_segment indexes `segments`
  std::vector<Segment> segments;
  SearchCounters counters;
  int grazes = 0;                  // graze crossings dropped (location.hpp)
};
struct LocateResult {
  Pose pose;
  std::array<SideLocation, 2> side;
};
// Locates with the workspace's search (or `search` when given, e.g. brute force for a check).
LocateResult locate(const Wheelset& wheelset, const Pose& pose, ContactWorkspace& workspace);
LocateResult locate_with(const Wheelset& wheelset, const Pose& pose, PoseSearch& search);
void describe(const LocateResult& result, FieldSink& out);
// One located patch (side, nominal point and normal, wheel point, cone, eps, ..., segments) and one segment.
void describe(const Patch& patch, const std::vector<Segment>& segments, FieldSink& out);
void describe(const Segment& segment, FieldSink& out);

}  // namespace wrc
