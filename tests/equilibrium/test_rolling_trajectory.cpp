// Rolling contact along a trajectory (Trajectory::wheel with a RollingRequest), on the synthetic profiles of
// tests/geometry/geometry_fixtures.hpp: every warm step (the normal and tangential solutions carried from the step
// before) against a cold solve of the same step in a fresh workspace (solve_wheel, the same options):
//  - both carry Fz within the force tolerance, their heights within two tolerances' worth of approach;
//  - creep forces, per-element tractions and the adhesion / slip split agree within what the tolerances allow (the
//    exact solver's 1e-6 on the slip; the approaches differing by up to 2e-6 Fz / stiffness);
//  - the warm step's own pose evaluated cold (evaluate_contact with the rolling request) gives its forces and
//    tractions;
//  - the warm steps cost what a time step should: about two contact evaluations (the frictionless step's count) and
//    at most two Newton iterations of the exact solver's last solve, where a cold solve needs ~6 evaluations and
//    starts its tangential problem from the coarse grid's solution.
#include "approx.hpp"
#include "wheelset/synthetic_wheelset.hpp"
#include "wrc/equilibrium/trajectory.hpp"
#include "wrc/equilibrium/wheel.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

using namespace wrc;
using wrc::test::synthetic_wheelset;
using wrc::test::within_abs;

namespace {

// Step k of a hunting-like motion at 1 kHz (y = 3 mm sin(2 pi 1.5 Hz t), the yaw following the path at V), its
// case and rolling request.
constexpr double kV = 30, kMu = 0.3, kTrajectoryFz = 90e3;
WheelCase step_case(int k) {
  const double w = 2 * std::numbers::pi * 1.5, t = 0.02 + 1e-3 * k;
  return {kLeft, 3e-3 * std::sin(w * t), -3e-3 * w * std::cos(w * t) / kV, 0.0, kTrajectoryFz};
}
RollingRequest step_rolling(int k, RollingMethod method) {
  const double w = 2 * std::numbers::pi * 1.5, t = 0.02 + 1e-3 * k;
  RollingRequest r;
  r.kinematics = Kinematics{kV, std::nullopt, 3e-3 * w * std::cos(w * t), 3e-3 * w * w / kV * std::sin(w * t)};
  r.friction = halfspace::Friction::coulomb(kMu);
  r.method = method;
  return r;
}

// The largest difference of two tractions over the grid, per mu pmax; the elements whose state differs.
struct TractionDifference {
  double max = 0;
  int split = 0;
};
TractionDifference compare(const PatchContact& a, const PatchContact& b) {
  const halfspace::TangentialSolution& s = a.rolling->solution;
  const halfspace::TangentialSolution& t = b.rolling->solution;
  REQUIRE(!s.px.empty());
  REQUIRE(s.px.size() == t.px.size());
  REQUIRE(s.grid.nx == t.grid.nx);
  REQUIRE(s.grid.ny == t.grid.ny);
  REQUIRE(s.grid.x0 == within_abs(t.grid.x0, 1e-12));  // m: the same grid
  REQUIRE(s.grid.y0 == within_abs(t.grid.y0, 1e-12));
  const double bound = kMu * *std::max_element(b.solution.pressure.begin(), b.solution.pressure.end());
  TractionDifference d;
  for (std::size_t k = 0; k < s.px.size(); ++k) {
    d.max = std::max(d.max, std::hypot(s.px[k] - t.px[k], s.py[k] - t.py[k]) / bound);
    d.split += s.state[k] != t.state[k];
  }
  return d;
}

}  // namespace

TEST_CASE("trajectory with rolling contact: each warm step equals a cold solve of the same step, at a time step's cost") {
  const auto ws = synthetic_wheelset();
  for (RollingMethod method : {RollingMethod::exact, RollingMethod::fastsim}) {
    CAPTURE(method_name(method));
    Trajectory tr(ws);
    WheelOptions cold_options;  // as Trajectory::wheel sets them
    cold_options.limits.normal_tolerance = tr.options().tolerance;
    cold_options.final_at_model_tolerance = false;
    constexpr int kSteps = 30;
    int warm_evaluations = 0, cold_evaluations = 0, last_newton = 0;
    double worst_force = 0, worst_traction = 0, worst_pose = 0, worst_pose_traction = 0;
    int worst_split = 0;
    for (int k = 0; k < kSteps; ++k) {
      CAPTURE(k);
      const WheelCase c = step_case(k);
      const RollingRequest rolling = step_rolling(k, method);
      const WheelResult warm = tr.wheel(c, rolling);
      auto fresh = ws->make_workspace();
      const WheelResult cold = solve_wheel(ws->contact_model(), c, *fresh, cold_options, std::nullopt, rolling);
      REQUIRE(warm.converged);
      REQUIRE(cold.converged);
      CHECK(std::abs(warm.wheel.force.z() - kTrajectoryFz) <= 1e-6 * kTrajectoryFz);
      CHECK(std::abs(cold.wheel.force.z() - kTrajectoryFz) <= 1e-6 * kTrajectoryFz);
      REQUIRE(warm.wheel.patches.size() == cold.wheel.patches.size());
      REQUIRE(warm.wheel.creep.solved);
      // The creep force in the contact plane (N) against the wheel's creep force scale mu Fz.
      const Eigen::Vector3d dF = warm.wheel.creep.force - cold.wheel.creep.force;
      worst_force = std::max(worst_force, dF.norm() / (kMu * kTrajectoryFz));
      for (std::size_t p = 0; p < warm.wheel.patches.size(); ++p) {
        const TractionDifference d = compare(warm.wheel.patches[p], cold.wheel.patches[p]);
        worst_traction = std::max(worst_traction, d.max);
        worst_split = std::max(worst_split, d.split);
        if (k > 0) last_newton = std::max(last_newton, warm.wheel.patches[p].rolling->solution.iterations);
      }
      // The warm step's pose evaluated cold (evaluate_contact, the trajectory's normal tolerance): the same contact.
      ContactRequest req;
      req.only_side = kLeft;
      req.tolerance = tr.options().tolerance;
      req.rolling = rolling;
      auto fresh_pose = ws->make_workspace();
      const ContactResult at = evaluate_contact(ws->contact_model(), {c.y, warm.z, c.roll, c.yaw}, *fresh_pose, req);
      worst_pose = std::max(worst_pose, (at.wheel[kLeft].force - warm.wheel.force).norm() / kTrajectoryFz);
      REQUIRE(at.wheel[kLeft].patches.size() == warm.wheel.patches.size());
      for (std::size_t p = 0; p < warm.wheel.patches.size(); ++p)
        worst_pose_traction = std::max(worst_pose_traction, compare(warm.wheel.patches[p], at.wheel[kLeft].patches[p]).max);
      if (k > 0) warm_evaluations += warm.iterations;  // the first step starts cold too
      cold_evaluations += cold.iterations;
    }
    MESSAGE(std::string(method_name(method)), ": against the cold solve, creep force within ", worst_force,
            " mu Fz, tractions within ", worst_traction, " mu pmax, ", worst_split,
            " elements of another state; against the pose evaluated cold, force within ", worst_pose,
            " Fz, tractions within ", worst_pose_traction, " mu pmax; evaluations per step warm ",
            double(warm_evaluations) / (kSteps - 1), ", cold ", double(cold_evaluations) / kSteps);
    // Agreement: the approaches may differ by 2e-6 Fz / stiffness; the exact solver converges the slip to 1e-6 of
    // the rigid slip. A warm start that changed the solution (a stale split, tractions of another area) would show
    // at the 1e-3 level.
    CHECK(worst_force <= 2e-5);
    CHECK(worst_traction <= 2e-4);
    CHECK(worst_split <= 2);
    CHECK(worst_pose <= 2e-6);  // two normal tolerances
    CHECK(worst_pose_traction <= 2e-4);
    // Cost: the frictionless step takes ~2 evaluations from the last approach.
    CHECK(double(warm_evaluations) / (kSteps - 1) <= 3.0);
    if (method == RollingMethod::exact) CHECK(last_newton <= 2);
  }
}

TEST_CASE("trajectory with rolling contact: prescribed poses warm equal their cold evaluations, the exact solver warm") {
  const auto ws = synthetic_wheelset();
  TrajectoryOptions options;
  options.keep_grids = true;
  Trajectory tr(ws, options);
  // The poses: each step's height from a cold wheel solve (as a multibody code's integrator gives them).
  constexpr int kSteps = 20;
  int warm_newton = 0, cold_newton = 0;
  double worst_force = 0, worst_traction = 0;
  for (int k = 0; k < kSteps; ++k) {
    CAPTURE(k);
    const WheelCase c = step_case(k);
    const RollingRequest rolling = step_rolling(k, RollingMethod::exact);
    auto fresh = ws->make_workspace();
    const WheelResult at = solve_wheel(ws->contact_model(), c, *fresh, {}, std::nullopt);
    REQUIRE(at.converged);
    const Pose pose{c.y, at.z, c.roll, c.yaw};
    const ContactResult warm = tr.contact(pose, rolling);
    ContactRequest req;
    req.tolerance = tr.options().tolerance;
    req.rolling = rolling;
    auto cold_ws = ws->make_workspace();
    const ContactResult cold = evaluate_contact(ws->contact_model(), pose, *cold_ws, req);
    const WheelContact &w = warm.wheel[kLeft], &cw = cold.wheel[kLeft];
    REQUIRE(w.patches.size() == cw.patches.size());
    worst_force = std::max(worst_force, (w.force - cw.force).norm() / kTrajectoryFz);
    for (std::size_t p = 0; p < w.patches.size(); ++p) {
      worst_traction = std::max(worst_traction, compare(w.patches[p], cw.patches[p]).max);
      if (k > 0) {
        warm_newton += w.patches[p].rolling->solution.iterations;
        cold_newton += cw.patches[p].rolling->solution.iterations;
      }
    }
  }
  MESSAGE("force within ", worst_force, " Fz, tractions within ", worst_traction, " mu pmax; Newton iterations of the "
          "exact solver warm ", warm_newton, ", cold ", cold_newton, " (on the fine grid, after the coarse grids' start)");
  CHECK(worst_force <= 2e-6);
  CHECK(worst_traction <= 2e-4);
  CHECK(warm_newton < cold_newton);
}
