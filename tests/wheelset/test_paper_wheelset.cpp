// The paper's wheelset (S1002 on 60E1, 1:40, gauge 1435 mm, r0 = 450 mm, grid 0.2 mm) built from C++ alone -- the
// profiles read by the text reader plugin, the built-in "accurate" strategy, no Lua state -- gives bit for bit the
// numbers of the same calls made through Lua (wrc.wheelset with the Lua strategy files, in a Lua session): one
// wheel with Fz given, an equilibrium and a small sweep. The profile files are written by the fixture
// tests/data/profile/write_text_profiles.lua (17 significant digits: they read back exactly).
#include "lua/lua.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/lua/host.hpp"
#include "wrc/profile/reader.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <string>

using namespace wrc;

namespace {

std::string profile_file(const char* name) { return fmt::format("{}/{}.csv", WRC_TEST_PROFILES, name); }

Profile load_text(const char* name, ProfileKind kind) {
  LoadOptions o;
  o.kind = kind;
  return load_profile_file(profile_file(name), o);
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
  WheelsetProfiles profiles;
  const Profile wheel = load_text("s1002", ProfileKind::wheel), rail = load_text("60e1", ProfileKind::rail);
  profiles.wheel = {wheel, wheel};
  profiles.rail = {rail, rail};
  const WheelsetParams params;  // the defaults are the paper's track and material
  CHECK(params.strategy == "accurate");
  const auto ws = build_wheelset(profiles, params);
  auto work = ws->make_workspace();
  const ContactModel& m = ws->contact_model();

  work->forget();
  const WheelResult w = solve_wheel(m, kLeft, 5e-3, 0.0, 0.0, 100e3, *work);
  work->forget();
  const EquilibriumResult e = solve_equilibrium(m, 3e-3, 0.0, 200e3, *work);
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
