// The elastic equilibrium of a case (y, yaw, Q): Newton on z and roll (wrc/equilibrium/newton.hpp), from the starts,
// the rigid position, a continuation or nested brackets (the rigid reference it starts from: kinematics/rigid.cpp).
#include "wrc/equilibrium/newton.hpp"

#include "pose_solve.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/roots.hpp"
#include "wrc/geometry/wheel_surface.hpp"
#include "wrc/wheelset/plausibility.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wrc {
namespace {

// Iterations in a row that may leave a wheel lifted and the merit above kSlowMerit of the iteration before, before
// Newton gives up (a Jacobian computed afresh without a step counts too: counting steps alone let the hollow wheel
// below run out of budget at y = 5 mm). Equilibria on one wheel (a flange climbed: the paper study at y = 7.5 mm,
// yaw 1 deg) take up to 10 lifted steps and come out the same bits with this limit (8 lifted steps of any speed cut
// them); a wheel with a 2 mm hollow took 50 slow ones, each 1-2 % down (tests/scripts/robust_inputs.lua).
constexpr int kSlowLiftedSteps = 5;
constexpr double kSlowMerit = 0.9;

using pose_solve::deepest;
using pose_solve::EvaluationBudget;
using pose_solve::UnreachableLoad;
using pose_solve::unreachable;
using pose_solve::too_deep;

// An iterate of the equilibrium: the contact at (z, roll), the residual (sum Fz - Q, sum Mx) and its Jacobian.
struct Iterate {
  double z = 0, roll = 0;
  ContactResult contact;
  Eigen::Vector2d R = Eigen::Vector2d::Zero();  // N, N m
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // d R / d(z, roll)
  double merit = 0;
  bool lifted = false;  // a wheel carries no load
  double tolerance = 0;  // of the normal solves it was evaluated with
};

// The equilibrium solver's methods for one call (a lateral position may change along a continuation).
class EquilibriumSolver {
 public:
  EquilibriumSolver(const ContactModel& model, double yaw, double Q, ContactWorkspace& ws, const NewtonOptions& opt,
                    const ContactRequest& request, EquilibriumResult& res)
      : model_(model), yaw_(yaw), Q_(Q), ws_(ws), opt_(opt), res_(res), req_(request) {
    req_.rolling.reset();  // the equilibrium is frictionless (add_rolling evaluates creep forces at its pose)
    req_.sensitivity = false;  // added when a Newton step needs it (not for line-search trials or the last iterate)
    req_.keep_grids = true;
    req_.max_penetration = INFINITY;  // an iterate may overshoot; the solve's own checks use its max_penetration
    // Inexact solves a tenth of the residual tolerance asked for (their force error is of the order of their
    // tolerance), so that the confirmation at the model's tolerance (confirm) rarely moves a solution out.
    const SolveLimits& l = opt.limits;
    inexact_ = std::max(std::min({l.normal_tolerance, 0.1 * l.force_tolerance, 0.1 * opt.moment_tolerance}),
                        model.options().normal.tolerance);
    req_.tolerance = inexact_;
    ftol_ = opt.limits.force_tolerance * Q;
    mtol_ = opt.moment_tolerance * Q * 1.0;  // the moment scale Q x 1 m
  }

  bool converged(const Iterate& it) const { return std::abs(it.R(0)) <= ftol_ && std::abs(it.R(1)) <= mtol_; }

  // Newton-Raphson from (z, roll) at lateral position y, with step limits and backtracking on the residual norm.
  // The Jacobian is computed at the first iterate -- from the normal problems' sensitivities with both wheels
  // loaded (two linearised solves), by forward differences with a wheel lifted (two evaluations; a difference
  // Jacobian handed in by the caller, e.g. from the previous case of a sweep, is used instead) -- and then
  // corrected by Broyden's rank-one update after every step. The update also learns what the sensitivities
  // miss where a conformal flange-root contact turns and moves with the pose (they are 10-20 % off there, which
  // made plain Newton converge linearly). A fresh Jacobian is computed when a step finds no descent or the
  // regime (a wheel lifted or not) changes. Leaves the last iterate in `cur`; false with a reason in `why`.
  bool newton(double y, double z, double roll, const std::optional<Eigen::Matrix2d>& J0, bool J0_lifted,
              Iterate& cur, std::string& why) {
    req_.tolerance = inexact_;
    cur = evaluate(y, z, roll);
    std::optional<Eigen::Matrix2d> J;
    bool J_lifted = cur.lifted;  // the regime the Jacobian belongs to
    if (J0 && J0_lifted == cur.lifted) J = J0;
    int slow_lifted = 0;  // iterations in a row with a wheel lifted and the merit above kSlowMerit of the last
    double last_merit = cur.merit;
    for (int k = 0;; ++k) {
      if (opt_.trace) opt_.trace(k, cur.z, cur.roll, cur.contact);
      res_.iterations = k;
      if (converged(cur)) {
        if (J) res_.jacobian = J, res_.jacobian_lifted = J_lifted;  // for a neighbouring case (a sweep)
        return true;
      }
      if (k >= opt_.limits.max_iterations) {
        why = fmt::format("Newton: no convergence in {} iterations ({} evaluations)", k, res_.evaluations);
        return false;
      }
      // With a wheel lifted both residuals come from the other wheel's contact (its force and that force's moment),
      // so the Jacobian is nearly singular and its steps can turn the wheelset about that contact the wrong way,
      // each descending a little (a wheel with a 2 mm hollow at 10 kN, y = 3 mm: 50 such steps per attempt, until
      // the evaluation budget was spent before the rigid start was tried). Leave it to the next start.
      slow_lifted = cur.lifted && k > 0 && cur.merit > kSlowMerit * last_merit ? slow_lifted + 1 : 0;
      last_merit = cur.merit;
      if (slow_lifted > kSlowLiftedSteps) {
        why = fmt::format("Newton: a wheel still lifted after {} slow iterations (at z = {:.6f} mm, roll = {:.6f} "
                          "mrad)", slow_lifted, cur.z * 1e3, cur.roll * 1e3);
        return false;
      }
      if (cur.contact.wheel[kLeft].patches.empty() && cur.contact.wheel[kRight].patches.empty()) {
        // No contact at all: lower the wheelset (the residual is -Q with no slope to follow).
        if (cur.z < -0.02) {
          why = "no contact: the wheelset falls 20 mm without touching the rails";
          return false;
        }
        cur = evaluate(y, cur.z - opt_.max_step_z, cur.roll);
        continue;
      }
      bool fresh = false;  // J computed at this iterate
      if (!J || J_lifted != cur.lifted) {
        J = jacobian(y, cur);
        J_lifted = cur.lifted;
        fresh = true;
      }
      Eigen::Vector2d dx = -J->fullPivLu().solve(cur.R);
      if (!dx.allFinite()) {
        why = "Newton: singular Jacobian";
        return false;
      }
      dx /= std::max({1.0, std::abs(dx(0)) / opt_.max_step_z, std::abs(dx(1)) / opt_.max_step_roll});
      const double merit0 = cur.merit;
      const Eigen::Vector2d R0 = cur.R, x0(cur.z, cur.roll);
      bool accepted = false;
      double t = 1;
      // Backtracking; an updated Jacobian gets one trial, then a fresh one is computed instead.
      for (int b = 0; b < (fresh ? 10 : 1) && !accepted; ++b, t *= 0.5) {
        // Within 1000 tolerances the step should converge (a sweep's predicted start is ~1e-4 Q off, and the
        // Newton step from it lands within the tolerance): evaluate it at the model's tolerance, so that the
        // solution needs no confirmation (confirm).
        if (std::abs(R0(0)) < 1000 * ftol_ && std::abs(R0(1)) < 1000 * mtol_) req_.tolerance = model_.options().normal.tolerance;
        Iterate trial = evaluate(y, cur.z + t * dx(0), cur.roll + t * dx(1));
        if (trial.merit < (1 - 1e-4 * t) * merit0) {
          cur = std::move(trial);
          accepted = true;
        }
      }
      if (!accepted) {
        if (!fresh) {
          J.reset();
          continue;
        }
        why = fmt::format("Newton: no descent at z = {:.6f} mm, roll = {:.6f} mrad", cur.z * 1e3, cur.roll * 1e3);
        return false;
      }
      // Broyden: make J map the step taken onto the residual change observed.
      const Eigen::Vector2d step = Eigen::Vector2d(cur.z, cur.roll) - x0, change = cur.R - R0;
      const double ss = step.squaredNorm();
      if (ss > 0) *J += (change - *J * step) * step.transpose() / ss;
    }
  }

  // Nested one-dimensional solves, each on a continuous function bracketed by sign changes: for a roll, the
  // height at which the wheels carry Q (sum Fz decreases with z); then the roll at which sum Mx changes sign.
  // Slow but it needs no Jacobian and no start close to the solution.
  bool nested(double y, Iterate& cur, std::string& why) {
    double z_guess = cur.z;
    ContactResult c;
    auto height_for = [&](double roll) {
      auto f = [&](double z) {
        c = contact_at(y, z, roll);
        return c.force.z() - Q_;
      };
      double a = z_guess, fa = f(a);
      if (std::abs(fa) <= ftol_) return a;
      double step = fa > 0 ? 0.05e-3 : -0.05e-3, b = a, fb = fa;
      for (int i = 0; i < 20 && (fb > 0) == (fa > 0); ++i) {
        a = b;
        fa = fb;
        b = std::clamp(a + step, -0.03, 0.05);
        fb = f(b);
        step *= 2;
      }
      if ((fb > 0) == (fa > 0)) throw Error(fmt::format("no height carries Q at roll {:.6g} rad", roll));
      bool ok = false;
      const double z = bracketed_root(f, a, b, fa, fb, ftol_, 100, ok);
      z_guess = z;
      return z;  // within the bracket even if the force is not exact: the moment is what is looked for
    };
    double best_z = cur.z, best_roll = cur.roll;
    auto moment_at = [&](double roll) {
      best_z = height_for(roll);
      best_roll = roll;
      return c.moment.x();
    };
    try {
      const double a = cur.roll, fa = moment_at(a);
      double root = a;
      if (std::abs(fa) > mtol_) {
        double step = 0.25e-3, b = a, fb = fa;
        bool bracketed = false;
        for (int i = 0; i < 8 && !bracketed; ++i, step *= 2)
          for (double sgn : {1.0, -1.0}) {
            const double x = a + sgn * step, fx = moment_at(x);
            if ((fx > 0) != (fa > 0)) {
              b = x;
              fb = fx;
              bracketed = true;
              break;
            }
          }
        if (!bracketed) throw Error("no roll within +-32 mrad balances the roll moment");
        bool ok = false;
        root = bracketed_root(moment_at, a, b, fa, fb, mtol_, 100, ok);
      }
      cur = evaluate(y, height_for(root), root);
      if (!converged(cur)) {
        // Polish with Newton from the bracketed point.
        std::string w;
        Iterate p;
        if (newton(y, cur.z, cur.roll, std::nullopt, false, p, w)) cur = std::move(p);
      }
      if (!converged(cur)) why = "nested solve: residuals above tolerance";
      return converged(cur);
    } catch (const Error& e) {
      why = std::string("nested solve: ") + e.what();
      cur = evaluate(y, best_z, best_roll);
      return false;
    }
  }

  // Newton from the rigid position at y pressed in by initial_approach (the rigid solution is kept in `rigid`).
  bool from_rigid(double y, Iterate& cur, std::vector<std::string>& why) {
    rigid = solve_rigid(model_.geometry(), y, yaw_, Q_);
    if (!rigid->message.empty()) {
      why.push_back("rigid start: " + rigid->message);
      return false;
    }
    std::string w;
    if (newton(y, rigid->z - opt_.initial_approach, rigid->roll, std::nullopt, false, cur, w)) return true;
    why.push_back("from the rigid position: " + w);
    return false;
  }

  // Continuation from the centred wheelset, in steps of y that shrink where Newton struggles: it follows the
  // branch of equilibria that a wheelset pushed out from the centre follows. (Beyond flange contact there are
  // several: e.g. one wheel lifted, or the wheelset climbed up the flange; the rigid position leads to the latter.)
  bool continuation(double y, Iterate& cur, std::vector<std::string>& why) {
    const RigidResult r0 = solve_rigid(model_.geometry(), 0.0, yaw_, Q_);
    if (!r0.message.empty()) {
      why.push_back("continuation: rigid start at y = 0: " + r0.message);
      return false;
    }
    Iterate path;
    std::string w;
    if (!newton(0.0, r0.z - opt_.initial_approach, r0.roll, std::nullopt, false, path, w)) {
      why.push_back("continuation: no equilibrium at y = 0: " + w);
      return false;
    }
    double y_at = 0, step = 0.5e-3 * (y > 0 ? 1 : -1);
    double z_prev = path.z, roll_prev = path.roll, y_prev = y_at;
    while (y_at != y) {
      const double y_next = std::abs(y - y_at) <= std::abs(step) ? y : y_at + step;
      // Linear predictor through the last two points of the path.
      const double s = y_at != y_prev ? (y_next - y_at) / (y_at - y_prev) : 0.0;
      Iterate next;
      if (newton(y_next, path.z + s * (path.z - z_prev), path.roll + s * (path.roll - roll_prev), std::nullopt, false, next, w) ||
          newton(y_next, path.z, path.roll, std::nullopt, false, next, w)) {
        y_prev = y_at;
        z_prev = path.z;
        roll_prev = path.roll;
        y_at = y_next;
        path = std::move(next);
        step = std::clamp(step * 1.5, -1e-3, 1e-3);
      } else if (std::abs(step) > 0.02e-3) {
        step *= 0.25;
      } else {
        why.push_back(fmt::format("continuation from y = 0 stopped at y = {:.3f} mm: {}", y_at * 1e3, w));
        return false;
      }
    }
    cur = std::move(path);
    return true;
  }

  // Nested bracketing at y from the last iterate there (or from the rigid position).
  bool bracketing(double y, Iterate& cur, std::vector<std::string>& why) {
    if (cur.contact.pose.y != y || cur.contact.pose.yaw != yaw_) {
      const bool r = rigid && rigid->message.empty();
      cur = evaluate(y, r ? rigid->z - opt_.initial_approach : 0.0, r ? rigid->roll : 0.0);
    }
    std::string w;
    const bool ok = nested(y, cur, w);
    if (!ok) why.push_back(w);
    return ok;
  }

  std::optional<RigidResult> rigid;  // the rigid solution at y, once from_rigid has run

  // A solution found with inexact normal solves, evaluated again at the model's tolerance (the forces
  // evaluate_contact gives at the pose; from the converged pressures, a few CG iterations); if that moved the
  // residuals out of tolerance, Newton goes on from there with solves at the model's tolerance.
  bool confirm(double y, Iterate& cur, std::string& why) {
    const double tight = model_.options().normal.tolerance;
    if (cur.tolerance <= tight) return true;
    req_.tolerance = tight;
    cur = evaluate(y, cur.z, cur.roll);
    if (converged(cur)) return true;
    const double saved = inexact_;
    inexact_ = tight;  // go on at the model's tolerance
    Iterate next;
    const bool ok = newton(y, cur.z, cur.roll, res_.jacobian, res_.jacobian_lifted, next, why);
    inexact_ = saved;
    if (ok) cur = std::move(next);
    return ok;
  }

  // One evaluation past the budget, for the last iterate of a failed solve.
  Iterate evaluate_unbudgeted(double y, double z, double roll) {
    unbudgeted_ = true;
    Iterate it = evaluate(y, z, roll);
    unbudgeted_ = false;
    return it;
  }

  Iterate evaluate(double y, double z, double roll) {
    Iterate it;
    it.z = z;
    it.roll = roll;
    it.contact = contact_at(y, z, roll);
    it.tolerance = req_.tolerance;
    const ContactResult& c = it.contact;
    it.R = {c.force.z() - Q_, c.moment.x()};
    it.lifted = !(c.wheel[kLeft].force.z() > 0) || !(c.wheel[kRight].force.z() > 0);
    const double rf = it.R(0) / Q_, rm = it.R(1) / Q_;
    it.merit = rf * rf + rm * rm;
    if (!unbudgeted_ && it.R(0) < 0 && deepest(c) > opt_.limits.max_penetration)  // deeper is the only way on: hopeless
      throw UnreachableLoad(unreachable("Q", Q_, c.force.z(), c.pose, deepest(c), opt_.limits.max_penetration));
    return it;
  }

 private:
  ContactResult contact_at(double y, double z, double roll) {
    if (res_.evaluations >= opt_.limits.max_evaluations && !unbudgeted_)
      throw EvaluationBudget(fmt::format("gave up after {} contact evaluations (max_evaluations)", res_.evaluations));
    ++res_.evaluations;
    return evaluate_contact(model_, {y, z, roll, yaw_}, ws_, req_);
  }

  // The Jacobian: from the sensitivities of the normal problems while both wheels are loaded (they hold the
  // contact planes fixed, which is exact to first order for the elastic stiffness); with a wheel lifted the roll
  // balance rests on where the loaded wheel's contact sits, a geometric effect they miss: forward differences.
  Eigen::Matrix2d jacobian(double y, Iterate& it) {
    ++res_.jacobians;
    Eigen::Matrix2d J;
    if (!it.lifted) {
      add_sensitivity(model_, it.contact, ws_);
      const Sensitivity& S = it.contact.sensitivity;
      J << S(2, 0), S(2, 1), S(3, 0), S(3, 1);
      return J;
    }
    const double hz = 1e-7, hr = 1e-7;
    auto R = [&](double z, double roll) {
      const ContactResult c = contact_at(y, z, roll);
      return Eigen::Vector2d(c.force.z() - Q_, c.moment.x());
    };
    J.col(0) = (R(it.z + hz, it.roll) - it.R) / hz;
    J.col(1) = (R(it.z, it.roll + hr) - it.R) / hr;
    return J;
  }

  const ContactModel& model_;
  double yaw_, Q_;
  ContactWorkspace& ws_;
  const NewtonOptions& opt_;
  EquilibriumResult& res_;
  ContactRequest req_;
  double inexact_ = 0;  // the normal solves' tolerance while far from a solution
  double ftol_ = 0, mtol_ = 0;
  bool unbudgeted_ = false;
};

}  // namespace

namespace {

// A lifted wheel raised above its rail by more than its flange height is off the rail; the first wheel past flange
// climb names the equilibrium's flag.
void flag_flange_climb(const ContactModel& model, EquilibriumResult& res) {
  for (int s : {kLeft, kRight}) {
    WheelContact& wc = res.contact.wheel[s];
    if (wc.flange_climb.empty() && !(wc.force.z() > 0))
      wc.flange_climb = lifted_off(model.flange(s), -deepest_point(model.geometry(), s, res.contact.pose).overlap);
    if (!wc.flange_climb.empty() && res.flange_climb.empty())
      res.flange_climb = fmt::format("{} wheel: {}", side_name(s), wc.flange_climb);
  }
}

// The result of a solve from its last iterate.
void finish_result(const ContactModel& model, ContactWorkspace& ws, const ContactRequest& request,
                   const NewtonOptions& opt, bool ok, std::vector<std::string>& why, EquilibriumSolver& solver,
                   Iterate& cur, EquilibriumResult& res) {
  res.converged = ok && solver.converged(cur);
  if (res.converged && deepest(cur.contact) > opt.limits.max_penetration) {
    res.converged = false;
    why.assign(1, too_deep(deepest(cur.contact), opt.limits.max_penetration));
  }
  if (!res.converged) {
    std::string m;
    for (const auto& s : why) m += (m.empty() ? "" : "; ") + s;
    res.message = m.empty() ? "no convergence" : m;
  }
  res.z = cur.z;
  res.roll = cur.roll;
  res.residual_force = cur.R(0);
  res.residual_moment = cur.R(1);
  res.Y = -cur.contact.force.y();
  res.My = -cur.contact.moment.y();
  res.Mz = -cur.contact.moment.z();
  if (request.sensitivity && !cur.lifted) add_sensitivity(model, cur.contact, ws);
  if (!request.keep_grids) drop_grids(cur.contact);
  res.contact = std::move(cur.contact);
  flag_flange_climb(model, res);
}

}  // namespace

void EquilibriumCase::validate(std::string_view context, bool plausible) const {
  check_lateral(y, context);
  check_yaw(yaw, context);
  pose_solve::check_load("Q", Q, context);
  if (plausible) check_plausible(context, "Q", Q, kWheelsetLoad);
}

void NewtonOptions::validate(std::string_view context) const {
  limits.validate(context);
  if (!(moment_tolerance > 0 && moment_tolerance <= 0.1))
    fail("{}: moment_tolerance = {} must be in ]0, 0.1] (relative to Q x 1 m)", context, moment_tolerance);
  if (!(max_step_z > 0 && max_step_z <= 0.01))
    fail("{}: max_step_z = {} m must be in ]0, 0.01] m", context, max_step_z);
  if (!(max_step_roll > 0 && max_step_roll <= 0.1))
    fail("{}: max_step_roll = {} rad must be in ]0, 0.1] rad", context, max_step_roll);
  if (!(initial_approach >= 0 && initial_approach <= 0.01))
    fail("{}: initial_approach = {} m must be in [0, 0.01] m", context, initial_approach);
}

namespace {

// A solve stopped before any attempt reached the case's y (continuation's path, the first attempt farther out;
// every attempt at y leaves its iterate there): its result is the rigid position at y, evaluated, and says so.
void last_at_case(const ContactModel& model, EquilibriumSolver& solver, double y, double yaw, double Q, Iterate& cur,
                  std::vector<std::string>& why) {
  if (cur.contact.pose.y == y) return;
  std::optional<RigidResult> r;
  try {
    r = solve_rigid(model.geometry(), y, yaw, Q);
  } catch (const Error&) {
  }
  const bool rigid = r && r->message.empty();
  const double z = rigid ? r->z : 0.0, roll = rigid ? r->roll : 0.0;
  why.push_back(fmt::format("no attempt reached y = {:.4f} mm: the result holds the {} (z = {:.6f} mm, roll = {:.6f} "
                            "mrad) evaluated there, not an iterate", y * 1e3, rigid ? "rigid position" : "centred pose",
                            z * 1e3, roll * 1e3));
  cur = solver.evaluate_unbudgeted(y, z, roll);
}

}  // namespace

EquilibriumResult solve_equilibrium(const ContactModel& model, const EquilibriumCase& c, ContactWorkspace& ws,
                                    const NewtonOptions& opt, const std::vector<Start>& starts,
                                    const ContactRequest& request) {
  c.validate("equilibrium", model.options().check_magnitudes);
  opt.validate("equilibrium");
  const double y = c.y, yaw = c.yaw, Q = c.Q;
  EquilibriumResult res;
  res.y = y;
  res.yaw = yaw;
  res.Q = Q;
  EquilibriumSolver solver(model, yaw, Q, ws, opt, request, res);
  Iterate cur;
  std::vector<std::string> why;
  bool ok = false;
  try {
    // 1. The given starts (neighbouring solutions, predictions), in order.
    for (std::size_t k = 0; k < starts.size() && !ok; ++k) {
      std::string w;
      ok = solver.newton(y, starts[k].z, starts[k].roll, starts[k].jacobian, starts[k].jacobian_lifted, cur, w);
      if (!ok) why.push_back(fmt::format("from the {} start: {}", ordinal(k + 1), w));
    }
    // 2. Near the centre, the rigid position pressed in a little; farther out, continuation first.
    const bool near_centre = std::abs(y) <= 2e-3;
    if (!ok) ok = near_centre ? solver.from_rigid(y, cur, why) : solver.continuation(y, cur, why);
    if (!ok) ok = near_centre ? (std::abs(y) > 0.5e-3 && solver.continuation(y, cur, why)) : solver.from_rigid(y, cur, why);
    // 3. Nested bracketing.
    if (!ok) ok = solver.bracketing(y, cur, why);
    if (ok) {
      std::string w;
      ok = solver.confirm(y, cur, w);
      if (!ok) why.push_back("confirming at the model's tolerance: " + w);
    }
  } catch (const EvaluationBudget& e) {
    why.push_back(e.what());
    last_at_case(model, solver, y, yaw, Q, cur, why);
  } catch (const UnreachableLoad& e) {
    why.assign(1, e.what());
    last_at_case(model, solver, y, yaw, Q, cur, why);
  }
  finish_result(model, ws, request, opt, ok, why, solver, cur, res);
  return res;
}

// ---- options, messages, fields ----

EquilibriumCase read_equilibrium_case(OptionReader& r) {
  EquilibriumCase c;
  c.y = r.need_number("y", {"m", "lateral position of the wheelset centre"});
  c.yaw = r.number("yaw", {"rad", "yaw angle of the wheelset"}, c.yaw);
  c.Q = r.need_number("Q", {"N", "vertical load at the wheelset centre"});
  return c;
}

NewtonOptions read_newton_options(OptionReader& r) {
  NewtonOptions o;
  o.limits = read_solve_limits(r);
  o.moment_tolerance =
      r.number("moment_tolerance", {"-", "converged: |sum Mx| <= this * Q * 1 m"}, o.moment_tolerance);
  if (r.boolean("trace", {"-", "print the Newton iterates to stderr"}, false)) {
    o.trace = [](int it, double z, double roll, const ContactResult& c) {
      std::fprintf(stderr, "  newton %2d: z = %+.6f mm, roll = %+.6f mrad, Fz = %.3f kN (left %.3f, right %.3f), Mx = %+.3f N m\n",
                   it, z * 1e3, roll * 1e3, c.force.z() / 1e3, c.wheel[kLeft].force.z() / 1e3,
                   c.wheel[kRight].force.z() / 1e3, c.moment.x());
    };
  }
  if (!r.documenting()) o.validate(r.context());
  return o;
}

std::string failure_message(const EquilibriumResult& e) {
  return fmt::format("no equilibrium found at y = {:.4f} mm, yaw = {:.6g} rad, Q = {:.6g} kN: {}; last iterate z = "
                     "{:.6f} mm, roll = {:.6f} mrad, residuals: force {:.4g} N, moment {:.4g} N m",
                     e.y * 1e3, e.yaw, e.Q / 1e3, e.message, e.z * 1e3, e.roll * 1e3, e.residual_force,
                     e.residual_moment);
}

void describe(const EquilibriumResult& e, FieldSink& out) {
  out.boolean("converged", e.converged, {"", "the equilibrium was found"});
  if (!e.message.empty()) out.string("error", e.message, {"", "why it was not (only when not converged)"});
  out.boolean("flange_climb", !e.flange_climb.empty(), {"", "a wheel is past flange climb"});
  if (!e.flange_climb.empty())
    out.string("flange_climb_reason", e.flange_climb, {"", "which wheel and why (only when flange_climb)"});
  out.number("y", e.y, {"m", "lateral position of the wheelset centre, + toward the left rail"});
  out.number("yaw", e.yaw, {"rad", "yaw, > 0 counter-clockwise seen from above"});
  out.number("Q", e.Q, {"N", "vertical load on the wheelset"});
  out.number("z", e.z, {"m", "solved height of the centre (or the last iterate), < 0 pressed into the rails"});
  out.number("roll", e.roll, {"rad", "solved roll (or the last iterate), > 0 lifts the left wheel"});
  out.number("Y", e.Y, {"N", "lateral force a support at the centre applies, -sum Fy: > 0 pushes toward the left rail"});
  out.number("My", e.My, {"N m", "moment about y the support applies, -sum My"});
  out.number("Mz", e.Mz, {"N m", "moment about z the support applies, -sum Mz"});
  out.number("Y_Q", e.Q > 0 ? e.Y / e.Q : 0.0, {"-", "derailment quotient Y / Q"});
  out.integer("iterations", e.iterations, {"-", "Newton iterations"});
  out.integer("evaluations", e.evaluations, {"-", "contact evaluations, line-search trials included"});
  out.begin("residual", {"", "the equilibrium's residuals at the result"});
  out.number("force", e.residual_force, {"N", "sum Fz - Q"});
  out.number("moment", e.residual_moment, {"N m", "sum Mx"});
  out.end();
  for (int s : {kLeft, kRight}) {
    out.begin(side_name(s), {"", "the contact of the wheel on that side (left: +y)"});
    describe(e.contact.wheel[s], out);
    out.end();
  }
  // Only with both wheels loaded: a lifted wheel has no rolling radius (Δr would be a wheel radius).
  if (e.contact.wheel[kLeft].force.z() > 0 && e.contact.wheel[kRight].force.z() > 0)
    out.number("rolling_radius_difference", e.contact.wheel[kLeft].rolling_radius - e.contact.wheel[kRight].rolling_radius,
               {"m", "left minus right wheel's rolling radius (only with both wheels loaded)"});
  out.vec3("force", e.contact.force, {"N", "contact forces of both wheels summed (track frame)"});
  out.vec3("moment", e.contact.moment, {"N m", "their moment about the wheelset centre (track axes)"});
  describe(e.contact.creep, out);
  describe_spin(e.contact, out);
}

}  // namespace wrc
