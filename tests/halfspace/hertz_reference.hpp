// Analytic Hertz solution of the elliptical contact of two bodies of the same material, written for the
// tests (independent of the engine): reusable by any test that needs the reference.
//
// Undeformed inter-penetration h = delta - A x^2 - B y^2 (A = 1/(2 Rx), B = 1/(2 Ry), relative radii of
// curvature in m). Hertz (Johnson, Contact Mechanics, 1985, sections 3.6 and 4.2): the pressure
// p = p0 sqrt(1 - x^2/a^2 - y^2/b^2) on the ellipse with semi-axes a (along x) and b (along y) displaces
// the pair by (L - M x^2 - N y^2) / (pi E*) with, for a >= b and e^2 = 1 - b^2/a^2,
//   L = pi p0 b K(e),  M = pi p0 b (K - E) / (e^2 a^2),  N = pi p0 b (a^2 E / b^2 - K) / (e^2 a^2),
// so delta = p0 b K / E*, A = M / (pi E*), B = N / (pi E*), F = 2/3 pi a b p0, and the shape follows from
// B / A = (E / (1 - e^2) - K) / (K - E), solved here for e by bisection. K, E: complete elliptic integrals
// of modulus e, by the arithmetic-geometric mean.
#pragma once

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace wrc::test {

struct EllipticKE {
  double K, E;
};

// Complete elliptic integrals of the first and second kind of modulus k, given the complementary modulus
// kp = sqrt(1 - k^2) in ]0, 1] (passing kp keeps accuracy for k near 1). AGM: K = pi / (2 M(1, kp)),
// E = K (1 - sum 2^(n-1) c_n^2) with c_0 = k.
inline EllipticKE elliptic_ke(double kp) {
  if (!(kp > 0 && kp <= 1)) throw std::invalid_argument("elliptic_ke: kp must be in ]0, 1]");
  double a = 1, b = kp, c = std::sqrt((1 - kp) * (1 + kp));
  double sum = 0.5 * c * c, power = 0.5;
  for (int n = 0; n < 60 && std::abs(c) > 1e-17 * a; ++n) {
    const double an = 0.5 * (a + b), bn = std::sqrt(a * b);
    c = 0.5 * (a - b);
    a = an;
    b = bn;
    power *= 2;
    sum += power * c * c;
  }
  const double K = std::numbers::pi / (2 * a);
  return {K, K * (1 - sum)};
}

struct HertzReference {
  double a = 0, b = 0;  // semi-axes along x and y (m)
  double p0 = 0;        // peak pressure (Pa)
  double force = 0;     // N
  double delta = 0;     // approach = max inter-penetration (m)
};

// Ratio b/a of the semi-axes (minor over major) for the curvature ratio q = max(A,B)/min(A,B) >= 1.
inline double hertz_axis_ratio(double q) {
  if (!(q >= 1)) throw std::invalid_argument("hertz_axis_ratio: q must be >= 1");
  if (q == 1) return 1;
  const auto ratio = [](double kp) {  // B/A as a function of kp = b/a
    const auto [K, E] = elliptic_ke(kp);
    return (E / (kp * kp) - K) / (K - E);
  };
  double lo = 1e-12, hi = 1 - 1e-15;  // ratio decreases from infinity (kp -> 0) to 1 (kp -> 1)
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ratio(mid) > q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Hertz contact for h = delta - A x^2 - B y^2 at the approach delta (m), combined modulus Estar (Pa).
inline HertzReference hertz_from_approach(double A, double B, double Estar, double delta) {
  if (!(A > 0 && B > 0 && Estar > 0 && delta > 0)) throw std::invalid_argument("hertz_from_approach: bad input");
  const bool swap = A > B;  // work with Amin along the major axis, then put the axes back
  const double Amin = swap ? B : A, Bmax = swap ? A : B;
  const double kp = hertz_axis_ratio(Bmax / Amin);
  HertzReference h;
  h.delta = delta;
  double major, minor;
  if (kp == 1) {  // circle: a^2 = R delta with 1/R = 2 A, p0 = 2 a E* / (pi R)
    major = minor = std::sqrt(delta / (2 * Amin));
    h.p0 = 2 * major * Estar * 2 * Amin / std::numbers::pi;
  } else {
    const auto [K, E] = elliptic_ke(kp);
    const double e2 = (1 - kp) * (1 + kp);
    major = std::sqrt(delta * (K - E) / (Amin * K * e2));
    minor = kp * major;
    h.p0 = delta * Estar / (minor * K);
  }
  h.a = swap ? minor : major;
  h.b = swap ? major : minor;
  h.force = 2.0 / 3.0 * std::numbers::pi * h.a * h.b * h.p0;
  return h;
}

// Hertz contact carrying the normal force F (N): F grows like delta^(3/2) at a fixed shape.
inline HertzReference hertz_from_force(double A, double B, double Estar, double F) {
  if (!(F > 0)) throw std::invalid_argument("hertz_from_force: F must be positive");
  const HertzReference unit = hertz_from_approach(A, B, Estar, 1e-6);
  return hertz_from_approach(A, B, Estar, 1e-6 * std::pow(F / unit.force, 2.0 / 3.0));
}

}  // namespace wrc::test
