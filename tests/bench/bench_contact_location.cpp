// Contact location benchmark: time per wheelset pose (both wheels) of each strategy on S1002 / 60E1 at the
// paper's 0.1 mm sampling, the ratio to brute force in the same run, the Lua-driven strategy against the same
// pipeline run natively, and a check of every strategy against brute force on its own discretisation.
//
//   bench_contact_location [poses=300] [brute_poses=12] [check_poses=300] [reps=5] [seed=1]
//
// Poses: |y| <= 10 mm, |yaw| <= 30 mrad, |roll| <= 10 mrad, deepest penetration log-uniform in 1 um .. 1 mm (as the
// tests). Times are thread CPU time (one core), the best of `reps` passes over the pose set, per pose, for
// locate_contact (search + segments + patches; not the Lua result tables of ws:contact).
#include "bench/timing.hpp"
#include "geometry/geometry_fixtures.hpp"
#include "lua/bindings.hpp"
#include "lua/strategy_binding.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/core/error.hpp"
#include "wrc/geometry/location.hpp"

#include <fmt/format.h>

#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

using wrc::bench::thread_cpu_s;  // the time on one core, unaffected by waiting for a core on a shared machine

struct Args {
  int poses = 300, brute_poses = 12, check_poses = 300, reps = 5;
  unsigned seed = 1;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const char* eq = std::strchr(argv[i], '=');
    if (!eq) continue;
    const std::string k(argv[i], static_cast<std::size_t>(eq - argv[i]));
    const int v = std::atoi(eq + 1);
    if (k == "poses") a.poses = v;
    else if (k == "brute_poses") a.brute_poses = v;
    else if (k == "check_poses") a.check_poses = v;
    else if (k == "reps") a.reps = v;
    else if (k == "seed") a.seed = static_cast<unsigned>(v);
  }
  return a;
}

void run(lua_State* L, const std::string& code) {
  if (luaL_loadstring(L, code.c_str()) != LUA_OK || wrc::lua::pcall_traceback(L, 0, 0) != LUA_OK) {
    std::fprintf(stderr, "lua: %s\n", lua_tostring(L, -1));
    std::exit(1);
  }
}

std::shared_ptr<const wrc::GeometryModel> build(lua_State* L, const std::string& strategy) {
  run(L, fmt::format("bench_ws = wrc.wheelset{{wheel = bench_wheel, rail = bench_rail, strategy = {}}}", strategy));
  lua_getglobal(L, "bench_ws");
  auto m = wrc::lua::check_wheelset(L, -1, "bench")->geometry_ptr();
  lua_pop(L, 1);
  return m;
}

// Time per pose (s) of two searches on one model, best of `reps` passes over poses[0..n) each, the passes of the
// two interleaved so that both see the same load of the (shared) machine.
struct PairTimes {
  double a = 1e30, b = 1e30;
  long long tests = 0;  // closed-form tests per pose (first search)
};
PairTimes time_pair(const wrc::GeometryModel& m, wrc::PoseSearch& sa, wrc::PoseSearch& sb,
                    const std::vector<wrc::Pose>& poses, int n, int reps) {
  wrc::LocationState st;
  PairTimes t;
  long long tests = 0;
  for (int r = 0; r < reps; ++r) {
    for (int which = 0; which < 2; ++which) {
      wrc::PoseSearch& s = which == 0 ? sa : sb;
      const double t0 = thread_cpu_s();
      for (int i = 0; i < n; ++i) {
        wrc::locate_contact(m, poses[i], st, s);
        if (r == 0 && which == 0) tests += st.counters(wrc::kLeft).tests + st.counters(wrc::kRight).tests;
      }
      const double dt = (thread_cpu_s() - t0) / n;
      (which == 0 ? t.a : t.b) = std::min(which == 0 ? t.a : t.b, dt);
    }
  }
  t.tests = tests / n;
  return t;
}

// Same patches and segments (segment ends within 1e-9 m, same lines and cones).
bool same(const wrc::LocationState& a, const wrc::LocationState& b) {
  for (int s : {wrc::kLeft, wrc::kRight}) {
    if (a.patches(s).size() != b.patches(s).size() || a.segments(s).size() != b.segments(s).size()) return false;
    for (std::size_t i = 0; i < a.segments(s).size(); ++i) {
      const auto &x = a.segments(s)[i], &y = b.segments(s)[i];
      if (x.line != y.line || x.cone_t != y.cone_t || x.cone_l != y.cone_l || std::abs(x.x_t - y.x_t) > 1e-9 ||
          std::abs(x.x_l - y.x_l) > 1e-9)
        return false;
    }
    for (std::size_t i = 0; i < a.patches(s).size(); ++i)
      if (a.patches(s)[i].first_segment != b.patches(s)[i].first_segment ||
          a.patches(s)[i].segment_count != b.patches(s)[i].segment_count)
        return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) try {
  const Args a = parse(argc, argv);
  lua_State* L = wrc::lua::new_state();
  run(L, "bench_wheel = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua'); "
         "bench_rail = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua')");

  struct Entry {
    const char* name;
    wrc::NativePlan plan;
    bool all_pairs;  // every line x every cone: timed on brute_poses only
  };
  using Scan = wrc::NativePlan::Scan;
  const std::vector<Entry> entries = {{"brute", {false, Scan::test}, true},
                                      {"uniform", {false, Scan::test}, true},
                                      {"constant_slope", {false, Scan::test}, true},
                                      {"coarse", {true, Scan::test}, false},
                                      {"topology", {false, Scan::walk}, false},
                                      {"fast", {true, Scan::walk}, false},
                                      {"uniform+coarse+topology", {true, Scan::walk}, false}};

  std::map<std::string, std::shared_ptr<const wrc::GeometryModel>> models;
  for (const auto& e : entries) {
    // "a+b+c" -> {'a', 'b', 'c'} (a composition), "a" -> 'a'
    std::string spec = "{'", name = e.name;
    for (char ch : name) spec += ch == '+' ? std::string("', '") : std::string(1, ch);
    spec += "'}";
    models[e.name] = build(L, name.find('+') == std::string::npos ? fmt::format("'{}'", name) : spec);
  }

  std::mt19937_64 rng(a.seed);
  std::vector<wrc::Pose> poses;
  for (int i = 0; i < a.poses; ++i)
    poses.push_back(wrc::test::random_pose(rng, *models["brute"]->track, wrc::test::log_uniform(rng, 1e-6, 1e-3)));

  std::printf("contact location, S1002 / 60E1, %d random poses (|y| <= 10 mm, |yaw| <= 30 mrad, |roll| <= 10 mrad, "
              "penetration 1 um .. 1 mm log-uniform); CPU time per pose, best of %d passes\n\n",
              a.poses, a.reps);
  std::printf("%-24s %6s %6s %11s %12s %12s %8s %10s\n", "strategy", "cones", "lines", "tests/pose", "Lua us/pose",
              "native us", "Lua/nat", "vs brute");
  const int nb = std::min(a.brute_poses, a.poses);
  wrc::NativeSearch brute_search({false, Scan::test});
  double brute_t = 0;
  for (const auto& e : entries) {
    const auto& m = *models[e.name];
    auto lua_search = wrc::lua::make_lua_search(L, m.strategy);
    wrc::NativeSearch native(e.plan);
    const int n = e.all_pairs ? nb : a.poses;
    const int reps = e.all_pairs ? 1 : a.reps;
    const PairTimes t = time_pair(m, *lua_search, native, poses, n, reps);
    if (std::string(e.name) == "brute") brute_t = t.a;
    std::printf("%-24s %6d %6d %11lld %12.2f %12.2f %8.3f %9.1fx\n", e.name, m.side[0].wheel.cone_count(),
                m.side[0].rail.count(), t.tests, t.a * 1e6, t.b * 1e6, t.a / t.b, brute_t / t.a);
  }
  std::printf("\n(brute: %.2f ms per pose over %d poses; 'vs brute' = brute time / Lua strategy time)\n", brute_t * 1e3,
              nb);

  // Each strategy against brute force on the same discretisation: one brute-force run per pose and discretisation
  // (coarse, topology and uniform+coarse+topology share the uniform one; fast has the constant-slope one).
  const int nc = std::min(a.check_poses, a.poses);
  std::printf("\ncheck against brute force on the same discretisation at 0.1 mm (%d poses):\n", nc);
  const std::vector<std::pair<std::string, std::vector<std::string>>> families = {
      {"coarse", {"coarse", "topology", "uniform+coarse+topology"}}, {"fast", {"fast"}}};
  for (const auto& [ref_name, members] : families) {
    std::vector<int> mismatches(members.size(), 0);
    std::vector<std::unique_ptr<wrc::lua::LuaSearch>> searches;
    for (const auto& name : members) searches.push_back(wrc::lua::make_lua_search(L, models[name]->strategy));
    int patches = 0, segments = 0;
    wrc::LocationState ref, st;
    for (int i = 0; i < nc; ++i) {
      wrc::locate_contact(*models[ref_name], poses[i], ref, brute_search);
      for (int s : {wrc::kLeft, wrc::kRight}) {
        patches += static_cast<int>(ref.patches(s).size());
        segments += static_cast<int>(ref.segments(s).size());
      }
      for (std::size_t k = 0; k < members.size(); ++k) {
        wrc::locate_contact(*models[members[k]], poses[i], st, *searches[k]);
        if (!same(st, ref)) ++mismatches[k];
      }
    }
    for (std::size_t k = 0; k < members.size(); ++k)
      std::printf("  %-24s %d of %d poses differ (%d patches, %d segments in the reference)\n", members[k].c_str(),
                  mismatches[k], nc, patches, segments);
  }
  lua_close(L);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_contact_location: %s\n", e.what());
  return 1;
}
