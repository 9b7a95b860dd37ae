// A location strategy against brute force on random poses (strategy_check.hpp).
#include "wrc/geometry/strategy_check.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/parallel.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/geometry/pose.hpp"
#include "wrc/geometry/wheel_surface.hpp"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <limits>
#include <random>

namespace wrc {
namespace {

// Largest radial overlap of a rail line with its wheel over both sides (> 0: inside), yaw included: the lines'
// closest approaches give a floor, then the deepest point of every line that can beat it.
double max_overlap(const GeometryModel& g, const Pose& pose) {
  const PoseFrame f(pose);
  double best = -std::numeric_limits<double>::infinity();
  for (int s : {kLeft, kRight}) {
    const RailLines& rail = g.side[s].rail;
    const WheelCones& w = g.side[s].wheel;
    for (int r = 0; r < rail.count(); ++r) best = std::max(best, line_overlap_at_closest(w, f, rail.y[r], rail.z[r]));
    for (int r = 0; r < rail.count(); ++r) best = std::max(best, line_approach(w, f, rail.y[r], rail.z[r], best).overlap);
  }
  return best;
}

// The height at which the wheelset at (y, roll, yaw) first touches: raising it by the overlap removes the overlap
// to first order (a vertical move changes every point's distance to the axle by about as much).
double touch_height(const GeometryModel& g, double y, double roll, double yaw) {
  double z = 0;
  for (int k = 0; k < 8; ++k) {
    const double m = max_overlap(g, {y, z, roll, yaw});
    if (!std::isfinite(m)) fail("check_strategy: no rail line meets the wheels at y = {} m", y);
    z += m;
    if (std::abs(m) < 1e-10) break;
  }
  return z;
}

std::string pose_text(const Pose& p) {
  return fmt::format("y = {:.4f} mm, z = {:.5f} mm, roll = {:.4f} mrad, yaw = {:.4f} mrad", p.y * 1e3, p.z * 1e3,
                     p.roll * 1e3, p.yaw * 1e3);
}

bool same_segment(const Segment& a, const Segment& b) {
  return a.line == b.line && a.cone_t == b.cone_t && a.cone_l == b.cone_l && std::abs(a.x_t - b.x_t) <= 1e-9 &&
         std::abs(a.x_l - b.x_l) <= 1e-9;
}

// What differs on one side between the strategy's location and brute force's, or "".
std::string side_difference(const LocationState& s, const LocationState& b, int side) {
  const auto &ss = s.segments(side), &bs = b.segments(side);
  const auto &sp = s.patches(side), &bp = b.patches(side);
  bool same = ss.size() == bs.size() && sp.size() == bp.size();
  for (std::size_t i = 0; same && i < ss.size(); ++i) same = same_segment(ss[i], bs[i]);
  for (std::size_t i = 0; same && i < sp.size(); ++i)
    same = sp[i].first_segment == bp[i].first_segment && sp[i].segment_count == bp[i].segment_count;
  if (same) return "";
  std::string what = fmt::format("{} wheel: {} area(s) of {} segments, brute force {} area(s) of {} segments",
                                 side_name(side), sp.size(), ss.size(), bp.size(), bs.size());
  for (const Segment& x : bs)
    if (std::none_of(ss.begin(), ss.end(), [&](const Segment& y) { return same_segment(x, y); })) {
      what += fmt::format("; the strategy misses rail line {} (y = {:.3f} mm, x = {:.3f} .. {:.3f} mm)", x.line + 1,
                          x.y * 1e3, x.x_t * 1e3, x.x_l * 1e3);
      break;
    }
  return what;
}

void check_range(const std::array<double, 2>& r, const char* key, double lo, double hi) {
  if (!(r[0] <= r[1]) || !(r[0] >= lo) || !(r[1] <= hi))
    fail("check_strategy: '{}' = {{{}, {}}} must be an increasing range within [{}, {}]", key, r[0], r[1], lo, hi);
}

// Per worker: its search, state and counts.
struct Worker {
  std::unique_ptr<PoseSearch> search;
  NativeSearch brute{{false, NativePlan::Scan::test}};
  LocationState mine, ref;
  StrategyCheckResult counts;
};

// A pose as drawn: its height follows from the geometry (touch_height), computed by the worker that checks it.
struct Draw {
  double y, yaw, roll, depth;
};

std::vector<Draw> draw_poses(const StrategyCheckOptions& o) {
  check_range(o.y, "y", -kMaxLateral, kMaxLateral);
  check_range(o.yaw, "yaw", -kMaxYaw, kMaxYaw);
  check_range(o.roll, "roll", -kMaxRoll, kMaxRoll);
  check_range(o.depth, "depth", 1e-9, 0.01);
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  auto draw = [&](double lo, double hi) { return lo + (hi - lo) * U(rng); };
  std::vector<Draw> d(static_cast<std::size_t>(std::max(0, o.poses)));
  for (Draw& p : d) {
    p.y = draw(o.y[0], o.y[1]);
    p.yaw = draw(o.yaw[0], o.yaw[1]);
    p.roll = draw(o.roll[0], o.roll[1]);
    p.depth = std::exp(draw(std::log(o.depth[0]), std::log(o.depth[1])));
  }
  return d;
}

Pose pose_of(const GeometryModel& g, const Draw& d) {
  return {d.y, touch_height(g, d.y, d.roll, d.yaw) - d.depth, d.roll, d.yaw};
}

}  // namespace

std::vector<Pose> strategy_check_poses(const GeometryModel& g, const StrategyCheckOptions& o) {
  std::vector<Pose> poses;
  for (const Draw& d : draw_poses(o)) poses.push_back(pose_of(g, d));
  return poses;
}

StrategyCheckResult check_strategy(const GeometryModel& g, const StrategyCheckOptions& o,
                                   const std::function<std::unique_ptr<PoseSearch>()>& make_search) {
  if (o.poses < 0) fail("check_strategy: poses must be >= 0, got {}", o.poses);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Draw> draws = draw_poses(o);
  const int n = static_cast<int>(draws.size());
  const int threads = thread_count(o.threads, n, "").threads;  // no more threads than poses (the result says how many)
  std::vector<Worker> workers(static_cast<std::size_t>(threads));
  for (Worker& w : workers) w.search = make_search();  // on the calling thread: a strategy may need it
  ProgressCount progress(o.progress, n);
  // A pose that differs throws: the error is the first such pose in drawing order, on any number of threads.
  std::atomic<int> checked{0};
  parallel_for(n, threads, [&](int worker, int i) {
    if (stop_requested(o.stop)) return;
    Worker& w = workers[static_cast<std::size_t>(worker)];
    const Pose p = pose_of(g, draws[static_cast<std::size_t>(i)]);
    auto differs = [&](const std::string& what) {
      fail("check_strategy: the strategy '{}' differs from brute force on the same discretisation at pose {} of {} "
           "(seed {}): {}: {}", g.strategy.name, i + 1, n, o.seed, pose_text(p), what);
    };
    try {
      locate_contact(g, p, w.mine, *w.search);
    } catch (const Error& e) {
      differs(fmt::format("the strategy fails: {}", e.what()));
    }
    locate_contact(g, p, w.ref, w.brute);
    std::string what;
    for (int s : {kLeft, kRight}) {
      if (what.empty()) what = side_difference(w.mine, w.ref, s);
      w.counts.tests += w.mine.counters(s).tests;
      w.counts.brute_tests += w.ref.counters(s).tests;
      w.counts.patches += static_cast<long long>(w.ref.patches(s).size());
    }
    if (!w.ref.patches(kLeft).empty() || !w.ref.patches(kRight).empty()) ++w.counts.contact_poses;
    if (!what.empty()) differs(what);
    ++checked;
    progress.add();
  });
  if (checked < n) fail("check_strategy: stopped after {} of {} poses: the strategy is not checked", checked.load(), n);
  StrategyCheckResult r;
  r.poses = n;
  r.threads = threads;
  for (const Worker& w : workers) {
    r.contact_poses += w.counts.contact_poses;
    r.patches += w.counts.patches;
    r.tests += w.counts.tests;
    r.brute_tests += w.counts.brute_tests;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

StrategyCheckOptions read_strategy_check_options(OptionReader& r) {
  StrategyCheckOptions o;
  o.poses = r.integer("poses", 1, 100'000'000, {"-", "random poses to check"}, o.poses);
  auto range = [&](const char* key, std::array<double, 2>& v, OptionDoc doc) {
    if (auto x = r.numbers(key, doc)) {
      if (x->size() != 2) fail("{}: '{}' must be two numbers {{min, max}}, got {}", r.context(), key, x->size());
      v = {(*x)[0], (*x)[1]};
    }
  };
  range("y", o.y, {"m", "range {min, max} of the lateral position"});
  range("yaw", o.yaw, {"rad", "range {min, max} of the yaw angle"});
  range("roll", o.roll, {"rad", "range {min, max} of the roll angle"});
  range("depth", o.depth, {"m", "range {min, max} below the touching height (log-uniform)"});
  o.seed = static_cast<std::uint64_t>(
      r.integer("seed", 0, INT_MAX, {"-", "seed of the random poses"}, static_cast<int>(o.seed)));
  o.threads = read_threads(r, o.threads);
  return o;
}

void describe(const StrategyCheckResult& r, FieldSink& out) {
  out.integer("poses", r.poses, {"-", "poses checked (all equal to brute force)"});
  out.integer("threads", r.threads, {"-", "worker threads used"});
  out.integer("contact_poses", r.contact_poses, {"-", "poses where brute force found an inter-penetration area"});
  out.integer("patches", r.patches, {"-", "areas found over all poses, both wheels"});
  out.integer("tests", r.tests, {"-", "closed-form line-cone tests of the strategy"});
  out.integer("brute_tests", r.brute_tests, {"-", "closed-form tests of brute force"});
  out.number("seconds", r.seconds, {"s", "wall time"});
}

}  // namespace wrc
