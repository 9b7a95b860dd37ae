// The wear loop's kernels (damage/profile_wear.hpp) against closed forms: a circular arc moved along its normals
// (the annulus between two concentric regular polygons), strips deposited and smoothed with their area summed by hand,
// a Gaussian's density, points projected back from known offsets.
#include "wrc/damage/profile_wear.hpp"
#include "wrc/core/error.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

using wrc::test::within_abs;
using wrc::test::within_rel;
using namespace wrc;
using namespace wrc::damage;

namespace {

// n + 1 points of the arc of radius R about (0, zc) from angle -half to +half below the centre (a wheel's tread seen
// in its profile frame: the material, toward the axle, is inside the circle).
Polyline arc_points(double R, double zc, double half, int n) {
  Polyline p;
  for (int i = 0; i <= n; ++i) {
    const double t = -half + 2 * half * i / n;
    p.y.push_back(R * std::sin(t));
    p.z.push_back(zc - R * std::cos(t));
  }
  return p;
}

double weighted_sum(const std::vector<double>& d, const std::vector<double>& c) {
  return std::inner_product(d.begin(), d.end(), c.begin(), 0.0);
}

}  // namespace

TEST_CASE("wear kernels: a circular arc moved inward by a uniform depth is the concentric arc, its area the annulus'") {
  const double R = 0.012, half = 1.0, d = 1e-4;
  const int n = 200;
  const Polyline p = arc_points(R, 0.45, half, n);
  // The end points keep their place (their normal is their one segment's, not radial).
  std::vector<double> depth(n + 1, d);
  depth.front() = depth.back() = 0;
  const Polyline m = move_along_normals(p.y, p.z, depth, ProfileKind::wheel);
  for (int i = 1; i < n; ++i) {  // on the circle of radius R - d, same angle
    CHECK(std::hypot(m.y[i], m.z[i] - 0.45) == within_rel(R - d, 1e-12));
    CHECK(std::atan2(m.y[i], 0.45 - m.z[i]) == within_abs(std::atan2(p.y[i], 0.45 - p.z[i]), 1e-12));
  }
  // Between two regular polygons of the same angles: n - 2 trapezoids of sin(dt) (R^2 - (R - d)^2) / 2, and at
  // either end a triangle of base d and height R sin(dt).
  const double dt = 2 * half / n;
  const double annulus = (n - 2) * std::sin(dt) * (R * R - (R - d) * (R - d)) / 2 + d * R * std::sin(dt);
  CHECK(area_between(p.y, p.z, m.y, m.z) == within_rel(annulus, 1e-9));
  // A rail's material is below its profile: the same points move outward of the circle, by the same area.
  const Polyline r = move_along_normals(p.y, p.z, std::vector<double>(n + 1, d), ProfileKind::rail);
  CHECK(std::hypot(r.y[n / 3], r.z[n / 3] - 0.45) == within_rel(R + d, 1e-12));
}

TEST_CASE("wear kernels: inward normals by body, whichever way the points run") {
  const std::vector<double> y = {0, 1e-3, 2e-3}, z = {0, 0, 0}, yr = {2e-3, 1e-3, 0};
  const Normals w = inward_normals(y, z, ProfileKind::wheel), wr = inward_normals(yr, z, ProfileKind::wheel);
  const Normals r = inward_normals(y, z, ProfileKind::rail);
  for (int i = 0; i < 3; ++i) {
    CHECK(w.nz[i] == within_abs(1, 1e-15));  // toward the axle: +z in the wheel's frame
    CHECK(wr.nz[i] == within_abs(1, 1e-15));
    CHECK(r.nz[i] == within_abs(-1, 1e-15));  // into the head
    CHECK(w.ny[i] == within_abs(0, 1e-15));
  }
  // A corner of 90 degrees: the mean of the two normals.
  const Normals c = inward_normals(std::vector<double>{0, 1e-3, 1e-3}, std::vector<double>{0, 0, -1e-3},
                                   ProfileKind::wheel);
  CHECK(c.ny[1] == within_abs(std::sqrt(0.5), 1e-15));
  CHECK(c.nz[1] == within_abs(std::sqrt(0.5), 1e-15));
}

TEST_CASE("wear kernels: strips deposited onto the points keep their area, a strip inside one cell fills it") {
  std::vector<double> arc;
  for (int i = 0; i <= 100; ++i) arc.push_back(1e-4 * i + 1e-6 * std::sin(i));  // uneven spacing
  const std::vector<double> c = cell_lengths(arc);
  CHECK(std::accumulate(c.begin(), c.end(), 0.0) == within_rel(arc.back() - arc.front(), 1e-14));
  std::vector<double> centre, width, area;
  double total = 0;
  for (int k = 0; k < 37; ++k) {  // strips of 0.2 .. 0.9 mm anywhere inside
    centre.push_back(1e-3 + 0.21e-3 * k);
    width.push_back(2e-4 + 1e-4 * (k % 8));
    area.push_back(1e-9 * (1 + k % 5));
    total += area.back();
  }
  const Deposit dep = deposit_strips(arc, centre, width, area);
  CHECK(dep.outside == 0);
  CHECK(weighted_sum(dep.depth, c) == within_rel(total, 1e-12));
  // Inside cell 50 alone (edges at the midpoints): depth = area / cell.
  const double mid = arc[50], w = 0.2 * (arc[51] - arc[49]) / 2;
  const Deposit one = deposit_strips(arc, std::vector<double>{mid}, std::vector<double>{w}, std::vector<double>{3e-9});
  CHECK(one.depth[50] == within_rel(3e-9 / c[50], 1e-12));
  CHECK(one.depth[49] == 0);
  CHECK(one.depth[51] == 0);
  // A strip across the last point: the part beyond it is reported, the rest deposited.
  const Deposit end = deposit_strips(arc, std::vector<double>{arc.back()}, std::vector<double>{4e-5},
                                     std::vector<double>{4e-9});
  CHECK(end.outside == within_rel(2e-9, 1e-9));
  CHECK(weighted_sum(end.depth, c) == within_rel(2e-9, 1e-9));
}

TEST_CASE("wear kernels: the smoothing keeps the area, is a Gaussian of the given length, keeps a constant") {
  std::vector<double> arc, spike, flat;
  const int n = 401;
  const double h = 5e-5, sigma = 5.1e-4;  // 3 sigma between two points (no point at the cut)
  for (int i = 0; i < n; ++i) {
    arc.push_back(h * i);
    spike.push_back(i == 200 ? 1e-4 : 0.0);
    flat.push_back(2e-5);
  }
  const std::vector<double> c = cell_lengths(arc);
  const std::vector<double> s = smooth_depths(arc, spike, sigma);
  CHECK(weighted_sum(s, c) == within_rel(weighted_sum(spike, c), 1e-13));
  // The spike's area A = 1e-4 h as a normal density A / (sigma sqrt(2 pi)) exp(-u^2 / 2) cut at 3 sigma (its mass
  // erf(3 / sqrt 2) spread over the window): about 10 points on sigma.
  const double A = 1e-4 * h / std::erf(3 / std::sqrt(2.0));
  for (int i : {200, 205, 210, 220, 225}) {
    const double u = (arc[i] - arc[200]) / sigma;
    const double g = A / (sigma * std::sqrt(2 * std::numbers::pi)) * std::exp(-0.5 * u * u);
    CHECK(s[i] == within_rel(g, 1e-3));  // the discrete sum against the integral
  }
  CHECK(s[200 + 31] == 0);  // beyond 3 sigma
  const std::vector<double> f = smooth_depths(arc, flat, sigma);
  CHECK(f[200] == within_rel(2e-5, 1e-12));  // inside: a constant stays
  CHECK(weighted_sum(f, c) == within_rel(weighted_sum(flat, c), 1e-13));  // at the ends too, in sum
  CHECK(smooth_depths(arc, spike, 0) == spike);
}

TEST_CASE("wear kernels: points offset along the normals project back to their arc and offset") {
  const Polyline p = arc_points(0.015, 0.45, 0.8, 300);
  const std::vector<double> arc = arc_length(p.y, p.z);
  const Normals nrm = inward_normals(p.y, p.z, ProfileKind::wheel);
  std::vector<double> py, pz;
  for (int i : {3, 100, 151, 299}) {
    py.push_back(p.y[i] - 2e-5 * nrm.ny[i]);  // 20 um outside the wheel
    pz.push_back(p.z[i] - 2e-5 * nrm.nz[i]);
  }
  const Projection q = project_onto(p.y, p.z, py, pz);
  int k = 0;
  for (int i : {3, 100, 151, 299}) {
    CHECK(q.arc[k] == within_abs(arc[i], 1e-12));
    CHECK(q.distance[k] == within_rel(2e-5, 1e-9));
    ++k;
  }
}

TEST_CASE("wear kernels: the projection is the nearest point of all segments, as a scan of every one finds it") {
  // A polyline that folds back (a hook: a flange face leaning over), with a repeated point, 170 segments; points
  // scattered around it in no order, on it (its vertices: distance 0) and equidistant from two segments (ties go to
  // the first, as a scan in order keeps it).
  Polyline p;
  for (int i = 0; i <= 120; ++i) p.y.push_back(-0.03 + 0.04 * i / 120.0), p.z.push_back(1e-3 * std::sin(i * 0.1));
  for (int i = 1; i <= 50; ++i) {
    const double t = std::numbers::pi * i / 50.0;
    p.y.push_back(0.01 + 0.01 * std::sin(t)), p.z.push_back(-0.01 + 0.01 * std::cos(t));
  }
  p.y.push_back(p.y.back()), p.z.push_back(p.z.back());
  const std::vector<double> arc = arc_length(p.y, p.z);
  std::vector<double> py, pz;
  unsigned state = 12345;
  auto uniform = [&]() { return (state = state * 1103515245u + 12345u) / 4294967296.0; };
  for (int k = 0; k < 400; ++k) py.push_back(-0.035 + 0.06 * uniform()), pz.push_back(-0.03 + 0.035 * uniform());
  for (std::size_t i = 0; i < p.y.size(); i += 7) py.push_back(p.y[i]), pz.push_back(p.z[i]);
  py.push_back(0.01), pz.push_back(-0.01);  // the centre of the half circle: every one of its segments as near
  const Projection q = project_onto(p.y, p.z, py, pz);
  for (std::size_t k = 0; k < py.size(); ++k) {
    double best = INFINITY, best_arc = 0;
    for (std::size_t i = 0; i + 1 < p.y.size(); ++i) {
      const double dy = p.y[i + 1] - p.y[i], dz = p.z[i + 1] - p.z[i], l2 = dy * dy + dz * dz;
      const double t = l2 == 0 ? 0 : std::clamp(((py[k] - p.y[i]) * dy + (pz[k] - p.z[i]) * dz) / l2, 0.0, 1.0);
      const double d = std::hypot(py[k] - (p.y[i] + t * dy), pz[k] - (p.z[i] + t * dz));
      if (d < best) best = d, best_arc = arc[i] + t * (arc[i + 1] - arc[i]);
    }
    CHECK(q.distance[k] == best);
    CHECK(q.arc[k] == best_arc);
  }
  // An exact tie (binary fractions): the first and the last segment lie on one line; (-1, 0.5) is nearest to the last
  // alone, then (2, 1) is 1 from both: the first one's arc (2), whichever the point before found.
  const double u = 1.0 / 256;
  const std::vector<double> ty = {0, 4 * u, 8 * u, 4 * u, -4 * u}, tz = {0, 0, 2 * u, 0, 0};
  const Projection tie = project_onto(ty, tz, std::vector<double>{-1 * u, 2 * u}, std::vector<double>{0.5 * u, 1 * u});
  CHECK(tie.distance[0] == 0.5 * u);
  CHECK(tie.distance[1] == 1 * u);
  CHECK(tie.arc[1] == 2 * u);
}

TEST_CASE("wear kernels: worn area deposited, smoothed and removed along the normals of a curved profile") {
  // A flange-root-like arc of 12 mm radius: the area removed equals the deposited one to d / 2R (0.4 % at 0.1 mm).
  const Polyline p = arc_points(0.012, 0.45, 1.2, 400);
  const std::vector<double> arc = arc_length(p.y, p.z), c = cell_lengths(arc);
  std::vector<double> centre, width, area;
  double total = 0;
  for (int k = 0; k < 60; ++k) {
    centre.push_back(arc.back() / 2 + (k - 30) * 1e-4);
    width.push_back(1e-4);
    area.push_back(1e-4 * 1e-4 * std::exp(-0.5 * ((k - 30) / 10.0) * ((k - 30) / 10.0)));
    total += area.back();
  }
  const std::vector<double> d = smooth_depths(arc, deposit_strips(arc, centre, width, area).depth, 3e-4);
  const Polyline m = move_along_normals(p.y, p.z, d, ProfileKind::wheel);
  CHECK(area_between(p.y, p.z, m.y, m.z) == within_rel(total, 5e-3));
}

TEST_CASE("wear kernels: bad input names what is wrong") {
  const std::vector<double> a = {0, 1e-3}, b = {0}, bad = {0, NAN};
  CHECK_THROWS_WITH_AS(arc_length(a, b), "arc_length: y has 2 points, z 1", Error);
  CHECK_THROWS_WITH_AS(smooth_depths(a, bad, 1e-3), "smooth_depths: the 2nd value of depth is not finite", Error);
  CHECK_THROWS_WITH_AS(smooth_depths(a, a, -1), "smooth_depths: length = -1 must be >= 0 (m)", Error);
  CHECK_THROWS_WITH_AS(cell_lengths(std::vector<double>{0, 0}),
                       "cell_lengths: arc must increase: the 2nd value of arc (= 0) after 0", Error);
  CHECK_THROWS_WITH_AS(deposit_strips(a, a, std::vector<double>{1e-3, 0}, a),
                       "deposit_strips: the 2nd value of width (= 0) must be > 0", Error);
}
