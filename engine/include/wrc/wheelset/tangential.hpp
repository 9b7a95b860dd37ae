// Rolling contact with friction on the wheelset's contact areas (docs/design.md sections 2 and 3): the kinematics of
// the wheelset, the request a call makes, and the tangential results of an area.
//
// Kinematics (track frame, section 2): the wheelset centre moves with velocity (V, vy, 0), the wheelset turns with
// angular velocity omega a + yaw_rate z, a = Rz(yaw) Rx(roll) y the axle's direction (omega > 0: forward rolling for
// V > 0). The rails are at rest. The rigid slip of the wheel relative to the rail at a point X is the wheel's
// material velocity there, v(X) = (V, vy, 0) + (omega a + yaw_rate z) x (X - centre); per |V| and in the area's
// contact frame (t1, t2, n of PatchContact; t1 the rolling direction) it is the w of halfspace/creep.hpp. It is
// evaluated at every element's contact point: the element's position in the plane moved along n to midway between
// the wheel's and the rail's undeformed surfaces, so that the rolling radius varying across a wide or curved patch
// (and the spin varying with the surface's slope) enters the slip of each element. Midway is where the wheel's
// material sits in the deformed contact (two bodies of one material each yield h / 2 along n): a material point
// turns about the axle at its deformed radius, and the flat half-space, whose tangential displacements leave out the
// wheel's curvature, would miss that the compressed rim is shorter (-omega h / 2 per element) if the rigid slip were
// taken on the undeformed wheel (SlipReference below; docs/design.md section 2). The area's creepages (xi, eta,
// phi) are this slip at the plane's origin (the reference point) and the spin omega . n / |V|. Materials roll through
// the contact toward -t1 when V > 0 (rolling direction +1), toward +t1 when V < 0.
//
// On a conformal area (wheelset/conformal.hpp) every element has its row's frame (e_x, t2(j), n(j)) and its contact
// point is its point on the rail's surface moved along -n(j) by h / 2 (by h with SlipReference::undeformed); the reference point is the grid's origin (at
// a row, j0), its frame (e_x, t2(j0), n(j0)); the slip and traction components are along e_x and each row's t2, on
// the unrolled grid (x, s), with the flat half-space's coefficients as for the normal problem (docs/design.md
// section 2).
//
// Or the creepages are prescribed (`creepage`), the same at every area's reference point, with the linear field
// w = (xi - phi y, eta + phi x) over the area; V then only scales the slip velocities and the power (1 m/s when not
// given).
#pragma once

#include "wrc/damage/damage.hpp"
#include "wrc/halfspace/rolling.hpp"
#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace wrc {

// Where the rigid slip of an element is taken along its normal: `undeformed` (default) on the wheel's undeformed
// surface (CONTACT's convention), `deformed` midway between the undeformed surfaces (h / 2 nearer the axle, h the
// element's overlap: xi larger by about h / (2 r), 1.2e-4 on S1002/60E1 under 100 kN). A rolling body's surface moves
// at omega R (1 + e), R its undeformed radius and e the tangential (hoop) strain there, and the half-space's surface
// strain already is e, compression included (exact for a disc: docs/validation.md, "The rolling radius"); the
// deformed point counts the compression twice.
enum class SlipReference { undeformed, deformed };

struct Kinematics {
  double V = 0;                  // forward speed of the wheelset centre along track x (m/s), != 0
  std::optional<double> omega;   // axle angular velocity about the wheelset's y axis (rad/s); none: V / r0, pure
                                 // rolling at the nominal radius
  double vy = 0;                 // lateral velocity of the centre (m/s)
  double yaw_rate = 0;           // rad/s, about track z
  SlipReference slip_reference = SlipReference::undeformed;
  // Free rolling: omega is not given but found, the one at which the creep forces of both wheels have no moment
  // about the axle (a wheelset without traction or braking torque; wheelset/free_rolling.hpp). Not with omega.
  bool free_rolling = false;
};

enum class RollingMethod { exact, fastsim };

// Friction varying across a rail's profile: mu(0) of the friction law (mu, or mu_static, or a falling law's mu0)
// against the rail profile's own lateral coordinate y (m, the profile file's frame: +y toward the field side, for
// either rail), linear between the points, constant beyond the ends. The law's other coefficients scale with it.
struct FrictionProfile {
  std::vector<double> y, mu;  // m (increasing), -
  double at(double y) const;
};
// Where a front end samples a friction profile given as a function of y (Lua): every 0.1 mm over -100 .. 100 mm of
// the rail profile's lateral coordinate, wider than any rail head.
inline constexpr double kFrictionProfileFrom = -0.1, kFrictionProfileTo = 0.1, kFrictionProfileStep = 1e-4;  // m

struct RollingRequest {
  std::optional<Kinematics> kinematics;          // either the wheelset's velocities
  std::optional<halfspace::Creepages> creepage;    // or creepages prescribed at every area's reference point
  double V = 1;                                  // m/s: with `creepage`, the speed of the slip velocities and power
  halfspace::Friction friction;                    // mu (static = kinetic), mu_static and mu_kinetic, or a law
  std::array<std::optional<FrictionProfile>, 2> friction_profile;  // per side (kLeft, kRight): mu across the rail
  RollingMethod method = RollingMethod::exact;
  double tolerance = 1e-6;                       // the exact solver's (halfspace/rolling.hpp)
  // The damage indices every solved area gets (PatchRolling::damage): T gamma and the fatigue indices always, the
  // wear fields when a call asks for a wear model (`wear = {...}`: with_wear).
  damage::DamageOptions damage{.wear = {}, .fatigue = {}, .with_wear = false};
  // With `plausible` (check_setup), the magnitudes against a railway wheelset's of nominal radius r0 (m): V, the
  // friction, spin, the friction law's constants, yaw_rate, vy, and omega against pure rolling (plausibility.hpp);
  // the reader checks the rest.
  void validate(std::string_view context, bool plausible, double r0) const;
};

// Reads a call's rolling keys: V, omega or free_rolling, vy, yaw_rate, slip_reference ("deformed" | "undeformed")
// (kinematics) or
// creepage = {xi, eta, phi} (with V optional),
// and mu or mu_static and mu_kinetic or friction = {law = "polach" | "linear" | "rational" | "exponential", ...} or
// friction = {preset = ...} (docs/guide/rolling.md), friction_profile = {y =, mu =} or {left = {y =, mu =}, right =
// ...}, method ("exact" | "fastsim"), rolling_tolerance, and the damage options `wear = {...}` and `fatigue = {...}`
// (damage/damage.hpp). Returns nothing when none of V, omega, vy, yaw_rate, creepage, mu, mu_static, mu_kinetic,
// friction, method, wear, fatigue is given (a frictionless call). Throws
// wrc::Error naming the key on: V = 0 (the creepages are slip velocities divided by V: undefined), kinematics keys
// without V, creepage together with omega, free_rolling, vy or yaw_rate, free_rolling with omega, a missing, zero, negative or non-finite mu, a kinetic
// coefficient above the static one, an unknown method, a creepage that is not a finite number, a falling law with a
// prescribed creepage and no V (its slip velocities need the speed), a friction profile whose y does not increase or
// whose mu is outside the friction range.
std::optional<RollingRequest> read_rolling_request(OptionReader& options);

// The tangential solution of one contact area.
struct PatchRolling {
  RollingMethod method = RollingMethod::exact;
  halfspace::Friction friction;
  double V = 0;                        // m/s, the speed that scales slip velocities and power
  halfspace::Creepages creepage;         // at the reference point (the grid's origin): -, -, 1/m
  double fx = 0, fy = 0;               // N, contact frame (t1, t2), on the wheel (conformal: sums along e_x and
                                       // along each row's t2)
  double mz = 0;                       // N m, about the reference point along n (conformal: in the unrolled (x, s))
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, track frame: fx t1 + fy t2 (conformal: sum over the rows)
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // N m, of the tangential tractions about the wheelset centre
  double adhesion = 0;                 // fraction of the contact area in adhesion
  double power = 0;                    // W: frictional power, |V| sum -(p . s) dA >= 0
  halfspace::TangentialSolution solution;  // grids on the area's grid: px, py (Pa), sx, sy (slip per |V|), state
  std::vector<double> friction_scale;  // with a friction profile: the law's factor per element (1 outside); else empty
  std::vector<double> rigid_x, rigid_y;  // the rigid slip per |V| of the contact elements (0 outside), per element
  damage::PatchDamage damage;          // the damage indices of the area (RollingRequest::damage)
};

// The fields of an area's tangential solution (Lua and C): method, mu = {static, kinetic}, V, creepage = {xi, eta,
// phi}, Fx, Fy, Mz, creep_force, creep_moment, adhesion, power, iterations; with the grids: px, py (Pa), slip_x,
// slip_y (slip velocity, m/s), adhesion_map (0 outside the contact, 1 adhesion, 2 slip), power_density (W/m^2),
// rigid_slip_x, rigid_slip_y (the rigid slip velocity, m/s, of the contact elements); then the damage indices
// (damage/damage.hpp: Tgamma, Tgamma_spin, ..., the wear fields when asked, rcf_damage, fi_surf, ...).
void describe(const PatchRolling& rolling, FieldSink& out);
const char* method_name(RollingMethod method);

}  // namespace wrc
