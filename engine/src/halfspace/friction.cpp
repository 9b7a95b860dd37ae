// Friction laws (friction.hpp).
#include "wrc/halfspace/friction.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wrc::halfspace {

Friction Friction::polach(double mu0, double A, double B) {
  Friction f = falling(FrictionLaw::exponential, A * mu0, {(1 - A) * mu0, 0.0}, {std::numbers::ln2 / B, 1.0});
  f.law = FrictionLaw::polach;
  return f;
}

Friction Friction::falling(FrictionLaw law, double mu_inf, std::array<double, 2> terms,
                           std::array<double, 2> velocities) {
  Friction f;
  f.law = law;
  f.kinetic_coefficient = mu_inf;
  f.term = terms;
  f.velocity = velocities;
  f.static_coefficient = mu_inf + terms[0] + terms[1];
  return f;
}

double Friction::at(double w) const {
  double mu = kinetic_coefficient;
  for (int i = 0; i < 2; ++i) {
    const double m = term[static_cast<std::size_t>(i)], r = w / velocity[static_cast<std::size_t>(i)];
    if (m == 0) continue;
    switch (law) {
      case FrictionLaw::coulomb: break;
      case FrictionLaw::linear: mu += m * std::max(0.0, 1 - 0.5 * r); break;
      case FrictionLaw::rational: mu += m / (1 + (i == 0 ? r : r * r)); break;
      case FrictionLaw::polach:
      case FrictionLaw::exponential: mu += m * std::exp(-std::numbers::ln2 * r); break;
    }
  }
  return mu;
}

const char* law_name(FrictionLaw law) {
  switch (law) {
    case FrictionLaw::coulomb: return "coulomb";
    case FrictionLaw::polach: return "polach";
    case FrictionLaw::linear: return "linear";
    case FrictionLaw::rational: return "rational";
    case FrictionLaw::exponential: return "exponential";
  }
  return "?";
}

void validate(const Friction& f, std::string_view context) {
  if (f.slip_dependent())
    for (std::size_t i = 0; i < 2; ++i) {
      if (!(f.term[i] >= 0 && std::isfinite(f.term[i])))
        fail("{}: the {} friction law's term {} is {}, expected a finite value >= 0 (friction falls with slip)",
             context, law_name(f.law), i + 1, f.term[i]);
      if (!(f.velocity[i] > 0 && std::isfinite(f.velocity[i])))
        fail("{}: the {} friction law's velocity {} is {} m/s, expected > 0 and finite", context, law_name(f.law),
             i + 1, f.velocity[i]);
    }
  for (double mu : {f.static_coefficient, f.kinetic_coefficient})
    if (!(mu >= kFrictionMin && mu <= kFrictionMax))
      fail("{}: friction coefficients mu_static = {}, mu_kinetic = {} must be in [{:g}, {:g}]", context,
           f.static_coefficient, f.kinetic_coefficient, kFrictionMin, kFrictionMax);
  if (f.kinetic_coefficient > f.static_coefficient)
    fail("{}: the kinetic friction coefficient {} exceeds the static one {}", context, f.kinetic_coefficient,
         f.static_coefficient);
  if (!f.slip_dependent()) return;
  const double mu0 = f.at(0);
  if (!(std::abs(mu0 - f.static_coefficient) <= 1e-12 * mu0))
    fail("{}: the {} friction law's mu(0) = {} differs from its static coefficient {}", context, law_name(f.law), mu0,
         f.static_coefficient);
}

}  // namespace wrc::halfspace
