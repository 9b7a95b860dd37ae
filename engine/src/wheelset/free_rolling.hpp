// Free rolling (Kinematics::free_rolling): the axle's angular velocity at which the creep forces of both wheels have no
// moment about the axle, for a wheelset that neither drives nor brakes.
#pragma once

#include "wrc/wheelset/contact.hpp"

namespace wrc {

// The ratio omega r0 / V at which a free-rolling search gives up: the axle torque has not changed sign between this
// and pure rolling at r0 (xi = +-0.5 at r0; a rolling-radius difference of a flange contact needs a few 1e-3).
inline constexpr double kFreeRollingSpan = 0.5;
// The axle torque at which the search stops, relative to the torque of both wheels' areas all sliding at their
// rolling radii (sum of mu N r): 1e-5 of it is 0.27 N m under 200 kN at mu 0.3, a longitudinal creep force of 0.6 N
// per wheel, above the exact solver's own noise at its default tolerance (1e-6 of the rigid slip). At the wear loop's
// 1e-4 the torque the solver returns scatters by about 1 N m on S1002/60E1 at y = 0 as its start moves: there the
// bracket's width ends the search (kFreeRollingResolution). Half the loop's tolerance instead (1.35 N m) moved a wear
// step's depths by 1.3 nm of its 0.1 mm, more than the solver's tolerance itself does (0.01 nm).
inline constexpr double kFreeRollingTolerance = 1e-5;
// Or where its bracket is this narrow in omega r0 / V (a creepage of 1e-9; 0.015 N m of axle torque on S1002/60E1
// at y = 0): the exact solver, started from the solution at the bracket's other end, returns that one unchanged for
// a change of the rigid slip within its tolerance, so that the torque is known to no finer than a few of these steps
// at rolling_tolerance = 1e-4 (0.3 to 0.7 N m on that case, above kFreeRollingTolerance).
inline constexpr double kFreeRollingResolution = 1e-9;

// Solves every area's tangential problem of `result` (its grids kept) at the spin that balances the axle torque:
// regula falsi (Illinois) on the axle torque against omega r0 / V, from the workspace's last free-rolling spin (or 1,
// pure rolling at r0), its bracket grown until the torque changes sign: first by Newton's step with the slope that
// search ended with (or by 1e-4 without one; at most 1e-3), then by the secant's prediction (1.2 times it, at least
// 1e-7, at most 4 times the step before; 4 times it where the torque did not fall: a step within the solver's noise or
// on a saturated plateau), always the way the torque's sign points (it is monotone in omega). A neighbouring case's spin and slope make it 2 to 3 solves where the torque
// is nearly linear in omega. The result holds the areas' solution at the spin it returns (result.omega,
// result.spin_evaluations). It stops at kFreeRollingTolerance or kFreeRollingResolution. Throws wrc::Error when no spin within 1 +- kFreeRollingSpan changes the torque's sign (naming
// the torque at the span's end against the areas' all sliding) or the search does not converge in its steps, naming
// the torques it saw.
void solve_free_rolling(const ContactModel& model, ContactResult& result, const RollingRequest& request,
                        ContactWorkspace& workspace);

}  // namespace wrc
