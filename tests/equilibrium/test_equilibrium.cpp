// The equilibrium solvers on synthetic profiles (tests/geometry/geometry_fixtures.hpp: a 1/40 tread with a 28 mm
// flange on an R300 rail head; the S1002/60E1 cases are Lua tests, tests/scripts/equilibrium_*.lua):
//  - the rigid reference against a kinematic computation written here on the placed 2-D profiles;
//  - the sweep's contract: cases in the order given, the same results on 1 and 2 threads and as single solves,
//    progress reported once per case, a failed case recorded while the sweep goes on;
//  - solve_equilibrium: tighter tolerances are honoured, a far start reaches the same solution, the trace sees
//    every iterate, bad input throws;
//  - the solvers (and evaluate_contact, run_sweep, a trajectory's wheel step) check their cases and options first.
#include "geometry/geometry_fixtures.hpp"
#include "wrc/core/error.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/equilibrium/trajectory.hpp"
#include "wheelset/synthetic_wheelset.hpp"
#include "approx.hpp"

#include <Eigen/Geometry>
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using wrc::test::within_rel;
using namespace wrc;

namespace {

constexpr double kQ = 200e3;

std::shared_ptr<const GeometryModel> synthetic_geometry() {
  auto g = std::make_shared<GeometryModel>(test::make_model(test::synthetic_wheel(0.5e-3), test::synthetic_rail(0.5e-3)));
  g->strategy.name = "native (test)";
  g->strategy.make_search = [] { return std::make_unique<NativeSearch>(NativePlan{}); };
  return g;
}

const ContactModel& synthetic_model() {
  static const ContactModel model = [] {
    ContactOptions o;
    o.element = 0.5e-3;  // coarse: fast tests; the physics does not change
    return ContactModel(synthetic_geometry(), halfspace::Material{2.1e11, 0.3}, o);
  }();
  return model;
}

// Kinematic contact of one side at yaw 0, on the rail as the engine sees it (its lines = the placed rail points)
// and the wheel as its cones (the placed wheel polyline): at yaw 0 the plane x = 0 holds the axle, so the section
// there is exact. Returns the height z at which the wheel just touches with this y and roll, and the touching rail
// point (index).
struct Touch {
  double z = 0;
  int line = -1;
};
Touch touch_height(const GeometryModel& g, int side, double y, double roll) {
  const WheelCones& w = g.side[side].wheel;
  const RailLines& r = g.side[side].rail;
  const double c = std::cos(roll), s = std::sin(roll);
  // The wheel's section at z = 0 (track frame); the cones' generatrix points without the closing points on the axle.
  std::vector<double> wy, wz;
  for (std::size_t i = 1; i + 1 < w.y.size(); ++i) {
    wy.push_back(y + c * w.y[i] - s * w.z[i]);
    wz.push_back(s * w.y[i] + c * w.z[i]);
  }
  Touch best;
  best.z = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < r.count(); ++k) {
    // Lowest wheel surface above the rail point: the section's segments spanning y_r (a vertical flange back
    // spans none, a point on it is reached through its neighbours).
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < wy.size(); ++i) {
      const double y0 = wy[i], y1 = wy[i + 1];
      if (y1 == y0 || (r.y[k] - y0) * (r.y[k] - y1) > 0) continue;
      const double t = (r.y[k] - y0) / (y1 - y0);
      lowest = std::min(lowest, wz[i] + t * (wz[i + 1] - wz[i]));
    }
    if (!std::isfinite(lowest)) continue;
    const double need = r.z[k] - lowest;  // raise the wheelset by this to clear the point
    if (need > best.z) {
      best.z = need;
      best.line = k;
    }
  }
  return best;
}

}  // namespace

TEST_CASE("rigid reference = both wheels touching, by an independent kinematic computation at yaw 0") {
  const GeometryModel& g = synthetic_model().geometry();
  for (double y : {-8e-3, -3e-3, 0.0, 2e-3, 5e-3, 7e-3}) {
    CAPTURE(y);
    // The roll at which both wheels touch at the same height: bisection on the height difference (the left wheel's
    // touching height falls as roll lifts the left side).
    auto diff = [&](double roll) { return touch_height(g, kLeft, y, roll).z - touch_height(g, kRight, y, roll).z; };
    double a = -0.02, b = 0.02;
    REQUIRE(diff(a) > 0);
    REQUIRE(diff(b) < 0);
    for (int i = 0; i < 60; ++i) {
      const double m = 0.5 * (a + b);
      (diff(m) > 0 ? a : b) = m;
    }
    const double roll = 0.5 * (a + b);
    const Touch left = touch_height(g, kLeft, y, roll), right = touch_height(g, kRight, y, roll);
    const RigidResult r = solve_rigid(g, y, 0.0, kQ);
    REQUIRE(r.converged);
    CHECK(std::abs(r.roll - roll) <= 1e-9);
    CHECK(std::abs(r.z - left.z) <= 1e-9);
    CHECK(std::abs(r.z - right.z) <= 1e-9);
    CHECK(r.wheel[kLeft].line == left.line);
    CHECK(r.wheel[kRight].line == right.line);
    // The normal forces balance Q with no roll moment, and Y, My, Mz follow from them (Y = -sum Fy:
    // docs/design.md, section 2).
    Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
    const Eigen::Vector3d centre(0, y, r.z);
    for (int s : {kLeft, kRight}) {
      const RigidWheel& w = r.wheel[s];
      CHECK(w.normal.norm() == within_rel(1, 1e-12));
      CHECK(std::abs(w.point.y() - g.side[s].rail.y[w.line]) <= 1e-15);
      F += w.normal_force * w.normal;
      M += (w.point - centre).cross(w.normal_force * w.normal);
    }
    CHECK(F.z() == within_rel(kQ, 1e-12));
    CHECK(std::abs(M.x()) <= 1e-9 * kQ);
    CHECK(r.Y == doctest::Approx(-F.y()).epsilon(1e-12).scale(kQ));
    CHECK(std::abs(r.Mz) <= 1e-9 * kQ);  // yaw 0
  }
}

TEST_CASE("sweep: cases in the order given, 1 and 2 threads agree with single solves, progress once per case") {
  const ContactModel& model = synthetic_model();
  const std::vector<double> ys{3e-3, -2e-3, 0.0, 1e-3, -4e-3};  // deliberately unsorted
  const std::vector<double> yaws{0.0, 0.01};
  auto make_workspace = [&] { return std::make_unique<ContactWorkspace>(model); };
  std::vector<SweepResult> runs;
  for (int threads : {1, 2}) {
    SweepOptions o;
    o.threads = threads;
    o.Q = kQ;
    o.rigid = true;
    std::vector<int> done_seen;
    o.progress = [&](int done, int total, int failed) {
      CHECK(total == 10);
      CHECK(failed == 0);
      done_seen.push_back(done);
    };
    runs.push_back(run_sweep(model, ys, yaws, o, make_workspace));
    const SweepResult& r = runs.back();
    CHECK(r.threads == threads);
    REQUIRE(r.cases.size() == 10);
    REQUIRE(done_seen.size() == 10);
    for (std::size_t k = 0; k < done_seen.size(); ++k) CHECK(done_seen[k] == static_cast<int>(k) + 1);
    for (std::size_t a = 0; a < yaws.size(); ++a)
      for (std::size_t i = 0; i < ys.size(); ++i) {
        const std::size_t c = a * ys.size() + i;
        CHECK(r.cases[c].y == ys[i]);
        CHECK(r.cases[c].yaw == yaws[a]);
        CHECK(r.elastic[c].y == ys[i]);
        CHECK(r.elastic[c].converged);
        CHECK(r.errors[c].empty());
        REQUIRE(r.rigid[c].has_value());
        CHECK(r.rigid[c]->converged);
      }
  }
  // Single solves from scratch: the same equilibria. Each result is within (tolerance / stiffness) of the exact
  // one: 0.2 N / 1e9 N/m = 2e-10 m and 0.2 N m / 1e8 N m/rad = 2e-9 rad; asserted 1e-8 (m, rad).
  ContactWorkspace ws(model);
  for (std::size_t c = 0; c < runs[0].cases.size(); ++c) {
    const SweepCase& sc = runs[0].cases[c];
    CAPTURE(sc.y);
    CAPTURE(sc.yaw);
    const EquilibriumResult e = solve_equilibrium(model, {sc.y, sc.yaw, kQ}, ws);
    REQUIRE(e.converged);
    for (const SweepResult& r : runs) {
      CHECK(std::abs(r.elastic[c].z - e.z) <= 1e-8);
      CHECK(std::abs(r.elastic[c].roll - e.roll) <= 1e-8);
      CHECK(std::abs(r.elastic[c].Y - e.Y) <= 1e-4 * kQ);
    }
  }
}

TEST_CASE("sweep: a repeated y continues from the points of distinct y and costs no more than a confirmation") {
  // A chain's start is the parabola through its last points of distinct y; at a y solved just before it is that
  // solution itself: one evaluation at the inner tolerance and one at the model's. (Weights computed over the
  // repeated y would not sum to one and start the case far off.)
  const ContactModel& model = synthetic_model();
  const std::vector<double> ys{0.0, 1e-3, 2e-3, 2e-3, 3e-3, 3e-3, 3e-3};
  SweepOptions o;
  o.Q = kQ;
  const SweepResult r = run_sweep(model, ys, {0.0}, o, [&] { return std::make_unique<ContactWorkspace>(model); });
  REQUIRE(r.elastic.size() == ys.size());
  ContactWorkspace ws(model);
  for (std::size_t c = 0; c < ys.size(); ++c) {
    CAPTURE(ys[c]);
    REQUIRE(r.elastic[c].converged);
    const EquilibriumResult e = solve_equilibrium(model, {ys[c], 0.0, kQ}, ws);
    REQUIRE(e.converged);
    CHECK(std::abs(r.elastic[c].z - e.z) <= 1e-8);  // within tolerance / stiffness, as above
    CHECK(std::abs(r.elastic[c].roll - e.roll) <= 1e-8);
    if (c > 0 && ys[c] == ys[c - 1]) CHECK(r.elastic[c].evaluations <= 2);
  }
}

// Bitwise equality of two solved cases (what a study's shards and threads must not change).
static void check_same_bits(const EquilibriumResult& a, const EquilibriumResult& b) {
  CHECK(a.converged == b.converged);
  CHECK(a.z == b.z);
  CHECK(a.roll == b.roll);
  CHECK(a.Y == b.Y);
  CHECK(a.My == b.My);
  CHECK(a.Mz == b.Mz);
  CHECK(a.residual_force == b.residual_force);
  CHECK(a.residual_moment == b.residual_moment);
  CHECK(a.iterations == b.iterations);
}

TEST_CASE("sweep: the plan cuts the cases into chunks that start cold, and any split over calls or threads gives the same bits") {
  const std::vector<double> ys{-4e-3, -3e-3, -2e-3, -1e-3, 0.0, 1e-3, 2e-3, 3e-3, 4e-3};
  const std::vector<double> yaws{0.0, 0.01};
  // Whole chains: per yaw, the chain below the centre (started from it, which it does not report) and the chain from
  // the centre up; chunks ordered by their first case, each a contiguous range.
  const SweepPlan whole = plan_sweep(ys, yaws, 0);
  REQUIRE(whole.cases.size() == 18);
  REQUIRE(whole.chunks.size() == 4);
  CHECK(whole.chunks[0].report == std::vector<int>{0, 1, 2, 3});
  CHECK(whole.chunks[0].solve == std::vector<int>{4, 3, 2, 1, 0});
  CHECK(whole.chunks[1].report == std::vector<int>{4, 5, 6, 7, 8});
  CHECK(whole.chunks[1].solve == std::vector<int>{4, 5, 6, 7, 8});
  CHECK(whole.chunks[3].solve == std::vector<int>{13, 14, 15, 16, 17});
  // Pieces of at most 3 reported cases; the pieces after the first start cold at their own first case.
  const SweepPlan cut = plan_sweep(ys, yaws, 3);
  REQUIRE(cut.chunks.size() == 8);
  CHECK(cut.chunks[0].report == std::vector<int>{0});
  CHECK(cut.chunks[0].solve == std::vector<int>{0});
  CHECK(cut.chunks[1].solve == std::vector<int>{4, 3, 2, 1});
  CHECK(cut.chunks[2].solve == std::vector<int>{4, 5, 6});
  CHECK(cut.chunks[3].solve == std::vector<int>{7, 8});
  for (const SweepPlan* plan : {&whole, &cut}) {
    std::vector<int> seen;
    for (const SweepChunk& c : plan->chunks) seen.insert(seen.end(), c.report.begin(), c.report.end());
    CHECK(seen == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17});
  }
  CHECK_THROWS_AS(plan_sweep(ys, yaws, -1), Error);

  const ContactModel& model = synthetic_model();
  auto make_workspace = [&] { return std::make_unique<ContactWorkspace>(model); };
  SweepOptions o;
  o.Q = kQ;
  o.threads = 1;
  std::vector<int> all(cut.chunks.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  const SweepResult ref = run_sweep(model, cut, all, o, make_workspace);
  REQUIRE(ref.index.size() == 18);
  for (const EquilibriumResult& e : ref.elastic) REQUIRE(e.converged);
  // 2 and 8 threads, and the chunks one call each in reverse order (as shards would run them): the same bits.
  for (int threads : {2, 8}) {
    o.threads = threads;
    const SweepResult r = run_sweep(model, cut, all, o, make_workspace);
    CHECK(r.threads == std::min(threads, 8));
    for (std::size_t i = 0; i < r.elastic.size(); ++i) check_same_bits(r.elastic[i], ref.elastic[i]);
  }
  o.threads = 1;
  for (int k = static_cast<int>(cut.chunks.size()) - 1; k >= 0; --k) {
    const SweepResult r = run_sweep(model, cut, {k}, o, make_workspace);
    REQUIRE(r.index == cut.chunks[static_cast<std::size_t>(k)].report);
    for (std::size_t i = 0; i < r.index.size(); ++i)
      check_same_bits(r.elastic[i], ref.elastic[static_cast<std::size_t>(r.index[i])]);
  }
  // A chunk's first case is a cold solve: the same bits as solve_equilibrium from nothing in a new workspace.
  ContactWorkspace cold(model);
  const SweepCase& first = cut.cases[static_cast<std::size_t>(cut.chunks[3].solve[0])];
  check_same_bits(solve_equilibrium(model, {first.y, first.yaw, kQ}, cold, o.equilibrium),
                  ref.elastic[static_cast<std::size_t>(cut.chunks[3].solve[0])]);
  CHECK_THROWS_WITH_AS(run_sweep(model, cut, {8}, o, make_workspace), doctest::Contains("chunk 9 does not exist"), Error);
  CHECK_THROWS_WITH_AS(run_sweep(model, cut, {1, 1}, o, make_workspace), doctest::Contains("listed twice"), Error);
}

TEST_CASE("sweep: the caller's stop ends it between cases and it throws, naming the cases solved") {
  // Ctrl-C in a front end: the flag is set from the progress callback after the 3rd case here. On one thread the
  // cases follow one another, so exactly 3 of the 10 are solved whatever their times; on two each worker finishes
  // the case it is solving, so 3 or 4. A flag that stays false changes nothing.
  const ContactModel& model = synthetic_model();
  const std::vector<double> ys{-4e-3, -2e-3, 0.0, 1e-3, 3e-3};
  const std::vector<double> yaws{0.0, 0.01};
  auto make_workspace = [&] { return std::make_unique<ContactWorkspace>(model); };
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    std::atomic<bool> stop{false};
    SweepOptions o;
    o.threads = threads;
    o.Q = kQ;
    o.stop = &stop;
    int reported = 0;
    o.progress = [&](int done, int, int) {
      reported = done;
      if (done == 3) stop = true;
    };
    try {
      run_sweep(model, ys, yaws, o, make_workspace);
      FAIL("a stopped sweep returned");
    } catch (const Error& e) {
      const std::string said = e.what();
      CHECK(said == fmt::format("sweep: stopped by its caller after {} of 10 cases (the others were not begun)",
                                reported));
      CHECK(reported >= 3);
      CHECK(reported <= 2 + threads);
    }
    stop = false;
    o.progress = {};
    const SweepResult whole = run_sweep(model, ys, yaws, o, make_workspace);
    o.stop = nullptr;
    const SweepResult plain = run_sweep(model, ys, yaws, o, make_workspace);
    REQUIRE(whole.elastic.size() == 10);
    for (std::size_t c = 0; c < 10; ++c) {
      CHECK(whole.elastic[c].converged);
      CHECK(whole.elastic[c].z == plain.elastic[c].z);
      CHECK(whole.elastic[c].roll == plain.elastic[c].roll);
    }
  }
  // set before it begins: no case is solved
  std::atomic<bool> stop{true};
  SweepOptions o;
  o.Q = kQ;
  o.stop = &stop;
  CHECK_THROWS_WITH_AS(run_sweep(model, ys, yaws, o, make_workspace),
                       "sweep: stopped by its caller after 0 of 10 cases (the others were not begun)", Error);
}

// A search that throws at the poses beyond y = 95 mm, as a Lua strategy's error would, and searches natively elsewhere.
class ThrowingSearch final : public PoseSearch {
 public:
  void search(SearchContext& ctx, int side) override {
    if (ctx.pose().y > 0.095) fail("test strategy: no search at y = {} m", ctx.pose().y);
    native_.search(ctx, side);
  }

 private:
  NativeSearch native_{NativePlan{}};
};

TEST_CASE("sweep: a case that throws or fails is recorded and the sweep goes on") {
  // A wheel without flange (the 1/40 tread from the tape circle outward): at y = 90 mm the left wheel has passed its
  // rail and only the right wheel's outer edge reaches the right rail's gauge corner, so no equilibrium exists (with a
  // flange the wheelset would tip over the rail and balance on it instead).
  std::vector<double> wy, wz;
  for (int i = 0; i <= 120; ++i) {
    wy.push_back(0.060 * i / 120);
    wz.push_back(wy.back() / 40);
  }
  auto g = std::make_shared<GeometryModel>(
      test::make_model(make_profile(ProfileKind::wheel, wy, wz, "flangeless wheel", "test"), test::synthetic_rail(0.5e-3)));
  g->strategy.make_search = [] { return std::make_unique<ThrowingSearch>(); };
  ContactOptions co;
  co.element = 1e-3;
  const ContactModel model(g, halfspace::Material{2.1e11, 0.3}, co);
  SweepOptions o;
  o.threads = 1;
  o.Q = kQ;
  int last_failed = -1;
  o.progress = [&](int, int, int failed) { last_failed = failed; };
  const auto workspace = [&] { return std::make_unique<ContactWorkspace>(model); };
  // A position out of the pose solvers' range (0.2 m: 200 mm meant as mm?) is the sweep's error, before any case.
  CHECK_THROWS_WITH_AS(run_sweep(model, {0.0, 1e-3, 0.09, 0.2}, {0.0}, o, workspace),
                       doctest::Contains("the 4th value of y: y = 0.2 m must be finite and within"), Error);
  // 0.09 m: no contact possible; 0.099 m: the strategy throws.
  const SweepResult r = run_sweep(model, {0.0, 1e-3, 0.09, 0.099}, {0.0}, o, workspace);
  REQUIRE(r.elastic.size() == 4);
  CHECK(r.elastic[0].converged);
  CHECK(r.elastic[1].converged);
  CHECK_FALSE(r.elastic[2].converged);
  CHECK_FALSE(r.elastic[2].message.empty());
  CHECK(std::isfinite(r.elastic[2].z));
  CHECK(std::isfinite(r.elastic[2].roll));
  // The last iterate shows why: a residual above its tolerance (the right wheel's field-side edge still reaches the
  // rail's gauge corner and may carry Q, but nothing can balance the roll moment).
  CHECK((std::abs(r.elastic[2].residual_force) > 1e-6 * kQ || std::abs(r.elastic[2].residual_moment) > 1e-6 * kQ));
  CHECK(r.errors[2].empty());  // no exception: a failed solve
  CHECK_FALSE(r.elastic[3].converged);
  CHECK(r.errors[3].find("test strategy: no search at y = 0.099") != std::string::npos);
  CHECK(r.elastic[3].message == r.errors[3]);
  CHECK(r.elastic[3].y == 0.099);
  CHECK(last_failed == 2);
}

TEST_CASE("solve_equilibrium: tolerances honoured, a far start converges to the same point, trace, bad input") {
  const ContactModel& model = synthetic_model();
  ContactWorkspace ws(model);
  const double y = 2e-3, yaw = 0.005;
  const EquilibriumResult ref = solve_equilibrium(model, {y, yaw, kQ}, ws);
  REQUIRE(ref.converged);
  CHECK(std::abs(ref.residual_force) <= 1e-6 * kQ);
  CHECK(std::abs(ref.residual_moment) <= 1e-6 * kQ);

  NewtonOptions tight;
  tight.limits.force_tolerance = tight.moment_tolerance = 1e-8;
  std::vector<int> traced;
  tight.trace = [&](int it, double, double, const ContactResult&) { traced.push_back(it); };
  const EquilibriumResult t = solve_equilibrium(model, {y, yaw, kQ}, ws, tight);
  REQUIRE(t.converged);
  CHECK(std::abs(t.residual_force) <= 1e-8 * kQ);
  CHECK(std::abs(t.residual_moment) <= 1e-8 * kQ);
  CHECK(std::abs(t.contact.force.z() - kQ) <= 1e-8 * kQ);
  REQUIRE_FALSE(traced.empty());
  CHECK(traced.back() == t.iterations);
  CHECK(std::abs(t.z - ref.z) <= 1e-8);

  // A start 1 mm above (no contact) and 3 mrad off: Newton lowers the wheelset and converges to the same point.
  Start start;
  start.z = ref.z + 1e-3;
  start.roll = ref.roll + 3e-3;
  const EquilibriumResult far = solve_equilibrium(model, {y, yaw, kQ}, ws, {}, {start});
  REQUIRE(far.converged);
  CHECK(std::abs(far.z - ref.z) <= 1e-8);
  CHECK(std::abs(far.roll - ref.roll) <= 1e-8);

  CHECK_THROWS_AS(solve_equilibrium(model, {std::nan(""), 0, kQ}, ws), Error);
  CHECK_THROWS_AS(solve_equilibrium(model, {0, 0, -1}, ws), Error);
  CHECK_THROWS_AS(solve_equilibrium(model, {0, 1.0, kQ}, ws), Error);
  CHECK_THROWS_AS(solve_wheel(model, {kLeft, 0, 0, 0, 0}, ws), Error);
  CHECK_THROWS_AS(solve_rigid(model.geometry(), 0.5, 0, kQ), Error);
}

// The solvers check their cases and options themselves (not only the option readers): a C++ caller gets an error that
// names the value, its unit and its range before any evaluation, instead of a solve that runs with a zero tolerance, a
// negative step or a side that indexes out of bounds (before these checks, each of these ran without an error).
TEST_CASE("cases and options are validated by the solvers themselves") {
  const ContactModel& model = synthetic_model();
  ContactWorkspace ws(model);
  auto fails = [](auto&& f, const char* text) { CHECK_THROWS_WITH_AS(f(), doctest::Contains(text), Error); };
  NewtonOptions newton;
  newton.limits.force_tolerance = 0;
  fails([&] { solve_equilibrium(model, {0, 0, kQ}, ws, newton); }, "equilibrium: force_tolerance = 0 must be in ]0, 0.1]");
  newton = {};
  newton.max_step_z = -1e-3;
  fails([&] { solve_equilibrium(model, {0, 0, kQ}, ws, newton); }, "max_step_z = -0.001 m must be in ]0, 0.01] m");
  newton = {};
  newton.limits.normal_tolerance = 0.5;
  fails([&] { solve_equilibrium(model, {0, 0, kQ}, ws, newton); }, "normal_tolerance = 0.5 must be in [1e-14, 1e-2[");
  fails([&] { solve_equilibrium(model, {0, 0, 2e10}, ws); }, "Q = 2e+10 N must be a positive number of at most");

  WheelOptions wheel;
  wheel.wheel_approach = 0;
  fails([&] { solve_wheel(model, {kLeft, 0, 0, 0, 1e5}, ws, wheel); }, "wheel: wheel_approach = 0 m must be in ]0, 0.01] m");
  wheel = {};
  wheel.limits.max_evaluations = 0;
  fails([&] { solve_wheel(model, {kLeft, 0, 0, 0, 1e5}, ws, wheel); }, "max_evaluations = 0 must be in [1, 1048576]");
  fails([&] { solve_wheel(model, {2, 0, 0, 0, 1e5}, ws); }, "wheel: side = 2 must be 0 (left) or 1 (right)");
  fails([&] { solve_wheel(model, {kRight, 0, 0, 0.5, 1e5}, ws); }, "roll = 0.5 rad must be finite and within +-0.1 rad");

  ContactRequest request;
  request.tolerance = 0.5;
  fails([&] { evaluate_contact(model, {0, 0, 0, 0}, ws, request); }, "contact: tolerance = 0.5 must be in [0, 1e-2]");
  request = {};
  request.only_side = 3;
  fails([&] { evaluate_contact(model, {0, 0, 0, 0}, ws, request); }, "only_side = 3 must be -1 (both wheels)");

  // A sweep refuses its options once, before its cases (not as every case's error).
  SweepOptions sweep;
  sweep.threads = 1;
  sweep.equilibrium.moment_tolerance = 0;
  fails([&] { run_sweep(model, {0.0}, {0.0}, sweep, [&] { return std::make_unique<ContactWorkspace>(model); }); },
        "sweep: moment_tolerance = 0 must be in ]0, 0.1]");
}

// A trajectory step that fails from its warm start is solved again cold before it fails (issue: a wheel step whose
// normal solve did not converge from the previous step's state, where a cold solve did). Here the kept pressures are
// made unusable (infinite), so that the warm start itself is refused by the normal solver.
TEST_CASE("trajectory: a step that fails warm is solved cold, with the result of a cold call") {
  const auto ws = test::synthetic_wheelset();
  Trajectory tr(ws);
  auto poison = [&] {
    for (auto& side : tr.workspace().previous)
      for (auto& area : side) std::fill(area.pressure.begin(), area.pressure.end(), INFINITY);
  };
  const Pose pose{1e-3, -0.08e-3, 0, 0.002};
  REQUIRE(tr.contact(pose).force.z() > 0);
  poison();
  ContactResult warm;
  REQUIRE_NOTHROW(warm = tr.contact({pose.y, pose.z - 1e-6, pose.roll, pose.yaw}));
  auto cold_ws = ws->make_workspace();
  ContactRequest req;
  req.tolerance = tr.options().tolerance;
  const ContactResult cold = evaluate_contact(ws->contact_model(), {pose.y, pose.z - 1e-6, pose.roll, pose.yaw}, *cold_ws, req);
  CHECK(warm.force.z() == within_rel(cold.force.z(), 1e-9));

  REQUIRE(tr.wheel({kLeft, 1e-3, 0.002, 0, 80e3}).converged);
  poison();
  WheelResult w;
  REQUIRE_NOTHROW(w = tr.wheel({kLeft, 1.2e-3, 0.002, 0, 85e3}));
  CHECK(w.converged);
  const WheelResult c = solve_wheel(ws->contact_model(), {kLeft, 1.2e-3, 0.002, 0, 85e3}, *cold_ws);
  CHECK(w.z == within_rel(c.z, 1e-6));
}

// A trajectory's wheel step checks its case before the side selects the last approaches (an out-of-range side indexed
// past them before).
TEST_CASE("trajectory: a wheel step with a side out of range is an error") {
  Trajectory tr(test::synthetic_wheelset());
  CHECK_THROWS_WITH_AS(tr.wheel({5, 1e-3, 0, 0, 80e3}), doctest::Contains("side = 5 must be 0 (left) or 1 (right)"), Error);
  CHECK(tr.wheel({kLeft, 1e-3, 0.002, 0, 80e3}).converged);
}
