// Rigid (kinematic) contact of a wheelset on its track: undeformable wheels and rails, the contact where the gap
// between the undeformed profiles vanishes (docs/design.md, sections 2 and 3; docs/guide/geometry.md).
//
// For a lateral position y and a yaw, the wheelset is lowered onto its rails:
//  - roll free: z and roll such that both wheels touch (the kinematic constraint of a wheelset on its track);
//  - roll fixed: the roll held at a given value (0 by default) and each wheel lowered onto its own rail: the two
//    wheels' heights are independent, as rolling-radius-difference tables "without roll" are made. `z` is then
//    the height at which the rigid wheelset would rest (the higher of the two wheels' touching heights) and the
//    other wheel's `gap` its clearance there.
//
// On the discretised geometry (wheel cones, rail lines), the gap of a rail line is minus the radial overlap of its
// deepest point (geometry/wheel_surface.hpp). The touching point is the line of zero gap; every other separate
// local minimum of the gap over the lines within `two_point_tolerance` of zero is a contact point too (two-point
// contact), separate meaning that the gap rises by more than that tolerance between them. Each contact point is
// located between the lines by the parabola through the gaps of its line and its neighbours.
//
// Δr = r_left - r_right (the rolling radii at the touching points; > 0 when the wheelset is displaced toward +y, the
// left rail, on coned wheels). A wheel that cannot touch its rail (no rail under it) is `lifted`: it has no contact
// point, radius or angle, and the result has no Δr.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/geometry/cone_line.hpp"
#include "wrc/geometry/flange.hpp"
#include "wrc/geometry/model.hpp"
#include "wrc/halfspace/ellipse.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wrc {

enum class RollMode { free, fixed };

// The normal load per contact point that the Hertz ellipse and Kalker's coefficients of rigid results assume (N):
// half the default Q, a wheel's static load.
inline constexpr double kHertzLoad = 100e3;

struct RigidOptions {
  RollMode roll_mode = RollMode::free;
  double roll = 0;                    // rad: the roll held with RollMode::fixed
  double Q = 200e3;                   // N: the load the normal forces carry (roll free)
  double hertz_load = kHertzLoad;     // N: the load of every contact point's Hertz ellipse
  // The pair's material (the wheelset's; the call layer sets it): with it every contact point gets its Hertz
  // ellipse and Kalker's coefficients; without, none.
  std::optional<halfspace::Material> material;
  double two_point_tolerance = 1e-6;  // m: a second separate minimum of the gap this close to zero is a contact
  // A start (z, roll) for the iteration, e.g. from the neighbouring row of a table (continuation).
  std::optional<Eigen::Vector2d> start;
};

// One contact point of a wheel.
struct RigidContactPoint {
  int line = -1;                      // rail line of the gap's minimum (0-based)
  double gap = 0;                     // m: 0 at the touching point, <= two_point_tolerance at a second one
  Eigen::Vector3d point = Eigen::Vector3d::Zero();        // track frame (m)
  Eigen::Vector3d wheel_point = Eigen::Vector3d::Zero();  // wheelset frame (m)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();      // the wheel's normal, into the wheel (track frame)
  double angle = 0;                   // contact angle (rad, > 0 toward the track centre)
  double rolling_radius = 0;          // wheel radius there (m)
  Eigen::Vector2d wheel_profile = Eigen::Vector2d::Zero();  // (s, z) on the wheel profile as loaded (m)
  Eigen::Vector2d rail_profile = Eigen::Vector2d::Zero();   // (y, z) on the rail profile as loaded (m)
  // Lateral curvature of the profiles there (1/m; > 0 convex, < 0 concave: Hertz's sign), from their smooth curves.
  double wheel_curvature = 0, rail_curvature = 0;
  // Hertz's ellipse for RigidOptions::hertz_load and the curvatures above (halfspace/ellipse.hpp; a along the track)
  // and Kalker's coefficients for it, when RigidOptions::material is set and both relative curvatures are convex.
  halfspace::ContactEllipses ellipses;
};

// Rigid contact of one wheel. point .. rolling_radius describe the deepest rail line itself (the reference of the
// equilibrium, unchanged from before contacts[] existed); contacts[0] is the same touching point located between
// the lines, the value tables and Δr use.
struct RigidWheel {
  double overlap = 0;                 // radial overlap at the deepest point (m; 0 at the solution)
  int line = -1;                      // rail line index
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // contact point (track frame, m)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // into the wheel
  double angle = 0;                   // contact angle (rad)
  double rolling_radius = 0;          // m
  double normal_force = 0;            // N, from the force balance (roll free)
  bool lifted = false;                // no rail under the wheel: no contact point
  double z = 0;                       // height of the wheelset centre at which this wheel touches (m)
  double gap = 0;                     // roll fixed: clearance of this wheel when the wheelset rests at its z (m)
  std::vector<RigidContactPoint> contacts;  // the touching point first, then the others by increasing gap
  std::string flange_climb;  // why the wheel is past flange climb (geometry/flange.hpp), "" when it is not
};

struct RigidResult {
  bool converged = false;     // both wheels touch (the kinematic constraint holds)
  std::string message;
  RollMode roll_mode = RollMode::free;
  double y = 0, yaw = 0, Q = 0;
  double z = 0, roll = 0;
  double Y = 0, My = 0, Mz = 0;  // the balancing forces (roll free)
  // A wheel would need a pulling normal force to balance Q with no roll moment (e.g. a flange contact steeper
  // than ~57 deg, whose line of action passes below the centre): the kinematics hold, the forces are no
  // equilibrium of a wheelset resting on its rails.
  bool tension = false;
  // The first wheel past flange climb, as the elastic results define it (geometry/flange.hpp): a contact point beyond
  // the steepest part of the flange face, L/V beyond Nadal's limit (roll free: the normal forces), or a wheel lifted
  // higher than its flange (roll fixed: its gap); "<side> wheel: <why>", "" when none is.
  std::string flange_climb;
  std::array<RigidWheel, 2> wheel;
  bool has_forces() const { return roll_mode == RollMode::free && converged; }
  bool touching() const { return converged && !wheel[0].contacts.empty() && !wheel[1].contacts.empty(); }
  // r_left - r_right at the touching points contacts[0] (m); only when touching().
  double rolling_radius_difference() const {
    return wheel[0].contacts[0].rolling_radius - wheel[1].contacts[0].rolling_radius;
  }
};

// Solves the rigid contact at (y, yaw). Throws wrc::Error on bad input (y, yaw, roll or Q out of range); a case
// without a solution is returned with converged = false and the reason in `message`.
RigidResult solve_rigid(const GeometryModel& geometry, double y, double yaw, const RigidOptions& options);
// The roll-free case carrying Q (the equilibrium's rigid reference).
RigidResult solve_rigid(const GeometryModel& geometry, double y, double yaw, double Q);

// The deepest rail line of one side at a pose (radial overlap > 0 inside the wheel), its point and normal.
RigidWheel deepest_point(const GeometryModel& geometry, int side, const Pose& pose);

// The searches for a touching height (m) bracket z within +-kTouchWindow first, where a wheelset on its rails touches,
// and then within +-touch_reach: as far as the profiles reach at that roll (the wheels' radial and the rails'
// vertical extent, e.g. a flange riding on the rail's top, plus what the roll moves the farthest wheel point, plus
// 1 mm). The roll of both wheels touching is searched within +-kTouchRollWindow, then +-touch_roll_reach (the roll
// that lifts one wheel by the profiles' reach over the distance between the tape circles).
inline constexpr double kTouchWindow = 0.02, kTouchRollWindow = 0.02;
double touch_reach(const GeometryModel& geometry, double roll);
double touch_roll_reach(const GeometryModel& geometry);
// The height of a pose at which one wheel just touches its rail (deepest overlap 0), at y, yaw and roll, searched as
// above; throws wrc::Error naming the wheel and the window when it touches nowhere (no rail under it).
double touch_height(const GeometryModel& geometry, int side, double y, double yaw, double roll, std::string_view context);

// Options as Lua and the C API give them: roll ("free", "fixed" or a number: fixed at that roll, rad), Q,
// hertz_load, two_point_tolerance, start = {z =, roll =}.
RigidOptions read_rigid_options(OptionReader& options, RigidOptions base = {});

// converged, tension, flange_climb (and flange_climb_reason when true), error, roll_mode, y, yaw, Q, z, roll, rolling_radius_difference (when both wheels touch),
// Y, My, Mz, Y_Q (roll free), left/right = {lifted, flange_climb (flange_climb_reason), z, gap, two_point, point, normal, angle, rolling_radius,
// normal_force (roll free), overlap, line, contacts = {{gap, line, point, wheel_point, normal, angle,
// rolling_radius, wheel_profile = {y, z}, rail_profile = {y, z}, wheel_curvature, rail_curvature,
// wheel_lateral_radius, rail_lateral_radius (1 / curvature, when not zero), hertz, kalker (halfspace/ellipse.hpp)},
// ...}} (docs/guide/geometry.md).
void describe(const RigidResult& result, FieldSink& out);
void describe(const RigidContactPoint& contact, FieldSink& out);

}  // namespace wrc
