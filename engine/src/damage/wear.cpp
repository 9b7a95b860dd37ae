#include "wrc/damage/wear.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::damage {

double kth_wear_coefficient(double p, double slip_speed, double hardness) {
  if (p > kKthPressureLimit * hardness) return kKthSeizure;
  const double v = std::abs(slip_speed);
  if (v < kKthSevereFrom) return kKthMildSlow;
  return v <= kKthSevereTo ? kKthSevere : kKthMildFast;
}

UsfdRegime usfd_regime(double t) {
  return t < kUsfdMildLimit ? UsfdRegime::mild : t <= kUsfdSevereLimit ? UsfdRegime::severe : UsfdRegime::catastrophic;
}

double usfd_wear_rate(double t) {
  const double x = t * 1e-6;  // N/mm^2, the function's own unit
  double w = 0;               // ug/(m mm^2)
  switch (usfd_regime(t)) {
    case UsfdRegime::mild: w = kUsfdMildSlope * x; break;
    case UsfdRegime::severe: w = kUsfdSevereRate; break;
    case UsfdRegime::catastrophic:  // the line is -0.02 at 77.2: no negative wear
      w = std::max(0.0, kUsfdCatastrophicSlope * x - kUsfdCatastrophicOffset);
      break;
  }
  return w * 1e-3;  // 1 ug/(m mm^2) = 1e-9 kg / (1 m 1e-6 m^2)
}

void WearOptions::validate(std::string_view context) const {
  if (k && !(*k > 0 && *k <= 1))
    fail("{}: k = {} must be in ]0, 1] (Archard's dimensionless coefficient; wheel on rail 1e-4 .. 4e-2)", context, *k);
  if (!(hardness >= 1e8 && hardness <= 1e11))
    fail("{}: hardness = {} Pa must be in [1e8, 1e11] (wheel and rail steel: 2.5e9 .. 4e9 Pa)", context, hardness);
  if (!(density >= 1000 && density <= 30000))
    fail("{}: density = {} kg/m^3 must be in [1000, 30000] (steel: 7850)", context, density);
}

WearOptions read_wear_options(OptionReader& r) {
  WearOptions w;
  if (r.choice("model", {"archard", "usfd"},
               {"-", "Archard's law (k p |s| / H per element) or the USFD wear function of T gamma / A"},
               "archard") == "usfd")
    w.model = WearModel::usfd;
  w.k = r.number("k", {"-", "Archard: a constant wear coefficient instead of the KTH map (Jendel 2002)"});
  w.hardness = r.number("hardness", {"Pa", "Archard: the hardness H of the steel"}, w.hardness);
  w.density = r.number("density", {"kg/m^3", "USFD: the steel's density (worn mass to volume)"}, w.density);
  if (r.documenting()) return w;
  const char* foreign[2][2] = {{"density", nullptr}, {"k", "hardness"}};
  for (const char* key : foreign[w.model == WearModel::usfd ? 1 : 0])
    if (key && r.has(key))
      fail("{}: '{}' belongs to the {} model; model = \"{}\" does not use it", r.context(), key,
           w.model == WearModel::usfd ? "archard" : "usfd", model_name(w.model));
  w.validate(r.context());
  return w;
}

const char* model_name(WearModel m) { return m == WearModel::usfd ? "usfd" : "archard"; }

const char* regime_name(UsfdRegime r) {
  switch (r) {
    case UsfdRegime::mild: return "mild";
    case UsfdRegime::severe: return "severe";
    case UsfdRegime::catastrophic: return "catastrophic";
  }
  return "?";
}

}  // namespace wrc::damage
