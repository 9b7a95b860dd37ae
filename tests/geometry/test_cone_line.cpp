// The closed form of eq. (1) (A.1-A.7) against an independent numerical root finder written here, and its
// degenerate cases one by one.
//
// Reference: the line is followed in long double along x; each point is mapped to the wheelset frame and to the
// meridian half-plane (Y, rho = distance to the axle). The cone is the segment G0 = (y_w, -z_w), G1 = (y_w1, -z_w1)
// of that half-plane; g(x) = (G1 - G0) x (P(x) - G0) vanishes on the (infinite) cone. rho(x) is convex and Y(x)
// linear, so g is convex (dY > 0), concave (dY < 0) or linear (dY = 0): its minimum is found by ternary search and
// the roots by bisection on either side. alpha is the projection of the root on the segment.
#include "wrc/geometry/cone_line.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using wrc::test::within_abs;
using wrc::test::within_rel;
namespace {

using ld = long double;

struct RefRoot {
  ld x, alpha;
};

struct RefCase {
  ld y, z, roll, yaw, y_r, z_r, y_w, z_w, y_w1, z_w1;
};

struct Meridian {
  ld Y, rho;
};

Meridian meridian(const RefCase& c, ld x) {
  const ld cf = std::cos(c.roll), sf = std::sin(c.roll), cp = std::cos(c.yaw), sp = std::sin(c.yaw);
  // A = Rz(yaw) Rx(roll); p_w = A^T (P - (0, y, z)).
  const ld A[3][3] = {{cp, -sp * cf, sp * sf}, {sp, cp * cf, -cp * sf}, {0, sf, cf}};
  const ld d[3] = {x, c.y_r - c.y, c.z_r - c.z};
  ld p[3];
  for (int i = 0; i < 3; ++i) p[i] = A[0][i] * d[0] + A[1][i] * d[1] + A[2][i] * d[2];
  return {p[1], std::sqrt(p[0] * p[0] + p[2] * p[2])};
}

// g(x) / |G1 - G0|: signed distance-like function of the line point to the cone's supporting line.
ld gfun(const RefCase& c, ld x) {
  const Meridian m = meridian(c, x);
  const ld dY = c.y_w1 - c.y_w, dR = (-c.z_w1) - (-c.z_w);
  const ld L = std::sqrt(dY * dY + dR * dR);
  return (dY * (m.rho - (-c.z_w)) - dR * (m.Y - c.y_w)) / L;
}

ld alpha_of(const RefCase& c, ld x) {
  const Meridian m = meridian(c, x);
  const ld dY = c.y_w1 - c.y_w, dR = (-c.z_w1) - (-c.z_w);
  return ((m.Y - c.y_w) * dY + (m.rho - (-c.z_w)) * dR) / (dY * dY + dR * dR);
}

ld bisect(const RefCase& c, ld a, ld b, ld sign) {
  ld ga = sign * gfun(c, a);
  for (int i = 0; i < 90 && b - a > 0; ++i) {
    const ld m = 0.5L * (a + b);
    if (m == a || m == b) break;
    const ld gm = sign * gfun(c, m);
    if ((gm > 0) == (ga > 0)) {
      a = m;
      ga = gm;
    } else {
      b = m;
    }
  }
  return 0.5L * (a + b);
}

// All crossings of the infinite cone, with their alpha; `gmin` is min |g| near the extremum (tangency measure).
std::vector<RefRoot> reference_roots(const RefCase& c, ld& tangency) {
  const ld X = 2.0L;
  const ld dY = c.y_w1 - c.y_w;
  std::vector<RefRoot> roots;
  tangency = INFINITY;
  if (dY == 0) {  // g linear in x
    const ld g0 = gfun(c, -X), g1 = gfun(c, X);
    if ((g0 > 0) != (g1 > 0)) {
      const ld x = bisect(c, -X, X, 1);
      roots.push_back({x, alpha_of(c, x)});
    }
    return roots;
  }
  const ld sign = dY > 0 ? 1 : -1;  // sign * g is convex
  ld a = -X, b = X;
  for (int i = 0; i < 150; ++i) {
    const ld m1 = a + (b - a) / 3, m2 = b - (b - a) / 3;
    if (sign * gfun(c, m1) < sign * gfun(c, m2)) b = m2; else a = m1;
  }
  const ld xm = 0.5L * (a + b), gm = sign * gfun(c, xm);
  tangency = std::abs(gm);
  if (gm > 0) return roots;
  if (sign * gfun(c, -X) > 0) { const ld x = bisect(c, -X, xm, sign); roots.push_back({x, alpha_of(c, x)}); }
  if (sign * gfun(c, X) > 0) { const ld x = bisect(c, xm, X, sign); roots.push_back({x, alpha_of(c, x)}); }
  return roots;
}

double uni(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

}  // namespace

TEST_CASE("cone_line_intersections agrees with a numerical root finder on random cases") {
  std::mt19937_64 rng(20180611);
  int compared = 0, intersecting = 0, near_tangent = 0, yawed_two_roots = 0;
  double worst = 0;
  const int n = 12000;
  for (int k = 0; k < n; ++k) {
    wrc::Pose pose;
    pose.y = uni(rng, -0.01, 0.01);
    pose.z = uni(rng, -2e-3, 1e-3);
    pose.roll = k % 10 == 1 ? 0.0 : uni(rng, -0.01, 0.01);
    pose.yaw = k % 10 == 2 ? 0.0 : uni(rng, -0.03, 0.03);
    const double side = k % 2 ? 1.0 : -1.0;
    // Cone: random position, length and inclination, with exact cylinders, flat rings and discs to the axle.
    const double Y0 = side * 0.75 + uni(rng, -0.07, 0.06), rho0 = uni(rng, 0.42, 0.48);
    const double len = std::pow(10.0, uni(rng, -5, -2)), th = uni(rng, -1.5, 1.5);
    double y_w = Y0, z_w = -rho0, y_w1 = Y0 + len * std::cos(th), z_w1 = -(rho0 + len * std::sin(th));
    if (k % 13 == 3) z_w1 = z_w;                // cylinder
    if (k % 13 == 5) y_w1 = y_w;                // flat ring
    if (k % 97 == 7) { y_w1 = y_w; z_w1 = 0; }  // closing disc down to the axle
    // Line near a point of the (extended) cone at a small angle, offset by 0.1 um .. 1 mm.
    const double a0 = uni(rng, -0.2, 1.2), e0 = uni(rng, -0.15, 0.15);
    const double Yp = y_w + a0 * (y_w1 - y_w), Zp = z_w + a0 * (z_w1 - z_w);
    const wrc::PoseFrame f(pose);
    const Eigen::Vector3d P = f.to_track({-Zp * std::sin(e0), Yp, Zp * std::cos(e0)});
    const double off = std::pow(10.0, uni(rng, -7, -3)), dir = uni(rng, 0, 2 * M_PI);
    const double y_r = P.y() + off * std::cos(dir), z_r = P.z() + off * std::sin(dir);

    wrc::ConeLineRoot roots[2];
    const int nr = wrc::cone_line_intersections(f, y_r, z_r, y_w, z_w, y_w1, z_w1, roots);

    const RefCase c{pose.y, pose.z, pose.roll, pose.yaw, y_r, z_r, y_w, z_w, y_w1, z_w1};
    ld tangency = 0;
    const auto all = reference_roots(c, tangency);
    std::vector<RefRoot> ref;
    bool borderline = tangency < 1e-12L;
    for (const auto& r : all) {
      if (std::abs(r.alpha) < 1e-12L || std::abs(r.alpha - 1) < 1e-12L) borderline = true;
      if (r.alpha > 0 && r.alpha <= 1) ref.push_back(r);
    }
    if (borderline) {
      ++near_tangent;
      continue;
    }
    ++compared;
    INFO("case ", k, " pose y=", pose.y, " z=", pose.z, " roll=", pose.roll, " yaw=", pose.yaw, " cone (", y_w, ",",
         z_w, ")-(", y_w1, ",", z_w1, ") line (", y_r, ",", z_r, ")");
    REQUIRE(nr == static_cast<int>(ref.size()));
    if (nr > 0) ++intersecting;
    if (nr == 2 && pose.yaw != 0) ++yawed_two_roots;
    std::sort(ref.begin(), ref.end(), [](const RefRoot& a, const RefRoot& b) { return a.x < b.x; });
    for (int i = 0; i < nr; ++i) {
      const double err = std::abs(roots[i].x - static_cast<double>(ref[i].x));
      worst = std::max(worst, err);
      CHECK(err < 1e-9);
      CHECK(std::abs(roots[i].alpha - static_cast<double>(ref[i].alpha)) < 1e-6);
    }
  }
  MESSAGE("compared ", compared, " cases (", intersecting, " intersecting, ", yawed_two_roots,
          " with two roots and yaw), skipped ", near_tangent, " within 1e-12 of tangency; worst |dx| = ", worst, " m");
  CHECK(compared >= 10000);
  CHECK(intersecting >= 3000);
  CHECK(yawed_two_roots >= 1000);
}

TEST_CASE("A.5 as printed returns -eps under the DESIGN conventions, the corrected sign satisfies eq. (1)") {
  // A point of a cone at a known (eps, alpha); the line through it. The corrected A.5 must give back eps; the
  // printed form gives -eps (visible only with yaw, through S ~ sin(yaw)).
  wrc::Pose pose{2e-3, -0.2e-3, 4e-3, 20e-3};
  const wrc::PoseFrame f(pose);
  const double y_w = 0.74, z_w = -0.451, y_w1 = 0.7402, z_w1 = -0.45098, eps = 0.031, alpha = 0.37;
  const double Y = y_w + alpha * (y_w1 - y_w), Z = z_w + alpha * (z_w1 - z_w);
  const Eigen::Vector3d P = f.to_track({-Z * std::sin(eps), Y, Z * std::cos(eps)});
  const auto t = wrc::cone_line_terms(f, P.y(), P.z(), y_w, z_w, y_w1, z_w1);
  REQUIRE(t.d > 0);
  REQUIRE(std::abs(t.S) > 0);
  const double printed[2] = {2 * std::atan((t.S + std::sqrt(t.d)) / (t.R - t.T)),
                             2 * std::atan((t.S - std::sqrt(t.d)) / (t.R - t.T))};
  const double fixed[2] = {2 * std::atan((-t.S + std::sqrt(t.d)) / (t.R - t.T)),
                           2 * std::atan((-t.S - std::sqrt(t.d)) / (t.R - t.T))};
  const double err_fixed = std::min(std::abs(fixed[0] - eps), std::abs(fixed[1] - eps));
  const double err_printed = std::min(std::abs(printed[0] - eps), std::abs(printed[1] - eps));
  const double err_printed_neg = std::min(std::abs(printed[0] + eps), std::abs(printed[1] + eps));
  CHECK(err_fixed < 1e-12);
  CHECK(err_printed > 1e-4);
  CHECK(err_printed_neg < 1e-12);
  // The engine finds the point itself.
  wrc::ConeLineRoot r[2];
  const int n = wrc::cone_line_intersections(f, P.y(), P.z(), y_w, z_w, y_w1, z_w1, r);
  REQUIRE(n >= 1);
  bool hit = false;
  for (int i = 0; i < n; ++i) hit = hit || (std::abs(r[i].x - P.x()) < 1e-12 && std::abs(r[i].alpha - alpha) < 1e-9);
  CHECK(hit);
  // The R, S, T of the engine (shifted origin) equal A.1-A.3 evaluated literally.
  const double dy = P.y() - pose.y, dz = P.z() - pose.z;
  const double R = (dy * f.a33 - dz * f.a23) * (z_w1 - z_w) + (f.a23 * f.a32 - f.a22 * f.a33) * (y_w * z_w1 - y_w1 * z_w);
  const double S = (dz * (z_w - z_w1) + (y_w * z_w1 - y_w1 * z_w) * f.a32) * f.a21;
  const double T = (dz * f.a22 - dy * f.a32) * (y_w - y_w1);
  CHECK(std::abs(t.R - R) < 1e-12 * std::abs(R));
  CHECK(std::abs(t.S - S) < 1e-9 * std::abs(S));
  CHECK(std::abs(t.T - T) < 1e-12 * std::abs(T));
}

TEST_CASE("degenerate cases of the closed form") {
  wrc::ConeLineRoot r[2];
  SUBCASE("zero yaw and roll: symmetric roots +-x with one alpha, d = 0 gives a double root") {
    const wrc::PoseFrame f(wrc::Pose{});
    // Cylinder of radius 0.45 between y = 0.7 and 0.8; the line 1 mm inside: x = +-sqrt(0.45^2 - 0.449^2).
    const int n = wrc::cone_line_intersections(f, 0.75, -0.449, 0.70, -0.45, 0.80, -0.45, r);
    REQUIRE(n == 2);
    const double x = std::sqrt((0.45 - 0.449) * (0.45 + 0.449));  // factored: no cancellation in the reference
    // x^2 = r^2 - z^2 from r and z loses ~eps (r^2 + z^2) / (2 x) = 1.5e-15 m to rounding (measured 1.2e-15 m).
    CHECK(r[0].x == within_abs(-x, 3e-15));
    CHECK(r[1].x == within_abs(x, 3e-15));
    CHECK(r[0].alpha == r[1].alpha);
    CHECK(r[0].alpha == within_rel(0.5, 1e-5));
    // Tangent line (d = 0 exactly): both roots at x = 0.
    const auto t = wrc::cone_line_terms(f, 0.75, -0.45, 0.70, -0.45, 0.80, -0.45);
    CHECK(t.d == 0);
    REQUIRE(wrc::cone_line_intersections(f, 0.75, -0.45, 0.70, -0.45, 0.80, -0.45, r) == 2);
    CHECK(r[0].x == 0);
    CHECK(r[1].x == 0);
    // Just outside: none.
    CHECK(wrc::cone_line_intersections(f, 0.75, -0.4500001, 0.70, -0.45, 0.80, -0.45, r) == 0);
  }
  SUBCASE("cylinder with zero roll: A.6 (row 3) degenerates, alpha comes from row 2") {
    const wrc::PoseFrame f(wrc::Pose{0, 0, 0, 0.01});
    const int n = wrc::cone_line_intersections(f, 0.75, -0.449, 0.70, -0.45, 0.80, -0.45, r);
    REQUIRE(n == 2);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p = f.to_wheelset({r[i].x, 0.75, -0.449});
      CHECK(std::hypot(p.x(), p.z()) == within_rel(0.45, 1e-13));
      CHECK(r[i].alpha == within_rel((p.y() - 0.70) / 0.10, 1e-12));
    }
  }
  SUBCASE("flat ring: one crossing of the ring's plane when yawed") {
    const wrc::PoseFrame f(wrc::Pose{0, 0, 0, 0.02});
    // Ring at y_w = 0.75 from radius 0.44 to 0.46; the line at z = -0.45 crosses its plane once.
    const int n = wrc::cone_line_intersections(f, 0.75, -0.45, 0.75, -0.44, 0.75, -0.46, r);
    REQUIRE(n == 1);
    const Eigen::Vector3d p = f.to_wheelset({r[0].x, 0.75, -0.45});
    CHECK(p.y() == within_rel(0.75, 1e-14));
    CHECK(std::hypot(p.x(), p.z()) == within_rel(0.44 + 0.02 * r[0].alpha, 1e-12));
  }
  SUBCASE("flat ring, zero yaw, line off its plane: roots at eps = +-pi/2 where both alpha equations degenerate") {
    const wrc::PoseFrame f(wrc::Pose{0, 0, 0.0, 0.0});
    const auto t = wrc::cone_line_terms(f, 0.76, -0.45, 0.75, -0.44, 0.75, -0.46);
    CHECK(t.S == 0);
    CHECK(t.T == 0);
    CHECK(t.d > 0);  // the eliminant has roots (cos eps = 0), but no alpha satisfies rows 2 and 3
    CHECK(wrc::cone_line_intersections(f, 0.76, -0.45, 0.75, -0.44, 0.75, -0.46, r) == 0);
    // With roll too.
    const wrc::PoseFrame g(wrc::Pose{0, 0, 0.004, 0.0});
    CHECK(wrc::cone_line_intersections(g, 0.76, -0.45, 0.75, -0.44, 0.75, -0.46, r) == 0);
  }
  SUBCASE("flat ring, zero yaw, line in its plane: R = S = T = 0, no isolated crossing") {
    const wrc::PoseFrame f(wrc::Pose{});
    const auto t = wrc::cone_line_terms(f, 0.75, -0.45, 0.75, -0.44, 0.75, -0.46);
    CHECK(t.R == 0);
    CHECK(t.S == 0);
    CHECK(t.T == 0);
    CHECK(wrc::cone_line_intersections(f, 0.75, -0.45, 0.75, -0.44, 0.75, -0.46, r) == 0);
  }
  SUBCASE("R - T = 0: a root at the top of the wheel (eps = pi)") {
    const wrc::PoseFrame f(wrc::Pose{});
    // Cylinder of radius 0.45; a line through the top (z = +0.45) is tangent there: d = 0, R = T.
    const auto t = wrc::cone_line_terms(f, 0.75, 0.45, 0.70, -0.45, 0.80, -0.45);
    CHECK(t.R - t.T == 0);
    REQUIRE(wrc::cone_line_intersections(f, 0.75, 0.45, 0.70, -0.45, 0.80, -0.45, r) == 2);
    CHECK(r[0].cos_eps == -1);
    CHECK(r[0].x == 0);
    // A cone whose line meets it at the top and at a finite eps: R - T = 0 with d > 0.
    // Line through the top of the radius-0.45 circle at y = 0.75 of the cone (0.70, 0.44)-(0.80, 0.46), with roll.
    const wrc::PoseFrame g(wrc::Pose{0, 0, 0.01, 0.0});
    const Eigen::Vector3d top = g.to_track({0, 0.75, 0.45});
    const auto u = wrc::cone_line_terms(g, top.y(), top.z(), 0.70, -0.44, 0.80, -0.46);
    CHECK(std::abs(u.R - u.T) < 1e-15);
    const int n = wrc::cone_line_intersections(g, top.y(), top.z(), 0.70, -0.44, 0.80, -0.46, r);
    bool at_top = false;
    for (int i = 0; i < n; ++i) at_top = at_top || (r[i].cos_eps < -1 + 1e-12 && std::abs(r[i].x) < 1e-12);
    CHECK(at_top);
  }
  SUBCASE("alpha interval is ]0, 1]: a crossing through the circle shared by two cones counts once") {
    const wrc::PoseFrame f(wrc::Pose{});
    // Cones (0.70, -0.45)-(0.75, -0.46) and (0.75, -0.46)-(0.80, -0.455); the line at y = 0.75 exactly.
    const int n1 = wrc::cone_line_intersections(f, 0.75, -0.455, 0.70, -0.45, 0.75, -0.46, r);
    CHECK(n1 == 2);
    CHECK(r[0].alpha == 1.0);
    const int n2 = wrc::cone_line_intersections(f, 0.75, -0.455, 0.75, -0.46, 0.80, -0.455, r);
    CHECK(n2 == 0);
  }
}
