#include "wrc/damage/fatigue.hpp"

#include <cmath>
#include <numbers>

namespace wrc::damage {

double tgamma(double fx, double fy, const halfspace::Creepages& c) { return std::abs(fx * c.xi) + std::abs(fy * c.eta); }

double tgamma_spin(double fx, double fy, double mz, const halfspace::Creepages& c) {
  return tgamma(fx, fy, c) + std::abs(mz * c.phi);
}

BurstowRegime burstow_regime(double t, const BurstowFunction& f) {
  if (t < f.threshold) return BurstowRegime::none;
  if (t <= f.peak) return BurstowRegime::rcf;
  return t < f.limit ? BurstowRegime::rcf_and_wear : BurstowRegime::wear;
}

double burstow_damage(double t, const BurstowFunction& f) {
  switch (burstow_regime(t, f)) {
    case BurstowRegime::rcf: return f.peak_damage * (t - f.threshold) / (f.peak - f.threshold);
    case BurstowRegime::rcf_and_wear: return f.peak_damage * (f.limit - t) / (f.limit - f.peak);
    case BurstowRegime::none:
    case BurstowRegime::wear: return 0.0;
  }
  return 0.0;
}

double surface_fatigue_index(double mu, double a, double b, double shear_yield, double fz) {
  return mu - 2 * std::numbers::pi * a * b * shear_yield / (3 * fz);
}

void FatigueOptions::validate(std::string_view context) const {
  halfspace::check_shear_yield(context, shear_yield);
  const BurstowFunction& f = burstow;
  if (!(std::isfinite(f.limit) && f.threshold >= 0 && f.threshold < f.peak && f.peak < f.limit))
    fail("{}: threshold = {}, peak = {}, limit = {} N must be finite with 0 <= threshold < peak < limit "
         "(Burstow: 15, 65, 175)", context, f.threshold, f.peak, f.limit);
  if (!(f.peak_damage > 0 && f.peak_damage <= 1))
    fail("{}: peak_damage = {} must be in ]0, 1] (Burstow: 5e-5 per passage)", context, f.peak_damage);
}

FatigueOptions read_fatigue_options(OptionReader& r) {
  FatigueOptions o;
  o.shear_yield = r.number("shear_yield", {"Pa", "Ekberg's FI_surf: the shear yield limit k"}, o.shear_yield);
  BurstowFunction& f = o.burstow;
  f.threshold = r.number("threshold", {"N", "Burstow: the T gamma below which there is no RCF damage"}, f.threshold);
  f.peak = r.number("peak", {"N", "Burstow: the T gamma of the largest RCF damage"}, f.peak);
  f.limit = r.number("limit", {"N", "Burstow: the T gamma above which wear removes all RCF damage"}, f.limit);
  f.peak_damage = r.number("peak_damage", {"-", "Burstow: the RCF damage per passage at the peak"}, f.peak_damage);
  if (!r.documenting()) o.validate(r.context());
  return o;
}

const char* regime_name(BurstowRegime r) {
  switch (r) {
    case BurstowRegime::none: return "none";
    case BurstowRegime::rcf: return "rcf";
    case BurstowRegime::rcf_and_wear: return "rcf and wear";
    case BurstowRegime::wear: return "wear";
  }
  return "?";
}

}  // namespace wrc::damage
