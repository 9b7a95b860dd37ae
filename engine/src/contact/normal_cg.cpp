// Fast normal solver: projected, preconditioned conjugate gradients on the active set with FFT products.
//
// The normal problem is the bound-constrained quadratic programme min 1/2 p.Kp - (h + approach).p, p >= 0
// (K = 2 D, symmetric positive definite), whose optimality conditions are the complementarity conditions
// of normal.hpp. The iteration (after Polonsky and Keer, Wear 231, 1999) runs CG on the working set
// S = {p > 0} U {p = 0 and g < 0}, projects p onto p >= 0 after every step, and restarts the conjugate
// directions (beta = 0) whenever S changes. For a prescribed force the approach is the Lagrange multiplier
// of sum p dA = F: the residual and the search directions are kept at zero mean on S, so a step keeps the
// force, and a projection that clips pressures is followed by a rescaling to the force.
//
// Preconditioner: z = P_S C^-1 P_S r, where C is the circulant of the zero-padded periodic grid (whose
// restriction to the grid is K exactly) inverted by FFT. K's symbol behaves like 1/|wave number|, so plain
// CG needs more iterations as the contact gets wider in elements; the circulant inverse removes most of
// that growth (the idea of Vollebregt's NormCG, J. Comput. Phys. 257, 2014, without its deflation).
#include "normal_internal.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace wrc::contact {
namespace {

// K = factor * I applied by FFT (exact, zero-padded); the preconditioner is the inverse of the grid's
// periodic circulant.
struct FftOperator {
  const InfluenceSpectrum& spectrum;
  const InfluenceSpectrum& periodic;
  const Grid& grid;
  double factor;
  ConvolutionWorkspace& ws;
  int products = 0;

  void apply(const std::vector<double>& x, std::vector<double>& y) {
    convolve(spectrum, grid, x.data(), y.data(), ws, factor);
    ++products;
  }
  void invert(const std::vector<double>& r, std::vector<double>& z) {
    deconvolve(periodic, grid, r.data(), z.data(), ws, 1.0 / factor);
    ++products;
  }
  // y += K e_at * amount: a direct sum over the grid, cheaper than a product for a few elements.
  void add_element(int at, double amount, std::vector<double>& y) const {
    const InfluenceTable& table = spectrum.table();
    const int nx = grid.nx, ia = at % nx, ja = at / nx;
    const double f = factor * amount;
    for (int j = 0; j < grid.ny; ++j) {
      double* row = y.data() + static_cast<std::size_t>(nx) * j;
      const double* t = table.row(j - ja);
      for (int i = 0; i < ia; ++i) row[i] += f * t[ia - i];
      for (int i = ia; i < nx; ++i) row[i] += f * t[i - ia];
    }
  }
  // Clipped elements up to this count are corrected by direct sums rather than a new product. Measured
  // (bench machine): a direct sum costs ~0.4 ns per grid element, a pruned FFT round trip ~0.35 ns per
  // point and log2(points); the limit keeps a factor 2 of margin.
  int direct_limit() const {
    const double points = static_cast<double>(spectrum.Mx()) * spectrum.My();
    return std::max(1, static_cast<int>(points * std::log2(points) / (2.0 * grid.size())));
  }
};

}  // namespace

NormalSolver::NormalSolver(const Material& material, FftPlanning planning) : material_(material), cache_(planning) {
  validate(material, "NormalSolver");
}

NormalSolution NormalSolver::solve(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                                   const NormalOptions& options) const {
  NormalWorkspace ws;
  return solve(grid, h, load, ws, options);
}

namespace {

// The grid twice as coarse: coarse element (I, J) covers fine elements 2I..2I+1 x 2J..2J+1 (one row or
// column less at an odd edge); its h is the mean of the fine ones it covers.
Grid coarse_grid(const Grid& fine) {
  Grid c;
  c.nx = (fine.nx + 1) / 2;
  c.ny = (fine.ny + 1) / 2;
  c.dx = 2 * fine.dx;
  c.dy = 2 * fine.dy;
  c.x0 = fine.x0 + 0.5 * fine.dx;
  c.y0 = fine.y0 + 0.5 * fine.dy;
  return c;
}

std::vector<double> restrict_to(const Grid& fine, const Grid& coarse, std::span<const double> h) {
  std::vector<double> sum(coarse.size(), 0.0), count(coarse.size(), 0.0);
  for (int j = 0; j < fine.ny; ++j)
    for (int i = 0; i < fine.nx; ++i) {
      const int c = coarse.index(i / 2, j / 2);
      sum[c] += h[fine.index(i, j)];
      count[c] += 1;
    }
  for (int c = 0; c < coarse.size(); ++c) sum[c] /= count[c];
  return sum;
}

// Bilinear interpolation of the coarse pressure at the fine element centres (>= 0), kept only under coarse
// elements in contact.
void prolong(const Grid& coarse, const std::vector<double>& pc, const Grid& fine, std::vector<double>& p) {
  const auto locate = [](int i, int n, int& i0, double& t) {
    const double s = std::clamp(0.5 * i - 0.25, 0.0, static_cast<double>(n - 1));  // coarse index coordinate
    i0 = std::min(static_cast<int>(s), std::max(0, n - 2));
    t = n > 1 ? s - i0 : 0.0;
  };
  for (int j = 0; j < fine.ny; ++j) {
    int j0;
    double ty;
    locate(j, coarse.ny, j0, ty);
    const int j1 = std::min(j0 + 1, coarse.ny - 1);
    for (int i = 0; i < fine.nx; ++i) {
      int i0;
      double tx;
      locate(i, coarse.nx, i0, tx);
      const int i1 = std::min(i0 + 1, coarse.nx - 1);
      const double v = (1 - ty) * ((1 - tx) * pc[coarse.index(i0, j0)] + tx * pc[coarse.index(i1, j0)]) +
                       ty * ((1 - tx) * pc[coarse.index(i0, j1)] + tx * pc[coarse.index(i1, j1)]);
      // Only under coarse elements in contact: interpolation alone smears the edge outward, and each
      // element started in contact that is not costs the CG a clipping step.
      const bool parent = pc[coarse.index(i / 2, j / 2)] > 0;
      p[fine.index(i, j)] = parent ? std::max(0.0, v) : 0.0;
    }
  }
}

}  // namespace

NormalSolution NormalSolver::solve(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                                   NormalWorkspace& ws, const NormalOptions& options) const {
  validate_normal_input(material_, grid, h, load, options, "NormalSolver::solve");
  return solve_checked(grid, h, load, ws, options);
}

NormalSolution NormalSolver::solve_checked(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                                           NormalWorkspace& ws, const NormalOptions& options) const {
  const bool force_control = load.control == NormalLoad::Control::force;
  const int n = grid.size();
  const double hmax = *std::max_element(h.begin(), h.end());
  if ((force_control && load.force == 0) || (!force_control && hmax <= 0)) return detail::zero_solution(grid, h, load);

  // Nested start: the coarse grid's solution, interpolated, is a start whose contact set is right to a
  // coarse element or two, so the fine grid mostly runs the CG's converging phase.
  int coarse_iterations = 0, coarse_products = 0;
  std::vector<double> start;
  if (options.initial_pressure.empty() && options.nested && n > options.coarse_limit && grid.nx >= 4 &&
      grid.ny >= 4) {
    const Grid coarse = coarse_grid(grid);
    const std::vector<double> hc = restrict_to(grid, coarse, h);
    NormalOptions coarse_options = options;
    coarse_options.tolerance = std::max(options.tolerance, 1e-2);  // a start only: the coarse grid's own
                                                                   // discretisation error is of this order
    const NormalSolution sc = solve_checked(coarse, hc, load, ws, coarse_options);
    coarse_iterations = sc.iterations + sc.coarse_iterations;
    coarse_products = sc.products + sc.coarse_products;
    if (sc.force > 0) {
      start.resize(n);
      prolong(coarse, sc.pressure, grid, start);
    }
  } else if (!options.initial_pressure.empty()) {
    start.assign(options.initial_pressure.begin(), options.initial_pressure.end());
  }

  const auto spectrum = cache_.get(grid);
  const auto periodic = cache_.get(grid, InfluenceSpectrum::Kind::periodic);
  FftOperator K{*spectrum, *periodic, grid, 1.0 / (std::numbers::pi * material_.combined_modulus()), ws.fft};
  const double dA = grid.element_area();
  const int max_iterations = options.max_iterations > 0 ? options.max_iterations : 2000;
  auto& p = ws.p;
  auto& u = ws.u;
  auto& r = ws.r;
  auto& z = ws.z;
  auto& d = ws.d;
  auto& q = ws.q;
  for (auto* v : {&p, &u, &r, &z, &d, &q}) v->assign(n, 0.0);
  ws.active.assign(n, 0);
  ws.previous_active.assign(n, 0);

  // Start: the warm or nested start, else nothing (penetration) or a uniform pressure on {h > 0} (force).
  for (std::size_t k = 0; k < start.size(); ++k) p[k] = std::max(0.0, start[k]);
  const auto rescale_to_force = [&] {
    double sum = 0;
    for (double v : p) sum += v;
    const double f = load.force / (sum * dA);
    for (int k = 0; k < n; ++k) p[k] *= f, u[k] *= f;
  };
  if (force_control) {
    double sum = 0;
    for (double v : p) sum += v;
    if (!(sum > 0)) {
      int count = 0;
      for (int k = 0; k < n; ++k) count += h[k] > 0;
      if (count > 0) {
        for (int k = 0; k < n; ++k) p[k] = h[k] > 0 ? 1.0 : 0.0;
      } else {
        p[std::max_element(h.begin(), h.end()) - h.begin()] = 1.0;
      }
    }
  }
  if (std::any_of(p.begin(), p.end(), [](double v) { return v > 0; })) K.apply(p, u);  // else u = 0 already
  if (force_control) rescale_to_force();

  double delta = 0;  // the approach
  double rz_previous = 0;
  bool have_direction = false, fresh = true;
  int iterations = 0;
  const int direct_limit = K.direct_limit();
  std::vector<std::pair<int, double>> clipped;
  const double* hp = h.data();
  for (;;) {
    // Working set S = {p > 0} U {g < 0}, the approach, and the residual r = -g on S (0 elsewhere).
    std::swap(ws.active, ws.previous_active);
    unsigned char* S = ws.active.data();
    const unsigned char* S_previous = ws.previous_active.data();
    if (force_control) {  // the approach seen by the current contact, then by the working set
      double sum = 0;
      int count = 0;
      for (int k = 0; k < n; ++k)
        if (p[k] > 0) sum += u[k] - hp[k], ++count;
      delta = sum / count;
    }
    bool changed = false;
    double error = 0, sum = 0;
    int count = 0;
    for (int k = 0; k < n; ++k) {
      const double g = u[k] - hp[k] - delta;
      const unsigned char in = p[k] > 0 || g < 0;
      S[k] = in;
      changed |= in != S_previous[k];
      r[k] = in ? -g : 0.0;
      sum += in ? u[k] - hp[k] : 0.0;
      count += in;
    }
    if (force_control) {  // re-centre on S: the residual has zero mean there
      const double shift = sum / count - delta;
      delta += shift;
      for (int k = 0; k < n; ++k) r[k] += S[k] ? shift : 0.0;
    }
    for (int k = 0; k < n; ++k) error = std::max(error, std::abs(r[k]));
    const double scale = hmax + delta;
    if (error <= options.tolerance * scale) {
      if (fresh) break;
      K.apply(p, u);  // incremental updates may have drifted: confirm with a fresh product
      fresh = true;
      continue;
    }
    if (iterations >= max_iterations)
      fail("NormalSolver::solve: no convergence in {} CG iterations on a {} x {} grid (max |gap| on the contact "
           "set {:.3g} of the penetration, tolerance {:.3g})",
           max_iterations, grid.nx, grid.ny, error / scale, options.tolerance);
    ++iterations;

    // Preconditioned residual z on S (zero mean on S for a prescribed force).
    if (options.precondition)
      K.invert(r, z);
    else
      z = r;
    double rz = 0, zsum = 0;
    for (int k = 0; k < n; ++k) {
      z[k] = S[k] ? z[k] : 0.0;
      rz += r[k] * z[k];
      zsum += z[k];
    }
    const double zmean = force_control ? zsum / count : 0.0;  // r sums to zero on S: rz is unchanged
    const double beta = have_direction && !changed ? rz / rz_previous : 0.0;
    for (int k = 0; k < n; ++k) d[k] = S[k] ? z[k] - zmean + beta * d[k] : 0.0;
    K.apply(d, q);
    double dq = 0;
    for (int k = 0; k < n; ++k) dq += d[k] * q[k];
    if (!(dq > 0) || !(rz > 0)) {  // lost to rounding at the end of convergence: restart afresh
      have_direction = false;
      K.apply(p, u);
      fresh = true;
      continue;
    }
    // Step, projection onto p >= 0, and the matching update of u = K p.
    const double alpha = rz / dq;
    clipped.clear();
    for (int k = 0; k < n; ++k) {
      const double v = p[k] + alpha * d[k];
      if (v < 0) clipped.emplace_back(k, -v);  // the projection adds -v back
      p[k] = std::max(v, 0.0);
      u[k] += alpha * q[k];
    }
    if (static_cast<int>(clipped.size()) > direct_limit) {
      K.apply(p, u);
      fresh = true;
    } else {
      for (const auto& [k, amount] : clipped) K.add_element(k, amount, u);
      fresh = false;
    }
    if (force_control && !clipped.empty()) rescale_to_force();
    rz_previous = rz;
    have_direction = true;
  }

  NormalSolution s;
  s.grid = grid;
  s.load = load;
  s.pressure = p;
  s.approach = force_control ? delta : 0.0;
  s.iterations = iterations;
  s.products = K.products;
  s.coarse_iterations = coarse_iterations;
  s.coarse_products = coarse_products;
  detail::finish_solution(s, u, h);
  return s;
}

NormalResponse NormalSolver::response(const NormalSolution& solution, std::span<const double> dh,
                                      NormalWorkspace& ws, double tolerance) const {
  detail::validate_response_input(solution, dh, "NormalSolver::response");
  if (!std::isfinite(tolerance) || !(tolerance > 0) || tolerance >= 1)
    fail("NormalSolver::response: tolerance {} must be in ]0, 1[", tolerance);
  const Grid& grid = solution.grid;
  const int n = grid.size();
  const bool force_control = solution.load.control == NormalLoad::Control::force;
  NormalResponse out;
  out.pressure.assign(n, 0.0);
  auto& A = ws.active;
  A.assign(n, 0);
  int count = 0;
  for (int k = 0; k < n; ++k) count += (A[k] = solution.pressure[k] > 0);
  if (count == 0) {
    detail::finish_response(out, grid);
    return out;
  }
  const auto spectrum = cache_.get(grid);
  const auto periodic = cache_.get(grid, InfluenceSpectrum::Kind::periodic);
  FftOperator K{*spectrum, *periodic, grid, 1.0 / (std::numbers::pi * material_.combined_modulus()), ws.fft};
  auto& x = out.pressure;
  auto& r = ws.r;
  auto& z = ws.z;
  auto& d = ws.d;
  auto& q = ws.q;
  for (auto* v : {&r, &z, &d, &q}) v->assign(n, 0.0);
  // Plain PCG on the fixed set (projected to sum dp = 0 for a prescribed force); x = 0 to start.
  double rhs_norm = 0, mean = 0;
  for (int k = 0; k < n; ++k)
    if (A[k]) mean += dh[k];
  mean = force_control ? mean / count : 0.0;
  for (int k = 0; k < n; ++k) {
    r[k] = A[k] ? dh[k] - mean : 0.0;
    rhs_norm = std::max(rhs_norm, std::abs(A[k] ? dh[k] : 0.0));
  }
  double dapproach = -mean;
  if (rhs_norm == 0) {
    detail::finish_response(out, grid);
    return out;
  }
  double rz_previous = 0;
  const int max_iterations = 2000;
  for (int it = 0;; ++it) {
    double error = 0;
    for (int k = 0; k < n; ++k) error = std::max(error, std::abs(r[k]));
    if (error <= tolerance * rhs_norm) break;
    if (it >= max_iterations)
      fail("NormalSolver::response: no convergence in {} CG iterations ({:.3g} of the perturbation)", max_iterations,
           error / rhs_norm);
    K.invert(r, z);
    double rz = 0, zsum = 0;
    for (int k = 0; k < n; ++k) {
      z[k] = A[k] ? z[k] : 0.0;
      rz += r[k] * z[k];
      zsum += z[k];
    }
    const double zmean = force_control ? zsum / count : 0.0;
    const double beta = it == 0 ? 0.0 : rz / rz_previous;
    for (int k = 0; k < n; ++k) d[k] = A[k] ? z[k] - zmean + beta * d[k] : 0.0;
    K.apply(d, q);
    double dq = 0;
    for (int k = 0; k < n; ++k) dq += d[k] * q[k];
    if (!(dq > 0) || !(rz > 0)) break;  // converged to rounding
    const double alpha = rz / dq;
    double rsum = 0;
    for (int k = 0; k < n; ++k) {
      x[k] += alpha * d[k];
      r[k] -= A[k] ? alpha * q[k] : 0.0;
      rsum += r[k];
    }
    if (force_control) {  // the approach absorbs the mean of the residual
      const double m = rsum / count;
      dapproach -= m;
      for (int k = 0; k < n; ++k) r[k] -= A[k] ? m : 0.0;
    }
    rz_previous = rz;
    out.iterations = it + 1;
  }
  out.approach = force_control ? dapproach : 0.0;
  detail::finish_response(out, grid);
  return out;
}

}  // namespace wrc::contact
