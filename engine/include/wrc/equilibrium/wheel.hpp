// One wheel-rail pair with its vertical force prescribed (CONTACT / multibody style; docs/design.md section 3): the
// wheelset height z that makes that wheel's vertical contact force equal Fz at the given y, yaw and roll.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/equilibrium/limits.hpp"
#include "wrc/wheelset/contact.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace wrc {

// What a wheel solve is asked for.
struct WheelCase {
  int side = kLeft;  // kLeft or kRight
  double y = 0;      // lateral position of the wheelset centre (m), within +-kMaxLateral (geometry/pose.hpp)
  double yaw = 0;    // rad, within +-kMaxYaw
  double roll = 0;   // rad, within +-kMaxRoll
  double Fz = 0;     // the wheel's vertical force (N), in ]0, kMaxLoad]
  // Throws wrc::Error "<context>: <key> = <value> <unit> must be ..." for the first value out of its range;
  // `plausible`: also for an Fz no railway wheel carries (kWheelLoad, wheelset/plausibility.hpp).
  void validate(std::string_view context, bool plausible = false) const;
};

// The wheel solver's settings.
struct WheelOptions {
  SolveLimits limits;  // force_tolerance (of Fz), secant steps, evaluations, max_penetration, normal_tolerance
  // The cold start for Fz = 100 kN (m below the touching height, in ]0, 0.01]), scaled as Fz^(2/3) (Hertz): a little
  // deeper than a tread contact's approach (S1002/60E1: 75-115 um on the tread, 150 um at the flange root), so that
  // the first prediction's grid, which covers the rigid overlap at this approach, holds most of the contact.
  double wheel_approach = 0.08e-3;
  // Evaluate the solved pose once more at the model's own tolerance (the forces ws:contact gives there); a
  // trajectory, content with limits.normal_tolerance, turns it off.
  bool final_at_model_tolerance = true;
  bool keep_grids = true;  // the result's pressure and h grids (`grids`, as ws:contact and ws:equilibrium have it)
  // The wheel's Jacobian at the solved pose (WheelContact::jacobian) and with its Fz held (jacobian_fz), when it
  // converged (`sensitivity`, as ws:contact has it).
  bool sensitivity = false;
  // Throws wrc::Error naming the first member out of its range (its key, value, unit and range).
  void validate(std::string_view context) const;
};

// What a solve with friction tells the next solve of the same wheel nearby (a trajectory's next step).
struct WheelHint {
  double creep = 0;      // the creep forces' vertical part (N)
  double stiffness = 0;  // d(vertical normal force)/d(approach) (N/m) measured on the way; 0: not known
};

struct WheelResult {
  // |residual| <= force_tolerance Fz; with friction also where the creep forces' vertical part jumps across the
  // approach by more than twice that (a coarse grid's FASTSIM, whose rows grow an element at a time; its ellipse grows
  // continuously, halfspace/ellipse.hpp) and Fz falls inside the jump: then no approach carries Fz closer, and the solve concludes at
  // the jump, on its side nearer Fz where it can, |residual| within the jump plus the tolerance (jumps of at most 2e-3
  // Fz or 10 % of the creep forces' vertical part; a larger one fails with its size).
  bool converged = false;
  std::string message;
  int side = kLeft;
  double Fz = 0;             // the prescribed vertical force (N)
  double z = 0;              // solved height of the wheelset centre (m)
  double approach = 0;       // how far that is below the height at which the wheel just touches its rail (m)
  double residual = 0;       // Fz(side) - Fz (N)
  int iterations = 0;        // contact evaluations
  WheelContact wheel;        // the side's contact
  WheelHint hint;            // with friction: for the next solve nearby (not a field of the results)
};

// Solves the height for the case. With `rolling`, the tangential problems are solved too and Fz includes the creep
// forces' vertical part: the normal problem is solved for Fz less that part (hint.creep, e.g. the previous time
// step's; 0 when not given), the tangential problems on normal solutions only (first on the prediction's, whose creep
// forces move the load and, by hint.stiffness or the normal problem's linearised response, the approach), and both
// again, each from the last solution, while the total misses Fz (Newton steps on the normal load, kept inside the
// bracket of the loads tried once Fz is passed, down to a jump of the creep forces: WheelResult::converged). `start`: an approach to start from (m below
// the touching height; e.g. the previous time step's, which follows the load where the height does not); otherwise
// options.wheel_approach scaled to Fz. The approach is predicted by the wheel's normal problem solved for Fz itself
// (an internal entry point of the contact pipeline), twice from afar (the first only estimated on the coarse grid) and
// once from a close start, then confirmed (and corrected by secant steps) by evaluations of the pose; the result is
// always such an evaluation, at the model's normal tolerance. A load that the wheel does not carry at an approach of
// max_penetration is out of reach: not converged, with the reason. Throws wrc::Error on bad input (the case's and the
// options' validate(), first) and for a wheel that does not touch its rail within z = +-20 mm.
WheelResult solve_wheel(const ContactModel& model, const WheelCase& c, ContactWorkspace& ws,
                        const WheelOptions& options = {}, std::optional<double> start = std::nullopt,
                        const std::optional<RollingRequest>& rolling = std::nullopt,
                        const std::optional<WheelHint>& hint = std::nullopt);

// Reads side ("left" | "right", required), y, yaw, roll (default 0) and Fz (required) of ws:wheel{} and tr:wheel{}
// into a case (validated by the solver).
WheelCase read_wheel_case(OptionReader& options);
// The wheel options as Lua and the C API give them: force_tolerance, max_iterations, max_evaluations, max_penetration
// (read_solve_limits), grids (default true); validated.
WheelOptions read_wheel_options(OptionReader& options);
std::string failure_message(const WheelResult& result);

// The result as fields: the side's wheel fields (wheelset/contact.hpp), converged, error, z, approach, residual,
// iterations.
void describe(const WheelResult& result, FieldSink& out);

}  // namespace wrc
