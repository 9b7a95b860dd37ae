// The limits of the pose solvers (wrc/equilibrium/limits.hpp) and what they share when a case ends (pose_solve.hpp).
#include "wrc/equilibrium/limits.hpp"

#include "pose_solve.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {

void SolveLimits::validate(std::string_view context) const {
  if (!(force_tolerance > 0 && force_tolerance <= 0.1))
    fail("{}: force_tolerance = {} must be in ]0, 0.1] (relative to the load)", context, force_tolerance);
  if (max_iterations < 1 || max_iterations > kMaxSolveCount)
    fail("{}: max_iterations = {} must be in [1, {}]", context, max_iterations, kMaxSolveCount);
  if (max_evaluations < 1 || max_evaluations > kMaxSolveCount)
    fail("{}: max_evaluations = {} must be in [1, {}]", context, max_evaluations, kMaxSolveCount);
  if (!(max_penetration > 0) || !std::isfinite(max_penetration))
    fail("{}: max_penetration = {} m must be a positive number", context, max_penetration);
  if (!(normal_tolerance >= 1e-14 && normal_tolerance < 1e-2))
    fail("{}: normal_tolerance = {} must be in [1e-14, 1e-2[ (relative)", context, normal_tolerance);
}

SolveLimits read_solve_limits(OptionReader& r) {
  SolveLimits l;
  l.force_tolerance = r.number("force_tolerance", {"-", "converged: |carried - load| <= this * load"}, l.force_tolerance);
  l.max_iterations = r.integer("max_iterations", 1, kMaxSolveCount, {"-", "iterations per attempt"}, l.max_iterations);
  l.max_evaluations =
      r.integer("max_evaluations", 1, kMaxSolveCount, {"-", "contact evaluations per solve"}, l.max_evaluations);
  l.max_penetration = read_max_penetration(r, l.max_penetration);
  if (!r.documenting()) l.validate(r.context());
  return l;
}

namespace pose_solve {

void check_load(std::string_view name, double load, std::string_view context) {
  if (!std::isfinite(load) || !(load > 0) || load > kMaxLoad)
    fail("{}: {} = {:.6g} N must be a positive number of at most {:.0e} N (loads are in N: 100 kN is 1e5)", context,
         name, load, kMaxLoad);
}

double deepest(const ContactResult& c, int side) {
  double d = 0;
  for (int s : {kLeft, kRight})
    if (side < 0 || side == s)
      for (const PatchContact& p : c.wheel[s].patches) d = std::max(d, p.penetration);
  return d;
}

std::string unreachable(std::string_view what, double load, double carried, const Pose& p, double depth, double limit) {
  return fmt::format("the load is out of reach: {} = {:.4g} N, but at y = {:.4f} mm, z = {:.4f} mm, roll = {:.4f} mrad "
                     "the contacts are {:.3f} mm deep (max_penetration = {:.3g} mm) and still carry only {:.4g} N; "
                     "expected a load the wheels carry within max_penetration (wheel-rail contacts at realistic loads "
                     "are 0.05-0.3 mm deep; beyond ~1 mm the half-space model no longer holds)",
                     what, load, p.y * 1e3, p.z * 1e3, p.roll * 1e3, depth * 1e3, limit * 1e3, carried);
}

std::string too_deep(double depth, double limit) {
  return fmt::format("the solution's contacts are {:.4g} mm deep, more than max_penetration = {:.4g} mm (wheel-rail "
                     "contacts at realistic loads are 0.05-0.3 mm deep; beyond ~1 mm the half-space model no longer "
                     "holds); raise the option max_penetration to accept it", depth * 1e3, limit * 1e3);
}

}  // namespace pose_solve
}  // namespace wrc
