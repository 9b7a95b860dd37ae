// The Newton-GMRES core of the steady-rolling solver (rolling.hpp): one grid level.
//
// Unknowns: the traction p_k of every contact element k (two components, interleaved). Slip per |V|:
// s = w + M p with M = -D B (D the upwind difference along the rolling direction, B the tangential influence).
// At the current adhesion / slip split the equations are
//   adhesion k:  s_k = 0                                  (two equations)
//   slip k:      t_k . s_k = 0,  e_k . p_k = g_k           (the traction along e_k, t_k = e_k turned by +90 deg)
// and their linearisation (the slip direction turns with the traction: d e = t (t . dp) / g) is
//   adhesion:  (M dp)_k = -s_k
//   slip:      t . (M dp)_k + c_k t . dp_k = -t . s_k,  e . dp_k = g_k - |p_k|,   c_k = -(e . s_k) / |p_k| >= 0.
// After each step the split is updated: adhesion elements whose traction exceeds mu_s p_n start to slip; slip
// elements whose slip runs along their traction (e . s > 0) adhere. The step's slip change M dp comes from GMRES (the
// combination of its products that dp is), so s = w + M p follows without a product. While the split moves, the
// slip tractions are put back on the bound (|p + dp| = sqrt(g^2 + (t . dp)^2) after a step) and their slip is a
// product; once it has settled (the steps that finish a warm start along a trajectory) they stay off it by that
// second-order amount, which the convergence measure includes and the next step's bound equation removes, and are
// put on it at the end. Measured: putting them back only at the end fails to converge on partial-slip patches (the
// split cycles); along bench_online's section 6 at 0.2 mm the settled steps save 0.8 of 19.6 products per solve.
// Friction falling with the slip velocity: the bound g_k = mu(|V| sigma_k) p_n of a slip element depends on its slip
// magnitude sigma_k = -e . s_k (per |V|). It is taken at the slip of the last iterate (a fixed point on the bounds
// inside the Newton iteration on the split), and its change joins the convergence measure, in slip units (times M's
// diagonal). Why not Newton on it too (the bound equation e . dp + g' e . (M dp) = g - |p|): measured on S1002/60E1,
// that cycled between adhesion and slip at leading-edge elements, where the element's own elastic slip K g is as
// large as the rigid slip and a steep law makes 1 + g' K small or negative, in cases the fixed point solves in 2-9
// iterations. Where the law falls steeply enough (|d mu / dw| |V| beyond about 12, e.g. Polach's B = 3 s/m at 30
// m/s) the discrete problem has several solutions at those elements and neither converges: the solve fails with
// its message (docs/guide/rolling.md).
//
// Why this preconditioner (measured on Hertzian patches of 300 to 2,500 elements, partial slip): a sweep from the
// leading edge with each element's own and upstream coupling needed 15-19 GMRES iterations per Newton step, growing
// with the grid; adding lateral or second-upstream neighbours made it worse (the odd kernel truncated one-sidedly);
// inverting the upwind difference exactly (a sum along the row) and B by its periodic circulant on the adhesion
// elements, with the sweep on the slip elements, needs 8-12 and grows little.
#include "rolling_internal.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace wrc::halfspace::detail {
namespace {

// A settled step's GMRES reduces its residual (2-norm, all elements) to kForcing tolerance / err, err the convergence
// measure (max-norm, relative): a step that then misses the tolerance costs one more Newton step. Measured along
// bench_online's section 6 at 0.2 mm (403 solves): 0.3 -> 917 Newton steps, 18.8 products per solve; 0.5 -> 915,
// 18.1; 0.7 -> 924, 17.8; 1.0 -> 959, 17.9.
constexpr double kForcing = 0.7;
// ... but no looser than kLoosest: a settled step of a loose solve (the load loop's first, to 1e-4, from ~2e-4) then
// lands near its tolerance instead of ~10x below it (the GMRES of such a step was held to 0.1 before: along that
// section at 0.2 mm over 667 steps 30.1 -> 29.5 products and 25.1 -> 24.5 GMRES iterations per step, the evaluations
// unchanged; 1.0: 29.5 and 24.4).
constexpr double kLoosest = 0.5;

// Products with B on a level's cropped grid and the slip operator M = -D B on its contact elements.
class SlipOperator {
 public:
  SlipOperator(const Level& level, const ShearSpectrum& linear, const ShearSpectrum& periodic, RollingWorkspace& ws)
      : L_(level), linear_(linear), periodic_(periodic), ws_(ws) {
    const auto n = static_cast<std::size_t>(level.field.grid.size());
    for (auto* v : {&ws.qx, &ws.qy, &ws.ux, &ws.uy}) v->assign(n, 0.0);
  }
  int products = 0;

  // out = M v (v, out: 2 values per contact element).
  void apply(const double* v, double* out) {
    scatter(v);
    shear_convolve(linear_, L_.field.grid, ws_.qx.data(), ws_.qy.data(), ws_.ux.data(), ws_.uy.data(), ws_.fft);
    ++products;
    const double inv_dx = 1.0 / L_.field.grid.dx;
    const int d = L_.direction;
    for (int k = 0; k < L_.size(); ++k) {
      const int c = L_.cell[static_cast<std::size_t>(k)];
      out[2 * k] = -(ws_.ux[static_cast<std::size_t>(c + d)] - ws_.ux[static_cast<std::size_t>(c)]) * inv_dx;
      out[2 * k + 1] = -(ws_.uy[static_cast<std::size_t>(c + d)] - ws_.uy[static_cast<std::size_t>(c)]) * inv_dx;
    }
  }
  // s = w + M p.
  void slip(const double* p, double* s) {
    apply(p, s);
    for (int k = 0; k < L_.size(); ++k) {
      s[2 * k] += L_.wx[static_cast<std::size_t>(k)];
      s[2 * k + 1] += L_.wy[static_cast<std::size_t>(k)];
    }
  }
  // The preconditioner's grid arrays (px, py) -> C^-1 (px, py) in place (the periodic circulant of B, inverted).
  // They share the products' output buffers, which no product needs between two calls.
  void deconvolve_in_place() {
    shear_deconvolve(periodic_, L_.field.grid, ws_.ux.data(), ws_.uy.data(), ws_.ux.data(), ws_.uy.data(),
                     ws_.fft_periodic);
  }
  std::vector<double>& px() { return ws_.ux; }
  std::vector<double>& py() { return ws_.uy; }

 private:
  // The product's input: zero outside the contact elements since construction, so only they are written.
  void scatter(const double* v) {
    for (int k = 0; k < L_.size(); ++k) {
      const auto c = static_cast<std::size_t>(L_.cell[static_cast<std::size_t>(k)]);
      ws_.qx[c] = v[2 * k];
      ws_.qy[c] = v[2 * k + 1];
    }
  }
  const Level& L_;
  const ShearSpectrum& linear_;
  const ShearSpectrum& periodic_;
  RollingWorkspace& ws_;
};

// The 2 x 2 diagonal of M: K = (B(0, 0) - B(1, 0)) / dx, and M's upstream block -K (B_xy vanishes on the x axis).
struct LocalBlocks {
  double kx = 0, ky = 0;
};
LocalBlocks local_blocks(const Material& material, const Grid& grid) {
  const ShearInfluenceTable t(material, grid.dx, grid.dy, 2, 1);
  return {(t.xx(0, 0) - t.xx(1, 0)) / grid.dx, (t.yy(0, 0) - t.yy(1, 0)) / grid.dx};
}

// The linearisation at the current split: Jacobian products and the preconditioner.
class Linearisation {
 public:
  Linearisation(const Level& level, SlipOperator& op, const LocalBlocks& K, const LevelState& st,
                const std::vector<double>& s)
      : L_(level), op_(op), K_(K), st_(st), c_(static_cast<std::size_t>(level.size()), 0.0),
        ex_(c_.size(), 0.0), ey_(c_.size(), 0.0), mag_(c_.size(), 0.0) {
    for (int k = 0; k < L_.size(); ++k) {
      const auto q = static_cast<std::size_t>(k);
      if (st_.state[q] != kSlip) continue;
      mag_[q] = std::sqrt(st_.px[q] * st_.px[q] + st_.py[q] * st_.py[q]);
      ex_[q] = st_.px[q] / mag_[q];
      ey_[q] = st_.py[q] / mag_[q];
      c_[q] = std::max(0.0, -(ex_[q] * s[2 * k] + ey_[q] * s[2 * k + 1])) / mag_[q];
    }
    set_sweep();
  }
  // The right-hand side -F of the step (a slip traction off the bound is brought back to it).
  void rhs(const std::vector<double>& s, double* b) const {
    for (int k = 0; k < L_.size(); ++k) {
      const auto q = static_cast<std::size_t>(k);
      if (st_.state[q] == kSlip) {
        b[2 * k] = -(-dir_y(k) * s[2 * k] + dir_x(k) * s[2 * k + 1]);
        b[2 * k + 1] = kappa() * ((L_.falling() ? st_.bound[q] : L_.gk[q]) - mag_[q]);
      } else {
        b[2 * k] = -s[2 * k];
        b[2 * k + 1] = -s[2 * k + 1];
      }
    }
  }
  // out = J v; `image` (optional) receives M v, the slip's change for the traction's change v.
  void jacobian(const double* v, double* out, double* image = nullptr) {
    op_.apply(v, out);
    if (image) std::copy(out, out + 2 * L_.size(), image);
    finish(v, out);
  }
  // out = J v from out = M v (no product).
  void finish(const double* v, double* out) const {
    for (int k = 0; k < L_.size(); ++k) {
      if (st_.state[static_cast<std::size_t>(k)] != kSlip) continue;
      const double ex = dir_x(k), ey = dir_y(k), tx = -ey, ty = ex;
      const double mt = tx * out[2 * k] + ty * out[2 * k + 1];
      out[2 * k] = mt + c_[static_cast<std::size_t>(k)] * (tx * v[2 * k] + ty * v[2 * k + 1]);
      out[2 * k + 1] = kappa() * (ex * v[2 * k] + ey * v[2 * k + 1]);
    }
  }
  // The bound equation e . dp = g - |p| is in Pa, the others in slip per |V|: scaled by the typical slip per
  // traction (M's diagonal), so that GMRES's residual norm weighs them alike.
  double kappa() const { return 0.5 * (K_.kx + K_.ky); }
  // z = P r: adhesion runs by the row sum and B's circulant inverse, then the slip elements swept from upstream.
  void precondition(const double* r, double* z) {
    adhesion_part(r, z);
    for (const SweepStep& w : sweep_) {  // contact elements are in marching order: upstream ones come first
      const int k = w.k, u = w.up;
      const double r1 = r[2 * k] + (u >= 0 ? w.ux * z[2 * u] + w.uy * z[2 * u + 1] : 0.0);
      z[2 * k] = w.m11 * r1 + w.m12 * r[2 * k + 1];
      z[2 * k + 1] = w.m21 * r1 + w.m22 * r[2 * k + 1];
    }
  }

 private:
  // The slip direction e_k of the traction at the linearisation point (slip elements).
  double dir_x(int k) const { return ex_[static_cast<std::size_t>(k)]; }
  double dir_y(int k) const { return ey_[static_cast<std::size_t>(k)]; }

  // B dp = dx * (sum of r along the adhesion run from its upstream end): the exact inverse of the upwind difference,
  // then B inverted by its periodic circulant.
  void adhesion_part(const double* r, double* z) {
    auto& qx = op_.px();
    auto& qy = op_.py();
    std::fill(qx.begin(), qx.end(), 0.0);
    std::fill(qy.begin(), qy.end(), 0.0);
    const double dx = L_.field.grid.dx;
    bool any = false;
    for (int k = 0; k < L_.size(); ++k) {
      if (st_.state[static_cast<std::size_t>(k)] != kAdhesion) continue;
      const int u = L_.up[static_cast<std::size_t>(k)];
      const bool run = u >= 0 && st_.state[static_cast<std::size_t>(u)] == kAdhesion;
      const auto c = static_cast<std::size_t>(L_.cell[static_cast<std::size_t>(k)]);
      const auto cu = run ? static_cast<std::size_t>(L_.cell[static_cast<std::size_t>(u)]) : c;
      qx[c] = (run ? qx[cu] : 0.0) + dx * r[2 * k];
      qy[c] = (run ? qy[cu] : 0.0) + dx * r[2 * k + 1];
      any = true;
    }
    if (any) op_.deconvolve_in_place();
    for (int k = 0; k < L_.size(); ++k) {
      if (st_.state[static_cast<std::size_t>(k)] != kAdhesion) continue;
      const auto c = static_cast<std::size_t>(L_.cell[static_cast<std::size_t>(k)]);
      z[2 * k] = qx[c];
      z[2 * k + 1] = qy[c];
    }
  }

  // A slip element's step of the sweep: its upstream element's coupling (the upstream block -K seen along t) and its
  // own 2 x 2 block [tx (kx + c), ty (ky + c); kappa ex, kappa ey] inverted, once per linearisation: each sweep is a
  // chain along the rows (an element waits on its upstream one), which a division per element made latency-bound.
  struct SweepStep {
    int k, up;
    double ux, uy, m11, m12, m21, m22;
  };
  void set_sweep() {
    const double kx = K_.kx, ky = K_.ky;
    for (int k = 0; k < L_.size(); ++k) {
      if (st_.state[static_cast<std::size_t>(k)] != kSlip) continue;
      const double ex = dir_x(k), ey = dir_y(k), tx = -ey, ty = ex, c = c_[static_cast<std::size_t>(k)];
      const double a11 = tx * (kx + c), a12 = ty * (ky + c), a21 = kappa() * ex, a22 = kappa() * ey;
      const double inv = 1 / (a11 * a22 - a12 * a21);
      sweep_.push_back({k, L_.up[static_cast<std::size_t>(k)], tx * kx, ty * ky, a22 * inv, -a12 * inv, -a21 * inv,
                        a11 * inv});
    }
  }

  const Level& L_;
  SlipOperator& op_;
  LocalBlocks K_;
  const LevelState& st_;
  std::vector<double> c_, ex_, ey_, mag_;
  std::vector<SweepStep> sweep_;
};

double dot(const double* __restrict a, const double* __restrict b, std::size_t n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;  // four partial sums: the loop vectorises without -ffast-math
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += a[i] * b[i];
    s1 += a[i + 1] * b[i + 1];
    s2 += a[i + 2] * b[i + 2];
    s3 += a[i + 3] * b[i + 3];
  }
  for (; i < n; ++i) s0 += a[i] * b[i];
  return (s0 + s1) + (s2 + s3);
}
// y -= a x
void axpy_minus(double a, const double* __restrict x, double* __restrict y, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) y[i] -= a * x[i];
}

// Restarted GMRES with right preconditioning for J x = b from x = 0, to |b - J x| <= rtol |b|. Returns iterations.
// Also mx = M x, from the products J needs anyway (M times each preconditioned vector, kept): the caller's slip
// changes by it without a product of its own, and a restart's true residual needs none either.
int gmres(Linearisation& lin, const std::vector<double>& b, std::vector<double>& x, std::vector<double>& mx,
          double rtol, int max_iterations, RollingWorkspace& ws) {
  constexpr int m = 30;
  const std::size_t n = b.size();
  ws.basis.resize((m + 1) * n);
  ws.precond.resize(m * n);
  ws.images.resize(m * n);
  std::vector<double> r = b, w(n);
  x.assign(n, 0.0);
  mx.assign(n, 0.0);
  const double bnorm = std::sqrt(dot(b.data(), b.data(), n));
  if (bnorm == 0) return 0;
  int total = 0;
  double H[m + 1][m], g[m + 1], cs[m], sn[m];
  for (;;) {
    const double beta = std::sqrt(dot(r.data(), r.data(), n));
    if (beta <= rtol * bnorm || total >= max_iterations) return total;
    double* V = ws.basis.data();
    double* Z = ws.precond.data();
    double* MZ = ws.images.data();
    for (std::size_t i = 0; i < n; ++i) V[i] = r[i] / beta;
    std::fill(g, g + m + 1, 0.0);
    g[0] = beta;
    int j = 0;
    for (; j < m && total < max_iterations; ++j) {
      ++total;
      lin.precondition(V + j * n, Z + j * n);
      lin.jacobian(Z + j * n, w.data(), MZ + j * n);
      for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
        H[i][j] = dot(w.data(), V + i * n, n);
        axpy_minus(H[i][j], V + i * n, w.data(), n);
      }
      H[j + 1][j] = std::sqrt(dot(w.data(), w.data(), n));
      if (H[j + 1][j] > 0) {
        const double scale = 1 / H[j + 1][j];  // a division per element was ~6 % of gmres's own time (perf)
        for (std::size_t q = 0; q < n; ++q) V[(j + 1) * n + q] = w[q] * scale;
      }
      for (int i = 0; i < j; ++i) {
        const double t = cs[i] * H[i][j] + sn[i] * H[i + 1][j];
        H[i + 1][j] = -sn[i] * H[i][j] + cs[i] * H[i + 1][j];
        H[i][j] = t;
      }
      const double d = std::hypot(H[j][j], H[j + 1][j]);
      cs[j] = d > 0 ? H[j][j] / d : 1.0;
      sn[j] = d > 0 ? H[j + 1][j] / d : 0.0;
      H[j][j] = d;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      if (std::abs(g[j + 1]) <= rtol * bnorm || H[j + 1][j] == 0) {
        ++j;
        break;
      }
    }
    double y[m];
    for (int i = j - 1; i >= 0; --i) {  // back substitution
      double s = g[i];
      for (int q = i + 1; q < j; ++q) s -= H[i][q] * y[q];
      y[i] = H[i][i] != 0 ? s / H[i][i] : 0.0;
    }
    for (int i = 0; i < j; ++i)
      for (std::size_t q = 0; q < n; ++q) x[q] += y[i] * Z[i * n + q], mx[q] += y[i] * MZ[i * n + q];
    if (std::abs(g[j]) <= rtol * bnorm) return total;
    w = mx;  // restart from the true residual (J x from M x: M is linear)
    lin.finish(x.data(), w.data());
    for (std::size_t q = 0; q < n; ++q) r[q] = b[q] - w[q];
  }
}

// The convergence measure: max |s| over adhesion and max |t . s| over slip, relative to the rigid slip scale, and the
// slip elements' distance to their bound | |p| - g | (g(sigma) with a slip-dependent law) times M's diagonal `kappa`
// (a slip).
double residual_of(const Level& L, const LevelState& st, const std::vector<double>& s, double kappa) {
  double err = 0;
  for (int k = 0; k < L.size(); ++k) {
    const double sx = s[2 * k], sy = s[2 * k + 1];
    if (st.state[static_cast<std::size_t>(k)] == kSlip) {
      const auto q = static_cast<std::size_t>(k);
      const double g = std::sqrt(st.px[q] * st.px[q] + st.py[q] * st.py[q]);
      err = std::max(err, std::abs(-st.py[q] / g * sx + st.px[q] / g * sy));
      const double bound = L.falling() ? L.bound(k, std::max(0.0, -(st.px[q] * sx + st.py[q] * sy) / g)) : L.gk[q];
      err = std::max(err, kappa * std::abs(g - bound));
    } else {
      err = std::max(err, std::sqrt(sx * sx + sy * sy));
    }
  }
  return err / L.scale;
}

// An element's state after a step: slip elements whose slip runs along their traction adhere; adhesion elements
// beyond the static bound slip (the next step brings them to the kinetic bound).
unsigned char next_state(const Level& L, const LevelState& st, const std::vector<double>& s, int k) {
  const auto q = static_cast<std::size_t>(k);
  const double px = st.px[q], py = st.py[q];
  if (st.state[q] == kSlip) return px * s[2 * k] + py * s[2 * k + 1] > 0 ? kAdhesion : kSlip;
  return std::sqrt(px * px + py * py) > L.gs[q] ? kSlip : kAdhesion;
}

// Updates the split; true when an element changed state.
bool update_split(const Level& L, LevelState& st, const std::vector<double>& s) {
  bool changed = false;
  for (int k = 0; k < L.size(); ++k) {
    const unsigned char next = next_state(L, st, s, k);
    changed = changed || next != st.state[static_cast<std::size_t>(k)];
    st.state[static_cast<std::size_t>(k)] = next;
  }
  return changed;
}

// Whether update_split would change the split.
bool split_moves(const Level& L, const LevelState& st, const std::vector<double>& s) {
  for (int k = 0; k < L.size(); ++k)
    if (next_state(L, st, s, k) != st.state[static_cast<std::size_t>(k)]) return true;
  return false;
}

// Slip tractions back on the bound after a step (their direction from the step); a slip-dependent one on its bound
// at the last slip.
void renormalise(const Level& L, LevelState& st) {
  for (int k = 0; k < L.size(); ++k) {
    const auto q = static_cast<std::size_t>(k);
    if (st.state[q] != kSlip) continue;
    const double mag = std::sqrt(st.px[q] * st.px[q] + st.py[q] * st.py[q]);
    if (!(mag > 0)) continue;
    const double to = L.falling() ? st.bound[q] : L.gk[q];
    st.px[q] *= to / mag;
    st.py[q] *= to / mag;
  }
}

// A slip-dependent law: each slip element's bound at its present slip.
void update_bounds(const Level& L, LevelState& st, const std::vector<double>& s) {
  if (!L.falling()) return;
  for (int k = 0; k < L.size(); ++k) {
    const auto q = static_cast<std::size_t>(k);
    if (st.state[q] != kSlip) continue;
    const double mag = std::hypot(st.px[q], st.py[q]);
    if (mag > 0) st.bound[q] = L.bound(k, std::max(0.0, -(st.px[q] * s[2 * k] + st.py[q] * s[2 * k + 1]) / mag));
  }
}

}  // namespace

bool newton(const Level& L, const Material& material, const ShearSpectrum& linear, const ShearSpectrum& periodic,
            RollingWorkspace& ws, const TangentialOptions& opt, LevelState& st, bool settled) {
  const int n = L.size();
  SlipOperator op(L, linear, periodic, ws);
  const LocalBlocks K = local_blocks(material, L.field.grid);
  std::vector<double> p(2 * static_cast<std::size_t>(n)), s(p.size()), b(p.size()), dp(p.size()), ds(p.size());
  const auto pack = [&] {
    for (int k = 0; k < n; ++k) p[2 * k] = st.px[static_cast<std::size_t>(k)], p[2 * k + 1] = st.py[static_cast<std::size_t>(k)];
  };
  pack();
  op.slip(p.data(), s.data());
  bool changed = !settled || update_split(L, st, s), converged = false;
  if (L.falling()) st.bound = L.gk;
  update_bounds(L, st, s);
  for (int it = 0;; ++it) {
    const double err = residual_of(L, st, s, 0.5 * (K.kx + K.ky));
    st.residual = err;
    if (!changed && err <= opt.tolerance) {
      converged = true;
      break;
    }
    if (it >= opt.max_iterations) break;
    ++st.iterations;
    Linearisation lin(L, op, K, st, s);
    lin.rhs(s, b.data());
    // Inexact Newton: loose while the split moves, then just tight enough to meet the tolerance.
    const double eta = changed ? 0.1 : std::clamp(kForcing * opt.tolerance / std::max(err, 1e-300), 1e-6, kLoosest);
    st.linear += gmres(lin, b, dp, ds, eta, 400, ws);
    for (int k = 0; k < n; ++k) {
      st.px[static_cast<std::size_t>(k)] += dp[2 * k];
      st.py[static_cast<std::size_t>(k)] += dp[2 * k + 1];
    }
    for (std::size_t q = 0; q < s.size(); ++q) s[q] += ds[q];  // s = w + M p, M linear: no product
    // While the split moves (and with a slip-dependent law, whose bounds are a fixed point on the slip), the slip
    // tractions go back on their bound and their slip is computed anew.
    if (changed || L.falling() || split_moves(L, st, s)) {
      renormalise(L, st);
      pack();
      op.slip(p.data(), s.data());
    }
    changed = update_split(L, st, s);
    update_bounds(L, st, s);
  }
  // Onto the bound (settled steps leave them off it by a second-order amount): a move within the residual just
  // checked, which includes the distance to the bound, so the slip kept (of the tractions before it) stays within
  // the tolerance.
  renormalise(L, st);
  st.products += op.products;
  st.slip = std::move(s);  // the solution's slip needs no product of its own
  return converged;
}

int linearise(const Level& L, const Material& material, const ShearSpectrum& linear, const ShearSpectrum& periodic,
              RollingWorkspace& ws, const LevelState& st, const std::vector<double>& dw, const std::vector<double>& dg,
              double rtol, std::vector<double>& dp) {
  const int n = L.size();
  SlipOperator op(L, linear, periodic, ws);
  const LocalBlocks K = local_blocks(material, L.field.grid);
  std::vector<double> p(2 * static_cast<std::size_t>(n)), s(p.size()), b(p.size());
  for (int k = 0; k < n; ++k) p[2 * k] = st.px[static_cast<std::size_t>(k)], p[2 * k + 1] = st.py[static_cast<std::size_t>(k)];
  op.slip(p.data(), s.data());
  Linearisation lin(L, op, K, st, s);
  // The step's equations with the solution's residuals replaced by the data's change: adhesion M dp = -dw; slip
  // t . (M dp) + c t . dp = -t . dw and e . dp = dg (scaled as the solve scales it).
  for (int k = 0; k < n; ++k) {
    const auto q = static_cast<std::size_t>(k);
    if (st.state[q] == kSlip) {
      const double mag = std::hypot(st.px[q], st.py[q]), ex = st.px[q] / mag, ey = st.py[q] / mag;
      b[2 * k] = -(-ey * dw[2 * k] + ex * dw[2 * k + 1]);
      b[2 * k + 1] = lin.kappa() * dg[q];
    } else {
      b[2 * k] = -dw[2 * k];
      b[2 * k + 1] = -dw[2 * k + 1];
    }
  }
  std::vector<double> image;
  return gmres(lin, b, dp, image, rtol, 2000, ws);
}

void slip_of(const Level& L, const ShearSpectrum& linear, RollingWorkspace& ws, const LevelState& st,
             std::vector<double>& sx, std::vector<double>& sy) {
  SlipOperator op(L, linear, linear, ws);
  const int n = L.size();
  std::vector<double> p(2 * static_cast<std::size_t>(n)), s(p.size());
  for (int k = 0; k < n; ++k) p[2 * k] = st.px[static_cast<std::size_t>(k)], p[2 * k + 1] = st.py[static_cast<std::size_t>(k)];
  op.slip(p.data(), s.data());
  sx.resize(static_cast<std::size_t>(n));
  sy.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) sx[static_cast<std::size_t>(k)] = s[2 * k], sy[static_cast<std::size_t>(k)] = s[2 * k + 1];
}

}  // namespace wrc::halfspace::detail
