// Hertz's ellipse, FASTSIM's equivalent ellipses and Kalker's coefficients of a contact (ellipse.hpp).
#include "wrc/halfspace/ellipse.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/union_find.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace wrc::halfspace {
namespace {

using std::numbers::pi;

// An element of a contact region counts toward its equivalent ellipse by the weight w = s^2 (3 - 2 s), s = min(1, p /
// (kEdgeWeight pmax)), pmax the region's largest pressure: an element entering the contact (p rising from 0 with the
// approach) grows the ellipse continuously, and with a continuous slope (w' = 0 at s = 0 and 1: a weight linear in
// s put a kink into the creep forces wherever an element entered, and their differences along a pose were no
// derivative), instead of by a whole element at once (FASTSIM's creep forces jumped by ~30 N at a 0.8 mm grid where
// 2 nm of approach let one element in, and a solve from elsewhere concluded on the jump's other side). (With a weight
// linear in s, 1e-3 left a jump of 0.1 N there, 1e-2 and 5e-2 none up to 1.2 mm.) In a Hertzian contact an element
// weighs less than 1 only when its centre lies within kEdgeWeight^2 / 2 (1.3e-3) of the semi-axis from the edge.
constexpr double kEdgeWeight = 0.05;

// K and K - E, the complete elliptic integrals of modulus e = sqrt(1 - kp^2), by the arithmetic-geometric mean:
// K = pi / (2 M(1, kp)), K - E = K sum_n 2^(n-1) c_n^2 with c_0 = e (K - E kept as a sum: no cancellation as e -> 0).
struct Elliptic {
  double K, K_minus_E;
};
Elliptic elliptic(double kp) {
  double a = 1, g = kp, c2 = (1 - kp) * (1 + kp), weight = 0.5, sum = 0.5 * c2;
  for (int n = 0; n < 40 && c2 > 1e-30 * a * a; ++n) {  // quadratic convergence: ~6 steps; a cap against rounding
    const double c = 0.5 * (a - g);
    const double an = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = an;
    c2 = c * c;
    weight *= 2;
    sum += weight * c2;
  }
  const double K = pi / (2 * a);
  return {K, K * sum};
}

// Hertz's shape: the ratio of the larger to the smaller relative curvature as a function of kp = minor / major
// semi-axis, (E / kp^2 - K) / (K - E); it falls from infinity at kp -> 0 to 1 at kp = 1.
double curvature_ratio(double kp) {
  const Elliptic f = elliptic(kp);
  const double E = f.K - f.K_minus_E;
  return (E / (kp * kp) - f.K) / f.K_minus_E;
}

// kp for the curvature ratio q > 1. ln(ratio) is nearly linear in ln kp (ratio ~ kp^-1.5 for small kp): secant steps
// in ln kp from Greenwood's kp ~ q^(-2/3), kept inside a bracket that each step narrows (bisection when a step would
// leave it); 4-6 evaluations.
double axis_ratio(double q) {
  const double target = std::log(q);
  const auto f = [&](double x) { return std::log(curvature_ratio(std::exp(x))) - target; };  // decreasing in x
  double lo = std::log(1e-12), hi = 0;
  const auto narrow = [&](double x, double fx) { (fx > 0 ? lo : hi) = x; };  // the root lies above x where f > 0
  double x0 = std::clamp(-2.0 / 3.0 * target, lo, -1e-9), f0 = f(x0);
  narrow(x0, f0);
  double x1 = 0.5 * (x0 + (f0 > 0 ? hi : lo)), f1 = f(x1);
  for (int it = 0; it < 100 && f1 != 0 && hi - lo > 1e-14; ++it) {
    narrow(x1, f1);
    double next = f1 != f0 ? x1 - f1 * (x1 - x0) / (f1 - f0) : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x1) < 1e-15) break;
    x0 = x1, f0 = f1;
    x1 = next, f1 = f(x1);
  }
  return std::exp(x1);
}

}  // namespace

std::optional<HertzContact> hertz_contact(double kx, double ky, double force, const Material& m) {
  if (!std::isfinite(kx) || !std::isfinite(ky) || !std::isfinite(force))
    fail("hertz_contact: curvatures kx = {}, ky = {} 1/m and load {} N must be finite", kx, ky, force);
  validate(m, "hertz_contact");
  if (!(kx > 0) || !(ky > 0) || !(force > 0)) return std::nullopt;
  const double Es = m.combined_modulus(), kmin = std::min(kx, ky), q = std::max(kx, ky) / kmin;
  HertzContact h;
  h.kx = kx;
  h.ky = ky;
  h.force = force;
  double major, minor;
  if (q < 1 + 1e-12) {  // a circle: a^3 = 3 F R / (4 E*), R = 1 / k
    major = minor = std::cbrt(3 * force / (4 * Es * kmin));
    h.approach = major * major * kmin;
  } else {
    // Johnson (3.64 .. 3.66): the smaller curvature kmin / 2 = A along the major axis, A = 3 F (K - E) / (2 pi e^2
    // major^3 E*); the approach p0 minor K / E*.
    const double kp = axis_ratio(q), e2 = (1 - kp) * (1 + kp);
    const Elliptic f = elliptic(kp);
    major = std::cbrt(3 * force * f.K_minus_E / (pi * e2 * kmin * Es));
    minor = kp * major;
    h.approach = 3 * force / (2 * pi * major * minor) * minor * f.K / Es;
  }
  h.a = kx <= ky ? major : minor;
  h.b = kx <= ky ? minor : major;
  h.p0 = 3 * force / (2 * pi * h.a * h.b);
  return h;
}

RelativeCurvature wheel_rail_curvature(double rolling_radius, double angle, double wheel_curvature,
                                       double rail_curvature) {
  return {std::cos(angle) / rolling_radius, wheel_curvature + rail_curvature};
}

namespace {

// The regions of `p` with their ellipses and, given dp (else empty), the ellipses' changes: equivalent_ellipses and
// ellipse_changes in one.
std::vector<EquivalentEllipse> ellipses(const Grid& g, std::span<const double> p, std::vector<int>& label,
                                        std::span<const double> dp, std::vector<EllipseChange>* changes) {
  label.assign(static_cast<std::size_t>(g.size()), -1);
  struct Run {
    int j, i0, i1, top;  // top: the element of the largest pressure
    double force;
  };
  std::vector<Run> runs;
  std::vector<int> row_start(static_cast<std::size_t>(g.ny) + 1, 0);
  for (int j = 0; j < g.ny; ++j) {
    row_start[static_cast<std::size_t>(j)] = static_cast<int>(runs.size());
    const double* row = p.data() + static_cast<std::size_t>(g.nx) * j;
    for (int i = 0; i < g.nx;) {
      if (!(row[i] > 0)) {
        ++i;
        continue;
      }
      const int start = i;
      int top = i;
      double sum = 0;
      for (; i < g.nx && row[i] > 0; ++i) sum += row[i], top = row[i] > row[top] ? i : top;
      runs.push_back({j, start, i - 1, g.index(top, j), sum});
    }
  }
  row_start[static_cast<std::size_t>(g.ny)] = static_cast<int>(runs.size());
  UnionFind sets;
  sets.reset(static_cast<int>(runs.size()));
  for (int j = 1; j < g.ny; ++j)
    for (int a = row_start[j - 1], b = row_start[j]; a < row_start[j] && b < row_start[j + 1];) {
      const Run &ra = runs[static_cast<std::size_t>(a)], &rb = runs[static_cast<std::size_t>(b)];
      if (ra.i1 + 1 >= rb.i0 && rb.i1 + 1 >= ra.i0) sets.unite(a, b);  // touching, diagonally included
      (ra.i1 < rb.i1 ? a : b) += 1;
    }
  // Each region's bounding box, force and largest pressure; then its elements' weights (kEdgeWeight): summed for the
  // area, their largest per column and per row summed for the length and the width. With dp, the same for the
  // weights' changes (the largest weight's, per column and row; none where it is 1).
  struct Extent {
    int i0 = 1 << 30, i1 = -1, j0 = 1 << 30, j1 = -1, top = -1;
    double force = 0, count = 0, dcount = 0;
    std::size_t cols = 0, rows = 0;  // offsets of its column and row maxima in `most`
  };
  std::vector<int> region(runs.size(), -1), run_region(runs.size());
  std::vector<Extent> ext;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    int& id = region[static_cast<std::size_t>(sets.find(static_cast<int>(r)))];
    if (id < 0) id = static_cast<int>(ext.size()), ext.emplace_back();
    run_region[r] = id;
    const Run& run = runs[r];
    Extent& e = ext[static_cast<std::size_t>(id)];
    e.i0 = std::min(e.i0, run.i0), e.i1 = std::max(e.i1, run.i1), e.j0 = std::min(e.j0, run.j), e.j1 = std::max(e.j1, run.j);
    e.force += run.force;
    if (e.top < 0 || p[static_cast<std::size_t>(run.top)] > p[static_cast<std::size_t>(e.top)]) e.top = run.top;
    std::fill(label.begin() + g.index(run.i0, run.j), label.begin() + g.index(run.i1, run.j) + 1, id);
  }
  std::size_t size = 0;
  for (Extent& e : ext) {
    e.cols = size, size += static_cast<std::size_t>(e.i1 - e.i0 + 1);
    e.rows = size, size += static_cast<std::size_t>(e.j1 - e.j0 + 1);
  }
  const bool derive = changes != nullptr;
  std::vector<double> most(size, 0.0), dmost(derive ? size : 0, 0.0);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Run& run = runs[r];
    Extent& e = ext[static_cast<std::size_t>(run_region[r])];
    const double pmax = p[static_cast<std::size_t>(e.top)], inv = 1 / (kEdgeWeight * pmax);
    const double dpmax = derive ? dp[static_cast<std::size_t>(e.top)] : 0.0;
    const std::size_t across = e.rows + static_cast<std::size_t>(run.j - e.j0);
    for (int i = run.i0; i <= run.i1; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, run.j)), along = e.cols + static_cast<std::size_t>(i - e.i0);
      const double s = std::min(1.0, p[k] * inv), w = s * s * (3 - 2 * s);
      e.count += w;
      if (derive) {
        const double dw = s < 1 ? 6 * s * (1 - s) * (dp[k] - p[k] * dpmax / pmax) * inv : 0.0;
        e.dcount += dw;
        if (w > most[along]) dmost[along] = dw;
        if (w > most[across]) dmost[across] = dw;
      }
      most[along] = std::max(most[along], w), most[across] = std::max(most[across], w);
    }
  }
  std::vector<EquivalentEllipse> out;
  out.reserve(ext.size());
  if (derive) changes->clear();
  const double dA = g.element_area();
  const auto sum = [](const std::vector<double>& v, std::size_t from, int n) {
    const auto first = v.begin() + static_cast<std::ptrdiff_t>(from);
    return std::accumulate(first, first + n, 0.0);
  };
  for (const Extent& e : ext) {
    const int nx = e.i1 - e.i0 + 1, ny = e.j1 - e.j0 + 1;
    const double length = sum(most, e.cols, nx) * g.dx, width = sum(most, e.rows, ny) * g.dy;
    const double aspect = length / width, area = e.count * dA;
    const EquivalentEllipse& el = out.emplace_back(
        EquivalentEllipse{std::sqrt(area * aspect / pi), std::sqrt(area / (pi * aspect)), e.force * dA});
    if (!derive) continue;
    // a = sqrt(area aspect / pi), b = sqrt(area / (pi aspect)): relative changes of half the area's -+ the aspect's.
    const double rel_area = e.dcount / e.count;
    const double rel_aspect = sum(dmost, e.cols, nx) * g.dx / length - sum(dmost, e.rows, ny) * g.dy / width;
    changes->push_back({0.5 * el.a * (rel_area + rel_aspect), 0.5 * el.b * (rel_area - rel_aspect)});
  }
  return out;
}

}  // namespace

std::vector<EquivalentEllipse> equivalent_ellipses(const Grid& g, std::span<const double> p, std::vector<int>& label) {
  return ellipses(g, p, label, {}, nullptr);
}

std::vector<RegionSpan> region_spans(const Grid& g, std::span<const int> label, std::span<const int> regions) {
  if (label.size() != static_cast<std::size_t>(g.size()))
    fail("region_spans: {} labels for a grid of {} x {} elements", label.size(), g.nx, g.ny);
  // A pass in storage order (x fastest) per region asked for (one or two, as a rule): its elements in each row, and in
  // each column summed over the rows. Branch-free, so that the compiler vectorises it: 4.5 M instructions over 60 steps
  // of bench_online's trajectory at 0.2 mm (128 areas), against 17.0 M for one pass looking up each element's region.
  const auto nx = static_cast<std::size_t>(g.nx);
  std::vector<RegionSpan> span(regions.size());
  std::vector<int> in_column(nx);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    std::fill(in_column.begin(), in_column.end(), 0);
    const int region = regions[k];
    for (int j = 0; j < g.ny; ++j) {
      const int* row = label.data() + static_cast<std::size_t>(j) * nx;
      int in_row = 0;
      for (std::size_t i = 0; i < nx; ++i) {
        const int here = row[i] == region;
        in_row += here;
        in_column[i] += here;
      }
      span[k].x = std::max(span[k].x, in_row);
    }
    span[k].y = nx ? *std::max_element(in_column.begin(), in_column.end()) : 0;
  }
  return span;
}

std::vector<EllipseChange> ellipse_changes(const Grid& g, std::span<const double> p, std::span<const double> dp) {
  std::vector<int> label;
  std::vector<EllipseChange> changes;
  ellipses(g, p, label, dp, &changes);
  return changes;
}

ContactEllipses hertz_ellipses(const RelativeCurvature& k, double load, const Material& m) {
  ContactEllipses e;
  e.hertz = hertz_contact(k.kx, k.ky, load, m);
  if (e.hertz && m.nu >= 0 && m.nu <= 0.5) e.kalker = kalker_coefficients(e.hertz->a / e.hertz->b, m.nu);
  return e;
}

std::optional<EquivalentEllipse> fastsim_ellipse(const Grid& grid, std::span<const double> pressure) {
  std::vector<int> label;
  const std::vector<EquivalentEllipse> all = equivalent_ellipses(grid, pressure, label);
  if (all.empty()) return std::nullopt;
  return *std::max_element(all.begin(), all.end(),
                           [](const EquivalentEllipse& x, const EquivalentEllipse& y) { return x.force < y.force; });
}

void describe(const ContactEllipses& e, FieldSink& out) {
  if (e.ellipse) {
    out.begin("ellipse", {"", "FASTSIM's equivalent ellipse of the region carrying the most force: length and width "
                              "of the region (element edges included) give a/b, its area pi a b; an element with "
                              "less than 5 % of the region's peak pressure counts with a weight rising smoothly "
                              "from 0 to 1 with its pressure"});
    out.number("a", e.ellipse->a, {"m", "semi-axis along the rolling direction (grid x)"});
    out.number("b", e.ellipse->b, {"m", "semi-axis across it (grid y)"});
    out.end();
  }
  if (!e.hertz) return;
  const HertzContact& h = *e.hertz;
  out.begin("hertz", {"", "Hertz's ellipse from the relative curvatures at the point and the load (only where both "
                          "curvatures are convex)"});
  out.number("a", h.a, {"m", "semi-axis along the track (rolling direction)"});
  out.number("b", h.b, {"m", "semi-axis across the track"});
  out.number("p0", h.p0, {"Pa", "peak pressure 3 load / (2 pi a b)"});
  out.number("approach", h.approach, {"m", "approach of the two bodies"});
  out.number("load", h.force, {"N", "the normal load assumed"});
  out.number("kx", h.kx, {"1/m", "relative curvature along the track: cos(angle) / rolling radius"});
  out.number("ky", h.ky, {"1/m", "relative curvature across it: wheel + rail profile curvature (> 0 convex)"});
  out.end();
  if (!e.kalker) return;
  const CreepCoefficients& k = *e.kalker;
  out.begin("kalker",
            {"", "Kalker's creep coefficients for hertz's a/b and the material's nu (creep.hpp; only for nu in 0 .. 0.5)"});
  out.number("C11", k.c11, {"-", "longitudinal: Fx = -G a b C11 xi"});
  out.number("C22", k.c22, {"-", "lateral: Fy = -G a b C22 eta - G (a b)^1.5 C23 phi"});
  out.number("C23", k.c23, {"-", "lateral-spin coupling"});
  out.number("C33", k.c33, {"-", "spin: Mz = G (a b)^1.5 C23 eta - G (a b)^2 C33 phi"});
  out.boolean("tabulated", k.tabulated, {"", "a/b within Kalker's table (0.1 .. 10); else extrapolated"});
  out.end();
}

}  // namespace wrc::halfspace
