#include "wrc/damage/profile_wear.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::damage {
namespace {

void check_polyline(std::span<const double> y, std::span<const double> z, const char* what) {
  if (y.size() != z.size()) fail("{}: y has {} points, z {}", what, y.size(), z.size());
  if (y.size() < 2) fail("{}: a polyline needs at least 2 points, got {}", what, y.size());
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i]) || !std::isfinite(z[i])) fail("{}: the {} point is not finite", what, ordinal(i + 1));
  }
}

void check_sizes(std::size_t n, std::size_t m, const char* what, const char* field) {
  if (n != m) fail("{}: {} has {} values, expected {}", what, field, m, n);
}

void check_finite(std::span<const double> v, const char* what, const char* field) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) fail("{}: {} is not finite", what, value_at(i, field));
  }
}

// The arc must increase: a repeated point would give a cell without length and a depth without a meaning.
void check_arc(std::span<const double> arc, const char* what) {
  if (arc.size() < 2) fail("{}: needs at least 2 points, got {}", what, arc.size());
  check_finite(arc, what, "arc");
  for (std::size_t i = 1; i < arc.size(); ++i) {
    if (!(arc[i] > arc[i - 1]))
      fail("{}: arc must increase: {} (= {}) after {}", what, value_at(i, "arc"), arc[i], arc[i - 1]);
  }
}

// The point of segment [a, b] nearest to p, as the fraction along it.
double nearest_fraction(double ay, double az, double by, double bz, double py, double pz) {
  const double dy = by - ay, dz = bz - az, l2 = dy * dy + dz * dz;
  if (l2 == 0) return 0;
  return std::clamp(((py - ay) * dy + (pz - az) * dz) / l2, 0.0, 1.0);
}

}  // namespace

std::vector<double> arc_length(std::span<const double> y, std::span<const double> z) {
  check_polyline(y, z, "arc_length");
  std::vector<double> s(y.size(), 0.0);
  for (std::size_t i = 1; i < y.size(); ++i) s[i] = s[i - 1] + std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  return s;
}

std::vector<double> cell_lengths(std::span<const double> arc) {
  check_arc(arc, "cell_lengths");
  const std::size_t n = arc.size();
  std::vector<double> c(n);
  c[0] = (arc[1] - arc[0]) / 2;
  c[n - 1] = (arc[n - 1] - arc[n - 2]) / 2;
  for (std::size_t i = 1; i + 1 < n; ++i) c[i] = (arc[i + 1] - arc[i - 1]) / 2;
  return c;
}

// The segments in blocks of kBlock with their bounding boxes: a block whose box is farther from a point than the
// nearest segment found so far holds no nearer one, and is skipped. The rows of a contact area come in order along
// the profile, so the previous point's nearest segment makes a close first guess.
constexpr std::size_t kBlock = 16;
struct Box {
  double y0, y1, z0, z1;
};

// The distance of (py, pz) to the box (0 inside).
double box_distance(const Box& b, double py, double pz) {
  const double dy = std::max({b.y0 - py, 0.0, py - b.y1}), dz = std::max({b.z0 - pz, 0.0, pz - b.z1});
  return std::sqrt(dy * dy + dz * dz);
}

Projection project_onto(std::span<const double> y, std::span<const double> z, std::span<const double> py,
                        std::span<const double> pz) {
  const std::vector<double> arc = arc_length(y, z);
  check_sizes(py.size(), pz.size(), "project_onto", "the points' z");
  check_finite(py, "project_onto", "points y");
  check_finite(pz, "project_onto", "points z");
  const std::size_t segments = y.size() - 1;
  std::vector<Box> boxes;
  for (std::size_t b = 0; b < segments; b += kBlock) {
    Box box{y[b], y[b], z[b], z[b]};
    for (std::size_t i = b + 1; i <= std::min(b + kBlock, segments); ++i)
      box = {std::min(box.y0, y[i]), std::max(box.y1, y[i]), std::min(box.z0, z[i]), std::max(box.z1, z[i])};
    boxes.push_back(box);
  }
  Projection out{std::vector<double>(py.size()), std::vector<double>(py.size())};
  std::size_t guess = 0;
  for (std::size_t k = 0; k < py.size(); ++k) {
    double best = INFINITY, best_arc = 0;
    std::size_t best_i = segments;
    // Every segment could be the nearest (profiles fold back at flanges): the first of the nearest, as a scan of all
    // in order finds it (ties go to the lower index).
    auto visit = [&](std::size_t i) {
      const double t = nearest_fraction(y[i], z[i], y[i + 1], z[i + 1], py[k], pz[k]);
      const double qy = y[i] + t * (y[i + 1] - y[i]), qz = z[i] + t * (z[i + 1] - z[i]);
      const double d = std::hypot(py[k] - qy, pz[k] - qz);
      if (d < best || (d == best && i < best_i)) best = d, best_i = i, best_arc = arc[i] + t * (arc[i + 1] - arc[i]);
    };
    visit(guess);
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      if (box_distance(boxes[b], py[k], pz[k]) > best * (1 + 1e-9) + 1e-15) continue;  // margins: rounding
      for (std::size_t i = b * kBlock; i < std::min((b + 1) * kBlock, segments); ++i) visit(i);
    }
    guess = best_i;
    out.arc[k] = best_arc;
    out.distance[k] = best;
  }
  return out;
}

Deposit deposit_strips(std::span<const double> arc, std::span<const double> centre, std::span<const double> width,
                       std::span<const double> area) {
  const char* what = "deposit_strips";
  check_arc(arc, what);
  check_sizes(centre.size(), width.size(), what, "width");
  check_sizes(centre.size(), area.size(), what, "area");
  check_finite(centre, what, "centre");
  check_finite(area, what, "area");
  const std::size_t n = arc.size();
  const std::vector<double> c = cell_lengths(arc);
  // Cell i is [edge[i], edge[i + 1]].
  std::vector<double> edge(n + 1);
  edge[0] = arc[0];
  edge[n] = arc[n - 1];
  for (std::size_t i = 1; i < n; ++i) edge[i] = (arc[i - 1] + arc[i]) / 2;
  Deposit out{std::vector<double>(n, 0.0), 0.0};
  for (std::size_t k = 0; k < centre.size(); ++k) {
    if (!(width[k] > 0) || !std::isfinite(width[k]))
      fail("{}: {} (= {}) must be > 0", what, value_at(k, "width"), width[k]);
    const double a = centre[k] - width[k] / 2, b = centre[k] + width[k] / 2, density = area[k] / width[k];
    out.outside += density * (std::max(0.0, std::min(b, edge[0]) - a) + std::max(0.0, b - std::max(a, edge[n])));
    // The first cell whose right edge is past a.
    std::size_t i = static_cast<std::size_t>(std::upper_bound(edge.begin() + 1, edge.end(), a) - edge.begin()) - 1;
    for (; i < n && edge[i] < b; ++i) {
      const double overlap = std::min(b, edge[i + 1]) - std::max(a, edge[i]);
      if (overlap > 0) out.depth[i] += density * overlap;
    }
  }
  for (std::size_t i = 0; i < n; ++i) out.depth[i] /= c[i];
  return out;
}

std::vector<double> smooth_depths(std::span<const double> arc, std::span<const double> depth, double length) {
  const char* what = "smooth_depths";
  check_arc(arc, what);
  check_sizes(arc.size(), depth.size(), what, "depth");
  check_finite(depth, what, "depth");
  if (!(length >= 0) || !std::isfinite(length)) fail("{}: length = {} must be >= 0 (m)", what, length);
  if (length == 0) return {depth.begin(), depth.end()};
  const std::size_t n = arc.size();
  const std::vector<double> c = cell_lengths(arc);
  const double reach = 3 * length;
  std::vector<double> area(n, 0.0);
  // The window [lo, hi) of points within reach of source j: |arc_i - arc_j| <= reach, the same test both ways (a
  // constant stays constant inside).
  std::size_t lo = 0, hi = 0;
  for (std::size_t j = 0; j < n; ++j) {
    while (arc[j] - arc[lo] > reach) ++lo;
    if (hi < lo) hi = lo;
    while (hi < n && arc[hi] - arc[j] <= reach) ++hi;
    if (depth[j] == 0) continue;
    double total = 0;
    for (std::size_t i = lo; i < hi; ++i) {
      const double u = (arc[i] - arc[j]) / length;
      total += std::exp(-0.5 * u * u) * c[i];
    }
    const double share = depth[j] * c[j] / total;  // total >= c[j] > 0: the source itself is in its window
    for (std::size_t i = lo; i < hi; ++i) {
      const double u = (arc[i] - arc[j]) / length;
      area[i] += share * std::exp(-0.5 * u * u) * c[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) area[i] /= c[i];
  return area;
}

Normals inward_normals(std::span<const double> y, std::span<const double> z, ProfileKind kind) {
  check_polyline(y, z, "inward_normals");
  const std::size_t n = y.size();
  // The left normal (-tz, ty) of a polyline running toward +y points to +z: into a wheel, out of a rail.
  const double run = y[n - 1] - y[0];
  if (run == 0) fail("inward_normals: the polyline's first and last points have the same y ({} m)", y[0]);
  const double sign = (kind == ProfileKind::wheel ? 1.0 : -1.0) * (run > 0 ? 1.0 : -1.0);
  std::vector<double> sy(n - 1), sz(n - 1);  // the segments' inward unit normals
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dy = y[i + 1] - y[i], dz = z[i + 1] - z[i], l = std::hypot(dy, dz);
    if (l == 0) fail("inward_normals: points {} and {} coincide", i + 1, i + 2);
    sy[i] = -sign * dz / l;
    sz[i] = sign * dy / l;
  }
  Normals out{std::vector<double>(n), std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    double ny = 0, nz = 0;
    if (i > 0) ny += sy[i - 1], nz += sz[i - 1];
    if (i + 1 < n) ny += sy[i], nz += sz[i];
    const double l = std::hypot(ny, nz);
    if (l == 0) fail("inward_normals: the polyline turns back on itself at point {}", i + 1);
    out.ny[i] = ny / l;
    out.nz[i] = nz / l;
  }
  return out;
}

Polyline move_along_normals(std::span<const double> y, std::span<const double> z, std::span<const double> depth,
                            ProfileKind kind) {
  const Normals nrm = inward_normals(y, z, kind);
  check_sizes(y.size(), depth.size(), "move_along_normals", "depth");
  check_finite(depth, "move_along_normals", "depth");
  Polyline out{std::vector<double>(y.size()), std::vector<double>(y.size())};
  for (std::size_t i = 0; i < y.size(); ++i) {
    out.y[i] = y[i] + depth[i] * nrm.ny[i];
    out.z[i] = z[i] + depth[i] * nrm.nz[i];
  }
  return out;
}

double area_between(std::span<const double> ya, std::span<const double> za, std::span<const double> yb,
                    std::span<const double> zb) {
  check_polyline(ya, za, "area_between");
  check_polyline(yb, zb, "area_between");
  check_sizes(ya.size(), yb.size(), "area_between", "the second polyline");
  double sum = 0;  // twice the signed area
  for (std::size_t i = 0; i + 1 < ya.size(); ++i) {
    // Relative to a_i: the areas are small against the coordinates (wear of 0.1 mm on a profile 0.75 m off).
    const double qy[4] = {0, ya[i + 1] - ya[i], yb[i + 1] - ya[i], yb[i] - ya[i]};
    const double qz[4] = {0, za[i + 1] - za[i], zb[i + 1] - za[i], zb[i] - za[i]};
    for (int k = 0; k < 4; ++k) sum += qy[k] * qz[(k + 1) % 4] - qy[(k + 1) % 4] * qz[k];
  }
  return std::abs(sum) / 2;
}

}  // namespace wrc::damage
