// One wheel with its vertical force given (wrc/equilibrium/wheel.hpp): predictions of the approach from the wheel's
// normal problem solved for Fz itself, then secant steps on evaluations of the pose.
#include "wrc/equilibrium/wheel.hpp"

#include "pose_solve.hpp"
#include "wheelset/vertical_load.hpp"

#include "wrc/core/error.hpp"
#include "wrc/wheelset/plausibility.hpp"
#include "wrc/core/roots.hpp"
#include "wrc/kinematics/rigid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace wrc {
namespace {

using pose_solve::deepest;
using pose_solve::EvaluationBudget;
using pose_solve::UnreachableLoad;

// The tangential solver's tolerance for a wheel solve's first solution with friction (with_friction).
constexpr double kFirstRollingTolerance = 1e-4;
// The largest jump of the creep forces' vertical part C across the approach that a wheel solve with friction
// concludes at (WheelResult::converged: within it): 2e-3 Fz, or 10 % of C (an element more in a region of ten
// along the rolling direction lengthens FASTSIM's rows by 10 %); larger ones are no grid element's.
constexpr double kMaxJump = 2e-3, kMaxCreepJump = 0.1;
// The evaluation after the creep forces moved the load and the approach, solved this much tighter than
// normal_tolerance: its start carries the old load (~1e-4 off), and at 1x its force missed the load by its solve's
// noise in a tenth of the steps (an evaluation more). With that evaluation concluding within the whole force
// tolerance (with_friction), 0.7x misses as rarely as 0.5x (S1002/60E1 at 0.2 mm, 667 time steps: 2.03 evaluations
// per step either way, 1.75 CG iterations in it against 1.99; 1x: 2.07 evaluations; docs/performance.md).
constexpr double kMovedTolerance = 0.7;
// The force change (N) across a measured pair below which its stiffness weighs less than the last (measure_stiffness).
constexpr double kStiffnessNoise = 1.0;

// One solve_wheel call, on the approach a = z_touch - z (m, the wheel pressed below its touching height).
//
// Predictions (predict) bring a within ~1e-6 of the load's in two evaluations. From there, or without them:
// phi(a) = Fz(a)^(2/3) - Fz^(2/3) is close to linear and passes through (0, -Fz^(2/3)): a Hertz contact has F ~ a^1.5
// (a conformal one grows a little faster or slower). Secant steps on it, kept inside the bracket once the load is
// passed, converge in a few evaluations without sensitivities.
//
// The normal problems are solved only as well as the step needs: to 1e-2 while > 5 % off the load (their force is then
// ~1e-3 off, well within what the step needs; 1e-3 solves cost 10 % more in all), to normal_tolerance while > 1e-3 off,
// then at the model's own tolerance (the result's). Only an evaluation at normal_tolerance or tighter may conclude,
// and one at normal_tolerance is evaluated once more at the model's tolerance first; a looser one brackets only when it
// is more than 10x its tolerance off the load (nearer, its side of the load is not sure), but its secant step counts.
class WheelSolver {
 public:
  WheelSolver(const ContactModel& model, const WheelCase& c, ContactWorkspace& ws, const WheelOptions& opt,
              WheelResult& res)
      : model_(model), c_(c), ws_(ws), opt_(opt), res_(res) {
    z_touch_ = touch_height(model.geometry(), c.side, c.y, c.yaw, c.roll, "wheel");
    tight_ = std::max(opt.limits.normal_tolerance, model.options().normal.tolerance);
    loose_ = std::max(tight_, 1e-2);
    final_ = opt.final_at_model_tolerance ? model.options().normal.tolerance : tight_;
    set_load(c.Fz, 1.0);
  }

  // The vertical force the normal pressure is to carry (N): Fz, or with friction Fz less the creep forces' vertical
  // part, within share x force_tolerance of it.
  void set_load(double load, double share) {
    load_ = load;
    target_ = std::cbrt(load * load);
    ftol_ = share * (2.0 / 3.0) * opt_.limits.force_tolerance * target_;  // |F - load| <= tol load, in phi's units
  }

  // Two predictions first: one on the grid of the start (cold: only estimated on the coarse grid, a few per cent off),
  // then one at normal_tolerance on the grid the first leads to, which corrects what the first one's grid, coarseness
  // and linearised geometry missed. The conformal grid's elements stay on the rail's lattice, so the second one's model
  // differs from the evaluation of the pose it predicts only by h's curvature in z (second order in its step) and its
  // solve's ~1e-6: the evaluation at the model's tolerance that follows concludes (3 evaluations in all) but where the
  // step is large (deep in the flange), and then the secant steps go on from it, as they do for a wheel with several
  // areas or steep normals (no prediction). From a close start (a trajectory's last approach) the first step is within
  // 1e-3 of the approach and the second is skipped. `predicted_at`: called with the last prediction's evaluation and
  // approach when it was solved at normal_tolerance; it may set another load and move the approach (then true). The
  // evaluation there no longer starts from the solution it needs (its pressures carry the old load): it is solved to
  // kMovedTolerance x normal_tolerance, or its force would miss by its solve's noise (~1e-6 of the load at 1e-6) and
  // cost an evaluation more; its force measures the stiffness on the way. True when converged frictionless.
  bool solve(std::optional<double> start, const std::function<bool(double&)>& predicted_at = {}) {
    const double cold = opt_.wheel_approach * std::cbrt((load_ / 100e3) * (load_ / 100e3));  // Hertz: a ~ F^(2/3)
    double a1 = std::min(start && *start > 0 ? *start : cold, opt_.limits.max_penetration);
    const double from = a1;
    bool predicted = opt_.limits.max_evaluations >= 4 && predict(a1, start ? tight_ : loose_, !start);
    bool tight = predicted && start;
    if (predicted && std::abs(a1 - from) > 1e-3 * a1) tight = predicted = predict(a1, tight_);
    const double a0 = a1, f0 = wheel_force();  // the prediction carries the load (to round-off)
    const bool moved = tight && predicted_at && predicted_at(a1);
    const double f1 =
        phi(a1, moved ? std::min(final_, kMovedTolerance * tight_) : predicted ? final_ : start ? tight_ : loose_);
    if (moved) measure_stiffness(a0, f0);
    return secant(a1, f1);
  }

  // From the evaluation just made, of the normal problem alone, and one at approach a carrying N: their secant, when
  // positive. Within a step the approach moves by nanometres, over which the normal force is linear, but the secant
  // carries the evaluations' force noise (~0.01-0.05 N at 1e-6) over their force change, a few newtons: it moves the
  // last stiffness (a step before: the stiffness changes by < 1 % per step) by E^2 / (E^2 + kStiffnessNoise^2) of the
  // way, E the change the last stiffness expects over da (taken whole once the change passed 1 N, it was 5-9 % off
  // after a close pair, and the next step missed its load: S1002/60E1 at 0.2 mm, 667 time steps, 33 -> 21 evaluations
  // after the moved one; docs/performance.md). Without a last stiffness, the secant when dN > kStiffnessNoise.
  void measure_stiffness(double a, double N) {
    const double dN = wheel_force() - N, da = res_.approach - a, k = dN / da;
    if (!(k > 0)) return;
    if (stiffness_ > 0) {
      const double E = stiffness_ * da;
      stiffness_ += E * E / (E * E + kStiffnessNoise * kStiffnessNoise) * (k - stiffness_);
    } else if (std::abs(dN) > kStiffnessNoise) {
      stiffness_ = k;
    }
  }

  // With friction the creep forces' vertical part C joins Fz (a tilted contact plane turns lateral creep forces partly
  // vertical). The tangential problems are solved on normal solutions only: the normal problem is solved frictionless
  // (solve) for Fz - C, C from the hint (e.g. the last time step's; 0 cold), within half the force tolerance. When
  // solve predicts the approach (one area), the tangential problems are solved first, loosely, on the prediction's
  // normal solution (within ~1e-6 of the one it predicts): their C moves the load, and the approach by the normal
  // problem's stiffness (the hint's, measured by the last step; else its linearised response), before the pose is
  // evaluated; along a trajectory that evaluation then concludes with one more tangential solve from the first's
  // tractions. (One solve per step would need C known to ~0.05 N before it; from step to step C moves by ~0.5 N more
  // than its trend, the contact's edge crossing elements.) While the total misses Fz by more than the tolerance, the
  // load moves by a Newton step on it (dC/dload: C / load at first, as for creep forces proportional to the load,
  // then the secant of the last two), kept inside the bracket of the loads tried (inside), the approach with it
  // (shift), and the tangential problems are solved again from their last tractions. True when converged, or at a
  // jump of C that Fz falls in (jump_).
  bool with_friction(const RollingRequest& rolling, std::optional<double> start, const WheelHint& hint) {
    double creep = hint.creep;
    stiffness_ = hint.stiffness;
    constexpr double kShare = 0.5;   // of the force tolerance, for the normal solves: the rest is C's change
    double load = std::max(c_.Fz - creep, 0.1 * c_.Fz);
    set_load(load, kShare);
    // The first tangential solve only moves the load (C to ~1e-5 of itself, ~0.01 N): looser (the solver's tolerance
    // is on the slip; the forces converge faster); the last is always at the request's tolerance.
    RollingRequest first = rolling;
    first.tolerance = std::max(rolling.tolerance, kFirstRollingTolerance);
    bool loose = first.tolerance > rolling.tolerance;
    // On the prediction's normal solution (the load's pressure on the grid of a nearby approach, within ~1e-6 of the
    // solution it predicts), the creep forces already move the load and the approach before the pose is evaluated.
    // That evaluation concludes within the whole force tolerance, not kShare of it: the total is checked with the
    // tangential solve that follows, and C moves between the two normal solutions by ~0.003 N (median; 0.05 N in a
    // tenth of the steps) where the evaluation's miss (its noise, the stiffness's error) passed kShare in one step in
    // twenty, each then an evaluation more (S1002/60E1, FASTSIM at 0.2 mm: 2.05 -> 2.03 evaluations per step).
    bool early = false;
    const auto on_prediction = [&](double& a) {
      add_rolling(model_, cur_, first, ws_);
      const double c = cur_.wheel[c_.side].creep.force.z(), e = wheel_force() - c_.Fz;
      load = std::max(load_ - e / (1 + std::max(c / load_, -0.5)), 0.1 * c_.Fz);
      if (!(stiffness_ > 0))
        stiffness_ = areas::vertical_stiffness(model_, cur_.pose, cur_.wheel[c_.side].patches[0], ws_);
      a = std::clamp(a + (load - load_) / (stiffness_ > 0 ? stiffness_ : 1.5 * load_ / a), 0.5 * a,
                     std::min(2 * a, opt_.limits.max_penetration));
      set_load(load, 1.0);
      early = true;
      return true;
    };
    if (!solve(start, on_prediction)) return false;
    loose = loose && !early;
    double last_load = NAN, last_creep = NAN;
    const double tol = opt_.limits.force_tolerance * c_.Fz;
    Bracket below{-INFINITY, NAN}, above{INFINITY, NAN};  // loads whose total fell short of Fz / passed it
    bool crossed = false;  // the far side of a jump tried
    for (int it = 0;; ++it) {
      add_rolling(model_, cur_, loose ? first : rolling, ws_);
      creep = cur_.wheel[c_.side].creep.force.z();
      const double a = res_.approach, N = wheel_force() - creep;  // the normal solution's
      const double e = wheel_force() - c_.Fz;
      if (std::abs(e) <= tol) {
        if (!loose) return true;
        loose = false;  // the same normal solution again, the tangential problems at their tolerance
        continue;
      }
      if (!loose) (e < 0 ? below : above) = {load, e};
      loose = false;
      // Loads closer than the tolerance on either side of Fz (or the same load on both, its edge elements' near-zero
      // pressures differing with the start), neither within it: C jumps between them (the normal force is continuous),
      // and no approach carries Fz closer than half the jump. Such a point is the solution when the jump is one of a
      // coarse grid's (FASTSIM's rows grow by an element at a time; its ellipse did too, by ~1e-5 .. 4e-4 of Fz at
      // 0.7 .. 1 mm, 2 % of C in saturation, before it weighed entering elements); the residual says how near it is.
      if (above.load - below.load <= tol) {
        const double jump = above.e - below.e;
        if (jump > std::max(kMaxJump * c_.Fz, kMaxCreepJump * std::abs(creep))) {
          res_.message = fmt::format("the creep forces' vertical part jumps by {:.4g} N at z = {:.6f} mm (more than "
                                     "a grid element's): no approach carries Fz", jump, res_.z * 1e3);
          return false;
        }
        // The nearer side of the jump; its far side when this is not it (once: the same load may stay on this side,
        // the warm start deciding which edge elements carry pressure).
        if (std::abs(e) <= 0.5 * jump + tol || crossed) {
          jump_ = jump;
          return true;
        }
        crossed = true;
      }
      if (it >= opt_.limits.max_iterations) {
        res_.message = fmt::format("no convergence in {} iterations with the creep forces", opt_.limits.max_iterations);
        return false;
      }
      const double slope = std::isfinite(last_load) && load != last_load ? (creep - last_creep) / (load - last_load)
                                                                        : creep / load;
      last_load = load, last_creep = creep;
      if (above.load - below.load <= tol)
        load = e < 0 ? above.load : below.load;  // the jump's far side, which then concludes
      else
        load = inside(std::max(load - e / std::max(1 + slope, 0.5), 0.1 * c_.Fz), below, above);
      set_load(load, kShare);
      if (!shift(a, N)) return false;
    }
  }

  // A load whose total fell short of Fz (e < 0) or passed it (e > 0), e the total's miss (N).
  struct Bracket {
    double load, e;
  };

  // The next load, kept well inside the bracket of the loads tried. On a coarse grid the creep forces (FASTSIM's
  // rows) may jump where an element enters the contact; a Newton step across such a jump
  // overshoots to and fro (the secant's slope is the jump's), so where it lands outside the bracket's middle 80 %
  // the bracket is halved.
  static double inside(double load, const Bracket& below, const Bracket& above) {
    if (!std::isfinite(below.load) || !std::isfinite(above.load)) return load;
    const double w = above.load - below.load;
    if (load > below.load + 0.1 * w && load < above.load - 0.1 * w) return load;
    return 0.5 * (below.load + above.load);
  }

  // After set_load: from the normal solution at approach a carrying N, a step with the stiffness (the last measured,
  // else Hertz's 3/2 N / a) to the approach that carries the load, then secant steps from both points (the first
  // concludes when the stiffness is the last step's, measured on a nearby pose). Measures the stiffness on the way.
  // The step is solved no looser than the evaluation at a: from its pressures nanometres away a looser solve meets
  // its tolerance at once and repeats its force, and the secant of equal forces jumps far (one step along 667 time
  // steps at 0.5 mm went to 2.7x the load and took 7 evaluations).
  bool shift(double a, double N) {
    const double k = stiffness_ > 0 ? stiffness_ : 1.5 * N / a;
    const double a1 = std::clamp(a + (load_ - N) / k, 0.5 * a, 2 * a);
    const double f1 = phi(a1, std::min(final_, tolerance_));
    if (!secant(a1, f1, a, std::cbrt(N * N) - target_)) return false;
    measure_stiffness(a, N);
    return true;
  }

  double stiffness() const { return stiffness_; }

  // The result from the last evaluation: converged only within the force tolerance and max_penetration.
  // The solved wheel's Jacobians (its grids are still there).
  void jacobian(const std::optional<RollingRequest>& rolling) {
    add_jacobian(model_, cur_, rolling, ws_);
    WheelContact& w = cur_.wheel[c_.side];
    w.jacobian_fz = constant_fz(*w.jacobian);
  }

  void finish() {
    const SolveLimits& l = opt_.limits;
    res_.iterations = evaluations_;
    res_.residual = wheel_force() - c_.Fz;
    res_.converged = res_.converged && std::abs(res_.residual) <= l.force_tolerance * c_.Fz + jump_;
    if (res_.converged && deepest(cur_, c_.side) > l.max_penetration) {  // the creep forces' steps are not held within
      res_.converged = false;
      res_.message = pose_solve::too_deep(deepest(cur_, c_.side), l.max_penetration);
    }
    if (!res_.converged && res_.message.empty())
      res_.message = fmt::format("the last evaluation is {:.4g} N off, beyond force_tolerance x Fz = {:.4g} N",
                                 res_.residual, l.force_tolerance * c_.Fz);
    if (!opt_.keep_grids) drop_grids(cur_);
    res_.wheel = std::move(cur_.wheel[c_.side]);
  }

 private:
  // An approach and phi there; a0, f0 the one before (first: the exact point of no contact); lo, hi the bracket.
  struct Secant {
    double a0, f0, a1, f1;
    double lo = 0, hi = INFINITY;
  };

  // The wheel's vertical force (N): the normal pressure's, with the creep forces' once their problems are solved.
  double wheel_force() const { return cur_.wheel[c_.side].force.z(); }

  // The wheel pressed in by a, within the budget; `load`: the predictor's evaluation.
  void evaluate_at(double a, const ContactRequest& req, const areas::VerticalLoad* load = nullptr) {
    if (evaluations_++ >= opt_.limits.max_evaluations)
      throw EvaluationBudget(
          fmt::format("gave up after {} contact evaluations (max_evaluations)", opt_.limits.max_evaluations));
    const Pose pose{c_.y, z_touch_ - a, c_.roll, c_.yaw};
    ContactResult next = load ? areas::evaluate_vertical_load(model_, pose, ws_, req, *load)
                              : evaluate_contact(model_, pose, ws_, req);
    recycle_tangential(cur_, ws_);  // (after the evaluation: a throw leaves the last one whole)
    cur_ = std::move(next);
    res_.z = z_touch_ - a;
    res_.approach = a;
  }

  // Frictionless, the normal problems solved to tol.
  void evaluate(double a, double tol, const areas::VerticalLoad* load = nullptr) {
    ContactRequest req;
    req.only_side = c_.side;
    req.max_penetration = INFINITY;  // the approach is held within max_penetration, the result checked by finish
    req.tolerance = tolerance_ = tol;
    evaluate_at(a, req, load);
  }

  double phi(double a, double tol) {
    evaluate(a, tol);
    return std::cbrt(std::pow(std::max(wheel_force(), 0.0), 2)) - target_;
  }

  // A prediction: the wheel's area solved for Fz itself on the grid of approach a (its normals' vertical parts as
  // weights, the approach deepening h as it does), whose multiplier is the further approach that carries Fz there; a
  // moves on by it. False when the wheel has several areas or steep normals (the pipeline then solved the penetration)
  // or the step is unusable.
  bool predict(double& a, double tol, bool estimate = false) {
    const areas::VerticalLoad load{load_, estimate};
    evaluate(a, tol, &load);
    const auto& patches = cur_.wheel[c_.side].patches;
    if (patches.size() != 1 || patches[0].solution.load.control != halfspace::NormalLoad::Control::force) return false;
    const double next = a + patches[0].solution.approach;
    if (!(next > 0)) return false;
    a = std::min(next, opt_.limits.max_penetration);
    return true;
  }

  double tolerance_for(double error) const { return error > 0.05 ? loose_ : error > 1e-3 ? tight_ : final_; }

  // Secant steps on phi from the start (a1, f1) until an evaluation at the final tolerance carries the load. True
  // when converged.
  bool secant(double a1, double f1, double a0 = 0, double f0 = NAN) {
    Secant s{a0, std::isnan(f0) ? -target_ : f0, a1, f1};
    for (int it = 0;; ++it) {
      const double error = std::abs(wheel_force() - load_) / load_;
      const bool settled = tolerance_ <= tight_;  // a looser evaluation may be off by about its tolerance
      if (settled && std::abs(s.f1) <= ftol_) {
        if (tolerance_ <= final_) break;
        // The result at the model's own tolerance (the forces evaluate_contact gives at the solved pose, from the
        // converged pressures in a few CG iterations); its force may move out of the tolerance by the noise of the
        // looser solve, and then the steps go on from it.
        s.f1 = phi(s.a1, final_);
        continue;
      }
      if (it >= opt_.limits.max_iterations) {
        res_.message = fmt::format("no convergence in {} iterations", opt_.limits.max_iterations);
        break;
      }
      // F grows with the approach: no approach within max_penetration carries Fz.
      if (s.f1 < 0 && s.a1 >= opt_.limits.max_penetration)
        throw UnreachableLoad(pose_solve::unreachable("Fz", c_.Fz, wheel_force(), cur_.pose, deepest(cur_, c_.side),
                                                      opt_.limits.max_penetration));
      if (settled || error > 10 * tolerance_) (s.f1 < 0 ? s.lo : s.hi) = s.a1;
      advance(s);
      // A settled evaluation within 10x its own tolerance of the load is within the noise of its normal solve (a
      // trajectory's 1e-6 solves against the 1e-6 force tolerance): the next is solved 10x tighter, or the secant
      // would wander in that noise. After a settled one never looser: a looser solve from its pressures a step of
      // ~1e-6 away meets its tolerance at once and repeats the force, and a secant of equal forces jumps far. A loose
      // one that did not bracket and was not moved (the step lands on it again) is tightened for the same reason.
      double next = settled && error < 10 * tolerance_ ? std::min(tolerance_for(error), 0.1 * tolerance_)
                                                       : tolerance_for(error);
      if (settled) next = std::min(next, tolerance_);
      if (!settled && s.a1 == s.a0) next = std::min(next, tight_);
      s.f1 = phi(s.a1, next);
    }
    return tolerance_ <= final_ && std::abs(s.f1) <= ftol_;
  }

  // The secant's next approach: inside the bracket once there is one, at most 4x the last before.
  // F grows with the approach: a secant that falls (two points nanometres apart, their forces within their solves'
  // noise) is replaced by the one through the touching point (0, -target), phi being close to linear.
  void advance(Secant& s) const {
    double slope = (s.f1 - s.f0) / (s.a1 - s.a0);
    if (!(slope > 0)) slope = (s.f1 + target_) / s.a1;
    double a = slope > 0 ? s.a1 - s.f1 / slope : 2 * s.a1;
    if (!std::isfinite(s.hi)) a = std::clamp(a, s.lo, 4 * s.a1);
    if (std::isfinite(s.hi) && !(a > s.lo && a < s.hi)) a = 0.5 * (s.lo + s.hi);
    s.a0 = s.a1, s.f0 = s.f1, s.a1 = std::min(a, opt_.limits.max_penetration);
  }

  const ContactModel& model_;
  const WheelCase& c_;
  ContactWorkspace& ws_;
  const WheelOptions& opt_;
  WheelResult& res_;
  double z_touch_ = 0;     // the height at which the wheel just touches (m)
  double load_ = 0;        // the vertical force the normal pressure is to carry (set_load; N)
  double target_ = 0;      // load_^(2/3)
  double tight_ = 0, loose_ = 0, final_ = 0;  // the normal solves' tolerances (tolerance_for)
  double ftol_ = 0;        // the normal solves' force tolerance in phi's units
  int evaluations_ = 0;
  double jump_ = 0;        // with friction: the creep forces' jump where the solve concluded at one (N), else 0
  double stiffness_ = 0;   // dFz/da of the normal solutions (N/m), measured by shift; 0: not known
  double tolerance_ = 0;   // of the last frictionless evaluation
  ContactResult cur_;      // the last evaluation
};

}  // namespace

void WheelCase::validate(std::string_view context, bool plausible) const {
  if (side != kLeft && side != kRight)
    fail("{}: side = {} must be {} (left) or {} (right)", context, side, +kLeft, +kRight);
  check_lateral(y, context);
  check_yaw(yaw, context);
  check_roll(roll, context);
  pose_solve::check_load("Fz", Fz, context);
  if (plausible) check_plausible(context, "Fz", Fz, kWheelLoad);
}

void WheelOptions::validate(std::string_view context) const {
  limits.validate(context);
  if (!(wheel_approach > 0 && wheel_approach <= 0.01))
    fail("{}: wheel_approach = {} m must be in ]0, 0.01] m", context, wheel_approach);
}

WheelResult solve_wheel(const ContactModel& model, const WheelCase& c, ContactWorkspace& ws, const WheelOptions& opt,
                        std::optional<double> start, const std::optional<RollingRequest>& rolling,
                        const std::optional<WheelHint>& hint) {
  c.validate("wheel", model.options().check_magnitudes);
  if (rolling) rolling->validate("wheel", model.options().check_magnitudes, model.geometry().track->params.radius);
  if (rolling && rolling->kinematics && rolling->kinematics->free_rolling)
    fail("wheel: free_rolling balances the axle torque of both wheels at one omega; a single wheel's solve cannot "
         "(give omega: e.g. the one ws:contact or ws:sweep found with free_rolling)");
  opt.validate("wheel");
  WheelResult res;
  res.side = c.side;
  res.Fz = c.Fz;
  WheelSolver solver(model, c, ws, opt, res);
  try {
    res.converged = rolling ? solver.with_friction(*rolling, start, hint.value_or(WheelHint{})) : solver.solve(start);
  } catch (const EvaluationBudget& e) {
    res.message = e.what();
  } catch (const UnreachableLoad& e) {
    res.message = e.what();
  }
  if (opt.sensitivity && res.converged) solver.jacobian(rolling);
  solver.finish();
  if (rolling) res.hint = {res.wheel.creep.force.z(), solver.stiffness()};
  return res;
}

// ---- options, messages, fields ----

WheelCase read_wheel_case(OptionReader& r) {
  WheelCase c;
  const std::optional<std::string> side = r.string("side", {"-", "the wheel: \"left\" or \"right\" (required)"});
  if (!r.documenting() && !side) fail("{}: 'side' is required (\"left\" or \"right\")", r.context());
  if (!r.documenting()) c.side = parse_side(*side, r.context());
  c.y = r.number("y", {"m", "lateral position of the wheelset centre"}, c.y);
  c.yaw = r.number("yaw", {"rad", "yaw angle of the wheelset"}, c.yaw);
  c.roll = r.number("roll", {"rad", "roll angle of the wheelset"}, c.roll);
  c.Fz = r.need_number("Fz", {"N", "the wheel's vertical force"});
  return c;
}

WheelOptions read_wheel_options(OptionReader& r) {
  WheelOptions o;
  o.limits = read_solve_limits(r);
  o.keep_grids = r.boolean("grids", {"-", "keep the pressure and h grids in the result"}, o.keep_grids);
  o.sensitivity = read_sensitivity(r);
  if (!r.documenting()) o.validate(r.context());
  return o;
}

std::string failure_message(const WheelResult& w) {
  return fmt::format("the {} wheel's vertical force {:.6g} N was not reached: {}; last iterate z = {:.6f} mm, residual "
                     "{:.4g} N", side_name(w.side), w.Fz, w.message, w.z * 1e3, w.residual);
}

void describe(const WheelResult& w, FieldSink& out) {
  describe(w.wheel, out);
  out.boolean("converged", w.converged, {"", "the vertical force was reached"});
  if (!w.message.empty()) out.string("error", w.message, {"", "why it was not (only when not converged)"});
  out.number("z", w.z, {"m", "solved height of the wheelset centre (or the last iterate)"});
  out.number("approach", w.approach, {"m", "how far z is below the height at which the wheel just touches its rail"});
  out.number("residual", w.residual, {"N", "the wheel's vertical force minus the prescribed Fz"});
  out.integer("iterations", w.iterations, {"-", "contact evaluations"});
}

}  // namespace wrc
