// Friction laws of the tangential solvers (rolling.hpp): Coulomb's with a static and a kinetic coefficient, and
// friction falling with the local slip velocity w (m/s, the magnitude of the slip velocity of an element, elastic
// slip included): Polach's exponential law and the linear, rational and exponential laws of CONTACT (Vollebregt,
// CONTACT user guide, section "Slip velocity dependent friction", friction laws L = 2, 3, 4):
//   polach       mu(w) = mu0 ((1 - A) exp(-B w) + A)                      (Polach, Wear 258, 2005)
//   linear       mu(w) = mu_inf + sum_i m_i max(0, 1 - w / (2 s_i))       (CONTACT L = 2)
//   rational     mu(w) = mu_inf + m_1 / (1 + w / s_1) + m_2 / (1 + (w / s_2)^2)   (L = 3)
//   exponential  mu(w) = mu_inf + sum_i m_i exp(-ln 2 w / s_i)            (L = 4)
// with mu_inf the limit at large slip velocity (CONTACT's FKIN), m_i >= 0 the terms (FLIN, FRAT, FEXP) and s_i > 0
// the velocities that set their decay (SABSH, m/s here where CONTACT takes mm/s). An element adheres while its
// traction is within mu(0) p_n and slides with |p| = mu(w) p_n. Polach's law is the exponential one with mu_inf =
// A mu0, m_1 = (1 - A) mu0, s_1 = ln 2 / B.
#pragma once

#include <array>
#include <string_view>

namespace wrc::halfspace {

// The range of a friction coefficient: wheel on rail 0.05 .. 0.6. Far below it the traction bound mu p_n underflows
// (mu = 1e-300 made the exact solver's result not finite); a huge coefficient is the no-slip limit (Kalker's linear
// theory, e.g. mu = 1e9), up to where mu p_n stays a number the solvers can square.
inline constexpr double kFrictionMin = 1e-4, kFrictionMax = 1e12;

enum class FrictionLaw { coulomb, polach, linear, rational, exponential };

// A friction law. Coulomb: kinetic <= static (a static coefficient above the kinetic one allows adhesion up to
// mu_s p_n and slides at mu_k p_n), both in [kFrictionMin, kFrictionMax]. A falling law: static = mu(0), kinetic =
// mu_inf, and its terms; mu(w) decreases from mu(0) to mu_inf.
struct Friction {
  double static_coefficient = 0;   // mu_s (-); a falling law's mu(0)
  double kinetic_coefficient = 0;  // mu_k (-); a falling law's mu_inf
  FrictionLaw law = FrictionLaw::coulomb;
  std::array<double, 2> term{};          // m_1, m_2 (-), >= 0
  std::array<double, 2> velocity{1, 1};  // s_1, s_2 (m/s), > 0

  static Friction coulomb(double mu) { return {mu, mu}; }
  static Friction polach(double mu0, double A, double B);  // -, -, s/m
  // A CONTACT law (linear, rational or exponential) from mu_inf and its two terms.
  static Friction falling(FrictionLaw law, double mu_inf, std::array<double, 2> terms, std::array<double, 2> velocities);
  bool slip_dependent() const { return law != FrictionLaw::coulomb; }
  double at(double w) const;     // mu at the slip velocity w >= 0 (m/s); Coulomb: the kinetic coefficient
};

const char* law_name(FrictionLaw law);

// Throws wrc::Error naming `context` when a coefficient is outside [kFrictionMin, kFrictionMax] or not finite, the
// kinetic one exceeds the static one, a falling law's term is negative or its velocity not > 0, or static is not
// mu(0).
void validate(const Friction& friction, std::string_view context);

}  // namespace wrc::halfspace
