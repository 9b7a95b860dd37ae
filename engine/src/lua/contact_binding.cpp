// Normal contact and equilibrium from Lua: ws:contact, ws:equilibrium, ws:wheel, ws:rigid, ws:sweep
// (DESIGN.md section 5). Results are plain tables built here, on the calling thread, after the engine's work
// (a sweep's worker threads never touch the Lua state).
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/equilibrium/equilibrium.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace wrc::lua {
namespace {

const std::shared_ptr<Wheelset>& check_wheelset(lua_State* L, const char* ctx) {
  return check_shared<Wheelset>(L, 1, kWheelsetType, ctx);
}

// The wheelset's own search (bound to the state that built it) seen through a non-owning PoseSearch.
class ForwardSearch final : public PoseSearch {
 public:
  explicit ForwardSearch(LuaSearch* s) : s_(s) {}
  void search(SearchContext& ctx, int side) override { s_->search(ctx, side); }

 private:
  LuaSearch* s_;
};

// The calling thread's workspace of a wheelset (made on first use).
ContactWorkspace& main_workspace(lua_State* L, Wheelset& ws) {
  ws.search->set_thread(L);
  if (!ws.workspace)
    ws.workspace = std::make_unique<ContactWorkspace>(*ws.contact, std::make_unique<ForwardSearch>(ws.search.get()));
  return *ws.workspace;
}

// values[j][i] of a grid vector (index i + nx j) as nested Lua arrays, rows along the grid's second axis.
void push_grid_values(lua_State* L, const contact::Grid& g, const std::vector<double>& v) {
  lua_createtable(L, g.ny, 0);
  for (int j = 0; j < g.ny; ++j) {
    push_array(L, v.data() + static_cast<std::size_t>(g.nx) * j, static_cast<std::size_t>(g.nx));
    lua_rawseti(L, -2, j + 1);
  }
}

// One contact area (DESIGN.md section 5). With a location state, the geometric fields of the located patch(es)
// come first (segments, nominal point, ...); then the normal-contact fields.
void push_area(lua_State* L, const LocationState* st, const PatchContact& pc) {
  if (st) {
    const auto& patches = st->patches(pc.side);
    push_patch(L, *st, patches[static_cast<std::size_t>(pc.patches.front())]);
    if (pc.patches.size() > 1) {  // merged areas: all their segments
      const auto& segs = st->segments(pc.side);
      lua_createtable(L, 0, 0);
      int k = 0;
      for (int p : pc.patches) {
        const Patch& patch = patches[static_cast<std::size_t>(p)];
        for (int i = 0; i < patch.segment_count; ++i) {
          push_segment(L, segs[static_cast<std::size_t>(patch.first_segment + i)]);
          lua_rawseti(L, -2, ++k);
        }
      }
      lua_setfield(L, -2, "segments");
    }
  } else {
    lua_createtable(L, 0, 20);
    set_string(L, "side", side_name(pc.side));
    push_vec3(L, pc.nominal);
    lua_setfield(L, -2, "nominal_point");
  }
  set_integer(L, "merged", static_cast<long long>(pc.patches.size()));
  const contact::NormalSolution& s = pc.solution;
  set_number(L, "normal_force", pc.normal_force);
  push_vec3(L, pc.force);
  lua_setfield(L, -2, "force");
  push_vec3(L, pc.moment);
  lua_setfield(L, -2, "moment");
  push_vec3(L, pc.point);
  lua_setfield(L, -2, "point");
  push_vec3(L, pc.normal);
  lua_setfield(L, -2, "normal");
  set_number(L, "angle", pc.angle);
  set_number(L, "nominal_angle", pc.nominal_angle);
  set_number(L, "area", s.area);
  set_number(L, "pmax", s.max_pressure);
  set_integer(L, "elements", s.elements_in_contact);
  set_integer(L, "regions", pc.regions);
  set_number(L, "penetration", pc.penetration);
  set_number(L, "rolling_radius", pc.rolling_radius);
  set_integer(L, "iterations", s.iterations);
  set_number(L, "complementarity", s.residual.relative);
  lua_createtable(L, 0, 3);  // the contact plane: grid coordinates (u, v) are at origin + u t1 + v t2
  push_vec3(L, pc.origin);
  lua_setfield(L, -2, "origin");
  push_vec3(L, pc.t1);
  lua_setfield(L, -2, "t1");
  push_vec3(L, pc.t2);
  lua_setfield(L, -2, "t2");
  lua_setfield(L, -2, "frame");
  lua_createtable(L, 0, 6);
  set_integer(L, "nx", s.grid.nx);
  set_integer(L, "ny", s.grid.ny);
  set_number(L, "dx", s.grid.dx);
  set_number(L, "dy", s.grid.dy);
  set_number(L, "x0", s.grid.x0);
  set_number(L, "y0", s.grid.y0);
  lua_setfield(L, -2, "grid");
  if (!s.pressure.empty()) {
    push_grid_values(L, s.grid, s.pressure);
    lua_setfield(L, -2, "pressure");
  }
  if (!pc.h.empty()) {
    push_grid_values(L, s.grid, pc.h);
    lua_setfield(L, -2, "h");
  }
}

void push_wheel(lua_State* L, const LocationState* st, const WheelContact& wc) {
  lua_createtable(L, 0, 6);
  set_bool(L, "lifted", !(wc.force.z() > 0));  // the wheel carries no load
  push_vec3(L, wc.force);
  lua_setfield(L, -2, "force");
  push_vec3(L, wc.moment);
  lua_setfield(L, -2, "moment");
  set_number(L, "angle", wc.angle);
  set_number(L, "rolling_radius", wc.rolling_radius);
  lua_createtable(L, static_cast<int>(wc.patches.size()), 0);
  for (std::size_t i = 0; i < wc.patches.size(); ++i) {
    push_area(L, st, wc.patches[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "patches");
}

void push_pose(lua_State* L, const Pose& p) {
  lua_createtable(L, 0, 4);
  set_number(L, "y", p.y);
  set_number(L, "z", p.z);
  set_number(L, "roll", p.roll);
  set_number(L, "yaw", p.yaw);
}

// d(force, moment)/d(z, roll) as {z = {Fx, Fy, Fz, Mx, My, Mz}, roll = {...}} (N/m, N m/m, N/rad, N m/rad).
void push_sensitivity(lua_State* L, const Sensitivity& S) {
  lua_createtable(L, 0, 2);
  for (int col = 0; col < 2; ++col) {
    const double v[6] = {S(0, col), S(1, col), S(2, col), S(3, col), S(4, col), S(5, col)};
    push_array(L, v, 6);
    lua_setfield(L, -2, col == 0 ? "z" : "roll");
  }
}

void push_contact_result(lua_State* L, const LocationState* st, const ContactResult& c, bool sensitivity) {
  lua_createtable(L, 0, 6);
  if (sensitivity) {
    push_sensitivity(L, c.sensitivity);
    lua_setfield(L, -2, "sensitivity");
  }
  for (int s : {kLeft, kRight}) {
    push_wheel(L, st, c.wheel[s]);
    lua_setfield(L, -2, side_name(s));
  }
  push_vec3(L, c.force);
  lua_setfield(L, -2, "force");
  push_vec3(L, c.moment);
  lua_setfield(L, -2, "moment");
  push_pose(L, c.pose);
  lua_setfield(L, -2, "pose");
}

void push_rigid(lua_State* L, const RigidResult& r) {
  lua_createtable(L, 0, 12);
  set_bool(L, "converged", r.converged);
  set_bool(L, "tension", r.tension);
  if (!r.message.empty()) set_string(L, "error", r.message);
  set_number(L, "y", r.y);
  set_number(L, "yaw", r.yaw);
  set_number(L, "Q", r.Q);
  set_number(L, "z", r.z);
  set_number(L, "roll", r.roll);
  set_number(L, "Y", r.Y);
  set_number(L, "My", r.My);
  set_number(L, "Mz", r.Mz);
  set_number(L, "Y_Q", r.Y / r.Q);
  for (int s : {kLeft, kRight}) {
    const RigidWheel& w = r.wheel[s];
    lua_createtable(L, 0, 7);
    push_vec3(L, w.point);
    lua_setfield(L, -2, "point");
    push_vec3(L, w.normal);
    lua_setfield(L, -2, "normal");
    set_number(L, "angle", w.angle);
    set_number(L, "rolling_radius", w.rolling_radius);
    set_number(L, "normal_force", w.normal_force);
    set_number(L, "overlap", w.overlap);
    set_integer(L, "line", w.line + 1);
    lua_setfield(L, -2, side_name(s));
  }
}

void push_equilibrium(lua_State* L, const LocationState* st, const EquilibriumResult& e) {
  lua_createtable(L, 0, 20);
  set_bool(L, "converged", e.converged);
  if (!e.message.empty()) set_string(L, "error", e.message);
  set_number(L, "y", e.y);
  set_number(L, "yaw", e.yaw);
  set_number(L, "Q", e.Q);
  set_number(L, "z", e.z);
  set_number(L, "roll", e.roll);
  set_number(L, "Y", e.Y);
  set_number(L, "My", e.My);
  set_number(L, "Mz", e.Mz);
  set_number(L, "Y_Q", e.Q > 0 ? e.Y / e.Q : 0.0);
  set_integer(L, "iterations", e.iterations);
  set_integer(L, "evaluations", e.evaluations);
  lua_createtable(L, 0, 2);
  set_number(L, "force", e.residual_force);
  set_number(L, "moment", e.residual_moment);
  lua_setfield(L, -2, "residual");
  for (int s : {kLeft, kRight}) {
    push_wheel(L, st, e.contact.wheel[s]);
    lua_setfield(L, -2, side_name(s));
  }
  set_number(L, "rolling_radius_difference",
             e.contact.wheel[kLeft].rolling_radius - e.contact.wheel[kRight].rolling_radius);
  push_vec3(L, e.contact.force);
  lua_setfield(L, -2, "force");
  push_vec3(L, e.contact.moment);
  lua_setfield(L, -2, "moment");
}

Pose read_pose(lua_State* L, int idx, const char* ctx) {
  Pose p;
  p.y = get_number(L, idx, "y", 0.0, ctx);
  p.z = get_number(L, idx, "z", 0.0, ctx);
  p.roll = get_number(L, idx, "roll", 0.0, ctx);
  p.yaw = get_number(L, idx, "yaw", 0.0, ctx);
  return p;
}

// ws:contact{y=, z=, roll=, yaw=, grids = true, sensitivity = false, search = "strategy" | "brute"}: contact at
// a prescribed pose; with sensitivity = true also c.sensitivity, the linearised d(force, moment)/d(z, roll) of
// the normal problems (the Jacobian of the equilibrium).
int wheelset_contact(lua_State* L) {
  const char* ctx = "wheelset:contact";
  const auto& ws = check_wheelset(L, ctx);
  check_table(L, 2, ctx);
  check_keys(L, 2, ctx, {"y", "z", "roll", "yaw", "grids", "search", "sensitivity"});
  const Pose pose = read_pose(L, 2, ctx);
  ContactRequest req;
  req.keep_grids = opt_bool(L, 2, "grids", ctx).value_or(true);
  req.sensitivity = opt_bool(L, 2, "sensitivity", ctx).value_or(false);
  const std::string search = opt_string(L, 2, "search", ctx).value_or("strategy");
  if (search == "strategy") {
    ContactWorkspace& w = main_workspace(L, *ws);
    const ContactResult c = evaluate_contact(*ws->contact, pose, w, req);
    push_contact_result(L, &w.locator.state(), c, req.sensitivity);
  } else if (search == "brute") {
    ContactWorkspace w(*ws->contact, std::make_unique<NativeSearch>(NativePlan{false, NativePlan::Scan::test}));
    const ContactResult c = evaluate_contact(*ws->contact, pose, w, req);
    push_contact_result(L, &w.locator.state(), c, req.sensitivity);
  } else {
    fail("{}: search must be \"strategy\" or \"brute\", got \"{}\"", ctx, search);
  }
  return 1;
}

EquilibriumOptions read_equilibrium_options(lua_State* L, int idx, const char* ctx) {
  EquilibriumOptions o;
  o.force_tolerance = get_number(L, idx, "force_tolerance", o.force_tolerance, ctx);
  o.moment_tolerance = get_number(L, idx, "moment_tolerance", o.moment_tolerance, ctx);
  const double it = get_number(L, idx, "max_iterations", o.max_iterations, ctx);
  const double ev = get_number(L, idx, "max_evaluations", o.max_evaluations, ctx);
  if (!(o.force_tolerance > 0) || !(o.moment_tolerance > 0)) fail("{}: tolerances must be > 0", ctx);
  if (it != static_cast<int>(it) || it < 1) fail("{}: 'max_iterations' must be a whole number >= 1, got {}", ctx, it);
  if (ev != static_cast<int>(ev) || ev < 1) fail("{}: 'max_evaluations' must be a whole number >= 1, got {}", ctx, ev);
  o.max_iterations = static_cast<int>(it);
  o.max_evaluations = static_cast<int>(ev);
  return o;
}

bool failures_return(lua_State* L, int idx, const char* ctx) {
  const std::string f = opt_string(L, idx, "on_failure", ctx).value_or("error");
  if (f != "error" && f != "return") fail("{}: 'on_failure' must be \"error\" or \"return\", got \"{}\"", ctx, f);
  return f == "return";
}

// ws:equilibrium{y=, yaw=, Q=, start = {z=, roll=}, grids = true, trace = false, on_failure = "error" | "return",
//                force_tolerance=, moment_tolerance=, max_iterations=}
int wheelset_equilibrium(lua_State* L) {
  const char* ctx = "wheelset:equilibrium";
  const auto& ws = check_wheelset(L, ctx);
  check_table(L, 2, ctx);
  check_keys(L, 2, ctx, {"y", "yaw", "Q", "start", "grids", "trace", "on_failure", "force_tolerance",
                         "moment_tolerance", "max_iterations", "max_evaluations"});
  const double y = need_number(L, 2, "y", ctx);
  const double yaw = get_number(L, 2, "yaw", 0.0, ctx);
  const double Q = need_number(L, 2, "Q", ctx);
  EquilibriumOptions opt = read_equilibrium_options(L, 2, ctx);
  std::vector<Start> start;
  lua_getfield(L, 2, "start");
  if (!lua_isnil(L, -1)) {
    check_table(L, -1, std::string(ctx) + ": 'start'");
    start.push_back(Start{need_number(L, -1, "z", ctx), get_number(L, -1, "roll", 0.0, ctx), std::nullopt});
  }
  lua_pop(L, 1);
  if (opt_bool(L, 2, "trace", ctx).value_or(false)) {
    opt.trace = [](int it, double z, double roll, const ContactResult& c) {
      std::fprintf(stderr, "  newton %2d: z = %+.6f mm, roll = %+.6f mrad, Fz = %.3f kN (left %.3f, right %.3f), Mx = %+.3f N m\n",
                   it, z * 1e3, roll * 1e3, c.force.z() / 1e3, c.wheel[kLeft].force.z() / 1e3,
                   c.wheel[kRight].force.z() / 1e3, c.moment.x());
    };
  }
  const bool ret = failures_return(L, 2, ctx);
  ContactRequest req;
  req.keep_grids = opt_bool(L, 2, "grids", ctx).value_or(true);
  ContactWorkspace& w = main_workspace(L, *ws);
  const EquilibriumResult e = solve_equilibrium(*ws->contact, y, yaw, Q, w, opt, start, req);
  if (!e.converged && !ret)
    fail("{}: no equilibrium found at y = {:.4f} mm, yaw = {:.6g} rad, Q = {:.6g} kN: {}; last iterate z = {:.6f} mm, "
         "roll = {:.6f} mrad, residuals: force {:.4g} N, moment {:.4g} N m (on_failure = \"return\" gives the result)",
         ctx, y * 1e3, yaw, Q / 1e3, e.message, e.z * 1e3, e.roll * 1e3, e.residual_force, e.residual_moment);
  // The location state of the final iterate (the geometric fields of the patches).
  const LocationState& st = w.locator.locate({y, e.z, e.roll, yaw});
  push_equilibrium(L, &st, e);
  return 1;
}

// ws:wheel{side=, y=, yaw=, roll=, Fz=, on_failure=}: one wheel-rail pair, vertical force prescribed.
int wheelset_wheel(lua_State* L) {
  const char* ctx = "wheelset:wheel";
  const auto& ws = check_wheelset(L, ctx);
  check_table(L, 2, ctx);
  check_keys(L, 2, ctx, {"side", "y", "yaw", "roll", "Fz", "on_failure", "force_tolerance", "max_iterations",
                         "moment_tolerance", "max_evaluations"});
  lua_getfield(L, 2, "side");
  const int side = check_side_arg(L, -1, ctx);
  lua_pop(L, 1);
  const double y = get_number(L, 2, "y", 0.0, ctx), yaw = get_number(L, 2, "yaw", 0.0, ctx);
  const double roll = get_number(L, 2, "roll", 0.0, ctx), Fz = need_number(L, 2, "Fz", ctx);
  const EquilibriumOptions opt = read_equilibrium_options(L, 2, ctx);
  const bool ret = failures_return(L, 2, ctx);
  ContactWorkspace& w = main_workspace(L, *ws);
  const WheelResult r = solve_wheel(*ws->contact, side, y, yaw, roll, Fz, w, opt);
  if (!r.converged && !ret)
    fail("{}: the {} wheel's vertical force {:.6g} N was not reached: {}; last iterate z = {:.6f} mm, residual {:.4g} N",
         ctx, side_name(side), Fz, r.message, r.z * 1e3, r.residual);
  const LocationState& st = w.locator.locate({y, r.z, roll, yaw});
  push_wheel(L, &st, r.wheel);
  set_bool(L, "converged", r.converged);
  if (!r.message.empty()) set_string(L, "error", r.message);
  set_number(L, "z", r.z);
  set_number(L, "residual", r.residual);
  set_integer(L, "iterations", r.iterations);
  return 1;
}

// ws:rigid{y=, yaw=, Q=}: the rigid (kinematic) contact reference.
int wheelset_rigid(lua_State* L) {
  const char* ctx = "wheelset:rigid";
  const auto& ws = check_wheelset(L, ctx);
  check_table(L, 2, ctx);
  check_keys(L, 2, ctx, {"y", "yaw", "Q"});
  const RigidResult r = solve_rigid(*ws->model, need_number(L, 2, "y", ctx), get_number(L, 2, "yaw", 0.0, ctx),
                                    get_number(L, 2, "Q", 200e3, ctx));
  push_rigid(L, r);
  return 1;
}

// A list of numbers: an array, a single number, or {from=, to=, step=} (inclusive, the step's sign follows).
std::vector<double> number_list(lua_State* L, int idx, const char* key, const char* ctx) {
  lua_getfield(L, idx, key);
  std::vector<double> v;
  if (lua_isnumber(L, -1)) {
    v.push_back(check_number(L, -1, ctx));
  } else if (lua_istable(L, -1) && luaL_len(L, -1) == 0) {
    const std::string c = fmt::format("{}: '{}' (an array, or {{from=, to=, step=}})", ctx, key);
    const double from = need_number(L, -1, "from", c), to = need_number(L, -1, "to", c);
    const double step = need_number(L, -1, "step", c);
    if (!(step > 0)) fail("{}: '{}.step' must be > 0, got {}", ctx, key, step);
    const double n = std::floor(std::abs(to - from) / step + 1e-9);
    if (n > 1e6) fail("{}: '{}' asks for {} values", ctx, key, n);
    const double dir = to >= from ? 1.0 : -1.0;
    for (int i = 0; i <= static_cast<int>(n); ++i) v.push_back(from + dir * step * i);
  } else if (lua_istable(L, -1)) {
    v = number_array(L, -1, nullptr, std::string(ctx) + ": '" + key + "'");
  } else {
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    fail("{}: '{}' must be a number, an array of numbers or {{from=, to=, step=}}, got {}", ctx, key, tn);
  }
  lua_pop(L, 1);
  if (v.empty()) fail("{}: '{}' is empty", ctx, key);
  return v;
}

// ws:sweep{y = {...} | {from=, to=, step=}, yaw = {...} | number, Q=, threads=, rigid = false, grids = false,
//          progress = <stderr is a terminal>, force_tolerance=, moment_tolerance=, max_iterations=}
int wheelset_sweep(lua_State* L) {
  const char* ctx = "wheelset:sweep";
  const auto& ws = check_wheelset(L, ctx);
  check_table(L, 2, ctx);
  check_keys(L, 2, ctx, {"y", "yaw", "Q", "threads", "rigid", "grids", "progress", "force_tolerance",
                         "moment_tolerance", "max_iterations", "max_evaluations"});
  const std::vector<double> ys = number_list(L, 2, "y", ctx);
  std::vector<double> yaws{0.0};
  lua_getfield(L, 2, "yaw");
  const bool has_yaw = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (has_yaw) yaws = number_list(L, 2, "yaw", ctx);
  SweepOptions so;
  so.Q = need_number(L, 2, "Q", ctx);
  const double threads = get_number(L, 2, "threads", 0, ctx);
  if (threads != static_cast<int>(threads) || threads < 0 || threads > 256)
    fail("{}: 'threads' must be a whole number in 0..256 (0: all cores), got {}", ctx, threads);
  so.threads = static_cast<int>(threads);
  so.rigid = opt_bool(L, 2, "rigid", ctx).value_or(false);
  so.keep_grids = opt_bool(L, 2, "grids", ctx).value_or(false);
  so.equilibrium = read_equilibrium_options(L, 2, ctx);
  const bool progress = opt_bool(L, 2, "progress", ctx).value_or(isatty(STDERR_FILENO) == 1);
  const bool portable = ws->model->strategy.portable;
  if (!portable) so.threads = 1;  // an inline Lua strategy runs only in this state
  const auto t0 = std::chrono::steady_clock::now();
  if (progress) {
    so.progress = [t0](int done, int total, int failed) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "\rwrc sweep: %d / %d cases, %d failed, %.1f s", done, total, failed, s);
      if (done == total) std::fputc('\n', stderr);
      std::fflush(stderr);
    };
  }
  Wheelset& w = *ws;
  main_workspace(L, w);  // binds the wheelset's own search to this state
  const SweepResult r = run_sweep(*w.contact, ys, yaws, so, [&]() -> std::unique_ptr<ContactWorkspace> {
    if (so.threads == 1) return std::make_unique<ContactWorkspace>(*w.contact, std::make_unique<ForwardSearch>(w.search.get()));
    return std::make_unique<ContactWorkspace>(*w.contact);  // the strategy in the worker's own Lua state
  });
  int failed = 0;
  lua_createtable(L, static_cast<int>(r.cases.size()), 3);
  for (std::size_t i = 0; i < r.cases.size(); ++i) {
    push_equilibrium(L, nullptr, r.elastic[i]);
    if (!r.elastic[i].converged) ++failed;
    if (r.rigid[i]) {
      push_rigid(L, *r.rigid[i]);
      lua_setfield(L, -2, "rigid");
    }
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  set_number(L, "seconds", r.seconds);
  set_integer(L, "threads", r.threads);
  set_integer(L, "failed", failed);
  return 1;
}

}  // namespace

void open_contact(lua_State* L) {
  luaL_getmetatable(L, kWheelsetType);
  lua_getfield(L, -1, "methods");
  const luaL_Reg methods[] = {{"contact", guarded<wheelset_contact>},
                              {"equilibrium", guarded<wheelset_equilibrium>},
                              {"wheel", guarded<wheelset_wheel>},
                              {"rigid", guarded<wheelset_rigid>},
                              {"sweep", guarded<wheelset_sweep>},
                              {nullptr, nullptr}};
  luaL_setfuncs(L, methods, 0);
  lua_pop(L, 2);
}

}  // namespace wrc::lua
