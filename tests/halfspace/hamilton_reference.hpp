// Closed-form references for the stresses below a circular Hertz contact, independent of the engine (no engine
// header): Johnson's axis stresses (Contact Mechanics, 1985, eq. 3.45) and Hamilton's explicit equations for a sliding
// spherical contact (G. M. Hamilton, "Explicit equations for the stresses beneath a sliding spherical contact", Proc.
// IMechE C 197, 1983, 53-59). Lengths in the contact radius a, stresses in p0 (the normal load) or q0 (the traction's
// peak, along +x); tension positive, z the depth. Used by tests/halfspace (the engine) and tests/capi (the C call).
#pragma once

#include <cmath>
#include <numbers>

namespace wrc::test {

struct HamiltonStress {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
};
inline HamiltonStress operator+(HamiltonStress a, const HamiltonStress& b) {
  a.xx += b.xx, a.yy += b.yy, a.zz += b.zz, a.xy += b.xy, a.xz += b.xz, a.yz += b.yz;
  return a;
}
inline HamiltonStress operator*(double k, HamiltonStress a) {
  a.xx *= k, a.yy *= k, a.zz *= k, a.xy *= k, a.xz *= k, a.yz *= k;
  return a;
}
// von Mises from the components (the second invariant of the deviator).
inline double von_mises_of(const HamiltonStress& s) {
  const double d = (s.xx - s.yy) * (s.xx - s.yy) + (s.yy - s.zz) * (s.yy - s.zz) + (s.zz - s.xx) * (s.zz - s.xx);
  return std::sqrt(0.5 * d + 3 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz));
}

// Johnson eq. 3.45 on the axis (p0 = 1, z in a).
inline double axis_szz(double z) { return -1 / (1 + z * z); }
inline double axis_srr(double nu, double z) { return -(1 + nu) * (1 - z * std::atan(1 / z)) + 1 / (2 * (1 + z * z)); }

// Hamilton (1983): the stresses under the Hertz pressure sqrt(1 - r^2) (in p0) and under the traction
// sqrt(1 - r^2) along +x (in q0), contact radius 1; r = 0 by the axis forms.
struct HamiltonTerms {
  double A, S, M, N, phi;
};
inline HamiltonTerms hamilton_terms(double r2, double z) {
  HamiltonTerms t;
  t.A = r2 + z * z - 1;
  t.S = std::sqrt(t.A * t.A + 4 * z * z);
  t.M = std::sqrt((t.S + t.A) / 2);
  t.N = std::sqrt((t.S - t.A) / 2);
  t.phi = std::atan2(1, t.M);
  return t;
}

inline HamiltonStress hamilton_normal(double nu, double x, double y, double z) {
  const double r2 = x * x + y * y;
  if (r2 == 0) {
    const double srr = axis_srr(nu, z);
    return {srr, srr, axis_szz(z), 0, 0, 0};
  }
  const auto [A, S, M, N, phi] = hamilton_terms(r2, z);
  const double G = M * M - N * N + z * M - N, H = 2 * M * N + M + z * N;
  const double k = (1 - nu) * N * z * z - (1 - 2 * nu) / 3 * (N * S + 2 * A * N + 1) - nu * M * z;
  const double shear = z * H / (G * G + H * H) - N / S;
  return {(1 + nu) * z * phi + ((y * y - x * x) / r2 * k - N * (x * x + 2 * nu * y * y) - M * x * x * z / S) / r2,
          (1 + nu) * z * phi + ((x * x - y * y) / r2 * k - N * (y * y + 2 * nu * x * x) - M * y * y * z / S) / r2,
          -N + z * M / S,
          x * y * (1 - 2 * nu) / (r2 * r2) * (-N * r2 + 2.0 / 3 * N * (S + 2 * A) - z * (z * N + M) + 2.0 / 3) +
              x * y * z / (r2 * r2) * (M - M * r2 / S - z * N),
          z * x * shear,
          z * y * shear};
}

inline HamiltonStress hamilton_tangential(double nu, double x, double y, double z) {
  const double r2 = x * x + y * y;
  if (r2 == 0) return {0, 0, 0, 0, -1 + 1.5 * z * std::atan2(1, z) - z * z / (2 * (1 + z * z)), 0};
  const auto [A, S, M, N, phi] = hamilton_terms(r2, z);
  const double c = 1 - 2 * nu, r4 = r2 * r2, x2 = x * x, y2 = y * y, z2 = z * z;
  const double fx = 1.5 - 2 * x2 / r2, hx = 0.5 - 2 * x2 / r2, hy = 0.5 - 2 * y2 / r2;
  HamiltonStress s;
  s.xx = -x * (nu / 4 + 1) * phi + x * M / r4 * (fx * (S * nu - 2 * A * nu + z2) + x2 * z2 / S + 7 * nu * r2 / 4 -
                                                   2 * nu * x2 + r2) +
         x * z * N / r4 * (fx * (-c * S / 6 - c * A / 3 - (z2 + 3) / 2) + x2 / S - nu * r2 / 4 - 7 * r2 / 4) +
         4 * x * z / (3 * r4) * fx * c;
  s.yy = -3 * nu * x * phi / 4 + x * M / r4 * (hy * (nu * (S - 2 * A + r2) + z2) + y2 * z2 / S + 3 * nu * r2 / 4) +
         x * z * N / r4 * (hy * (-c * S / 6 - c * A / 3 - z2 / 2 - 1.5) + y2 / S - 3 * nu * r2 / 4 - r2 / 4) +
         4 * x * z / (3 * r4) * hy * c;
  s.zz = z * x * N / (2 * r2) * (1 - (r2 + z2 + 1) / S);
  s.xy = y / 2 * (nu / 2 - 1) * phi +
         y * M / r4 * (x2 * z2 / S + nu * ((S - 2 * A) * hx - 2 * x2 + r2 / 4) + r2 / 2 + z2 * hx) +
         y * z * N / r4 * (hx * (-c * (S / 6 + A / 3) - z2 / 2 - 1.5 - r2 / 2) + nu * r2 / 4 + x2 / S - y2 / 2 - 1.5 * x2) +
         4 * y * z / (3 * r4) * hx * c;
  s.xz = 1.5 * z * phi + z * M / r2 * (1 + x2 / r2 - x2 / S) +
         N / r2 * (-0.75 * (S + 2 * A) + z2 - 0.75 - r2 / 4 + z2 / 2 * hx);
  s.yz = x * y * z / (2 * r4) * (M * (0.5 + (z2 / 2 - 1.5 - r2 / 2) / S) + z * N / 2 * (-3 + (5 + z2 + r2) / S));
  return s;
}

}  // namespace wrc::test
