// The damage indices of one rolling-contact area, per element and per area: T gamma, wear (Archard with the KTH map
// or a constant k, or the USFD function: damage/wear.hpp), Burstow's RCF damage and Ekberg's surface fatigue index
// (damage/fatigue.hpp). All from the fields a solved area holds (pressure, tractions, slip, creepages, creep forces):
// O(elements), no solve. Every rolling solve of the wheelset fills them (PatchRolling::damage, wheelset/tangential.hpp;
// the fields of the area's AreaFields: wrc::area_fields, wheelset/contact.hpp). docs/guide/damage.md.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/damage/fatigue.hpp"
#include "wrc/damage/wear.hpp"
#include "wrc/halfspace/grid.hpp"

#include <optional>
#include <span>
#include <vector>

namespace wrc::damage {

struct DamageOptions {
  WearOptions wear;
  FatigueOptions fatigue;
  // Compute the wear fields (a call asked for a wear model). false: T gamma and the fatigue indices alone, no pass
  // over the elements for wear and no wear grids (what every rolling call gets without `wear`).
  bool with_wear = true;
  void validate() const;
};

// Reads and validates a call's `wear` and `fatigue` tables (both optional; their keys: wear.hpp, fatigue.hpp),
// finishing them; with_wear is whether `wear` was given. Messages name the reader's context ("ws:contact: 'wear': k =
// 2 must be ..."). Leaves the caller's own reader's finish() to the caller.
DamageOptions read_damage_options(OptionReader& options);

// What the indices read of a solved area: spans over the caller's storage (index i + nx j).
struct AreaFields {
  halfspace::Grid grid;                    // m: x the rolling direction
  std::span<const double> pressure;        // Pa, >= 0 (p > 0: the contact)
  std::span<const double> px, py;          // Pa: traction on the wheel
  std::span<const double> sx, sy;          // slip per |V| (-), 0 in adhesion
  double V = 0;                            // m/s, != 0: the rolling speed (slip velocity = |V| s)
  halfspace::Creepages creepage;           // at the reference point: -, -, 1/m
  double fx = 0, fy = 0, mz = 0;           // N, N, N m: the area's creep forces and spin moment (rolling.hpp)
};

struct PatchDamage {
  halfspace::Grid grid;
  double Tgamma = 0, Tgamma_spin = 0;  // N (= J/m)
  double normal_force = 0;             // N: sum p dA
  double contact_area = 0;             // m^2: elements with p > 0
  double Tgamma_per_area = 0;          // Pa (= N/m^2): Tgamma / contact_area (0 without contact)
  // Wear (WearOptions::model), when DamageOptions::with_wear (else wear is false and the rest stays empty).
  bool wear = false;
  WearModel model = WearModel::archard;
  bool map = false;                    // Archard with the KTH map (false: constant k)
  double wear_volume = 0;              // m^3/m: volume worn per metre rolled
  double wear_passage_max = 0;         // m: the largest of wear_passage
  std::vector<double> wear_depth;      // per element: depth worn off per metre rolled (m/m), while in the element
  std::vector<double> wear_passage;    // per grid row j: depth worn in one passage, sum_i wear_depth dx (m)
  std::vector<double> wear_coefficient;  // Archard: k per element (-; 0 outside the contact); USFD: empty
  std::vector<double> tgamma_density;  // per element |px sx| + |py sy| (Pa): the local T gamma / A
  UsfdRegime usfd_regime = UsfdRegime::mild;  // USFD: the regime of the area's Tgamma_per_area
  // Fatigue.
  double rcf_damage = 0;               // Burstow: per passage, from Tgamma
  BurstowRegime rcf_regime = BurstowRegime::none;
  double traction_coefficient = 0;     // mu = |(Fx, Fy)| / normal_force (0 without contact)
  double a = 0, b = 0;                 // m: the equivalent semi-axes, pi a b = contact_area (0 without contact)
  double shear_yield = 0;              // k (Pa)
  std::optional<double> fi_surf;       // Ekberg's FI_surf (-); none without contact
};

// How much of the fields compute_damage checks: every value (the default), or the sizes alone, for fields a solver of
// the engine has just made (finite by construction; the rolling solve of every area: a pass over every value of five
// grids would cost half as much as FASTSIM itself).
enum class FieldCheck { values, sizes };

// The indices of one area. Throws wrc::Error naming what is wrong: an invalid grid, a field of the wrong size or (with
// FieldCheck::values) not finite, a negative pressure; V = 0 or not finite, creepages or forces not finite; and
// invalid options.
PatchDamage compute_damage(const AreaFields& fields, const DamageOptions& options,
                           FieldCheck check = FieldCheck::values);

// Fields (Lua and C), flat so that they sit beside an area's own (p.Tgamma, p.wear_volume) with no name in common:
// Tgamma, Tgamma_spin, Tgamma_per_area; with wear: wear_model, wear_map (Archard) or usfd_regime (USFD),
// wear_volume, wear_passage_max, wear_passage (per row, while kept), the grids wear_depth, wear_coefficient
// (Archard), tgamma_density (when kept: drop_grids empties them); then rcf_damage, rcf_regime,
// traction_coefficient, fi_a, fi_b, shear_yield and fi_surf (with contact); each with its FieldDoc.
void describe(const PatchDamage& damage, FieldSink& out);
// Releases the per-element and, unless keep_rows, the per-row vectors (the scalars stay).
void drop_grids(PatchDamage& damage, bool keep_rows = false);

}  // namespace wrc::damage
