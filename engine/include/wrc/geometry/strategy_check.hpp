// The opt-in cross check of a location strategy against brute force (docs/guide/robustness.md "Checking a strategy"):
// random poses of a study's range are located with the strategy and with every line against every cone of the same
// discretisation (NativeSearch{false, test}, ws:locate{search = "brute"}); any difference is an error naming the first
// pose. A user strategy that prunes too much would otherwise miss contact areas silently (forces a few percent low).
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/core/parallel.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/geometry/model.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace wrc {

struct StrategyCheckOptions {
  int poses = 100;                            // random poses to check
  std::array<double, 2> y{-0.010, 0.010};     // lateral position (m), uniform
  std::array<double, 2> yaw{-0.030, 0.030};   // rad, uniform
  std::array<double, 2> roll{-0.010, 0.010};  // rad, uniform
  std::array<double, 2> depth{1e-6, 1e-3};    // m below the height where the wheelset first touches, log-uniform
  std::uint64_t seed = 1;
  int threads = 0;                            // worker threads (0: all cores); 1 for a strategy bound to one thread
  Progress progress;                          // (poses done, total, 0) after each pose, serialised
  // The front end's stop (Ctrl-C): once it turns true no pose begins, and the check throws "stopped" (a check cut
  // short has not checked the strategy).
  const std::atomic<bool>* stop = nullptr;
};

struct StrategyCheckResult {
  int poses = 0;            // poses checked (all equal to brute force)
  int threads = 1;
  int contact_poses = 0;    // poses where brute force found at least one inter-penetration area
  long long patches = 0;    // areas found over all poses (both wheels)
  long long tests = 0;      // closed-form tests of the strategy, and of brute force
  long long brute_tests = 0;
  double seconds = 0;       // wall time
};

// The poses the check uses (deterministic for a seed): y, yaw, roll drawn, z = first touch - depth (the touching
// height found from the rail lines' deepest points, yaw included).
std::vector<Pose> strategy_check_poses(const GeometryModel& model, const StrategyCheckOptions& options);

// Runs the check with searches made by `make_search` (one per worker thread). Throws wrc::Error naming the first
// pose (in drawing order) whose patches or segments differ from brute force's (segment ends within 1e-9 m), with
// what differs; or a pose the strategy fails on.
StrategyCheckResult check_strategy(const GeometryModel& model, const StrategyCheckOptions& options,
                                   const std::function<std::unique_ptr<PoseSearch>()>& make_search);

// ws:check_strategy{poses =, y = {min, max}, yaw = {min, max}, roll = {min, max}, depth = {min, max}, seed =,
// threads =} (ranges as two-number arrays; defaults as above). `progress` is left to the front end.
StrategyCheckOptions read_strategy_check_options(OptionReader& options);
// poses, threads, contact_poses, patches, tests, brute_tests, seconds.
void describe(const StrategyCheckResult& result, FieldSink& out);

}  // namespace wrc
