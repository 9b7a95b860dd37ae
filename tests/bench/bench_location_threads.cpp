// Contact location in worker threads (the pattern of parallel sweeps): one model shared read-only, each thread with
// its own state and its own Lua state running the model's strategy. Prints the throughput for 1..N threads and
// checks that every thread finds exactly the segments a serial run finds.
//
//   bench_location_threads [poses=2000] [threads=2] [strategy=fast]
//
// Two ways to give a worker the strategy: Locator(model), which calls model.strategy.make_search() (a fresh Lua state
// per call), and make_lua_search(L, model) with a Lua state the worker made with new_state() (its own state, as a
// sweep worker has).
#include "geometry/geometry_fixtures.hpp"
#include "lua/bindings.hpp"
#include "lua/strategy_binding.hpp"
#include "lua/wheelset_binding.hpp"
#include "wrc/geometry/location.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Args {
  int poses = 2000, threads = 2;
  std::string strategy = "fast";
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const char* eq = std::strchr(argv[i], '=');
    if (!eq) continue;
    const std::string k(argv[i], static_cast<std::size_t>(eq - argv[i]));
    if (k == "poses") a.poses = std::atoi(eq + 1);
    else if (k == "threads") a.threads = std::atoi(eq + 1);
    else if (k == "strategy") a.strategy = eq + 1;
  }
  return a;
}

using Segments = std::vector<wrc::Segment>;

Segments all_segments(const wrc::LocationState& st) {
  Segments s = st.segments(wrc::kLeft);
  s.insert(s.end(), st.segments(wrc::kRight).begin(), st.segments(wrc::kRight).end());
  return s;
}

bool same(const Segments& a, const Segments& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].line != b[i].line || a[i].x_t != b[i].x_t || a[i].x_l != b[i].x_l || a[i].cone_t != b[i].cone_t ||
        a[i].cone_l != b[i].cone_l)
      return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) try {
  const Args a = parse(argc, argv);
  lua_State* L = wrc::lua::new_state();
  const std::string code = fmt::format(
      "bench_ws = wrc.wheelset{{wheel = wrc.profile.load(wrc.paths.profiles .. '/s1002.lua'), "
      "rail = wrc.profile.load(wrc.paths.profiles .. '/60e1.lua'), strategy = '{}'}}",
      a.strategy);
  if (luaL_dostring(L, code.c_str()) != LUA_OK) {
    std::fprintf(stderr, "%s\n", lua_tostring(L, -1));
    return 1;
  }
  lua_getglobal(L, "bench_ws");
  const auto model = wrc::lua::check_wheelset(L, -1, "bench")->geometry_ptr();
  lua_pop(L, 1);

  std::mt19937_64 rng(3);
  std::vector<wrc::Pose> poses;
  for (int i = 0; i < a.poses; ++i)
    poses.push_back(wrc::test::random_pose(rng, *model->track, wrc::test::log_uniform(rng, 1e-6, 1e-3)));

  // Serial reference in the main Lua state.
  std::vector<Segments> ref(poses.size());
  const auto t0 = std::chrono::steady_clock::now();
  {
    wrc::Locator loc(model, wrc::lua::make_lua_search(L, model->strategy));
    for (std::size_t i = 0; i < poses.size(); ++i) ref[i] = all_segments(loc.locate(poses[i]));
  }
  const double serial = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("strategy '%s', %d poses; serial (main Lua state): %.2f us per pose\n", a.strategy.c_str(), a.poses,
              serial / a.poses * 1e6);

  for (int way = 0; way < 2; ++way) {
    for (int nt = 1; nt <= a.threads; ++nt) {
      std::atomic<int> mismatches{0}, next{0};
      std::vector<std::thread> threads;
      const auto t1 = std::chrono::steady_clock::now();
      for (int t = 0; t < nt; ++t) {
        threads.emplace_back([&, way] {
          lua_State* W = nullptr;
          std::unique_ptr<wrc::Locator> loc;
          if (way == 0) {
            loc = std::make_unique<wrc::Locator>(model);  // model.strategy.make_search(): its own Lua state
          } else {
            W = wrc::lua::new_state();  // the worker's own state, as a sweep worker has
            loc = std::make_unique<wrc::Locator>(model, wrc::lua::make_lua_search(W, model->strategy));
          }
          for (int i; (i = next.fetch_add(1)) < static_cast<int>(poses.size());)
            if (!same(all_segments(loc->locate(poses[i])), ref[i])) ++mismatches;
          loc.reset();
          if (W) lua_close(W);
        });
      }
      for (auto& th : threads) th.join();
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      std::printf("%s, %d thread%s: %.2f us per pose (wall), %d poses differing from the serial run\n",
                  way == 0 ? "Locator(model)          " : "make_lua_search(worker) ", nt, nt > 1 ? "s" : " ",
                  dt / a.poses * 1e6, mismatches.load());
    }
  }
  lua_close(L);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_location_threads: %s\n", e.what());
  return 1;
}
