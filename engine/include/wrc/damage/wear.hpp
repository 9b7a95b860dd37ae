// Wear of wheel and rail steel from the contact's per-element fields: Archard's law with the KTH wear map or a
// constant coefficient, and the USFD wear function (docs/guide/damage.md, "Wear and fatigue indices").
//
// Archard (Archard, J. Appl. Phys. 24, 1953): the volume worn off per sliding distance is k N / H. Per element of a
// contact area, in steady rolling at speed |V|: the element slides at |v_s| = |V| |s| (s the slip per |V| of the
// tangential solution, halfspace/rolling.hpp) under the pressure p, so the depth worn off per unit time is
// k p |v_s| / H and per metre rolled
//   d = k p |s| / H   (m/m: the element's wear depth per metre rolled, while the material is in the element).
// A material point crosses an element of length dx in dx / |V| (dx of rolling), so one passage through the area
// wears off sum_i d_i dx along its grid row (m per passage), and the area wears off
//   wear_volume = sum_elements d dA   (m^3/m, the volume per metre rolled; in full sliding k Fn |xi| / H).
// The same for the wheel and the rail (one hardness H, one k: the bodies alike).
//
// The KTH wear map (Jendel, "Prediction of wheel profile wear -- comparisons with field measurements", Wear 253,
// 2002, 89-99; dry wheel and rail steel, from pin-on-disc tests): k by the contact pressure p against the hardness
// and by the sliding velocity |v_s|, four regions with ranges of k:
//   K1   p > 0.8 H (seizure)                       300 .. 400 x 1e-4
//   K2   p <= 0.8 H, |v_s| < 0.2 m/s (mild)          1 ..  10 x 1e-4
//   K3   p <= 0.8 H, 0.2 <= |v_s| <= 0.7 m/s (severe) 30 ..  40 x 1e-4
//   K4   p <= 0.8 H, |v_s| > 0.7 m/s (mild, oxidative)  1 ..  10 x 1e-4
// This file takes the middle of each range (kKth* below). With prescribed creepages the sliding velocity scales with
// the call's V (1 m/s when not given: wheelset/tangential.hpp), which the map then depends on.
//
// The USFD wear function (University of Sheffield: Braghin, Lewis, Dwyer-Joyce & Bruni, "A mathematical model to
// predict railway wheel profile evolution due to wear", Wear 261, 2006, 1253-1264; twin-disc tests of R8T wheel
// steel against UIC60 900A rail steel -- the grade EN 13674 calls R260 -- by Lewis & Dwyer-Joyce, "Wear mechanisms
// and transitions in railway wheel steels", Proc. IMechE J 218, 2004, 467-478): the wheel's wear rate W (ug of
// steel per metre rolled per mm^2 of contact) against T gamma / A (N/mm^2, the frictional work per metre rolled per
// contact area):
//   mild          T gamma / A < 10.4           W = 5.3 T gamma / A
//   severe        10.4 <= T gamma / A <= 77.2  W = 55.0
//   catastrophic  T gamma / A > 77.2           W = 61.9 T gamma / A - 4778.7
// (as published: the catastrophic line starts at -0.02 at 77.2, taken as 0, and passes 55 at 78.1, a dip the fit
// leaves). Applied per element with the local T gamma / A = |px sx| + |py sy| (Pa = N/m^2: traction times slip per
// |V|; the power density over |V|), the depth per metre rolled is d = W / rho (W in kg/m^3 = kg per metre rolled per
// m^2; rho the steel's density).
#pragma once

#include "wrc/core/options.hpp"

#include <optional>
#include <string_view>

namespace wrc::damage {

enum class WearModel { archard, usfd };

// A wheel steel's hardness (245 HB, kgf/mm^2, in Pa): the default H of Archard's law.
inline constexpr double kDefaultHardness = 245 * 9.80665e6;
// The density of steel (kg/m^3): mass to volume for the USFD function.
inline constexpr double kSteelDensity = 7850;

// The KTH map (header): the middle of each region's range of k (-), and its limits.
inline constexpr double kKthSeizure = 350e-4, kKthMildSlow = 5.5e-4, kKthSevere = 35e-4, kKthMildFast = 5.5e-4;
inline constexpr double kKthPressureLimit = 0.8;                 // p / H above which K1 holds
inline constexpr double kKthSevereFrom = 0.2, kKthSevereTo = 0.7;  // m/s: K3 between them

// The USFD function's limits in T gamma / A (Pa = N/m^2; 10.4 and 77.2 N/mm^2) and coefficients in its own units
// (ug/(m mm^2) and N/mm^2; header).
inline constexpr double kUsfdMildLimit = 10.4e6, kUsfdSevereLimit = 77.2e6;
inline constexpr double kUsfdMildSlope = 5.3, kUsfdSevereRate = 55.0;
inline constexpr double kUsfdCatastrophicSlope = 61.9, kUsfdCatastrophicOffset = 4778.7;

enum class UsfdRegime { mild, severe, catastrophic };

// Archard's k of the KTH map at contact pressure p (Pa, >= 0), sliding velocity |v_s| (m/s) and hardness H (Pa).
double kth_wear_coefficient(double pressure, double slip_speed, double hardness);

// The USFD wear rate (kg/m^3: kg per metre rolled per m^2 of contact; 1 ug/(m mm^2) = 1e-3 kg/m^3) at
// T gamma / A (Pa, >= 0), and its regime.
double usfd_wear_rate(double tgamma_per_area);
UsfdRegime usfd_regime(double tgamma_per_area);

// The `wear` option of a call: wear = {model = "archard" | "usfd", k =, hardness =, density =}.
struct WearOptions {
  WearModel model = WearModel::archard;
  std::optional<double> k;            // Archard: a constant coefficient (-) in ]0, 1]; none: the KTH map
  double hardness = kDefaultHardness; // Archard: H (Pa), in [1e8, 1e11]
  double density = kSteelDensity;     // USFD: rho (kg/m^3), in [1000, 30000]
  // Throws wrc::Error "<context>: <key> = <value> must be ..." (its range).
  void validate(std::string_view context = "wear") const;
};

// Reads the keys of the `wear` table (model, k, hardness, density) and validates them under the reader's context;
// k and hardness belong to Archard, density to USFD: one given with the other model is an error naming it. Leaves
// finish() to the caller.
WearOptions read_wear_options(OptionReader& options);

const char* model_name(WearModel model);
const char* regime_name(UsfdRegime regime);

}  // namespace wrc::damage
