// Elastic equilibrium (Newton on z and roll), one wheel with its vertical force given, and the rigid reference.
#include "wrc/equilibrium/equilibrium.hpp"

#include "wrc/contact/wheel_surface.hpp"
#include "wrc/core/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {
namespace {

void check_case(double y, double yaw, double Q, const char* what) {
  if (!std::isfinite(y) || std::abs(y) > 0.1) fail("{}: y = {} m must be finite and within +-0.1 m", what, y);
  if (!std::isfinite(yaw) || std::abs(yaw) > 0.3) fail("{}: yaw = {} rad must be finite and within +-0.3 rad", what, yaw);
  if (!std::isfinite(Q) || !(Q > 0)) fail("{}: Q = {} N must be a positive number", what, Q);
}

// Root of f on a bracket [a, b] (f(a), f(b) of opposite signs) by the Illinois variant of regula falsi:
// superlinear on smooth functions, never leaves the bracket. Stops when |f| <= ftol; `ok` says whether it did.
template <class F>
double bracketed_root(F&& f, double a, double b, double fa, double fb, double ftol, int max_iter, bool& ok) {
  ok = false;
  int kept = 0;  // +1 / -1: which end was kept last (halve its value when kept twice)
  for (int it = 0; it < max_iter; ++it) {
    double x = b - fb * (b - a) / (fb - fa);
    if (!(x > std::min(a, b) && x < std::max(a, b))) x = 0.5 * (a + b);
    const double fx = f(x);
    if (std::abs(fx) <= ftol) {
      ok = true;
      return x;
    }
    if ((fx < 0) == (fb < 0)) {  // x replaces b, a is kept
      b = x;
      fb = fx;
      if (kept == 1) fa *= 0.5;
      kept = 1;
    } else {  // x replaces a... the bracket is now [b, x]
      a = b;
      fa = fb;
      b = x;
      fb = fx;
      kept = -1;
    }
  }
  return std::abs(fa) < std::abs(fb) ? a : b;
}

}  // namespace

RigidWheel deepest_point(const GeometryModel& g, int side, const Pose& pose) {
  const PoseFrame f(pose);
  const RailLines& rail = g.side[side].rail;
  const WheelCones& w = g.side[side].wheel;
  RigidWheel best;
  best.overlap = -std::numeric_limits<double>::infinity();
  double x = 0;
  for (int r = 0; r < rail.count(); ++r) {
    const LineApproach a = line_approach(w, f, rail.y[r], rail.z[r]);
    if (a.overlap > best.overlap) {
      best.overlap = a.overlap;
      best.line = r;
      x = a.x;
    }
  }
  if (best.line >= 0) {
    best.point = {x, rail.y[best.line], rail.z[best.line]};
    best.normal = wheel_inward_normal(w, f, best.point);
    const double sign = side == kLeft ? 1.0 : -1.0;
    best.angle = std::atan2(-sign * best.normal.y(), best.normal.z());
    best.rolling_radius = wheel_surface_at(w, f.to_wheelset(best.point).y()).radius;
  }
  return best;
}

RigidResult solve_rigid(const GeometryModel& g, double y, double yaw, double Q) {
  check_case(y, yaw, Q, "rigid contact");
  RigidResult res;
  res.y = y;
  res.yaw = yaw;
  res.Q = Q;
  auto pen = [&](int side, double z, double roll) { return deepest_point(g, side, {y, z, roll, yaw}).overlap; };
  // For a roll, the height at which the first wheel touches: max overlap over both sides = 0 (decreasing in z).
  auto touch_z = [&](double roll) {
    auto f = [&](double z) { return std::max(pen(kLeft, z, roll), pen(kRight, z, roll)); };
    double a = -0.02, b = 0.02;
    double fa = f(a), fb = f(b);
    if (!(fa > 0 && fb < 0)) fail("rigid contact: no touching height within +-20 mm at y = {}, yaw = {}", y, yaw);
    bool ok = false;
    return bracketed_root(f, a, b, fa, fb, 1e-13, 200, ok);
  };
  // Then the roll at which both wheels touch: the difference of the overlaps changes sign (left rises with roll).
  auto diff = [&](double roll) {
    const double z = touch_z(roll);
    return pen(kLeft, z, roll) - pen(kRight, z, roll);
  };
  try {
    double a = -0.02, b = 0.02;
    double fa = diff(a), fb = diff(b);
    if (!(fa > 0 && fb < 0)) fail("rigid contact: no roll within +-20 mrad puts both wheels on their rails");
    bool ok = false;
    res.roll = bracketed_root(diff, a, b, fa, fb, 1e-13, 200, ok);
    if (!ok) fail("rigid contact: the roll that puts both wheels on their rails was not found to 1e-13 m");
    res.z = touch_z(res.roll);
  } catch (const Error& e) {
    res.message = e.what();
    return res;
  }
  const Pose pose{y, res.z, res.roll, yaw};
  const Eigen::Vector3d c(0, y, res.z);
  for (int s : {kLeft, kRight}) res.wheel[s] = deepest_point(g, s, pose);
  // Normal forces from the vertical and roll balance: N_L n_L + N_R n_R carries Q with no moment about x.
  Eigen::Matrix2d A;
  Eigen::Vector2d rhs(Q, 0);
  for (int s : {kLeft, kRight}) {
    A(0, s) = res.wheel[s].normal.z();
    A(1, s) = (res.wheel[s].point - c).cross(res.wheel[s].normal).x();
  }
  const Eigen::Vector2d N = A.fullPivLu().solve(rhs);
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
  for (int s : {kLeft, kRight}) {
    res.wheel[s].normal_force = N(s);
    const Eigen::Vector3d f = N(s) * res.wheel[s].normal;
    F += f;
    M += (res.wheel[s].point - c).cross(f);
  }
  res.Y = -F.y();
  res.My = -M.y();
  res.Mz = -M.z();
  res.converged = std::isfinite(res.Y) && N.allFinite();
  if (!res.converged) res.message = "rigid contact: the contact normals give a singular force balance";
  return res;
}

namespace {

// An iterate of the equilibrium: the contact at (z, roll), the residual (sum Fz - Q, sum Mx) and its Jacobian.
struct Iterate {
  double z = 0, roll = 0;
  ContactResult contact;
  Eigen::Vector2d R = Eigen::Vector2d::Zero();  // N, N m
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // d R / d(z, roll)
  double merit = 0;
  bool lifted = false;  // a wheel carries no load
};

}  // namespace

EquilibriumResult solve_equilibrium(const ContactModel& model, double y, double yaw, double Q, ContactWorkspace& ws,
                                    const EquilibriumOptions& opt, std::optional<Start> start,
                                    const ContactRequest& request) {
  check_case(y, yaw, Q, "equilibrium");
  EquilibriumResult res;
  res.y = y;
  res.yaw = yaw;
  res.Q = Q;
  double z0 = 0, roll0 = 0;
  if (start) {
    z0 = start->z;
    roll0 = start->roll;
  } else {
    const RigidResult rigid = solve_rigid(model.geometry(), y, yaw, Q);
    if (!rigid.message.empty()) {
      res.message = rigid.message;
      return res;
    }
    z0 = rigid.z - opt.initial_approach;
    roll0 = rigid.roll;
  }
  ContactRequest req = request;
  req.sensitivity = false;  // added when a Newton step needs it (not for line-search trials or the last iterate)
  req.keep_grids = true;
  const double Mref = Q * 1.0;  // the moment scale Q x 1 m
  const double ftol = opt.force_tolerance * Q, mtol = opt.moment_tolerance * Mref;
  // Inexact Newton: far from the solution the normal problems need not be solved to the last digit; the
  // solver's tolerance follows the residual down to the model's own (about 1e-8).
  double accuracy = 1.0;  // the last relative residual
  auto contact_at = [&](double z, double roll) {
    ++res.evaluations;
    req.tolerance = std::clamp(1e-3 * accuracy, model.options().normal.tolerance, 1e-5);
    return evaluate_contact(model, {y, z, roll, yaw}, ws, req);
  };
  auto residual = [&](const ContactResult& c) { return Eigen::Vector2d(c.force.z() - Q, c.moment.x()); };
  auto evaluate = [&](double z, double roll) {
    Iterate it;
    it.z = z;
    it.roll = roll;
    it.contact = contact_at(z, roll);
    const ContactResult& c = it.contact;
    it.R = residual(c);
    it.lifted = !(c.wheel[kLeft].force.z() > 0) || !(c.wheel[kRight].force.z() > 0);
    const double rf = it.R(0) / Q, rm = it.R(1) / Mref;
    it.merit = rf * rf + rm * rm;
    return it;
  };
  // The Jacobian: from the sensitivities of the normal problems while both wheels are loaded (they hold the
  // contact planes fixed, which is exact to first order for elastic stiffness); with a wheel lifted the roll
  // balance rests on where the loaded wheel's contact sits, a geometric effect they miss: forward differences.
  auto jacobian = [&](Iterate& it) {
    if (!it.lifted) {
      add_sensitivity(model, it.contact, ws);
      const Sensitivity& S = it.contact.sensitivity;
      it.J << S(2, 0), S(2, 1), S(3, 0), S(3, 1);
      return;
    }
    const double hz = 1e-7, hr = 1e-7;
    it.J.col(0) = (residual(contact_at(it.z + hz, it.roll)) - it.R) / hz;
    it.J.col(1) = (residual(contact_at(it.z, it.roll + hr)) - it.R) / hr;
  };
  auto converged = [&](const Iterate& it) { return std::abs(it.R(0)) <= ftol && std::abs(it.R(1)) <= mtol; };

  Iterate cur = evaluate(z0, roll0);
  bool newton_failed = false;
  for (int k = 0;; ++k) {
    if (opt.trace) opt.trace(k, cur.z, cur.roll, cur.contact);
    res.iterations = k;
    accuracy = std::sqrt(cur.merit);
    if (converged(cur)) {
      if (req.tolerance <= model.options().normal.tolerance) break;
      cur = evaluate(cur.z, cur.roll);  // confirm with the normal problems solved to full accuracy
      if (converged(cur)) break;
    }
    if (k >= opt.max_iterations) {
      newton_failed = true;
      res.message = fmt::format("Newton: no convergence in {} iterations", opt.max_iterations);
      break;
    }
    if (cur.contact.wheel[kLeft].patches.empty() && cur.contact.wheel[kRight].patches.empty()) {
      // No contact at all: lower the wheelset (the residual is -Q with no slope to follow).
      if (cur.z < -0.02) {
        newton_failed = true;
        res.message = "no contact: the wheelset falls 20 mm without touching the rails";
        break;
      }
      cur = evaluate(cur.z - opt.max_step_z, cur.roll);
      continue;
    }
    jacobian(cur);
    Eigen::Vector2d dx = -cur.J.fullPivLu().solve(cur.R);
    if (!dx.allFinite()) {
      newton_failed = true;
      res.message = "Newton: singular Jacobian";
      break;
    }
    dx /= std::max({1.0, std::abs(dx(0)) / opt.max_step_z, std::abs(dx(1)) / opt.max_step_roll});
    double t = 1;
    bool accepted = false;
    for (int b = 0; b < 10; ++b, t *= 0.5) {
      Iterate trial = evaluate(cur.z + t * dx(0), cur.roll + t * dx(1));
      if (trial.merit < (1 - 1e-4 * t) * cur.merit) {
        cur = std::move(trial);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      newton_failed = true;
      res.message = "Newton: no descent";
      break;
    }
  }

  if (newton_failed) {
    // Fallback: nested one-dimensional solves, each on a continuous function bracketed by sign changes.
    // Inner: for a roll, the height at which the wheels carry Q (sum Fz decreases monotonically with z).
    // Outer: the roll at which sum Mx changes sign.
    const std::string newton_message = res.message;
    double z_guess = cur.z;
    auto height_for = [&](double roll, ContactResult& c, bool& ok) {
      auto f = [&](double z) {
        c = contact_at(z, roll);
        return c.force.z() - Q;
      };
      double a = z_guess, fa = f(a);
      if (std::abs(fa) <= ftol) {
        ok = true;
        return a;
      }
      // Bracket: step toward the sign change, doubling.
      double step = fa > 0 ? 0.05e-3 : -0.05e-3, b = a, fb = fa;
      for (int i = 0; i < 20 && (fb > 0) == (fa > 0); ++i) {
        a = b;
        fa = fb;
        b = a + step;
        fb = f(b);
        step *= 2;
        if (b < -0.03 || b > 0.05) break;
      }
      if ((fb > 0) == (fa > 0)) {
        ok = false;
        return b;
      }
      const double z = bracketed_root(f, a, b, fa, fb, ftol, 60, ok);
      if (ok) z_guess = z;
      c = contact_at(z, roll);
      return z;
    };
    ContactResult c;
    bool ok = false;
    double best_roll = cur.roll, best_z = cur.z;
    auto moment_at = [&](double roll) {
      const double z = height_for(roll, c, ok);
      if (!ok) throw Error(fmt::format("no height carries Q at roll {:.6g} rad", roll));
      best_roll = roll;
      best_z = z;
      return c.moment.x();
    };
    try {
      double a = cur.roll, fa = moment_at(a);
      bool found = std::abs(fa) <= mtol;
      double root = a;
      if (!found) {
        double step = 0.25e-3, b = a, fb = fa;
        bool bracketed = false;
        // Search both directions, widening.
        for (int i = 0; i < 8 && !bracketed; ++i, step *= 2) {
          for (double sgn : {1.0, -1.0}) {
            const double x = a + sgn * step, fx = moment_at(x);
            if ((fx > 0) != (fa > 0)) {
              b = x;
              fb = fx;
              bracketed = true;
              break;
            }
          }
        }
        if (!bracketed) throw Error("no roll within +-32 mrad balances the roll moment");
        bool rok = false;
        root = bracketed_root(moment_at, a, b, fa, fb, mtol, 80, rok);
        found = rok;
      }
      if (found) {
        cur = evaluate(height_for(root, c, ok), root);
        if (!ok) throw Error("the height solve failed at the final roll");
      }
      res.message = converged(cur) ? "" : newton_message + "; nested solve: no convergence";
    } catch (const Error& e) {
      res.message = newton_message + "; nested solve: " + e.what();
      cur = evaluate(best_z, best_roll);
    }
  }
  res.converged = converged(cur);
  if (res.converged) res.message.clear();
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
  return res;
}

WheelResult solve_wheel(const ContactModel& model, int side, double y, double yaw, double roll, double Fz,
                        ContactWorkspace& ws, const EquilibriumOptions& opt) {
  check_case(y, yaw, std::max(Fz, 1.0), "wheel");
  if (!std::isfinite(roll) || std::abs(roll) > 0.3) fail("wheel: roll = {} rad must be finite and within +-0.3", roll);
  if (!std::isfinite(Fz) || !(Fz > 0)) fail("wheel: Fz = {} N must be a positive number", Fz);
  WheelResult res;
  res.side = side;
  // Start: the height at which this wheel touches, pressed in a little.
  auto pen = [&](double z) { return deepest_point(model.geometry(), side, {y, z, roll, yaw}).overlap; };
  double fa = pen(-0.02), fb = pen(0.02);
  if (!(fa > 0 && fb < 0)) fail("wheel: the {} wheel does not touch its rail within z = +-20 mm", side_name(side));
  bool ok = false;
  double z = bracketed_root(pen, -0.02, 0.02, fa, fb, 1e-13, 200, ok) - opt.initial_approach;
  ContactRequest req;
  req.sensitivity = true;
  req.only_side = side;
  auto fz = [&](const ContactResult& c) { return c.wheel[side].force.z(); };
  ContactResult cur = evaluate_contact(model, {y, z, roll, yaw}, ws, req);
  for (int it = 0;; ++it) {
    res.iterations = it;
    res.residual = fz(cur) - Fz;
    if (std::abs(res.residual) <= opt.force_tolerance * Fz) {
      res.converged = true;
      break;
    }
    if (it >= opt.max_iterations) {
      res.message = fmt::format("no convergence in {} iterations (residual {:.3g} N)", opt.max_iterations, res.residual);
      break;
    }
    const double k = cur.wheel[side].sensitivity(2, 0);  // dFz/dz (< 0: pressing down raises the force)
    double dz = k < 0 ? -res.residual / k : -opt.max_step_z;
    dz = std::clamp(dz, -opt.max_step_z, opt.max_step_z);
    double t = 1;
    bool accepted = false;
    for (int kk = 0; kk < 12; ++kk, t *= 0.5) {
      ContactResult trial = evaluate_contact(model, {y, z + t * dz, roll, yaw}, ws, req);
      if (std::abs(fz(trial) - Fz) < (1 - 1e-4 * t) * std::abs(res.residual)) {
        z += t * dz;
        cur = std::move(trial);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      res.message = fmt::format("no descent (residual {:.3g} N)", res.residual);
      break;
    }
  }
  res.z = z;
  res.wheel = std::move(cur.wheel[side]);
  return res;
}

}  // namespace wrc
