// The requests of the call layer (wrc/api/calls.hpp): each reads its operation's keys over the defaults its structs
// hold and runs the engine, which validates (every solver calls its options' validate() first).
#include "wrc/api/calls.hpp"

#include "wrc/core/error.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/wheelset/plausibility.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::api {

void unknown_key_first(const OptionTable& table, const std::string& context, const OptionReader& partial,
                       const std::vector<OptionInfo>& documented) {
  OptionReader all(table, context);
  for (const OptionInfo& o : documented) all.value(std::string_view(o.key).substr(0, o.key.find('.')));  // "creepage"
  const auto unread = partial.rest();
  for (const auto& entry : table.entries)
    if (std::find(unread.begin(), unread.end(), &entry) == unread.end()) all.value(entry.first);
  all.finish();
}

void OnFailure::read(OptionReader& r) {
  returns = r.choice("on_failure", {"error", "return"},
                     {"-", "a failed solve: an error, or the result with converged = false (C: its status)"},
                     returns ? "return" : "error") == "return";
}

void ProgressAsked::read(OptionReader& r) {
  asked = r.boolean("progress", {"-", "draw a progress line on stderr (Lua: when stderr is a terminal; C: no)"});
}

// ---- contact, wheel, equilibrium ----

ContactCall ContactCall::read(OptionReader& r) {
  ContactCall c;
  c.pose = read_pose(r);
  c.request = read_contact_request(r);
  c.brute = r.choice("search", {"strategy", "brute"}, {"-", "locate with the strategy, or by brute force (checks)"},
                     c.brute ? "brute" : "strategy") == "brute";
  return c;
}

void ContactCall::validate() const { request.validate(); }

ContactResult ContactCall::run(const Wheelset& wheelset, ContactWorkspace& ws) const {
  const ContactModel& m = wheelset.contact_model();
  validate();
  if (!brute) return evaluate_contact(m, pose, ws, request);
  ContactWorkspace own(m, std::make_unique<NativeSearch>(NativePlan{false, NativePlan::Scan::test}));
  return evaluate_contact(m, pose, own, request);
}

WheelCall WheelCall::read(OptionReader& r) {
  WheelCall c;
  c.wheel = read_wheel_case(r);
  c.options = read_wheel_options(r);
  c.rolling = read_rolling_request(r);
  c.on_failure.read(r);
  return c;
}

void WheelCall::validate() const {
  wheel.validate("wheel");
  options.validate("wheel");
}

WheelResult WheelCall::run(const Wheelset& wheelset, ContactWorkspace& ws) const {
  validate();
  return solve_wheel(wheelset.contact_model(), wheel, ws, options, std::nullopt, rolling);
}

EquilibriumCall EquilibriumCall::read(OptionReader& r) {
  EquilibriumCall c;
  c.equilibrium = read_equilibrium_case(r);
  c.options = read_newton_options(r);
  if (auto s = r.table("start", {"-", "a start {z, roll} tried first"})) {
    Start st;
    st.z = s->need_number("z", {"m", "height of the wheelset centre to start from"});
    st.roll = s->number("roll", {"rad", "roll to start from"}, st.roll);
    s->finish();
    c.starts.push_back(st);
  }
  c.on_failure.read(r);
  c.request.keep_grids =
      r.boolean("grids", {"-", "keep the pressure and h grids in the result"}, c.request.keep_grids);
  return c;
}

void EquilibriumCall::validate() const {
  equilibrium.validate("equilibrium");
  options.validate("equilibrium");
  for (const Start& s : starts)
    if (!std::isfinite(s.z) || !std::isfinite(s.roll))
      fail("equilibrium: start = {{z = {} m, roll = {} rad}} must be finite", s.z, s.roll);
}

EquilibriumResult EquilibriumCall::run(const Wheelset& wheelset, ContactWorkspace& ws) const {
  validate();
  return solve_equilibrium(wheelset.contact_model(), equilibrium, ws, options, starts, request);
}

// ---- rigid, tables, conicity, flange measures ----

RigidCall RigidCall::read(OptionReader& r) {
  RigidCall c;
  c.y = r.need_number("y", {"m", "lateral position of the wheelset centre"});
  c.yaw = r.number("yaw", {"rad", "yaw angle of the wheelset"}, c.yaw);
  c.options = read_rigid_options(r, c.options);
  return c;
}

namespace {
// The rigid results' Hertz ellipses use the wheelset's material; their loads are checked as the elastic calls' are
// (plausibility.hpp; hertz_load = 100 meant kN gave p0 = 78 MPa).
RigidOptions with_material(RigidOptions o, const Wheelset& wheelset, std::string_view context) {
  o.material = wheelset.contact_model().material();
  if (wheelset.contact_model().options().check_magnitudes) {  // a load <= 0 is solve_rigid's error
    if (o.Q > 0) check_plausible(context, "Q", o.Q, kWheelsetLoad);
    if (o.hertz_load > 0) check_plausible(context, "hertz_load", o.hertz_load, kContactLoad);
  }
  return o;
}
}  // namespace

RigidResult RigidCall::run(const Wheelset& wheelset) const {
  return solve_rigid(wheelset.geometry(), y, yaw, with_material(options, wheelset, "rigid contact"));
}

GeometryTableCall GeometryTableCall::read(OptionReader& r) {
  GeometryTableCall c;
  c.options = read_geometry_table_options(r);
  c.progress.read(r);
  return c;
}

GeometryTable GeometryTableCall::run(const Wheelset& wheelset) const {
  GeometryTableOptions o = options;
  o.rigid = with_material(o.rigid, wheelset, "geometry table");
  return run_geometry_table(wheelset.geometry(), o);
}

WheelsetConicityCall WheelsetConicityCall::read(OptionReader& r) {
  WheelsetConicityCall c;
  c.options = read_wheelset_conicity_options(r);
  return c;
}

namespace {
// r0 and contact_distance only scale the wavelength, where nothing else would catch a radius in mm (450), given as the
// diameter (0.92) or a distance in mm (1500): the wavelength would look like one. 0 is the wheelset's (ws:conicity).
void check_wavelength_scales(const ConicityOptions& o, std::string_view context, std::string_view off) {
  if (o.r0 != 0) check_plausible(context, "r0", o.r0, kWheelRadius, off);
  if (o.contact_distance != 0) check_plausible(context, "contact_distance", o.contact_distance, kContactDistance, off);
}
}  // namespace

WheelsetConicity WheelsetConicityCall::run(const Wheelset& wheelset) const {
  if (wheelset.contact_model().options().check_magnitudes)
    check_wavelength_scales(options.conicity, "wheelset conicity", kUncheckedHint);
  return wheelset_conicity(wheelset.geometry(), options);
}

ConicityCall ConicityCall::read(OptionReader& table, OptionReader& options) {
  ConicityCall c;
  c.dr = read_delta_r(table);
  c.options = read_conicity_options(options, c.options);
  check_wavelength_scales(c.options, options.context(), "");  // no wheelset, no check_setup: always
  return c;
}

ConicityResult ConicityCall::run() const { return equivalent_conicity(dr, options); }

FlangeMeasuresCall FlangeMeasuresCall::read(OptionReader& r) {
  FlangeMeasuresCall c;
  c.tape_offset = r.number("tape_offset", {"m", "tape circle from the inner face of the wheel"}, c.tape_offset);
  return c;
}

FlangeMeasures FlangeMeasuresCall::run(const Profile& wheel) const { return flange_measures(wheel, tape_offset); }

// ---- trajectories ----

TrajectoryCall TrajectoryCall::read(OptionReader& r) { return {read_trajectory_options(r)}; }

std::unique_ptr<Trajectory> TrajectoryCall::run(std::shared_ptr<const Wheelset> wheelset) const {
  return std::make_unique<Trajectory>(std::move(wheelset), options);
}

TrajectoryContactCall TrajectoryContactCall::read(OptionReader& r) {
  TrajectoryContactCall c;
  c.pose = read_pose(r);
  c.rolling = read_rolling_request(r);
  c.sensitivity = read_sensitivity(r);
  return c;
}

ContactResult TrajectoryContactCall::run(Trajectory& trajectory) const {
  return trajectory.contact(pose, rolling, sensitivity);
}

TrajectoryWheelCall TrajectoryWheelCall::read(OptionReader& r) {
  TrajectoryWheelCall c;
  c.wheel = read_wheel_case(r);
  c.rolling = read_rolling_request(r);
  c.sensitivity = read_sensitivity(r);
  return c;
}

void TrajectoryWheelCall::validate() const { wheel.validate("wheel"); }

WheelResult TrajectoryWheelCall::run(Trajectory& trajectory) const {
  validate();
  return trajectory.wheel(wheel, rolling, sensitivity);
}

// ---- sweeps, strategy checks ----

SweepPlan read_sweep_plan(OptionReader& r) {
  const auto ys = r.number_list("y", {"m", "lateral positions (required): an array or {from, to, step}"});
  if (!ys && !r.documenting()) fail("{}: 'y' is required ({} or {})", r.context(), r.words().numbers, r.words().range);
  const std::vector<double> yaws =
      r.number_list("yaw", {"rad", "yaw angles: a number, an array or {from, to, step}"})
          .value_or(std::vector<double>{EquilibriumCase{}.yaw});
  const int chain = r.integer("chain", 0, 100000000, {"-", "reported cases per chunk at most (0: whole chains)"},
                              SweepOptions{}.chain);
  return plan_sweep(ys.value_or(std::vector<double>{0.0}), yaws, chain);
}

namespace {

// starts.contact = {start or false, ...}: per case, a wrc.ContactStart (a sweep result's contact_start) or none.
std::vector<std::shared_ptr<const ContactStart>> read_contact_starts(OptionReader& s, std::size_t cases) {
  std::vector<std::shared_ptr<const ContactStart>> out;
  const OptionValue* v = s.value("contact", "array", {"-", "per case: the contact_start of a sweep (contact_starts = "
                                 "true) whose pressures and tractions start its solves, or false: none"});
  if (!v || s.documenting()) return out;
  if (v->type != OptionValue::Type::array)
    fail("{}: starts.contact must hold one entry per start ({}), got {}", s.context(), cases, s.type_name(*v));
  if (v->array.size() != cases)
    fail("{}: starts.contact has {} entries, expected one per start ({})", s.context(), v->array.size(), cases);
  for (std::size_t k = 0; k < cases; ++k) {
    const OptionValue& e = v->array[k];
    if (e.type == OptionValue::Type::boolean && !e.boolean) {
      out.emplace_back();
    } else if (e.type == OptionValue::Type::object && e.string == ContactStart::kTypeName) {
      out.push_back(std::static_pointer_cast<const ContactStart>(e.object));
    } else {
      fail("{}: {} must be a {} or false, got {}", s.context(), value_at(k, "starts.contact"), ContactStart::kTypeName,
           s.type_name(e));
    }
  }
  return out;
}

// starts = {z = {...}, roll = {...}, contact = {...}}: per case of the plan, NaN in both z and roll for none
// (SweepOptions::starts, contact_starts).
void read_sweep_starts(OptionReader& r, SweepOptions& o) {
  auto s = r.table("starts", {"-", "per case of the plan (yaw major, then y): {z = {m, ...}, roll = {rad, ...}, "
                                   "contact = {...}} tried first; NaN in both z and roll: none"});
  if (!s) return;
  const auto z = s->numbers("z", {"m", "heights of the wheelset centre to start from"}, false);
  const auto roll = s->numbers("roll", {"rad", "rolls to start from"}, false);
  auto contact = read_contact_starts(*s, z ? z->size() : 0);
  s->finish();
  if (s->documenting()) return;
  if (!z || !roll || z->size() != roll->size())
    fail("{}: starts needs z and roll, arrays of the same length", r.context());
  for (std::size_t k = 0; k < z->size(); ++k) {
    const double zk = (*z)[k], rk = (*roll)[k];
    if (std::isnan(zk) != std::isnan(rk))
      fail("{}: {} and of starts.roll: z = {} m and roll = {} rad must both be NaN (none) or numbers", r.context(),
           value_at(k, "starts.z"), zk, rk);
    o.starts.push_back(std::isnan(zk) ? std::nullopt : std::optional<Start>(Start{zk, rk, std::nullopt, false}));
  }
  o.contact_starts = std::move(contact);
}

}  // namespace

SweepCall SweepCall::read(OptionReader& r) {
  SweepCall c;
  c.plan = read_sweep_plan(r);
  c.options = read_sweep_options(r);
  read_sweep_starts(r, c.options);
  c.options.keep_starts = r.boolean("contact_starts", {"-", "give each converged case its contact_start (its last "
                                    "pressures and tractions, to start it again: starts.contact)"},
                                    c.options.keep_starts);
  c.progress.read(r);
  if (const auto listed = r.numbers("chunks", {"-", "run these chunks alone (1-based, as ws:sweep_plan lists them)"})) {
    for (double k : *listed) {
      if (k != std::floor(k)) fail("{}: chunks must be whole numbers (1-based), got {}", r.context(), k);
      c.chunks.push_back(static_cast<int>(std::clamp(k, -1.0, 1e9)) - 1);
    }
  } else {
    for (std::size_t k = 0; k < c.plan.chunks.size(); ++k) c.chunks.push_back(static_cast<int>(k));
  }
  return c;
}

void SweepCall::validate() const { options.equilibrium.validate("sweep"); }

SweepResult SweepCall::run(const Wheelset& wheelset,
                           const std::function<std::unique_ptr<ContactWorkspace>()>& workspace) const {
  validate();
  return run_sweep(wheelset.contact_model(), plan, chunks, options, workspace);
}

// ---- subsurface stresses ----

SubsurfaceCall SubsurfaceCall::read(OptionReader& r) { return {halfspace::read_subsurface_request(r)}; }

halfspace::SubsurfaceResult SubsurfaceCall::run(const PatchLoad& load) const {
  halfspace::Material m;  // E does not enter the stresses (subsurface.hpp): the default's
  m.nu = load.nu;
  return halfspace::compute_subsurface(m, {load.grid, load.pressure, load.px, load.py}, request);
}

StrategyCheckCall StrategyCheckCall::read(OptionReader& r) {
  StrategyCheckCall c;
  c.options = read_strategy_check_options(r);
  c.progress.read(r);
  return c;
}

}  // namespace wrc::api
