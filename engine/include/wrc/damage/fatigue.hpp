// Rolling contact fatigue indices of a contact area: Burstow's RCF damage function of T gamma and Ekberg's surface
// fatigue index (docs/guide/damage.md, "Wear and fatigue indices").
//
// T gamma (N = J/m: the frictional work per metre rolled of the area's creep forces against its creepages) is
//   T gamma = |Fx xi| + |Fy eta|,   with spin   T gamma_spin = |Fx xi| + |Fy eta| + |Mz phi|
// (Fx, Fy, Mz of the area's tractions on the wheel, the creepages at its reference point: wheelset/tangential.hpp).
//
// Burstow's damage function (the Whole Life Rail Model: M. C. Burstow, "Whole Life Rail Model application and
// development for RSSB -- continued development of an RCF damage parameter", AEA Technology Rail report
// AEATR-ES-2004-880, RSSB, 2004; normal-grade rail, R260): the RCF damage of the rail per wheel (axle) passage,
// cracks initiating where the summed damage reaches 1,
//   T gamma <  15 N          0                                  (below the threshold: no damage)
//   15 <= T gamma <= 65 N    (T gamma - 15) x 1e-6              (RCF: rising to 5e-5 at 65 N)
//   65 <  T gamma <  175 N   5e-5 (175 - T gamma) / 110         (wear removes the cracks' start: falling to 0)
//   T gamma >= 175 N         0                                  (wear dominates)
// The four numbers are BurstowFunction's members (defaults as above).
//
// Ekberg's surface fatigue index (Ekberg, Kabo & Andersson, "An engineering model for prediction of rolling contact
// fatigue of railway wheels", Fatigue Fract. Engng Mater. Struct. 25, 2002, 899-909):
//   FI_surf = mu - 2 pi a b k / (3 Fz),
// mu = |(Fx, Fy)| / Fz the traction coefficient, a, b the contact's semi-axes, k the shear yield limit; surface
// initiated fatigue (ratchetting of the surface layer) is predicted for FI_surf > 0. For Hertz's ellipse
// 2 pi a b / (3 Fz) = 1 / p0: FI_surf = mu - k / p0, the surface limit of Johnson's shakedown map
// (halfspace/subsurface.hpp). On a non-Hertzian area a b is taken from its contact area A = pi a b (so the term is
// 2 A k / (3 Fz), k over the peak of the Hertzian pressure with the area's load and size); a / b from the ratio of
// its extents along x and y (reported; FI_surf needs a b alone).
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/halfspace/creep.hpp"
#include "wrc/halfspace/subsurface.hpp"

#include <string_view>

namespace wrc::damage {

// T gamma (N) of creep forces Fx, Fy (N) at creepages xi, eta; with the spin moment Mz (N m) and spin phi (1/m).
double tgamma(double fx, double fy, const halfspace::Creepages& c);
double tgamma_spin(double fx, double fy, double mz, const halfspace::Creepages& c);

// Burstow's function (header): the threshold, the peak and the end of the RCF range (N) and the damage at the peak
// (per passage).
struct BurstowFunction {
  double threshold = 15, peak = 65, limit = 175;  // N, 0 <= threshold < peak < limit
  double peak_damage = 5e-5;                       // per passage, > 0
};
enum class BurstowRegime { none, rcf, rcf_and_wear, wear };

// RCF damage per passage at T gamma (N, >= 0), and the range it falls in.
double burstow_damage(double tgamma, const BurstowFunction& f = {});
BurstowRegime burstow_regime(double tgamma, const BurstowFunction& f = {});

// Ekberg's FI_surf (-) from the traction coefficient mu (-), the semi-axes a, b (m), the shear yield limit k (Pa)
// and the normal force Fz (N, > 0).
double surface_fatigue_index(double mu, double a, double b, double shear_yield, double fz);

// The `fatigue` option of a call: fatigue = {shear_yield =, threshold =, peak =, limit =, peak_damage =}.
struct FatigueOptions {
  double shear_yield = halfspace::kDefaultShearYield;  // k (Pa), finite and > 0 (300 MPa, ER7: subsurface.hpp)
  BurstowFunction burstow;
  // Throws wrc::Error "<context>: <key> = <value> must be ..." (its range).
  void validate(std::string_view context = "fatigue") const;
};
// Reads the keys of the `fatigue` table and validates them under the reader's context; leaves finish() to the caller.
FatigueOptions read_fatigue_options(OptionReader& options);

const char* regime_name(BurstowRegime regime);

}  // namespace wrc::damage
