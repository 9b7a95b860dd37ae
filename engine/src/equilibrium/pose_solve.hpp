// What the two pose solvers (newton.cpp, wheel.cpp) share besides their limits: the checks of a case's numbers and
// the ends of a solve at a limit (the evaluation budget, a load out of reach, a solution too deep). Internal.
#pragma once

#include "wrc/core/error.hpp"
#include "wrc/wheelset/contact.hpp"

#include <string>
#include <string_view>

namespace wrc::pose_solve {

// A load `name` (N) in ]0, kMaxLoad]; else an error naming `context`.
void check_load(std::string_view name, double load, std::string_view context);

// Thrown when a solve has used its evaluation budget (SolveLimits::max_evaluations).
struct EvaluationBudget : Error {
  using Error::Error;
};
// Thrown when an iterate is deeper than max_penetration and still carries less than the load.
struct UnreachableLoad : Error {
  using Error::Error;
};

// The deepest contact area (max h, m) of one wheel, or of both (side < 0).
double deepest(const ContactResult& c, int side = -1);
// Why a load is out of reach: `what` = `load` (N) asked for, `carried` (N) at the pose p whose contacts are `depth` (m)
// deep, beyond max_penetration = `limit` (m).
std::string unreachable(std::string_view what, double load, double carried, const Pose& p, double depth, double limit);
// Why a solution `depth` (m) deep is no solution of the model (SolveLimits::max_penetration = `limit`).
std::string too_deep(double depth, double limit);

}  // namespace wrc::pose_solve
