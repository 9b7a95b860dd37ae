// FASTSIM, Kalker's simplified theory of rolling contact, strip by strip on the grid (rolling.hpp).
//
// The simplified theory replaces the half-space by a layer whose surface displaces locally, u = L p. With Kalker's
// three flexibilities the layer is diag(L1, L2) and the spin part of the rigid slip is scaled by L1/L3 (in x) and
// L2/L3 (in y), so that in adhesion (du/dx = w along the rolling direction, u = 0 at the leading edge) the linear
// theory's Fx and Fy come out exactly on an ellipse. Along each row, from the upstream end of every contact run:
//   u_pred = L p_upstream - dx (w + w_upstream) / 2     (trapezoidal; the run's first element gets half a step)
//   p_pred = L^-1 u_pred;  adhesion if |p_pred| <= mu_s p_n;
//   else slip: p minimises (p - p_pred)' L (p - p_pred) on |p| = mu_k p_n, and s = L (p - p_pred) / dx,
// so that p = -mu_k p_n s / |s| holds for the layer's own slip s.
#include "rolling_internal.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wrc::contact {
namespace {

// 8-connected regions of the contact (p > 0); label per element, -1 outside. Returns the region count.
int label_regions(const Grid& g, std::span<const double> p, std::vector<int>& label) {
  label.assign(static_cast<std::size_t>(g.size()), -1);
  std::vector<int> stack;
  int regions = 0;
  for (int start = 0; start < g.size(); ++start) {
    if (!(p[static_cast<std::size_t>(start)] > 0) || label[static_cast<std::size_t>(start)] >= 0) continue;
    label[static_cast<std::size_t>(start)] = regions;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int k = stack.back(), i = k % g.nx, j = k / g.nx;
      stack.pop_back();
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= g.nx || jj >= g.ny) continue;
          const auto m = static_cast<std::size_t>(g.index(ii, jj));
          if (p[m] > 0 && label[m] < 0) label[m] = regions, stack.push_back(static_cast<int>(m));
        }
    }
    ++regions;
  }
  return regions;
}

// The flexibilities of each region from its equivalent ellipse: the region's extent along x and y (element edges
// included) gives a/b, its area pi a b.
std::vector<Flexibilities> region_flexibilities(const Material& m, const Grid& g, const std::vector<int>& label,
                                                int regions) {
  std::vector<double> xmin(regions, INFINITY), xmax(regions, -INFINITY), ymin(regions, INFINITY),
      ymax(regions, -INFINITY), count(regions, 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int r = label[static_cast<std::size_t>(g.index(i, j))];
      if (r < 0) continue;
      xmin[r] = std::min(xmin[r], g.x(i)), xmax[r] = std::max(xmax[r], g.x(i));
      ymin[r] = std::min(ymin[r], g.y(j)), ymax[r] = std::max(ymax[r], g.y(j));
      count[r] += 1;
    }
  std::vector<Flexibilities> L(static_cast<std::size_t>(regions));
  for (int r = 0; r < regions; ++r) {
    const double aspect = (xmax[r] - xmin[r] + g.dx) / (ymax[r] - ymin[r] + g.dy);
    const double area = count[r] * g.element_area();
    L[static_cast<std::size_t>(r)] =
        kalker_flexibilities(std::sqrt(area * aspect / std::numbers::pi), std::sqrt(area / (std::numbers::pi * aspect)), m);
  }
  return L;
}

// The traction of magnitude g nearest to q in the norm (p - q)' diag(lx, ly) (p - q): p_i = l_i q_i / (l_i + lambda)
// with lambda > 0 from |p| = g (|q| > g). Safeguarded Newton on lambda; closed form for an isotropic layer.
void project(double lx, double ly, double qx, double qy, double g, double& px, double& py) {
  const double qn = std::hypot(qx, qy);
  if (std::abs(lx - ly) <= 1e-12 * (lx + ly)) {
    px = qx * g / qn, py = qy * g / qn;
    return;
  }
  const auto magnitude = [&](double lam) { return std::hypot(lx * qx / (lx + lam), ly * qy / (ly + lam)); };
  double lo = 0, hi = std::max(lx, ly) * qn / g, lam = 0.5 * (lo + hi);
  for (int it = 0; it < 60; ++it) {
    const double ax = lx * qx / (lx + lam), ay = ly * qy / (ly + lam), m = std::hypot(ax, ay);
    if (m > g) lo = lam;
    else hi = lam;
    // d|p|/dlambda = -(ax^2 / (lx + lam) + ay^2 / (ly + lam)) / |p|
    const double dm = -(ax * ax / (lx + lam) + ay * ay / (ly + lam)) / m;
    double next = lam - (m - g) / dm;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - lam) <= 1e-14 * hi) {
      lam = next;
      break;
    }
    lam = next;
  }
  px = lx * qx / (lx + lam), py = ly * qy / (ly + lam);
  const double s = g / magnitude(lam);  // exactly on the bound
  px *= s, py *= s;
}

}  // namespace

TangentialSolution solve_fastsim(const Material& material, const TangentialProblem& pb) {
  validate(pb, "solve_fastsim");
  validate(material, "solve_fastsim");
  const Grid& g = pb.grid;
  TangentialSolution out = detail::empty_solution(g);
  std::vector<int> label;
  const int regions = label_regions(g, pb.pressure, label);
  const std::vector<Flexibilities> flex = region_flexibilities(material, g, label, regions);
  const Creepages& c = pb.creepages;
  const Friction& f = pb.friction;
  // The layer's rigid slip: translational creepages and the extra slip as they are, the spin scaled per axis.
  const auto slip_of = [&](int i, int j, const Flexibilities& L, double& wx, double& wy) {
    const auto k = static_cast<std::size_t>(g.index(i, j));
    wx = c.xi - c.phi * (L.x / L.spin) * (g.y(j) - pb.ref_y) + (pb.extra_x.empty() ? 0.0 : pb.extra_x[k]);
    wy = c.eta + c.phi * (L.y / L.spin) * (g.x(i) - pb.ref_x) + (pb.extra_y.empty() ? 0.0 : pb.extra_y[k]);
  };
  for (int j = 0; j < g.ny; ++j) {
    double ux = 0, uy = 0, wx_up = 0, wy_up = 0;  // upstream element's layer displacement and slip (0 outside)
    for (int step = 0; step < g.nx; ++step) {
      const int i = pb.direction > 0 ? g.nx - 1 - step : step;
      const auto k = static_cast<std::size_t>(g.index(i, j));
      if (!(pb.pressure[k] > 0)) {
        ux = uy = wx_up = wy_up = 0;
        continue;
      }
      const Flexibilities& L = flex[static_cast<std::size_t>(label[k])];
      double wx, wy;
      slip_of(i, j, L, wx, wy);
      const double qx = (ux - 0.5 * g.dx * (wx + wx_up)) / L.x, qy = (uy - 0.5 * g.dx * (wy + wy_up)) / L.y;
      double px = qx, py = qy;
      if (std::hypot(qx, qy) > f.static_coefficient * pb.pressure[k]) {
        project(L.x, L.y, qx, qy, f.kinetic_coefficient * pb.pressure[k], px, py);
        out.state[k] = kSlip;
        out.sx[k] = L.x * (px - qx) / g.dx;
        out.sy[k] = L.y * (py - qy) / g.dx;
      } else {
        out.state[k] = kAdhesion;
      }
      out.px[k] = px, out.py[k] = py;
      ux = L.x * px, uy = L.y * py, wx_up = wx, wy_up = wy;
    }
  }
  detail::summarise(out, pb.ref_x, pb.ref_y);
  return out;
}

}  // namespace wrc::contact
