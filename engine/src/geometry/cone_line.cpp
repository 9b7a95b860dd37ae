// Closed form of eq. (1): one cone, one line. See cone_line.hpp for the conventions and the A.5 sign.
//
// Derivation (rows 2 and 3 of eq. (1), A31 = 0, c = cos eps, s = sin eps, Z = z_w + alpha dz_w, Y = y_w + alpha dy_w):
//   row 3: z_r - z = A32 Y + A33 Z c
//   row 2: y_r - y = -A21 Z s + A22 Y + A23 Z c
// Both are linear in alpha: a_i = alpha b_i. Eliminating alpha (a3 b2 - a2 b3 = 0) the c^2 and c s terms cancel
// (because A31 = 0) and what is left is R c - S s + T = 0 with R, S, T of A.1-A.3. With t = tan(eps/2):
//   (T - R) t^2 - 2 S t + (R + T) = 0,  t = (S +- sqrt(d)) / (T - R),  d = R^2 + S^2 - T^2  (A.4).
// The printed A.5 has +S where this has -S (it solves R c + S s + T = 0), see the header.
//
// Precision: every term is evaluated relative to the cone's first point (y_w shifted to 0, the line offsets
// y_r - y - A22 y_w and z_r - z - A32 y_w absorbing the shift; an exact algebraic identity), which removes the
// cancellation of the products y_w z_w1 - y_w1 z_w of two 0.3 m^2 numbers. The roots are taken in the
// cancellation-free quadratic form q = S + sign(S) sqrt(d), t1 = q / (T - R), t2 = (R + T) / q, and cos/sin eps are
// formed from the ratio n/m of each root as ((m^2 - n^2), 2nm) / (m^2 + n^2), which needs no trigonometric call and
// stays finite at eps = pi (T - R = 0).
#include "wrc/geometry/cone_line.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace wrc {

namespace {

// R, S, T with the cone's first point shifted to y = 0 (see the file comment).
struct Shifted {
  double dyp, dzp, dy_w, dz_w;
};

inline Shifted shift(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1, double z_w1) {
  (void)z_w;
  return {(y_r - f.y) - f.a22 * y_w, (z_r - f.z) - f.a32 * y_w, y_w1 - y_w, z_w1 - z_w};
}

inline ConeLineTerms terms(const PoseFrame& f, const Shifted& h, double z_w) {
  ConeLineTerms t;
  // A.1-A.3 with y_w -> 0, y_w1 -> dy_w (so y_w z_w1 - y_w1 z_w -> -dy_w z_w).
  const double cross = -h.dy_w * z_w;
  t.R = (h.dyp * f.a33 - h.dzp * f.a23) * h.dz_w + (f.a23 * f.a32 - f.a22 * f.a33) * cross;
  t.S = (-h.dzp * h.dz_w + cross * f.a32) * f.a21;
  t.T = -(h.dzp * f.a22 - h.dyp * f.a32) * h.dy_w;
  t.d = t.R * t.R + t.S * t.S - t.T * t.T;
  return t;
}

}  // namespace

ConeLineTerms cone_line_terms(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1,
                              double z_w1) {
  return terms(f, shift(f, y_r, z_r, y_w, z_w, y_w1, z_w1), z_w);
}

int cone_line_intersections(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1,
                            double z_w1, ConeLineRoot out[2], double alpha_slack) {
  const Shifted h = shift(f, y_r, z_r, y_w, z_w, y_w1, z_w1);
  const ConeLineTerms k = terms(f, h, z_w);
  if (k.d < 0) return 0;
  if (k.R == 0 && k.S == 0 && k.T == 0) return 0;  // identically satisfied: coplanar ring or apex (header)

  // The two roots as (numerator n, denominator m) of t = tan(eps/2) = n / m.
  const double sq = std::sqrt(k.d);
  const double q = k.S + (k.S >= 0 ? sq : -sq);
  double cs[2][2];
  int nroots = 0;
  if (q == 0) {
    // S = 0 and d = 0, so R^2 = T^2 (R, T not both 0 here): a double root at eps = 0 (R = -T) or eps = pi (R = T).
    const double c = (k.R == -k.T) ? 1.0 : -1.0;
    cs[0][0] = cs[1][0] = c;
    cs[0][1] = cs[1][1] = 0.0;
    nroots = 2;
  } else {
    const double m1 = k.T - k.R, n1 = q;  // t1 = q / (T - R); m1 = 0 gives eps = pi
    const double m2 = q, n2 = k.R + k.T;  // t2 = (R + T) / q
    const double i1 = 1.0 / (m1 * m1 + n1 * n1), i2 = 1.0 / (m2 * m2 + n2 * n2);
    cs[0][0] = (m1 * m1 - n1 * n1) * i1;
    cs[0][1] = 2 * n1 * m1 * i1;
    cs[1][0] = (m2 * m2 - n2 * n2) * i2;
    cs[1][1] = 2 * n2 * m2 * i2;
    nroots = 2;
  }

  const double len = std::abs(h.dy_w) + std::abs(h.dz_w);
  int found = 0;
  for (int i = 0; i < nroots; ++i) {
    const double c = cs[i][0], s = cs[i][1];
    // alpha from the better-conditioned row: a_i = alpha b_i.
    const double b3 = f.a32 * h.dy_w + f.a33 * h.dz_w * c;
    const double a3 = h.dzp - f.a33 * z_w * c;
    const double b2 = f.a22 * h.dy_w - f.a21 * h.dz_w * s + f.a23 * h.dz_w * c;
    const double a2 = h.dyp + f.a21 * z_w * s - f.a23 * z_w * c;
    const bool use3 = std::abs(b3) >= std::abs(b2);
    const double b = use3 ? b3 : b2, a = use3 ? a3 : a2;
    if (!(std::abs(b) > 1e-12 * len)) continue;  // both alpha equations degenerate (header)
    const double alpha = a / b;
    if (!(alpha > -alpha_slack && alpha <= 1.0 + alpha_slack)) continue;
    const double Y = y_w + alpha * h.dy_w, Z = z_w + alpha * h.dz_w;
    ConeLineRoot& r = out[found++];
    r.x = Z * (f.a13 * c - f.a11 * s) + Y * f.a12;  // A.7
    r.alpha = alpha;
    r.cos_eps = c;
    r.sin_eps = s;
  }
  if (found == 2 && out[1].x < out[0].x) std::swap(out[0], out[1]);
  return found;
}

// How far rounding may have moved alpha of a root (a bound, up to a small factor): the eliminant g(eps) = R cos eps -
// S sin eps + T carries an absolute error dg (the roundings of the shifted line offsets, of R, S, T and of g's own sum),
// and its root moves by dg / |g'| with |g'| = sqrt(d) at a root -- or, near a tangency, where g' vanishes, by
// sqrt(2 dg / |g''|) with |g''| = |T| there (the double root splits). alpha moves by |d alpha / d eps| times that, with
// d alpha / d eps = (a' - alpha b') / b for the row alpha was taken from (a_i = alpha b_i).
double cone_line_alpha_error(const PoseFrame& f, double y_r, double z_r, double y_w, double z_w, double y_w1,
                             double z_w1, const ConeLineRoot& root) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const Shifted h = shift(f, y_r, z_r, y_w, z_w, y_w1, z_w1);
  const ConeLineTerms k = terms(f, h, z_w);
  const double cross = std::abs(h.dy_w * z_w);
  // Absolute errors of the shifted offsets (a cancellation of metre-scale numbers), then of R, S, T.
  const double e_off = eps * (std::abs(y_r - f.y) + std::abs(f.a22 * y_w) + std::abs(z_r - f.z) + std::abs(f.a32 * y_w));
  const double mag_R = (std::abs(h.dyp * f.a33) + std::abs(h.dzp * f.a23)) * std::abs(h.dz_w) +
                       (std::abs(f.a23 * f.a32) + std::abs(f.a22 * f.a33)) * cross;
  const double mag_S = (std::abs(h.dzp * h.dz_w) + cross * std::abs(f.a32)) * std::abs(f.a21);
  const double mag_T = (std::abs(h.dzp * f.a22) + std::abs(h.dyp * f.a32)) * std::abs(h.dy_w);
  const double carried = ((std::abs(f.a33) + std::abs(f.a23) + std::abs(f.a21)) * std::abs(h.dz_w) +
                          (std::abs(f.a22) + std::abs(f.a32)) * std::abs(h.dy_w)) * e_off;
  const double dg = 8 * eps * (mag_R + mag_S + mag_T + std::abs(k.R) + std::abs(k.S) + std::abs(k.T)) + carried;
  double deps = k.d > 0 ? dg / std::sqrt(k.d) : INFINITY;
  if (k.T != 0) deps = std::min(deps, std::sqrt(2 * dg / std::abs(k.T)));
  const double c = root.cos_eps, s = root.sin_eps, alpha = root.alpha;
  const double b3 = f.a32 * h.dy_w + f.a33 * h.dz_w * c;
  const double b2 = f.a22 * h.dy_w - f.a21 * h.dz_w * s + f.a23 * h.dz_w * c;
  const bool use3 = std::abs(b3) >= std::abs(b2);  // the row cone_line_intersections took alpha from
  const double da = use3 ? f.a33 * z_w * s : f.a21 * z_w * c + f.a23 * z_w * s;
  const double db = use3 ? -f.a33 * h.dz_w * s : -f.a21 * h.dz_w * c - f.a23 * h.dz_w * s;
  return std::abs((da - alpha * db) / (use3 ? b3 : b2)) * deps;
}

}  // namespace wrc
