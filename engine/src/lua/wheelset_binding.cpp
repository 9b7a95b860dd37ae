// wrc.wheelset{...} and the methods of wrc.Wheelset (docs/reference/lua-api.md): each converts its arguments into
// engine options, calls the engine (wheelset/, equilibrium/) and pushes the result the engine describes.
#include "lua/wheelset_binding.hpp"

#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/results_binding.hpp"
#include "wrc/api/calls.hpp"
#include "wrc/host/terminal.hpp"

#include <algorithm>
#include <cmath>
#include <future>

namespace wrc::lua {

const char* const kWheelsetType = "wrc.Wheelset";

namespace {

LuaWheelset& self(lua_State* L, const char* ctx) { return *check_shared<LuaWheelset>(L, 1, kWheelsetType, ctx); }

// The workspace of calls from the building state, its search bound to the calling coroutine. Every call starts
// cold (forget), so that its result does not depend on earlier calls.
ContactWorkspace& workspace(lua_State* L, LuaWheelset& w) {
  PoseSearch& main = w.strategy->main_search(L);
  if (!w.workspace) w.workspace = w.model->make_workspace_with(main);
  w.workspace->forget();
  return *w.workspace;
}

// Shows on stderr a result's contact area that spans too few elements for its peak pressure (a coarse grid gives a
// plausible-looking pmax; wheelset/contact.hpp, kMinSpan), once per wheelset: each patch's `resolved` says it every
// time. `where` names the case of a sweep.
template <class Result>  // ContactResult, WheelContact
void show_resolution(bool& shown, const char* ctx, const Result& r, const std::string& where = "") {
  if (shown) return;
  const std::string note = resolution_note(r);
  if (note.empty()) return;
  shown = true;
  host::note_printer(fmt::format("{}: warning", ctx))(
      fmt::format("{}{} (shown once per wheelset; each area's `resolved` says it)", where, note));
}

// The options table of a method (argument 2) and its reader; the reader's keys are checked by finish().
struct MethodArgs {
  OptionTable table;
  OptionReader reader;
  MethodArgs(lua_State* L, const char* ctx) : table(table_options(L, 2, ctx)), reader(table, ctx) {}
};

// The request of a method from its options table (argument 2); unknown keys are errors.
template <class X>
X read_call(lua_State* L, const char* ctx) {
  return api::read<X>(table_options(L, 2, ctx), ctx);
}

int wheelset_new(lua_State* L) {
  const char* ctx = "wrc.wheelset";
  const OptionTable t = table_options(L, 1, ctx, {"strategy"});
  OptionReader r(t, ctx);
  r.allow({"strategy", "wheel", "rail", "left_wheel", "right_wheel", "left_rail", "right_rail"});
  const WheelsetParams params = read_wheelset_params(r);
  r.finish();  // a misspelt key first: it may be why a profile seems missing
  const WheelsetProfiles profiles = read_wheelset_profiles(r);
  lua_getfield(L, 1, "strategy");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_pushstring(L, params.strategy.c_str());  // the one default (WheelsetParams)
  }
  auto ws = std::make_shared<LuaWheelset>();
  ws->strategy = std::make_shared<LuaStrategy>(L, -1, params.contact.element);
  lua_pop(L, 1);
  ws->model = build_wheelset(profiles, params, ws->strategy);
  push_shared(L, std::move(ws), kWheelsetType);
  return 1;
}

// ws:locate{y=, z=, roll=, yaw=, search = "strategy" | "brute"}: the inter-penetration areas alone.
int wheelset_locate(lua_State* L) {
  const char* ctx = "wheelset:locate";
  LuaWheelset& w = self(L, ctx);
  MethodArgs a(L, ctx);
  const Pose pose = read_pose(a.reader);
  const bool brute = a.reader.choice("search", {"strategy", "brute"}).value_or("strategy") == "brute";
  a.reader.finish();
  NativeSearch brute_force({false, NativePlan::Scan::test});  // every line against every cone of the model
  const LocateResult r = brute ? locate_with(*w.model, pose, brute_force) : locate(*w.model, pose, workspace(L, w));
  for (int s : {kLeft, kRight}) w.last_tests[s] = r.side[s].counters.tests;
  push_result(L, r);
  return 1;
}

// ws:contact{y=, z=, roll=, yaw=, grids, sensitivity, max_penetration, search = "strategy" | "brute", and the rolling
// keys} (api::ContactCall)
int wheelset_contact(lua_State* L) {
  const char* ctx = "wheelset:contact";
  LuaWheelset& w = self(L, ctx);
  const auto call = read_call<api::ContactCall>(L, ctx);
  const ContactResult r = call.run(*w.model, workspace(L, w));
  show_resolution(*w.resolution_shown, ctx, r);
  push_result(L, r, call.request.sensitivity);
  return 1;
}

// ws:equilibrium{y=, yaw=, Q=, start = {z=, roll=}, grids, trace, on_failure, tolerances, ...} (api::EquilibriumCall)
int wheelset_equilibrium(lua_State* L) {
  const char* ctx = "wheelset:equilibrium";
  LuaWheelset& w = self(L, ctx);
  const auto call = read_call<api::EquilibriumCall>(L, ctx);
  const EquilibriumResult e = call.run(*w.model, workspace(L, w));
  if (!e.converged && !call.on_failure.returns)
    fail("{}: {} (on_failure = \"return\" gives the result)", ctx, failure_message(e));
  show_resolution(*w.resolution_shown, ctx, e.contact);
  push_result(L, e);
  return 1;
}

// ws:wheel{side=, y=, yaw=, roll=, Fz=, on_failure, limits, rolling keys}: one wheel-rail pair, vertical force
// prescribed (api::WheelCall).
int wheelset_wheel(lua_State* L) {
  const char* ctx = "wheelset:wheel";
  LuaWheelset& w = self(L, ctx);
  const auto call = read_call<api::WheelCall>(L, ctx);
  const WheelResult r = call.run(*w.model, workspace(L, w));
  if (!r.converged && !call.on_failure.returns) fail("{}: {}", ctx, failure_message(r));
  show_resolution(*w.resolution_shown, ctx, r.wheel);
  push_result(L, r);
  return 1;
}

// ws:rigid{y=, yaw=, roll = "free" | "fixed" | number, Q=, two_point_tolerance=, start=}: the rigid contact.
int wheelset_rigid(lua_State* L) {
  const char* ctx = "wheelset:rigid";
  LuaWheelset& w = self(L, ctx);
  push_result(L, read_call<api::RigidCall>(L, ctx).run(*w.model));
  return 1;
}

// ws:geometry_table{y = {from=, to=, step=}, yaw=, roll=, threads=, csv=, file=, progress=, ...}
int wheelset_geometry_table(lua_State* L) {
  const char* ctx = "wheelset:geometry_table";
  LuaWheelset& w = self(L, ctx);
  auto call = read_call<api::GeometryTableCall>(L, ctx);
  if (call.progress.on(host::stderr_is_terminal())) call.options.progress = host::progress_line("geometry table", "rows");
  call.options.notice = host::note_printer("geometry table");
  push_result(L, call.run(*w.model));
  return 1;
}

// ws:conicity{yhat=, roll = "fixed" | "free", method=, ...} -> {tan gamma_e per amplitude}, details
int wheelset_conicity(lua_State* L) {
  const char* ctx = "wheelset:conicity";
  LuaWheelset& w = self(L, ctx);
  const WheelsetConicity c = read_call<api::WheelsetConicityCall>(L, ctx).run(*w.model);
  push_array(L, c.conicity.tan_gamma);
  push_result(L, c);
  return 2;
}

// The table ws:sweep gives: one row per case (with its contact_start when asked for), then seconds, threads,
// threads_note, failed.
void push_sweep(lua_State* L, const SweepResult& r, bool& resolution_shown, const char* ctx) {
  for (std::size_t i = 0; i < r.cases.size() && !resolution_shown; ++i)
    show_resolution(resolution_shown, ctx, r.elastic[i].contact,
                    fmt::format("at y = {:.4f} mm, yaw = {:.4g} rad: ", r.cases[i].y * 1e3, r.cases[i].yaw));
  int failed = 0;
  lua_createtable(L, static_cast<int>(r.cases.size()), 3);
  for (std::size_t i = 0; i < r.cases.size(); ++i) {
    FieldRecorder row;
    describe_case(r, i, row);
    FieldRecord record = row.take();
    push_fields(L, record);
    if (i < r.contact_starts.size() && r.contact_starts[i]) {  // with contact_starts = true
      push_shared(L, r.contact_starts[i], ContactStart::kTypeName);
      lua_setfield(L, -2, "contact_start");
    }
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    if (!r.elastic[i].converged) ++failed;
  }
  set_number(L, "seconds", r.seconds);
  set_integer(L, "threads", r.threads);
  if (!r.threads_note.empty()) set_string(L, "threads_note", r.threads_note.c_str());
  set_integer(L, "failed", failed);
}

// Why a sweep with an inline Lua strategy runs on the calling thread alone (ws:sweep, ws:sweep_start).
constexpr const char* kInlineStrategy = "the strategy is an inline Lua table, which runs only in the calling Lua state";

// The sweep call of ws:sweep and ws:sweep_start, with its progress line and notices.
api::SweepCall read_sweep_call(lua_State* L, const char* ctx) {
  auto call = read_call<api::SweepCall>(L, ctx);
  SweepOptions& so = call.options;
  if (call.progress.on(host::stderr_is_terminal())) so.progress = host::progress_line("sweep", "cases");
  so.notice = host::note_printer("sweep");
  return call;
}

// ws:sweep{y = {...} | {from=, to=, step=}, yaw = ..., Q=, threads=, rigid=, grids=, chain=, chunks=, progress=,
// starts=, contact_starts=, tolerances}: chunks = {k, ...} (1-based, as ws:sweep_plan lists them) runs those chunks
// alone; contact_starts = true gives each converged case its contact_start (a wrc.ContactStart, for starts.contact).
int wheelset_sweep(lua_State* L) {
  const char* ctx = "wheelset:sweep";
  LuaWheelset& w = self(L, ctx);
  auto call = read_sweep_call(L, ctx);
  SweepOptions& so = call.options;
  // An inline Lua strategy runs only in this state: one thread, this state's search.
  const bool portable = w.model->strategy().info().portable;
  if (!portable) so.single_thread = kInlineStrategy;
  const SweepResult r = call.run(*w.model, [&]() -> std::unique_ptr<ContactWorkspace> {
    if (!portable || so.threads == 1) return w.model->make_workspace_with(w.strategy->main_search(L));
    return w.model->make_workspace();  // a worker's own Lua state
  });
  push_sweep(L, r, *w.resolution_shown, ctx);
  return 1;
}

// A sweep running on threads of its own (ws:sweep_start) while the script goes on; job:wait() gives its table.
// It holds the model; a job collected unfinished is waited for (std::async's future).
struct SweepJob {
  static constexpr const char* kTypeName = "wrc.SweepJob";
  std::shared_ptr<const Wheelset> model;
  std::shared_ptr<bool> resolution_shown;  // the wheelset's
  std::future<SweepResult> result;
  bool taken = false;
};

// ws:sweep_start{the keys of ws:sweep} -> job; job:wait() -> what ws:sweep gives (the same bits: no case depends on
// the thread that solves it), or the sweep's error. The calling state goes on meanwhile (other calls, other jobs).
// With an inline Lua strategy, which runs only in the calling state, the sweep runs here, before the job returns.
int wheelset_sweep_start(lua_State* L) {
  const char* ctx = "wheelset:sweep_start";
  LuaWheelset& w = self(L, ctx);
  auto call = read_sweep_call(L, ctx);
  call.validate();  // the errors of the keys here; the cases' own go into the rows
  auto job = std::make_shared<SweepJob>();
  job->model = w.model;
  job->resolution_shown = w.resolution_shown;
  if (!w.model->strategy().info().portable) {
    call.options.single_thread = kInlineStrategy;
    std::promise<SweepResult> done;
    done.set_value(call.run(*w.model, [&] { return w.model->make_workspace_with(w.strategy->main_search(L)); }));
    job->result = done.get_future();
  } else {
    job->result = std::async(std::launch::async, [call = std::move(call), model = w.model] {
      return call.run(*model, [&] { return model->make_workspace(); });  // each worker's own Lua state
    });
  }
  push_shared(L, std::move(job), SweepJob::kTypeName);
  return 1;
}

int sweep_job_wait(lua_State* L) {
  const char* ctx = "SweepJob:wait";
  SweepJob& job = *check_shared<SweepJob>(L, 1, SweepJob::kTypeName, ctx);
  if (job.taken) fail("{}: the job's result was taken by an earlier wait (it gives it once)", ctx);
  job.taken = true;
  push_sweep(L, job.result.get(), *job.resolution_shown, ctx);  // rethrows the sweep's error
  return 1;
}

// ws:sweep_plan{y =, yaw =, chain =} -> {cases = n, chunks = {{first =, last =, count =, solves =}, ...}}: the
// chunks ws:sweep cuts its cases into (1-based case indices; first .. last is a contiguous range when y is sorted).
int wheelset_sweep_plan(lua_State* L) {
  const char* ctx = "wheelset:sweep_plan";
  self(L, ctx);
  MethodArgs a(L, ctx);
  const SweepPlan plan = api::read_sweep_plan(a.reader);
  a.reader.finish();
  lua_createtable(L, 0, 2);
  set_integer(L, "cases", static_cast<long long>(plan.cases.size()));
  lua_createtable(L, static_cast<int>(plan.chunks.size()), 0);
  for (std::size_t k = 0; k < plan.chunks.size(); ++k) {
    const SweepChunk& c = plan.chunks[k];
    lua_createtable(L, 0, 4);
    set_integer(L, "first", c.report.front() + 1);
    set_integer(L, "last", c.report.back() + 1);
    set_integer(L, "count", static_cast<long long>(c.report.size()));
    set_integer(L, "solves", static_cast<long long>(c.solve.size()));
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  lua_setfield(L, -2, "chunks");
  return 1;
}

// ---- ws:trajectory{tolerance =, grids =}: a wrc.Trajectory with tr:contact{...}, tr:wheel{...}, tr:reset() ----

const char* const kTrajectoryType = "wrc.Trajectory";

struct LuaTrajectory {
  std::unique_ptr<Trajectory> trajectory;
  std::shared_ptr<LuaStrategy> strategy;  // binds the building state's search to the calling coroutine
  std::shared_ptr<bool> resolution_shown;  // the wheelset's
};

int wheelset_trajectory(lua_State* L) {
  const char* ctx = "wheelset:trajectory";
  LuaWheelset& w = self(L, ctx);
  const auto call = api::read<api::TrajectoryCall>(to_options(L, 2, ctx), ctx);
  w.strategy->main_search(L);
  auto lt = std::make_shared<LuaTrajectory>();
  lt->trajectory = call.run(w.model);
  lt->strategy = w.strategy;
  lt->resolution_shown = w.resolution_shown;
  push_shared(L, std::move(lt), kTrajectoryType);
  return 1;
}

LuaTrajectory& trajectory_self(lua_State* L, const char* ctx) {
  LuaTrajectory& t = *check_shared<LuaTrajectory>(L, 1, kTrajectoryType, ctx);
  t.strategy->main_search(L);
  return t;
}

// tr:contact{y=, z=, roll=, yaw=, rolling keys}: the contact at a prescribed pose, from the previous step's pressures.
int trajectory_contact(lua_State* L) {
  const char* ctx = "trajectory:contact";
  LuaTrajectory& t = trajectory_self(L, ctx);
  const ContactResult r = read_call<api::TrajectoryContactCall>(L, ctx).run(*t.trajectory);
  show_resolution(*t.resolution_shown, ctx, r);
  push_result(L, r);
  return 1;
}

// tr:wheel{side=, y=, yaw=, roll=, Fz=, rolling keys}: one wheel with Fz given, from the previous steps' approach.
int trajectory_wheel(lua_State* L) {
  const char* ctx = "trajectory:wheel";
  LuaTrajectory& t = trajectory_self(L, ctx);
  const WheelResult r = read_call<api::TrajectoryWheelCall>(L, ctx).run(*t.trajectory);
  if (!r.converged) fail("{}: {}", ctx, failure_message(r));
  show_resolution(*t.resolution_shown, ctx, r.wheel);
  push_result(L, r);
  return 1;
}

int trajectory_reset(lua_State* L) {
  trajectory_self(L, "trajectory:reset").trajectory->reset();
  return 0;
}

void open_trajectory(lua_State* L) {
  if (luaL_newmetatable(L, kTrajectoryType)) {
    lua_pushcfunction(L, gc_shared<LuaTrajectory>);
    lua_setfield(L, -2, "__gc");
    lua_newtable(L);
    const luaL_Reg methods[] = {{"contact", guarded<trajectory_contact>},
                                {"wheel", guarded<trajectory_wheel>},
                                {"reset", guarded<trajectory_reset>},
                                {nullptr, nullptr}};
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "__index");
  }
  lua_pop(L, 1);
}

// ws:check_strategy{poses =, y = {min, max}, yaw =, roll =, depth =, seed =, threads =, progress =}: the strategy
// against brute force on random poses; an error names the first pose that differs.
int wheelset_check_strategy(lua_State* L) {
  const char* ctx = "wheelset:check_strategy";
  LuaWheelset& w = self(L, ctx);
  auto call = read_call<api::StrategyCheckCall>(L, ctx);
  StrategyCheckOptions& o = call.options;
  if (call.progress.on(host::stderr_is_terminal())) o.progress = host::progress_line("check_strategy", "poses");
  const bool portable = w.model->strategy().info().portable;
  if (!portable) o.threads = 1;  // an inline Lua strategy runs in this state only
  const auto r = check_strategy(w.model->geometry(), o, [&]() -> std::unique_ptr<PoseSearch> {
    if (!portable) return std::make_unique<SearchRef>(w.strategy->main_search(L));
    return w.model->strategy().make_search();
  });
  push_result(L, r);
  return 1;
}

// Placed points are ordered by increasing track y on both sides: the profile's own order on the left, the reverse
// on the right (its field side first); `reversed` says which.
void push_placed(lua_State* L, const std::vector<double>& y, const std::vector<double>& z, const char* kind,
                 const char* frame, int side = -1) {
  lua_createtable(L, 0, 6);
  push_array(L, y);
  lua_setfield(L, -2, "y");
  push_array(L, z);
  lua_setfield(L, -2, "z");
  set_string(L, "kind", kind);
  set_string(L, "frame", frame);
  set_string(L, "order", "increasing y");
  if (side >= 0) set_bool(L, "reversed", side == kRight);
}

// ws:cones(side) -> {y, z, count}: the discretised wheel's generatrix points (wheelset frame; the first and last on
// the axle). ws:lines(side) -> {y, z, count}: the rail lines (track frame).
int wheelset_cones(lua_State* L) {
  const int side = parse_side(check_string(L, 2, "wheelset:cones"), "wheelset:cones");
  const WheelCones& c = self(L, "wheelset:cones").model->geometry().side[side].wheel;
  push_placed(L, c.y, c.z, "wheel", "wheelset", side);
  set_integer(L, "count", c.cone_count());
  return 1;
}

int wheelset_lines(lua_State* L) {
  const int side = parse_side(check_string(L, 2, "wheelset:lines"), "wheelset:lines");
  const RailLines& r = self(L, "wheelset:lines").model->geometry().side[side].rail;
  push_placed(L, r.y, r.z, "rail", "track", side);
  set_integer(L, "count", r.count());
  return 1;
}

// ws:coarse(side) -> nil or {wheel = {y, z}, lines = {y, z}, dilation = m, every = n, cells = {{first, last}, ...}}
int wheelset_coarse(lua_State* L) {
  const char* ctx = "wheelset:coarse";
  const SideGeometry& g = self(L, ctx).model->geometry().side[parse_side(check_string(L, 2, ctx), ctx)];
  if (!g.coarse) return lua_pushnil(L), 1;
  const CoarseLevel& c = *g.coarse;
  lua_createtable(L, 0, 5);
  push_placed(L, c.wheel.y, c.wheel.z, "wheel", "wheelset");
  lua_setfield(L, -2, "wheel");
  push_placed(L, c.lines.y, c.lines.z, "rail", "track");
  lua_setfield(L, -2, "lines");
  set_number(L, "dilation", c.dilation);
  set_integer(L, "every", c.every);
  lua_createtable(L, static_cast<int>(c.cell_first.size()), 0);
  for (std::size_t i = 0; i < c.cell_first.size(); ++i) {
    const double cell[2] = {c.cell_first[i] + 1.0, c.cell_last[i] + 1.0};
    push_array(L, cell, 2);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "cells");
  return 1;
}

void push_strategy_info(lua_State* L, const StrategyInfo& si) {
  lua_createtable(L, 0, 4);
  set_string(L, "name", si.name);
  set_bool(L, "portable", si.portable);
  lua_createtable(L, static_cast<int>(si.components.size()), 0);
  for (std::size_t i = 0; i < si.components.size(); ++i) {
    lua_pushstring(L, si.components[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "components");
  lua_createtable(L, 0, static_cast<int>(si.options.size()));
  for (const auto& [k, v] : si.options) {
    if (const double* d = std::get_if<double>(&v)) lua_pushnumber(L, *d);
    else if (const std::string* s = std::get_if<std::string>(&v)) lua_pushstring(L, s->c_str());
    else lua_pushboolean(L, std::get<bool>(v));
    lua_setfield(L, -2, k.c_str());
  }
  lua_setfield(L, -2, "options");
}

// Fields: left_wheel, right_wheel, left_rail, right_rail (placed profiles), gauge_points, tape_points, rail_top,
// params, strategy, tests (of the last ws:locate); otherwise the methods.
int wheelset_index(lua_State* L) {
  const LuaWheelset& w = self(L, "wheelset");
  const Track& t = w.model->track();
  const std::string_view key = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "";
  for (int s : {kLeft, kRight}) {
    const std::string side = side_name(s);
    if (key == side + "_wheel") return push_placed(L, t.wheel_y[s], t.wheel_z[s], "wheel", "wheelset", s), 1;
    if (key == side + "_rail") return push_placed(L, t.rail_y[s], t.rail_z[s], "rail", "track", s), 1;
  }
  if (key == "gauge_points" || key == "tape_points") {
    const auto& pts = key == "gauge_points" ? t.gauge_point : t.tape_point;
    lua_createtable(L, 0, 2);
    for (int s : {kLeft, kRight}) {
      lua_createtable(L, 0, 2);
      set_number(L, "y", pts[s].x());
      set_number(L, "z", pts[s].y());
      lua_setfield(L, -2, side_name(s));
    }
    return 1;
  }
  if (key == "rail_top") {
    lua_createtable(L, 0, 2);
    set_number(L, "left", t.rail_top[kLeft]);
    set_number(L, "right", t.rail_top[kRight]);
    return 1;
  }
  if (key == "params") return push_result(L, w.model->params()), 1;
  if (key == "strategy_check") {
    if (!w.model->strategy_check()) return lua_pushnil(L), 1;
    return push_result(L, *w.model->strategy_check()), 1;
  }
  if (key == "strategy") return push_strategy_info(L, w.model->geometry().strategy), 1;
  if (key == "tests") {
    if (w.last_tests[kLeft] < 0) return lua_pushnil(L), 1;
    lua_createtable(L, 0, 3);
    set_integer(L, "left", w.last_tests[kLeft]);
    set_integer(L, "right", w.last_tests[kRight]);
    set_integer(L, "total", w.last_tests[kLeft] + w.last_tests[kRight]);
    return 1;
  }
  luaL_getmetatable(L, kWheelsetType);
  lua_getfield(L, -1, "methods");
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}

int wheelset_gc(lua_State* L) {
  auto* p = static_cast<std::shared_ptr<LuaWheelset>*>(lua_touserdata(L, 1));
  if (p && *p && (*p)->strategy) (*p)->strategy->release(L);
  return gc_shared<LuaWheelset>(L);
}

// wrc.defaults: the wheelset parameters' defaults (read-only copy).
void push_defaults(lua_State* L) {
  lua_createtable(L, 0, 1);
  push_result(L, WheelsetParams{});
  lua_setfield(L, -2, "wheelset");
}

// ---- p:subsurface{...}: a contact area's table (wrc.Patch) ----

// A number field of the table at idx.
double field_number(lua_State* L, int idx, const char* key, const char* ctx) {
  lua_getfield(L, idx, key);
  if (!lua_isnumber(L, -1)) fail("{}: the area has no number '{}' (is it an area of a contact result?)", ctx, key);
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

// A grid field of the area (empty when absent); the pressure must be there.
std::vector<double> field_grid(lua_State* L, const char* key, const halfspace::Grid& g, const char* ctx) {
  lua_getfield(L, 1, key);
  int nx = 0, ny = 0;
  const std::vector<double>* v = grid_values(L, -1, nx, ny);
  std::vector<double> out = v ? *v : std::vector<double>{};
  lua_pop(L, 1);
  if (v && (nx != g.nx || ny != g.ny))
    fail("{}: the area's '{}' is {} x {}, its grid {} x {}", ctx, key, nx, ny, g.nx, g.ny);
  return out;
}

// The area's load from its fields: grid, pressure, px and py (when rolling), nu.
api::PatchLoad patch_load(lua_State* L, const char* ctx) {
  check_table(L, 1, ctx);
  api::PatchLoad load;
  lua_getfield(L, 1, "grid");
  if (!lua_istable(L, -1)) fail("{}: the area has no 'grid' table (is it an area of a contact result?)", ctx);
  const int t = lua_gettop(L);
  halfspace::Grid& g = load.grid;
  g.nx = static_cast<int>(std::clamp(field_number(L, t, "nx", ctx), -1.0, 1e9));  // validated by the engine
  g.ny = static_cast<int>(std::clamp(field_number(L, t, "ny", ctx), -1.0, 1e9));
  g.dx = field_number(L, t, "dx", ctx);
  g.dy = field_number(L, t, "dy", ctx);
  g.x0 = field_number(L, t, "x0", ctx);
  g.y0 = field_number(L, t, "y0", ctx);
  lua_pop(L, 1);
  load.nu = field_number(L, 1, "nu", ctx);
  load.pressure = field_grid(L, "pressure", g, ctx);
  if (load.pressure.empty())
    fail("{}: the area has no pressure grid: the call that made it must keep its grids (grids = true)", ctx);
  load.px = field_grid(L, "px", g, ctx);
  load.py = field_grid(L, "py", g, ctx);
  return load;
}

// p:subsurface{z = {...}, method =, body =, fields =, shear_yield =, shakedown_map =}: the stresses below the area.
int patch_subsurface(lua_State* L) {
  const char* ctx = "patch:subsurface";
  const api::PatchLoad load = patch_load(L, ctx);
  const auto call = read_call<api::SubsurfaceCall>(L, ctx);
  push_result(L, call.run(load));
  return 1;
}

void open_patch(lua_State* L) {
  if (luaL_newmetatable(L, kPatchType)) {
    lua_newtable(L);
    const luaL_Reg methods[] = {{"subsurface", guarded<patch_subsurface>}, {nullptr, nullptr}};
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "__index");
  }
  lua_pop(L, 1);
}

}  // namespace

std::shared_ptr<const Wheelset> check_wheelset(lua_State* L, int idx, const char* context) {
  return check_shared<LuaWheelset>(L, idx, kWheelsetType, context)->model;
}

void open_wheelset(lua_State* L) {
  if (luaL_newmetatable(L, kWheelsetType)) {
    const luaL_Reg meta[] = {{"__gc", wheelset_gc}, {"__index", guarded<wheelset_index>}, {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    const luaL_Reg methods[] = {{"locate", guarded<wheelset_locate>},   {"contact", guarded<wheelset_contact>},
                                {"equilibrium", guarded<wheelset_equilibrium>}, {"wheel", guarded<wheelset_wheel>},
                                {"rigid", guarded<wheelset_rigid>},     {"sweep", guarded<wheelset_sweep>},
                                {"sweep_plan", guarded<wheelset_sweep_plan>},
                                {"sweep_start", guarded<wheelset_sweep_start>},
                                {"geometry_table", guarded<wheelset_geometry_table>},
                                {"conicity", guarded<wheelset_conicity>},
                                {"cones", guarded<wheelset_cones>},     {"lines", guarded<wheelset_lines>},
                                {"coarse", guarded<wheelset_coarse>},   {"trajectory", guarded<wheelset_trajectory>},
                                {"check_strategy", guarded<wheelset_check_strategy>}, {nullptr, nullptr}};
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "methods");
  }
  lua_pop(L, 1);
  lua_pushcfunction(L, guarded<wheelset_new>);
  lua_setfield(L, -2, "wheelset");
  push_defaults(L);
  lua_setfield(L, -2, "defaults");
  if (luaL_newmetatable(L, SweepJob::kTypeName)) {  // ws:sweep_start's job: one method, wait
    lua_pushcfunction(L, gc_shared<SweepJob>);
    lua_setfield(L, -2, "__gc");
    lua_newtable(L);
    lua_pushcfunction(L, guarded<sweep_job_wait>);
    lua_setfield(L, -2, "wait");
    lua_setfield(L, -2, "__index");
  }
  lua_pop(L, 1);
  if (luaL_newmetatable(L, ContactStart::kTypeName)) {  // a sweep's contact_start: opaque
    lua_pushcfunction(L, gc_shared<const ContactStart>);
    lua_setfield(L, -2, "__gc");
  }
  lua_pop(L, 1);
  open_trajectory(L);
  open_patch(L);
  open_geometry(L);  // wrc.geometry: the strategies' helpers
}

}  // namespace wrc::lua
