// The paper's wheelset (S1002 on 60E1, 1:40, gauge 1435 mm, r0 = 450 mm, grid 0.2 mm) built from C++ alone -- the
// profiles read by the text reader plugin, the built-in "accurate" strategy, no Lua state -- gives bit for bit the
// numbers of the same calls made through Lua (wrc.wheelset with the Lua strategy files, in a Lua session): one
// wheel with Fz given, an equilibrium and a small sweep. The profile files are written by the fixture
// tests/data/profile/write_text_profiles.lua (17 significant digits: they read back exactly).
#include "lua/lua.hpp"
#include "wheelset/paper_profiles.hpp"
#include "wheelset/vertical_load.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/geometry/strategy.hpp"
#include "wrc/lua/host.hpp"
#include "wrc/profile/reader.hpp"
#include "wrc/wheelset/wheelset.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

using wrc::test::paper_profiles;
using wrc::test::profile_file;
using wrc::test::within_rel;
using namespace wrc;

namespace {

// The paper's wheelset on the coarser 0.5 mm grid the wheel and warm-start tests use.
constexpr double kCoarseElement = 0.5e-3;
std::shared_ptr<const Wheelset> coarse_paper_wheelset(ContactSurface surface = ContactSurface::conformal) {
  WheelsetParams params;
  params.contact.element = kCoarseElement;
  params.contact.surface = surface;
  return build_wheelset(paper_profiles(), params);
}

// A number of the Lua global table `R` at a dotted path.
double lua_number(lua::Session& s, const std::string& path) {
  auto* L = static_cast<lua_State*>(s.state());
  lua_getglobal(L, "R");
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string key = path.substr(start, dot - start);
    if (!key.empty() && key.find_first_not_of("0123456789") == std::string::npos) lua_geti(L, -1, std::stoll(key));
    else lua_getfield(L, -1, key.c_str());
    lua_remove(L, -2);
    start = dot + 1;
  }
  REQUIRE_MESSAGE(lua_isnumber(L, -1), path);
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

}  // namespace

TEST_CASE("the paper's wheelset from C++ alone gives bit for bit the numbers of the same calls through Lua") {
  const WheelsetProfiles profiles = paper_profiles();
  const WheelsetParams params;  // the defaults are the paper's track and material
  CHECK(params.strategy == "accurate");
  const auto ws = build_wheelset(profiles, params);
  auto work = ws->make_workspace();
  const ContactModel& m = ws->contact_model();

  work->forget();
  const WheelResult w = solve_wheel(m, {kLeft, 5e-3, 0.0, 0.0, 100e3}, *work);
  work->forget();
  const EquilibriumResult e = solve_equilibrium(m, {3e-3, 0.0, 200e3}, *work);
  SweepOptions so;
  so.threads = 2;
  so.rigid = true;
  const SweepResult s = run_sweep(m, {0.0, 2e-3, 4e-3, 5.5e-3, -3e-3}, {0.0, 0.01}, so, [&] { return ws->make_workspace(); });
  REQUIRE(w.converged);
  REQUIRE(e.converged);

  lua::Session lua;
  const auto err = lua.run(fmt::format(R"(
    local w = wrc.profile.load("{}", {{kind = "wheel"}})
    local r = wrc.profile.load("{}", {{kind = "rail"}})
    local ws = wrc.wheelset{{wheel = w, rail = r}}
    R = {{wheel = ws:wheel{{side = "left", y = 5e-3, Fz = 100e3}},
          eq = ws:equilibrium{{y = 3e-3, Q = 200e3}},
          sweep = ws:sweep{{y = {{0, 2e-3, 4e-3, 5.5e-3, -3e-3}}, yaw = {{0, 0.01}}, Q = 200e3, threads = 2,
                           rigid = true, progress = false}}}}
    assert(ws.strategy.name == "accurate")
  )", profile_file("s1002"), profile_file("60e1")));
  REQUIRE_MESSAGE(!err, err.value_or(""));

  CHECK(lua_number(lua, "wheel.z") == w.z);
  CHECK(lua_number(lua, "wheel.force.y") == w.wheel.force.y());
  CHECK(lua_number(lua, "wheel.force.z") == w.wheel.force.z());
  CHECK(lua_number(lua, "wheel.patches.1.pmax") == w.wheel.patches.at(0).solution.max_pressure);
  CHECK(lua_number(lua, "eq.z") == e.z);
  CHECK(lua_number(lua, "eq.roll") == e.roll);
  CHECK(lua_number(lua, "eq.Y") == e.Y);
  CHECK(lua_number(lua, "eq.left.patches.1.area") == e.contact.wheel[kLeft].patches.at(0).solution.area);
  for (std::size_t i = 0; i < s.cases.size(); ++i) {
    CAPTURE(i);
    const std::string row = fmt::format("sweep.{}.", i + 1);
    REQUIRE(s.elastic[i].converged);
    CHECK(lua_number(lua, row + "z") == s.elastic[i].z);
    CHECK(lua_number(lua, row + "roll") == s.elastic[i].roll);
    CHECK(lua_number(lua, row + "Y") == s.elastic[i].Y);
    CHECK(lua_number(lua, row + "Mz") == s.elastic[i].Mz);
    CHECK(lua_number(lua, row + "rigid.z") == s.rigid[i]->z);
  }
}

// A grid finer than the strategy's default step (0.1 mm) resolves the kinks between its cones and lines, and pmax then
// grows with the refinement (docs/guide/normal.md): the default step follows the grid instead, natively and in Lua
// alike. S1002 on 60E1 at a 0.05 mm grid, the left wheel at the flange root (y = 7 mm) with 1 kN, a contact ~0.6 mm
// wide: against the same wheel with the profiles resampled 4x finer than the grid (the discretisation converged),
// the default is within 0.5 % in pmax; the old default, step = 0.1 mm given explicitly (honoured), is 2 % or more
// above (measured 3.5 %).
TEST_CASE("a grid finer than 0.1 mm: the strategy's default step follows it, natively and in Lua alike") {
  const WheelsetProfiles profiles = paper_profiles();
  WheelsetParams params;
  params.contact.element = 0.05e-3;
  const auto pmax = [&](const std::shared_ptr<const Wheelset>& ws) {
    auto work = ws->make_workspace();
    const WheelResult w = solve_wheel(ws->contact_model(), {kLeft, 7e-3, 0.0, 0.0, 1e3}, *work);
    REQUIRE_MESSAGE(w.converged, w.message);
    REQUIRE(w.wheel.patches.size() == 1);
    return w.wheel.patches[0].solution.max_pressure;
  };
  const auto with_step = [&](double step) {
    OptionTable options;
    options.set("step", OptionValue::of(step));
    return build_wheelset(profiles, params, native_strategy("accurate", options, params.contact.element));
  };
  const auto ws = build_wheelset(profiles, params);
  CHECK(std::get<double>(ws->strategy().info().options.at("step")) == 0.05e-3);
  const double p_default = pmax(ws), p_fine = pmax(with_step(0.0125e-3)), p_old = pmax(with_step(0.1e-3));
  CHECK(p_default == within_rel(p_fine, 5e-3));
  CHECK(p_old > 1.02 * p_fine);
  // A grid coarser than the default step leaves it; a step given is kept; a strategy without one gets none.
  CHECK(std::get<double>(native_strategy("accurate", {}, 0.2e-3)->info().options.at("step")) == 0.1e-3);
  CHECK(std::get<double>(native_strategy("fast", {}, 0.05e-3)->info().options.at("step")) == 0.05e-3);
  CHECK(native_strategy("brute", {}, 0.05e-3)->info().options.count("step") == 0);

  lua::Session lua;
  const auto err = lua.run(fmt::format(R"(
    local w = wrc.profile.load("{}", {{kind = "wheel"}})
    local r = wrc.profile.load("{}", {{kind = "rail"}})
    local ws = wrc.wheelset{{wheel = w, rail = r, grid = 0.05e-3}}
    local given = wrc.wheelset{{wheel = w, rail = r, grid = 0.05e-3, strategy = {{"uniform", "topology", step = 0.1e-3}}}}
    assert(given.strategy.options.step == 0.1e-3, "a step given is kept")
    R = {{step = ws.strategy.options.step, wheel = ws:wheel{{side = "left", y = 7e-3, Fz = 1e3}}}}
  )",
                                       profile_file("s1002"), profile_file("60e1")));
  REQUIRE_MESSAGE(!err, err.value_or(""));
  CHECK(lua_number(lua, "step") == 0.05e-3);
  CHECK(lua_number(lua, "wheel.patches.1.pmax") == p_default);
}

// areas::evaluate_vertical_load (solve_wheel's predictor): the wheel's area solved for a vertical force F is the
// pose's penetration problem with the wheel pressed further down by the solution's approach. Against evaluations of
// the poses themselves (grid 0.5 mm), on the tread and at the flange root (contact angle 26 deg, where a force
// without the normals' vertical parts as weights would be ~10 % off): F of the pose gives approach 0; F of the pose
// 0.1 um lower gives 0.1 um. The conformal grid's elements stay on the rail's lattice and the approach deepens h by
// the wheel normal's z part, so the prediction is exact to first order: measured 2e-6 of the step on the tread,
// 6e-5 at the flange root (with elements aligned to the area's moving origin, and the approach deepening h by the
// row normals' z part, it was 2e-4 and 1e-2).
TEST_CASE("vertical load: the multiplier is the further vertical approach that carries the force") {
  const auto wheelset = coarse_paper_wheelset();
  const ContactModel& model = wheelset->contact_model();
  const auto work = wheelset->make_workspace();
  ContactWorkspace& ws = *work;
  for (double y : {3e-3, 6.4e-3}) {
    CAPTURE(y);
    const WheelResult w = solve_wheel(model, {kLeft, y, 0.0, 0.0, 100e3}, ws);
    REQUIRE(w.converged);
    ContactRequest pen;
    pen.only_side = kLeft;
    pen.tolerance = 1e-11;
    auto Fz = [&](double z) { return evaluate_contact(model, {y, z, 0.0, 0.0}, ws, pen).wheel[kLeft].force.z(); };
    auto predicted = [&](double F) {
      const ContactResult c = areas::evaluate_vertical_load(model, {y, w.z, 0.0, 0.0}, ws, pen, {F});
      REQUIRE(c.wheel[kLeft].patches.size() == 1);
      const halfspace::NormalSolution& s = c.wheel[kLeft].patches[0].solution;
      REQUIRE(s.load.control == halfspace::NormalLoad::Control::force);
      CHECK(c.wheel[kLeft].force.z() == within_rel(F, 1e-9));
      return s.approach;
    };
    const double F0 = Fz(w.z);
    CHECK(std::abs(predicted(F0)) < 1e-13);
    const double d = 1e-7, F1 = Fz(w.z - d);
    REQUIRE(F1 > F0);
    const double a = predicted(F1);
    MESSAGE("y = ", y * 1e3, " mm, contact angle ", w.wheel.angle * 180 / std::numbers::pi, " deg: predicted approach / actual - 1 = ", a / d - 1);
    CHECK(a == within_rel(d, 2e-4));
  }
  ContactRequest bad;
  const Pose centred{0.0, 0.0, 0.0, 0.0};
  CHECK_THROWS_WITH_AS(areas::evaluate_vertical_load(model, centred, ws, bad, {1e5}), doctest::Contains("only_side"), Error);
  bad.only_side = kLeft;
  bad.sensitivity = true;
  CHECK_THROWS_WITH_AS(areas::evaluate_vertical_load(model, centred, ws, bad, {1e5}), doctest::Contains("sensitivities"),
                       Error);
  bad.sensitivity = false;
  CHECK_THROWS_WITH_AS(areas::evaluate_vertical_load(model, centred, ws, bad, {-1}),
                       doctest::Contains("vertical load of -1 N"), Error);
}

// solve_wheel from cold: a coarse estimate, one prediction and the evaluation of the predicted pose, which carries Fz
// to 1e-6 on every single-area pose from the tread to the flange root (y = 0 .. 6.5 mm): 3 evaluations, the third
// at the model's tolerance and equal to a fresh evaluation of the pose.
TEST_CASE("solve_wheel: three evaluations from the tread to the flange root") {
  const auto wheelset = coarse_paper_wheelset();
  const ContactModel& model = wheelset->contact_model();
  const auto work = wheelset->make_workspace();
  for (int k = 0; k <= 13; ++k) {
    const double y = 0.5e-3 * k;
    CAPTURE(y);
    work->forget();
    const WheelResult w = solve_wheel(model, {kLeft, y, 0.0, 0.0, 100e3}, *work);
    CHECK(w.converged);
    CHECK(w.iterations == 3);
    CHECK(std::abs(w.wheel.force.z() - 100e3) <= 1e-6 * 100e3);
    work->forget();
    ContactRequest left;
    left.only_side = kLeft;
    const ContactResult fresh = evaluate_contact(model, {y, w.z, 0.0, 0.0}, *work, left);
    CHECK(fresh.wheel[kLeft].force.z() == within_rel(w.wheel.force.z(), 1e-8));
  }
}

// The conformal grids' elements lie on each rail's fixed lattice: track x and the arc length from the rail's lattice
// origin are integer multiples of the element at every pose (here three heights and two lateral positions, both
// wheels), and the two rails' lattice origins are mirror images (the point of each rail nearest its profile's origin).
TEST_CASE("conformal grids: the elements lie on the rail's fixed lattice, mirrored between the rails") {
  const auto wheelset = coarse_paper_wheelset();
  const ContactModel& model = wheelset->contact_model();
  const auto work = wheelset->make_workspace();
  const double e = kCoarseElement;
  auto on_lattice = [&](double v) { return std::abs(v / e - std::round(v / e)) < 1e-9; };
  for (double y : {1e-3, 6.3e-3})
    for (double dz : {0.0, 30e-6, 90e-6}) {
      const WheelResult w = solve_wheel(model, {kLeft, y, 0.0, 0.0, 100e3}, *work);
      REQUIRE(w.converged);
      const ContactResult c = evaluate_contact(model, {y, w.z - dz, 0.0, 0.0}, *work, {});
      for (int side : {kLeft, kRight})
        for (const PatchContact& pc : c.wheel[side].patches) {
          CAPTURE(y);
          CAPTURE(dz);
          CAPTURE(side);
          REQUIRE(pc.conformal);
          const halfspace::Grid& g = pc.solution.grid;
          const double s_lattice = model.rail_lattice_origin(side);
          for (int i : {0, g.nx - 1}) CHECK(on_lattice(pc.conformal->x0 + g.x(i)));
          for (int j : {0, g.ny / 2, g.ny - 1}) CHECK(on_lattice(pc.conformal->s0 + g.y(j) - s_lattice));
        }
    }
  // The rail points at the lattice origins: mirrored across the track's centre line.
  auto point_at = [&](int side, double s) {
    const RailLines& rail = model.geometry().side[side].rail;
    const std::vector<double>& arc = model.rail_arc(side);
    int r = 0;
    while (r + 2 < rail.count() && arc[static_cast<std::size_t>(r + 1)] <= s) ++r;
    const double t = (s - arc[static_cast<std::size_t>(r)]) / (arc[static_cast<std::size_t>(r + 1)] - arc[static_cast<std::size_t>(r)]);
    return std::array<double, 2>{rail.y[r] + t * (rail.y[r + 1] - rail.y[r]), rail.z[r] + t * (rail.z[r + 1] - rail.z[r])};
  };
  const auto left = point_at(kLeft, model.rail_lattice_origin(kLeft)), right = point_at(kRight, model.rail_lattice_origin(kRight));
  CHECK(left[0] == within_rel(-right[0], 1e-12));
  CHECK(left[1] == within_rel(right[1], 1e-12));
  CHECK(std::abs(std::abs(left[0]) - 0.7175) < 0.04);  // on the rail head, near its centre (gauge 1435 mm)
}

// Warm starts map the last evaluation's pressure onto the new grid: at the same pose they are the solution (no CG
// iteration), at a pose 0.2 um away close to it (far fewer iterations than a cold solve, and the same answer).
// Where the grids share the lattice and the new one carries the whole old pressure, the old displacements come too.
TEST_CASE("warm starts: the same pose needs no CG iteration, a nearby pose few, with the cold solve's answer") {
  for (ContactSurface surface : {ContactSurface::conformal, ContactSurface::planar}) {
    const std::string name = surface_name(surface);
    CAPTURE(name);
    const auto wheelset = coarse_paper_wheelset(surface);
    const ContactModel& model = wheelset->contact_model();
    const auto work = wheelset->make_workspace();
    ContactRequest left;
    left.only_side = kLeft;
    const Pose pose{3e-3, -0.1e-3, 0.164e-3, 0.002}, near{3.0002e-3, -0.10005e-3, 0.164e-3, 0.002};
    auto iterations = [](const ContactResult& c) {
      REQUIRE(c.wheel[kLeft].patches.size() == 1);
      const halfspace::NormalSolution& s = c.wheel[kLeft].patches[0].solution;
      return s.iterations + s.coarse_iterations;
    };
    const ContactResult first = evaluate_contact(model, pose, *work, left);
    const ContactResult again = evaluate_contact(model, pose, *work, left);
    CHECK(iterations(again) == 0);
    // On the conformal lattice the start's displacements are the last solve's too: only the check's product is left.
    if (surface == ContactSurface::conformal) CHECK(again.wheel[kLeft].patches[0].solution.products == 1);
    CHECK(again.wheel[kLeft].force.z() == within_rel(first.wheel[kLeft].force.z(), 1e-12));
    const ContactResult warm = evaluate_contact(model, near, *work, left);
    work->forget();
    const ContactResult cold = evaluate_contact(model, near, *work, left);
    MESSAGE(name, ": CG iterations warm ", iterations(warm), ", cold ", iterations(cold));
    CHECK(5 * iterations(warm) <= 3 * iterations(cold));
    CHECK(warm.wheel[kLeft].force.z() == within_rel(cold.wheel[kLeft].force.z(), 1e-7));
  }
}
