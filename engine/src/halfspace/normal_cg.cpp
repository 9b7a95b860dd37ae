// Fast normal solver: projected, preconditioned conjugate gradients on the active set with FFT products.
//
// The normal problem is the bound-constrained quadratic programme min 1/2 p.Kp - (h + approach).p, p >= 0
// (K = 2 D, symmetric positive definite), whose optimality conditions are the complementarity conditions
// of normal.hpp. The iteration (after Polonsky and Keer, Wear 231, 1999) runs CG on the working set
// S = {p > 0} U {p = 0 and g < 0}, projects p onto p >= 0 after every step, and restarts the conjugate
// directions (beta = 0) whenever S changes. For a prescribed force the approach is the Lagrange multiplier
// of sum w p dA = F (weights w, all 1 unless given): the residual and the search directions are kept orthogonal
// to w on S (zero mean for w = 1), so a step keeps the force, and a projection that clips pressures is followed
// by a rescaling to the force.
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
#include <optional>
#include <utility>

namespace wrc::halfspace {
namespace {

// K = factor * I applied by FFT (exact, zero-padded); the preconditioner is the inverse of the grid's
// periodic circulant.
struct FftOperator {
  const InfluenceSpectrum& spectrum;
  const InfluenceSpectrum& periodic;
  const Grid& grid;
  double factor;
  ConvolutionWorkspace& ws;
  ConvolutionWorkspace& ws_periodic;
  int products = 0;

  void apply(const std::vector<double>& x, std::vector<double>& y) {
    convolve(spectrum, grid, x.data(), y.data(), ws, factor);
    ++products;
  }
  void invert(const std::vector<double>& r, std::vector<double>& z) {
    deconvolve(periodic, grid, r.data(), z.data(), ws_periodic, 1.0 / factor);
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

std::shared_ptr<const InfluenceCache> shared_cache(FftPlanning planning) {
  static const auto estimate = std::make_shared<const InfluenceCache>(FftPlanning::estimate);
  static const auto measure = std::make_shared<const InfluenceCache>(FftPlanning::measure);
  return planning == FftPlanning::measure ? measure : estimate;
}

NormalSolver::NormalSolver(const Material& material, FftPlanning planning)
    : material_(material), cache_(shared_cache(planning)) {
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

// The start of a solve: the pressure to start from (empty: none) and the work done on coarser grids for it.
struct Start {
  std::vector<double> pressure;
  std::vector<double> displacement;  // u = D pressure where known (NaN elsewhere), or empty
  int iterations = 0, products = 0;
  double approach = 0;  // the coarse solution's (nested start, prescribed force)
  bool nested = false;
};

// Nested start: the coarse grid's solution, interpolated, is a start whose contact set is right to a coarse
// element or two, so the fine grid mostly runs the CG's converging phase. Otherwise the warm start if given.
// solve_coarse(coarse grid, its h, its load, its options) is the solver itself, one level down.
template <class SolveCoarse>
Start make_start(const Grid& grid, std::span<const double> h, const NormalLoad& load, const NormalOptions& options,
                 SolveCoarse&& solve_coarse) {
  Start start;
  if (options.initial_pressure.empty() && options.nested && grid.size() > options.coarse_limit && grid.nx >= 4 &&
      grid.ny >= 4) {
    const Grid coarse = coarse_grid(grid);
    const std::vector<double> hc = restrict_to(grid, coarse, h);
    NormalLoad coarse_load = load;
    if (!load.weights.empty()) coarse_load.weights = restrict_to(grid, coarse, load.weights);
    if (!load.gap_weights.empty()) coarse_load.gap_weights = restrict_to(grid, coarse, load.gap_weights);
    NormalOptions coarse_options = options;
    coarse_options.estimate = false;
    coarse_options.tolerance = std::max(options.tolerance, 1e-2);  // a start only: the coarse grid's own
                                                                   // discretisation error is of this order
    const NormalSolution sc = solve_coarse(coarse, hc, coarse_load, coarse_options);
    start.iterations = sc.iterations + sc.coarse_iterations;
    start.products = sc.products + sc.coarse_products;
    start.approach = sc.approach;
    start.nested = true;
    if (sc.force > 0) {
      start.pressure.resize(grid.size());
      prolong(coarse, sc.pressure, grid, start.pressure);
    }
  } else if (!options.initial_pressure.empty()) {
    start.pressure.assign(options.initial_pressure.begin(), options.initial_pressure.end());
    start.displacement.assign(options.initial_displacement.begin(), options.initial_displacement.end());
  }
  return start;
}

// The CG's vector kernels, kept out of line: inlined into the solver, their sums were spilled to the stack at every
// element for want of registers. Sums run in four partial sums (independent chains of additions).
[[gnu::noinline]] double dot(const double* a, const double* b, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int k = 0;
  for (; k + 4 <= n; k += 4) s0 += a[k] * b[k], s1 += a[k + 1] * b[k + 1], s2 += a[k + 2] * b[k + 2], s3 += a[k + 3] * b[k + 3];
  for (; k < n; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

// z = z on S, 0 elsewhere.
[[gnu::noinline]] void mask(const unsigned char* S, double* z, int n) {
  for (int k = 0; k < n; ++k) z[k] = S[k] ? z[k] : 0.0;
}

// In one pass: r.z (r is 0 off S) and w.z over S.
[[gnu::noinline]] void dots_on_set(const double* r, const double* z, const double* w, const unsigned char* S, int n,
                                   double& rz, double& wz) {
  double a0 = 0, a1 = 0, b0 = 0, b1 = 0;
  int k = 0;
  for (; k + 2 <= n; k += 2) {
    a0 += r[k] * z[k], a1 += r[k + 1] * z[k + 1];
    b0 += S[k] ? w[k] * z[k] : 0.0, b1 += S[k + 1] ? w[k + 1] * z[k + 1] : 0.0;
  }
  for (; k < n; ++k) a0 += r[k] * z[k], b0 += S[k] ? w[k] * z[k] : 0.0;
  rz = a0 + a1, wz = b0 + b1;
}

// The projected CG on one grid (see the top of the file), on the workspace's vectors: p the pressure, u = K p,
// r the residual, z the preconditioned residual, d the search direction, q = K d.
class ProjectedCg {
 public:
  ProjectedCg(FftOperator& K, const Grid& grid, std::span<const double> h, const NormalLoad& load,
              NormalWorkspace& ws)
      : K_(K), grid_(grid), h_(h), load_(load), force_control_(load.control == NormalLoad::Control::force),
        n_(grid.size()), dA_(grid.element_area()), direct_limit_(K.direct_limit()), ws_(ws), p_(ws.p), u_(ws.u),
        r_(ws.r), z_(ws.z), d_(ws.d), q_(ws.q) {
    for (auto* v : {&p_, &d_}) v->assign(n_, 0.0);  // the others are written before they are read
    for (auto* v : {&u_, &r_, &z_, &q_}) v->resize(n_);
    if (force_control_) {
      w_ = load.weights.empty() ? std::vector<double>(n_, 1.0) : load.weights;
      g_ = load.gap_weights.empty() ? w_ : load.gap_weights;
    }
    ws_.active.assign(n_, 0);
    ws_.previous_active.assign(n_, 0);
  }

  void start(const std::vector<double>& pressure, const std::vector<double>& displacement);
  // Iterates until the gap on the working set is within options.tolerance of the penetration max(h + approach gw)
  // (confirmed on a fresh product unless the caller confirms it on its own); throws wrc::Error after the iteration
  // limit.
  void run(const NormalOptions& options, double hmax, bool confirm);

  double approach() const { return delta_; }
  int iterations() const { return iterations_; }

 private:
  struct Residual {
    bool changed;  // the working set differs from the previous iteration's
    double error;  // max |r|
  };
  Residual update_working_set();
  bool find_direction(const Residual& res, bool precondition, double& rz, double& dq);
  void take_step(double alpha);
  void rescale_to_force();

  FftOperator& K_;
  const Grid& grid_;
  std::span<const double> h_;
  const NormalLoad& load_;
  const bool force_control_;
  const int n_;
  const double dA_;
  const int direct_limit_;  // clipped elements up to this count are added back by direct sums
  NormalWorkspace& ws_;
  std::vector<double>&p_, &u_, &r_, &z_, &d_, &q_;
  std::vector<double> w_, g_;  // the force's weights and the approach's on the gap (force control)
  double ww_ = 0;              // sum of w^2 on S
  double delta_ = 0;  // the approach
  // max(h + approach gw): the penetration the convergence test scales with. Not max h + approach: where the deepest
  // element's gap weight is below 1 (a flange row's n_z under a vertical force), that is negative once the approach
  // lifts the wheel by more than max h, and no gap could ever meet the test (a trajectory's wheel step from the last
  // step's deeper approach ran into the iteration limit so).
  double penetration_ = 0;
  double rz_previous_ = 0;
  bool have_direction_ = false, fresh_ = true;  // fresh: u = K p by a product, not by updates
  int iterations_ = 0;
  std::vector<std::pair<int, double>> clipped_;
};

// A prescribed force is kept by scaling p (and u = K p with it).
void ProjectedCg::rescale_to_force() {
  const double f = load_.force / (dot(w_.data(), p_.data(), n_) * dA_);
  for (int k = 0; k < n_; ++k) p_[k] *= f, u_[k] *= f;
}

// The warm or nested start, else nothing (penetration) or a uniform pressure on {h > 0} (force). u = K p is the
// start's own displacement where it is given for every element (a warm start's reuse), else a product.
void ProjectedCg::start(const std::vector<double>& pressure, const std::vector<double>& displacement) {
  bool given = false;
  for (std::size_t k = 0; k < pressure.size(); ++k) p_[k] = std::max(0.0, pressure[k]), given |= p_[k] > 0;
  if (given && displacement.size() == static_cast<std::size_t>(n_) &&
      std::all_of(displacement.begin(), displacement.end(), [](double v) { return std::isfinite(v); })) {
    std::copy(displacement.begin(), displacement.end(), u_.begin());
    if (force_control_) rescale_to_force();
    return;
  }
  if (force_control_) {
    double sum = 0;
    for (double v : p_) sum += v;
    if (!(sum > 0)) {
      int count = 0;
      for (int k = 0; k < n_; ++k) count += h_[k] > 0;
      if (count > 0) {
        for (int k = 0; k < n_; ++k) p_[k] = h_[k] > 0 ? 1.0 : 0.0;
      } else {
        p_[std::max_element(h_.begin(), h_.end()) - h_.begin()] = 1.0;
      }
    }
  }
  if (std::any_of(p_.begin(), p_.end(), [](double v) { return v > 0; }))
    K_.apply(p_, u_);
  else
    std::fill(u_.begin(), u_.end(), 0.0);
  if (force_control_) rescale_to_force();
}

// Working set S = {p > 0} U {g < 0}, the approach, and the residual r = -g on S (0 elsewhere). The loops read and
// write through local pointers: a store to S (unsigned char) may alias anything, and through the vectors it would
// make the compiler reload every vector's data pointer at every element.
ProjectedCg::Residual ProjectedCg::update_working_set() {
  std::swap(ws_.active, ws_.previous_active);
  unsigned char* S = ws_.active.data();
  const unsigned char* S_previous = ws_.previous_active.data();
  const double *hp = h_.data(), *p = p_.data(), *u = u_.data();
  double* r = r_.data();
  const int n = n_;
  Residual res{false, 0.0};
  double error = 0;
  int changed = 0;
  if (!force_control_) {  // g = u - h
    for (int k = 0; k < n; ++k) {
      const double e = u[k] - hp[k];
      const bool in = p[k] > 0 || e < 0;
      S[k] = in;
      changed |= in != S_previous[k];
      r[k] = in ? -e : 0.0;
      error = std::max(error, std::abs(r[k]));
    }
    res.changed = changed;
    res.error = error;
    return res;
  }
  // g = u - h - delta gw (gw: the gap weights, w unless given). The approach seen by the current contact (least
  // squares of u - h = delta gw on it), then re-centred on the working set, where the residual is made orthogonal
  // to w (the directions keep sum w p; with gw != w the projection along gw is oblique, which CG tolerates for
  // gw within a few per cent of w).
  const double *w = w_.data(), *gw = g_.data();
  double we = 0, wg = 0;
  for (int k = 0; k < n; ++k)
    if (p[k] > 0) we += gw[k] * (u[k] - hp[k]), wg += gw[k] * gw[k];
  delta_ = we / wg;
  const double delta = delta_;
  double ww = 0;
  we = 0, wg = 0;
  for (int k = 0; k < n; ++k) {
    const double e = u[k] - hp[k];
    const bool in = p[k] > 0 || e < delta * gw[k];
    S[k] = in;
    changed |= in != S_previous[k];
    r[k] = in ? delta * gw[k] - e : 0.0;
    we += in ? w[k] * e : 0.0;
    wg += in ? w[k] * gw[k] : 0.0;
    ww += in ? w[k] * w[k] : 0.0;
  }
  const double shift = we / wg - delta_;
  delta_ += shift;
  ww_ = ww;
  double reach = -INFINITY;
  for (int k = 0; k < n; ++k) {
    r[k] += S[k] ? shift * gw[k] : 0.0;
    error = std::max(error, std::abs(r[k]));
    reach = std::max(reach, hp[k] + delta_ * gw[k]);
  }
  penetration_ = reach;
  res.changed = changed;
  res.error = error;
  return res;
}

// Preconditioned residual z on S (orthogonal to w on S for a prescribed force), the conjugate direction d
// (restarted when S changed) and q = K d. Returns false if rz or dq lost their sign to rounding.
bool ProjectedCg::find_direction(const Residual& res, bool precondition, double& rz, double& dq) {
  if (precondition)
    K_.invert(r_, z_);
  else
    z_ = r_;
  // z counts on S only: r is 0 off S, and the direction takes z on S.
  const unsigned char* S = ws_.active.data();
  double *z = z_.data(), *d = d_.data();
  const int n = n_;
  double wz = 0;
  if (force_control_)
    dots_on_set(r_.data(), z, w_.data(), S, n, rz, wz);
  else
    rz = dot(r_.data(), z, n);
  const double beta = have_direction_ && !res.changed ? rz / rz_previous_ : 0.0;
  if (force_control_) {  // z minus its part along w (r is orthogonal to w on S: rz is unchanged)
    const double c = wz / ww_, *w = w_.data();
    for (int k = 0; k < n; ++k) d[k] = S[k] ? z[k] - c * w[k] + beta * d[k] : 0.0;
  } else {
    for (int k = 0; k < n; ++k) d[k] = S[k] ? z[k] + beta * d[k] : 0.0;
  }
  K_.apply(d_, q_);
  dq = dot(d, q_.data(), n);
  return dq > 0 && rz > 0;
}

// Step, projection onto p >= 0, and the matching update of u = K p: the clipped elements are added back by
// direct sums when few, else u is recomputed by a product.
void ProjectedCg::take_step(double alpha) {
  clipped_.clear();
  double *p = p_.data(), *u = u_.data();
  const double *d = d_.data(), *q = q_.data();
  for (int k = 0; k < n_; ++k) {
    const double v = p[k] + alpha * d[k];
    if (v < 0) clipped_.emplace_back(k, -v);  // the projection adds -v back
    p[k] = std::max(v, 0.0);
    u[k] += alpha * q[k];
  }
  if (static_cast<int>(clipped_.size()) > direct_limit_) {
    K_.apply(p_, u_);
    fresh_ = true;
  } else {
    for (const auto& [k, amount] : clipped_) K_.add_element(k, amount, u_);
    fresh_ = false;
  }
  if (force_control_ && !clipped_.empty()) rescale_to_force();
}

void ProjectedCg::run(const NormalOptions& options, double hmax, bool confirm) {
  const int max_iterations = options.max_iterations > 0 ? options.max_iterations : 2000;
  for (;;) {
    const Residual res = update_working_set();
    const double scale = force_control_ ? penetration_ : hmax;
    if (res.error <= options.tolerance * scale) {
      if (fresh_ || !confirm) break;
      K_.apply(p_, u_);  // incremental updates may have drifted: confirm with a fresh product
      fresh_ = true;
      continue;
    }
    if (iterations_ >= max_iterations)
      fail("NormalSolver::solve: no convergence in {} CG iterations on a {} x {} grid (max |gap| on the contact "
           "set {:.3g} of the penetration, tolerance {:.3g})",
           max_iterations, grid_.nx, grid_.ny, res.error / scale, options.tolerance);
    ++iterations_;
    double rz, dq;
    if (!find_direction(res, options.precondition, rz, dq)) {  // lost to rounding at the end of convergence:
      have_direction_ = false;                                  // restart afresh
      K_.apply(p_, u_);
      fresh_ = true;
      continue;
    }
    take_step(rz / dq);
    rz_previous_ = rz;
    have_direction_ = true;
  }
}

}  // namespace

NormalSolution NormalSolver::solve(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                                   NormalWorkspace& ws, const NormalOptions& options) const {
  validate_normal_input(material_, grid, h, load, options, "NormalSolver::solve");
  return solve_checked(grid, h, load, ws, options);
}

namespace {

// A rectangle of a grid's elements, [i0, i1] x [j0, j1], and the grid of just those elements.
struct Window {
  int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
  int size() const { return (i1 - i0 + 1) * (j1 - j0 + 1); }
  Grid of(const Grid& g) const {
    Grid w = g;
    w.nx = i1 - i0 + 1;
    w.ny = j1 - j0 + 1;
    w.x0 = g.x(i0);
    w.y0 = g.y(j0);
    return w;
  }
  void extend(int i, int j) {
    if (i1 < i0) {
      i0 = i1 = i, j0 = j1 = j;
      return;
    }
    i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  }
  void dilate(const Grid& g, int margin) {
    if (i1 < i0) return;  // empty: stays so (a start without pressure solves on the whole grid)
    i0 = std::max(0, i0 - margin), j0 = std::max(0, j0 - margin);
    i1 = std::min(g.nx - 1, i1 + margin), j1 = std::min(g.ny - 1, j1 + margin);
  }
};

// The window holding the elements where v > 0 (empty: none).
Window support(const Grid& g, std::span<const double> v) {
  Window w;
  if (v.empty()) return w;
  for (int j = 0; j < g.ny; ++j) {  // per row, its first and last element > 0, scanning in from both ends
    const double* row = v.data() + g.index(0, j);
    int first = 0, last = g.nx - 1;
    while (first < g.nx && !(row[first] > 0)) ++first;
    if (first == g.nx) continue;
    while (!(row[last] > 0)) --last;
    w.extend(first, j);
    w.extend(last, j);
  }
  return w;
}

// The window's values of a grid vector, and back (the rest zero).
std::vector<double> cut(const Grid& g, const Window& w, std::span<const double> v) {
  std::vector<double> out;
  out.reserve(w.size());
  for (int j = w.j0; j <= w.j1; ++j)
    for (int i = w.i0; i <= w.i1; ++i) out.push_back(v[g.index(i, j)]);
  return out;
}

void paste(const Grid& g, const Window& w, std::span<const double> in, std::vector<double>& v) {
  v.assign(g.size(), 0.0);
  std::size_t k = 0;
  for (int j = w.j0; j <= w.j1; ++j)
    for (int i = w.i0; i <= w.i1; ++i) v[g.index(i, j)] = in[k++];
}

// Solving on a window pays when it leaves out at least this share of the grid's elements.
constexpr double kWindowGain = 0.25;
// Elements around the start's contact set that the window keeps. A coarse start places the contact edge to a coarse
// element or two, a warm start from a neighbouring pose to a fine element or so; a window that misses some is
// widened from what it found (a retry costs a few iterations and a product). Measured (callgrind instructions of
// bench_online): margin 2 against 4 saves 3.5 % of cold and warm evaluations, 7 % along a trajectory and 3 % of
// ws:wheel; margin 1 fails windows at the flange root.
constexpr int kWindowMargin = 2;

}  // namespace

namespace {

// The projected CG on the whole of `grid` from `start`.
// `window`: the grid is a window that solve_window checks by a product on the whole grid, which confirms the
// CG's convergence as well (no confirming product here) and gives the solution's summaries (none here).
NormalSolution solve_grid(const InfluenceCache& cache, double factor, const Grid& grid, std::span<const double> h,
                          const NormalLoad& load, NormalWorkspace& ws, const NormalOptions& options, const Start& start,
                          double hmax, bool window = false) {
  const auto spectrum = cache.get(grid);
  const auto periodic = cache.get(grid, InfluenceSpectrum::Kind::periodic);
  FftOperator K{*spectrum, *periodic, grid, factor, ws.fft, ws.fft_periodic};
  ProjectedCg cg(K, grid, h, load, ws);
  cg.start(start.pressure, start.displacement);
  cg.run(options, hmax, !window);

  NormalSolution s;
  s.grid = grid;
  s.load = load;
  s.pressure = ws.p;
  s.approach = load.control == NormalLoad::Control::force ? cg.approach() : 0.0;
  s.iterations = cg.iterations();
  s.products = K.products;
  s.coarse_iterations = start.iterations;
  s.coarse_products = start.products;
  if (!window) {
    detail::finish_solution(s, ws.u, h);
    s.displacement = ws.u;
  }
  return s;
}

// max(h + approach gw) over the grid: the penetration the convergence tests scale with (ProjectedCg::penetration_).
double penetration(std::span<const double> h, const NormalLoad& load, double approach, double hmax) {
  if (load.control != NormalLoad::Control::force) return hmax;
  double reach = -INFINITY;
  for (std::size_t k = 0; k < h.size(); ++k) reach = std::max(reach, h[k] + approach * load.gap_weight(k));
  return reach;
}

// The solve on a window of the grid, checked on the whole grid by one product: the solution of the whole grid
// when no element outside the window penetrates (its gap below -tolerance x max(h + approach gw), the condition the
// CG itself enforces), else nothing, those elements in `penetrating` and the window's solution on the whole grid in
// `pressure` (the start of the next attempt). The same product confirms the CG's convergence inside the window,
// which its incremental updates of K p may have drifted from (then it is solved again from there, confirming on its
// own).
std::optional<NormalSolution> solve_window(const InfluenceCache& cache, double factor, const Grid& grid,
                                           std::span<const double> h, const NormalLoad& load, NormalWorkspace& ws,
                                           const NormalOptions& options, const Window& w, const Start& start,
                                           double hmax, std::vector<double>& pressure, std::vector<int>& penetrating) {
  const Grid sub = w.of(grid);
  const std::vector<double> hs = cut(grid, w, h);
  NormalLoad sub_load = load;
  if (!load.weights.empty()) sub_load.weights = cut(grid, w, load.weights);
  if (!load.gap_weights.empty()) sub_load.gap_weights = cut(grid, w, load.gap_weights);
  Start sub_start{start.pressure.empty() ? std::vector<double>{} : cut(grid, w, start.pressure),
                  start.displacement.empty() ? std::vector<double>{} : cut(grid, w, start.displacement),
                  start.iterations, start.products};
  NormalSolution s;
  s.grid = grid;
  s.load = load;
  for (int attempt = 0;; ++attempt) {
    const NormalSolution part = solve_grid(cache, factor, sub, hs, sub_load, ws, options, sub_start, hmax, attempt == 0);
    s.approach = part.approach;
    s.iterations += part.iterations;
    s.products += part.products + 1;
    s.coarse_iterations = part.coarse_iterations;
    s.coarse_products = part.coarse_products;
    paste(grid, w, part.pressure, pressure);
    std::vector<double>& u = ws.u;
    u.resize(grid.size());
    convolve(*cache.get(grid), grid, pressure.data(), u.data(), ws.fft, factor);
    penetrating.clear();
    const double bound = options.tolerance * penetration(h, load, s.approach, hmax);
    bool drifted = false;
    auto gap = [&](int k) { return u[k] - h[k] - s.approach * load.gap_weight(static_cast<std::size_t>(k)); };
    auto outside = [&](int k0, int k1) {  // elements [k0, k1) outside the window: those that penetrate
      for (int k = k0; k < k1; ++k)
        if (gap(k) < -bound) penetrating.push_back(k);
    };
    for (int j = 0; j < grid.ny; ++j) {
      const int row = grid.index(0, j);
      if (j < w.j0 || j > w.j1) {
        outside(row, row + grid.nx);
        continue;
      }
      outside(row, row + w.i0);
      for (int k = row + w.i0; k <= row + w.i1; ++k) {
        const double g = gap(k);
        drifted |= pressure[k] > 0 ? std::abs(g) > bound : g < -bound;
      }
      outside(row + w.i1 + 1, row + grid.nx);
    }
    if (!penetrating.empty()) return std::nullopt;
    if (drifted && attempt == 0) {
      sub_start.pressure = part.pressure;
      sub_start.displacement = cut(grid, w, u);
      continue;
    }
    s.pressure = std::move(pressure);
    detail::finish_solution(s, u, h);
    s.displacement = u;
    return s;
  }
}

// The nested start as the solution (NormalOptions::estimate): its pressure, the coarse approach, and the gaps of
// one product.
NormalSolution estimate(const InfluenceCache& cache, const Grid& grid, std::span<const double> h,
                        const NormalLoad& load, NormalWorkspace& ws, double factor, Start& start) {
  NormalSolution s;
  s.grid = grid;
  s.load = load;
  s.pressure = std::move(start.pressure);
  s.approach = load.control == NormalLoad::Control::force ? start.approach : 0.0;
  s.products = 1;
  s.coarse_iterations = start.iterations;
  s.coarse_products = start.products;
  ws.u.resize(grid.size());
  convolve(*cache.get(grid), grid, s.pressure.data(), ws.u.data(), ws.fft, factor);
  detail::finish_solution(s, ws.u, h);
  s.displacement = ws.u;
  return s;
}

}  // namespace

NormalSolution NormalSolver::solve_checked(const Grid& grid, std::span<const double> h, const NormalLoad& load,
                                           NormalWorkspace& ws, const NormalOptions& options) const {
  const bool force_control = load.control == NormalLoad::Control::force;
  const double hmax = *std::max_element(h.begin(), h.end());
  if ((force_control && load.force == 0) || (!force_control && hmax <= 0)) return detail::zero_solution(grid, h, load);

  Start start = make_start(grid, h, load, options, [&](const Grid& coarse, std::span<const double> hc,
                                                       const NormalLoad& coarse_load, const NormalOptions& coarse_options) {
    return solve_checked(coarse, hc, coarse_load, ws, coarse_options);
  });
  const double factor = material_.pair_compliance();
  if (options.estimate && start.nested && !start.pressure.empty())
    return estimate(*cache_, grid, h, load, ws, factor, start);
  // The contact lies where the start says, to a few elements: solve on that window, check the whole grid (one
  // product) and widen the window to the elements that would penetrate, starting from what was found.
  Window w = support(grid, start.pressure);
  w.dilate(grid, kWindowMargin);
  std::vector<int> penetrating;
  std::vector<double> found;
  for (int attempt = 0; attempt < 3 && w.size() > 0 && w.size() <= (1 - kWindowGain) * grid.size(); ++attempt) {
    if (auto s = solve_window(*cache_, factor, grid, h, load, ws, options, w, start, hmax, found, penetrating)) return std::move(*s);
    for (int k : penetrating) w.extend(k % grid.nx, k / grid.nx);
    w.dilate(grid, kWindowMargin);
    start.pressure = found;
    start.displacement = ws.u;  // the check's product: u of `found` on the whole grid
  }
  return solve_grid(*cache_, factor, grid, h, load, ws, options, start, hmax);
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
  const auto spectrum = cache_->get(grid);
  const auto periodic = cache_->get(grid, InfluenceSpectrum::Kind::periodic);
  FftOperator K{*spectrum, *periodic, grid, material_.pair_compliance(), ws.fft, ws.fft_periodic};
  auto& x = out.pressure;
  auto& r = ws.r;
  auto& z = ws.z;
  auto& d = ws.d;
  auto& q = ws.q;
  for (auto* v : {&r, &z, &d, &q}) v->assign(n, 0.0);
  // Plain PCG on the fixed set (projected to sum w dp = 0 for a prescribed force, with the force's weights w);
  // x = 0 to start. along_w(v): the factor of v's part along w on the set; absorbed(v): the approach change that
  // leaves v orthogonal to w once it moves the gap by that times the gap weights gw (= along_w for gw = w).
  const NormalLoad& load = solution.load;
  double ww = 0, wg = 0;
  if (force_control)
    for (int k = 0; k < n; ++k)
      if (A[k]) ww += load.weight(k) * load.weight(k), wg += load.weight(k) * load.gap_weight(k);
  auto along_w = [&](const std::vector<double>& v) {
    if (!force_control) return 0.0;
    double s = 0;
    for (int k = 0; k < n; ++k) s += A[k] ? load.weight(k) * v[k] : 0.0;
    return s / ww;
  };
  auto absorbed = [&](const std::vector<double>& v) { return force_control ? along_w(v) * ww / wg : 0.0; };
  double rhs_norm = 0;
  for (int k = 0; k < n; ++k) {
    r[k] = A[k] ? dh[k] : 0.0;
    rhs_norm = std::max(rhs_norm, std::abs(r[k]));
  }
  const double mean = absorbed(r);
  for (int k = 0; k < n; ++k) r[k] -= A[k] ? mean * load.gap_weight(k) : 0.0;
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
    mask(A.data(), z.data(), n);
    const double rz = dot(r.data(), z.data(), n);  // out of line: inlined here, the sum lived on the stack
    const double zw = along_w(z);
    const double beta = it == 0 ? 0.0 : rz / rz_previous;
    for (int k = 0; k < n; ++k) d[k] = A[k] ? z[k] - zw * load.weight(k) + beta * d[k] : 0.0;
    K.apply(d, q);
    const double dq = dot(d.data(), q.data(), n);
    if (!(dq > 0) || !(rz > 0)) break;  // converged to rounding
    const double alpha = rz / dq;
    for (int k = 0; k < n; ++k) {
      x[k] += alpha * d[k];
      r[k] -= A[k] ? alpha * q[k] : 0.0;
    }
    if (force_control) {  // the approach absorbs the residual's part along w
      const double m = absorbed(r);
      dapproach -= m;
      for (int k = 0; k < n; ++k) r[k] -= A[k] ? m * load.gap_weight(k) : 0.0;
    }
    rz_previous = rz;
    out.iterations = it + 1;
  }
  out.approach = force_control ? dapproach : 0.0;
  detail::finish_response(out, grid);
  return out;
}

}  // namespace wrc::halfspace
