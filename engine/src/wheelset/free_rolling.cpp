// Free rolling: the spin of a wheelset without traction or braking torque (free_rolling.hpp).
//
// Both wheels sit on one rigid axle and turn at one omega; a wheel whose contact lies off the nominal radius r0
// (a hollow-worn tread, a flange contact in a curve, a rolling-radius difference) rolls with a longitudinal creepage
// xi = 1 - omega r / V at its contact radius r, and the creep forces of the two wheels, acting at different radii,
// have a moment about the axle. A free wheelset (the axle's spin a degree of freedom without a driving or braking
// torque, its inertia at steady rolling out of play) turns at the omega at which that moment vanishes. The axle torque
// falls monotonically with omega (a faster wheel gets a forward creep force below the axle, whose moment turns it
// back), so a 1-D bracketing search finds it. In linear theory (Kalker's Fx = -G c^2 C11 xi per area) the balance is
// sum f11 xi r = 0 over the areas, xi = 1 - omega r / V: omega = V sum f11 r / sum f11 r^2.
#include "free_rolling.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/roots.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace wrc {

namespace {

constexpr double kFirstStep = 1e-4;  // omega r0 / V: xi 1e-4, the creepage of a new tread's balance
// The longest first (Newton) step: a slope from another case may be far off (a flat, saturated torque), and a bracket
// reaching into full sliding would leave regula falsi on its plateau.
constexpr double kNewtonStep = 1e-3;
constexpr double kSlopeBase = 1e-7;  // the shortest secant the slope is taken from (100 x kFreeRollingResolution)
// The secant's step past its predicted root, so that the bracket closes where the torque is known only to the exact
// solver's noise (a secant from one side stalled at -0.68 N m, 1.6e-7 short of the root, on a flange at 1e-4).
constexpr double kOvershoot = 1.2;
constexpr int kGrowSteps = 24;      // 1e-7 x 4^12 already spans kFreeRollingSpan; secant steps come before
constexpr int kRootSteps = 40;      // regula falsi (Illinois) within the bracket

// The torque of all areas sliding at their rolling radii (the search's scale).
double sliding_torque(const ContactResult& result, const RollingRequest& request) {
  double t = 0;
  for (const WheelContact& wc : result.wheel)
    for (const PatchContact& pc : wc.patches)
      t += request.friction.static_coefficient * pc.normal_force * pc.rolling_radius;
  return t;
}

}  // namespace

void solve_free_rolling(const ContactModel& model, ContactResult& result, const RollingRequest& request,
                        ContactWorkspace& ws) {
  RollingRequest fixed = request;
  Kinematics& k = *fixed.kinematics;
  k.free_rolling = false;
  const double r0 = model.geometry().track->params.radius, V = k.V;
  int evaluations = 0;
  double at = 0;                 // the ratio the result was last solved at
  double s1 = 0, t1 = 0, slope = 0;  // the last evaluation, the secant through the last two far enough apart
  const auto torque = [&](double s) {
    k.omega = s * V / r0;
    add_rolling(model, result, fixed, ws);
    const double t = result.creep.axle_torque;
    if (++evaluations > 1 && std::abs(s - s1) >= kSlopeBase) slope = (t - t1) / (s - s1);
    s1 = s;
    t1 = t;
    at = s;
    return t;
  };
  const double sliding = sliding_torque(result, request), tol = kFreeRollingTolerance * sliding;
  const double lo = 1 - kFreeRollingSpan, hi = 1 + kFreeRollingSpan;
  const bool started = ws.spin && ws.spin->ratio > lo && ws.spin->ratio < hi;
  double a = started ? ws.spin->ratio : 1.0;
  // The torque falls with omega (for V < 0, omega = s V / r0 turns the other way: it rises with s).
  const double falls = V > 0 ? -1.0 : 1.0;
  const double known = started && ws.spin->slope * falls > 0 ? ws.spin->slope : 0.0;
  double fa = torque(a);
  const auto finish = [&](double s) {
    if (s != at) torque(s);
    ws.spin = ContactWorkspace::Spin{s, slope * falls > 0 ? slope : known};
    result.spin_evaluations = evaluations;
  };
  if (std::abs(fa) <= tol) return finish(a);
  // The first step: Newton's with the slope the last search ended with, else a probe of kFirstStep. The direction is
  // the torque's sign, never turned: the torque is monotone in omega (each area's Fx is in its xi, the normal problems
  // are fixed), so a step whose torque does not fall is one within the exact solver's noise (started from the solution
  // a step of 1e-7 before, it returns that one unchanged) or on a saturated plateau, and the root lies further on.
  // (Turning there sent the search away from a root it started within the noise of, to the span's end.)
  const double dir = (fa > 0) == (falls < 0) ? 1.0 : -1.0;
  double b = a, fb = fa;
  double h = known != 0 ? std::clamp(std::abs(fa / known), kSlopeBase, kNewtonStep) : kFirstStep;
  std::string seen = fmt::format("{:.4g} N m at omega r0 / V = {:.6f}", fa, a);
  bool bracketed = false;
  for (int step = 0; step < kGrowSteps && !bracketed; ++step) {
    b = std::clamp(a + dir * h, lo, hi);
    fb = torque(b);
    seen += fmt::format(", {:.4g} at {:.6f}", fb, b);
    if (std::abs(fb) <= tol) return finish(b);
    if ((fb > 0) != (fa > 0)) {
      bracketed = true;
    } else {
      if (b == lo || b == hi) break;
      // The secant's distance to the root along dir where the torque fell; 4 times the step where it did not.
      const double ahead = std::abs(fb) < std::abs(fa) ? fb * (b - a) / (fa - fb) * dir : 0.0;
      h = ahead > 0 ? std::clamp(kOvershoot * ahead, kSlopeBase, 4 * h) : 4 * h;
      a = b;
      fa = fb;
    }
  }
  if (!bracketed && (b == lo || b == hi))
    fail("free_rolling: no omega within {:g} .. {:g} times V / r0 = {:.6g} rad/s balances the axle torque of the creep "
         "forces: at the span's end it is {:.4g} N m, {:.3g} of the areas' torque all sliding (sum mu N r = {:.4g} N m), "
         "and it does not change sign ({}); give omega instead", lo, hi, V / r0, fb, std::abs(fb) / sliding, sliding,
         seen);
  if (!bracketed)
    fail("free_rolling: the axle torque did not change sign within {} steps from omega r0 / V = {:.8f} ({}); give omega "
         "instead", kGrowSteps, a, seen);
  bool ok = false;
  const double s = bracketed_root(torque, a, b, fa, fb, tol, kRootSteps, ok, kFreeRollingResolution);
  if (!ok)
    fail("free_rolling: the axle torque did not fall below {:.3g} N m within {} steps between omega r0 / V = {:.8f} "
         "and {:.8f} ({:.4g} and {:.4g} N m at the bracket's ends)", tol, kRootSteps, a, b, fa, fb);
  finish(s);
}

}  // namespace wrc
