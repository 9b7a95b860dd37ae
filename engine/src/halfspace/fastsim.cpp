// FASTSIM, Kalker's simplified theory of rolling contact, strip by strip on the grid (rolling.hpp).
//
// The simplified theory replaces the half-space by a layer whose surface displaces locally, u = L p. With Kalker's
// three flexibilities the layer is diag(L1, L2) and the spin part of the rigid slip is scaled by L1/L3 (in x) and
// L2/L3 (in y), so that in adhesion (du/dx = w along the rolling direction, u = 0 at the leading edge) the linear
// theory's Fx and Fy come out exactly on an ellipse. Along each row, from the upstream end of every contact run:
//   u_pred = L p_upstream - dx (w + w_upstream) / 2     (trapezoidal; the run's first element gets half a step)
//   p_pred = L^-1 u_pred;  adhesion if |p_pred| <= mu_s p_n (mu_k p_n after a slipping upstream element);
//   else slip: p minimises (p - p_pred)' L (p - p_pred) on |p| = mu_k p_n, and s = L (p - p_pred) / dx,
// so that p = -mu_k p_n s / |s| holds for the layer's own slip s. The upstream element is the same material point a
// moment earlier: a point that slides keeps sliding (at mu_k) until the stick traction falls within mu_k p_n, i.e.
// until its slip would reverse -- as the exact solver's split update has it. Testing it against mu_s instead let a
// sliding point stick again at once, and with mu_s > mu_k the slip zone became a sawtooth of stick and slip whose
// mean traction lay between mu_k and mu_s (|F|/N 0.22 for mu_s 0.4, mu_k 0.1, where the exact solver gives 0.10).
//
// Friction falling with the slip velocity (friction.hpp): a slip element's bound g solves g = mu(|V| |s(g)|) p_n, s(g)
// the layer's slip of the projection onto g. Unlike the half-space's, the layer's slip per traction is L / dx, so
// that g - mu(|V| |s(g)|) p_n need not be monotone (d mu / dw |V| L p_n / dx reaches 1 on fine grids): of its roots
// the one nearest to adhesion where it increases with g (a stable sliding state) is taken, found by a scan from the
// top of [mu_inf p_n, min(|q|, mu(0) p_n)] and bisection. An element adheres while |q| <= mu(0) p_n, and after a
// sliding one while no sliding state exists.
#include "rolling_internal.hpp"

#include "wrc/core/error.hpp"
#include "wrc/halfspace/ellipse.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace wrc::halfspace {
namespace {

// The contact regions (8-connected, p > 0) of the problem's pressure with their equivalent ellipses (ellipse.hpp), and
// each element's region: the problem's when it brings them (found with the pressure's other results), else found here.
class Regions {
 public:
  explicit Regions(const TangentialProblem& pb) {
    if (!pb.regions.empty()) {
      ellipses_ = pb.regions, label_ = pb.region_label;
      return;
    }
    found_ = equivalent_ellipses(pb.grid, pb.pressure, found_label_);
    ellipses_ = found_, label_ = found_label_;
  }
  Regions(const Regions&) = delete;
  Regions& operator=(const Regions&) = delete;
  std::span<const EquivalentEllipse> ellipses() const { return ellipses_; }
  // The region of contact element k (an index into ellipses()); throws on a given label that names none.
  std::size_t of(std::size_t k) const {
    const auto r = static_cast<std::size_t>(label_[k]);
    if (r >= ellipses_.size()) [[unlikely]]
      bad_label(k);
    return r;
  }

 private:
  [[noreturn, gnu::cold, gnu::noinline]] void bad_label(std::size_t k) const {
    fail("FASTSIM: contact element {} has region label {}, expected 0 .. {} (the regions given with the problem)", k,
         label_[k], ellipses_.size() - 1);
  }
  std::vector<EquivalentEllipse> found_;
  std::vector<int> found_label_;
  std::span<const EquivalentEllipse> ellipses_;
  std::span<const int> label_;
};

// The traction of magnitude g nearest to q in the norm (p - q)' diag(lx, ly) (p - q) (|q| > g): p_i = l_i q_i / (l_i +
// lambda) with lambda > 0 from |p| = g. Newton on 1 / |p(lambda)| - 1 / g, which is linear in lambda for an isotropic
// layer (then exact at the start) and nearly so for Kalker's flexibilities; the result is scaled onto the bound.
// (Measured against the converged projection: one step leaves the direction within 2e-6 rad for the flexibilities of
// a/b = 0.1 .. 10, |q| / g = 1 .. 100.)
// Inlined: called from two places since the falling laws, the call alone cost the constant-friction sweep 8 % more
// instructions (callgrind).
[[gnu::always_inline]] inline void project(double lx, double ly, double qx, double qy, double g, double& px,
                                           double& py) {
  const double inv_g = 1 / g;
  double lam = std::sqrt(lx * ly) * (std::sqrt(qx * qx + qy * qy) * inv_g - 1);  // the isotropic answer to start
  {  // one Newton step: lambda += (|p| / g - 1) |p|^2 / sum(a_i^2 / (l_i + lambda)), a_i = l_i q_i / (l_i + lambda)
    const double bx = 1 / (lx + lam), by = 1 / (ly + lam), ax = lx * qx * bx, ay = ly * qy * by;
    const double m2 = ax * ax + ay * ay;
    lam = std::max(0.0, lam + (std::sqrt(m2) * inv_g - 1) * m2 / (ax * ax * bx + ay * ay * by));
  }
  px = lx * qx / (lx + lam), py = ly * qy / (ly + lam);
  const double s = g / std::sqrt(px * px + py * py);
  px *= s, py *= s;
}

// A slip element's traction under a slip-dependent law: its bound g (Pa), or 0 when no sliding state exists; p and
// s as project() gives them for g. q: the predicted traction, gp: p_n times the law's factor.
struct FallingSlip {
  double lx, ly, inv_dx, speed;
  const Friction& law;
  double residual(double qx, double qy, double g, double gp, double& px, double& py, double& sx, double& sy) const {
    project(lx, ly, qx, qy, g, px, py);
    sx = lx * (px - qx) * inv_dx, sy = ly * (py - qy) * inv_dx;
    return g - law.at(speed * std::sqrt(sx * sx + sy * sy)) * gp;
  }
  double solve(double qx, double qy, double gp, double& px, double& py, double& sx, double& sy) const {
    constexpr int scan = 16;
    const double q = std::sqrt(qx * qx + qy * qy), lo = law.kinetic_coefficient * gp;
    const double hi = std::min(q, law.static_coefficient * gp);
    if (!(hi > lo)) return q > lo ? (residual(qx, qy, hi, gp, px, py, sx, sy), hi) : 0.0;  // no fall left
    double above = -1;  // the lowest scanned g with residual > 0 so far
    for (int j = 0; j <= scan; ++j) {
      const double g = hi - (hi - lo) * j / scan;
      const double f = residual(qx, qy, g, gp, px, py, sx, sy);
      if (f > 0) {
        above = g;
      } else if (above > 0) {  // a crossing between g and `above`: bisect
        double a = g, b = above;
        for (int it = 0; it < 60 && b - a > 1e-13 * b; ++it) {
          const double m = 0.5 * (a + b);
          (residual(qx, qy, m, gp, px, py, sx, sy) > 0 ? b : a) = m;
        }
        residual(qx, qy, b, gp, px, py, sx, sy);
        return b;
      }
    }
    if (q > hi) return residual(qx, qy, hi, gp, px, py, sx, sy), hi;  // mu(0) p_n exactly
    return 0;
  }
};

// Per contact region: the layer's flexibilities (its equivalent ellipse's), their inverses, and the spin creepage
// scaled per axis (L1 / L3 in x, L2 / L3 in y).
struct Layer {
  double lx, ly, inv_lx, inv_ly, spin_x, spin_y;
};

std::vector<Layer> region_layers(const Regions& regions, const Material& material, double phi) {
  std::vector<Layer> layers;
  for (const EquivalentEllipse& e : regions.ellipses()) {
    const Flexibilities L = kalker_flexibilities(e.a, e.b, material);
    layers.push_back({L.x, L.y, 1 / L.x, 1 / L.y, phi * L.x / L.spin, phi * L.y / L.spin});
  }
  return layers;
}

// What a row's march carries from one element to the next (all 0 outside the contact).
struct Strip {
  double ux = 0, uy = 0, wx_up = 0, wy_up = 0;  // upstream element's layer displacement and rigid slip
  bool sliding = false;                          // the upstream element slipped
};

// The march along the rows from their upstream ends (the method on top), writing each element's traction, slip and
// state into `out`, whose grids have the problem's size.
class March {
 public:
  March(const TangentialProblem& pb, const Regions& regions, std::span<const Layer> layers, TangentialSolution& out)
      : pb_(pb), g_(pb.grid), regions_(regions), layers_(layers), out_(out), half_(0.5 * g_.dx), inv_dx_(1 / g_.dx),
        extra_(!pb.extra_x.empty()) {}

  // All rows, compiled apart for constant and slip-dependent friction (the latter's branch in the constant one's loop
  // cost it 5 % more instructions). Each element hangs on its upstream neighbour (in slip through project()'s
  // divisions and roots, whose latency the march waited on), the rows on nothing: kRows of them are marched in
  // lockstep, so that the processor overlaps their chains (a third less time at 0.2 mm; the same operations per
  // element, the same results).
  template <bool kFalling>
  void rows() const {
    constexpr int kRows = 4;
    for (int j0 = 0; j0 < g_.ny; j0 += kRows) {
      const int rows = std::min(kRows, g_.ny - j0);
      Strip st[kRows];
      for (int step = 0; step < g_.nx; ++step) {
        const int i = pb_.direction > 0 ? g_.nx - 1 - step : step;
        const double x = g_.x(i) - pb_.ref_x;
        if (rows == kRows) {
#pragma GCC unroll 4
          for (int r = 0; r < kRows; ++r) element<kFalling>(i, j0 + r, x, st[r]);
        } else {
          for (int r = 0; r < rows; ++r) element<kFalling>(i, j0 + r, x, st[r]);
        }
      }
    }
  }

 private:
  // Element (i, j) at x from the reference point, its row's march state st (the upstream element's, then its own).
  template <bool kFalling>
  [[gnu::always_inline]] void element(int i, int j, double x, Strip& st) const {
    const auto k = static_cast<std::size_t>(g_.index(i, j));
    const double pn = pb_.pressure[k];
    out_.sx[k] = out_.sy[k] = 0;
    if (!(pn > 0)) {
      out_.px[k] = out_.py[k] = 0;
      out_.state[k] = kExterior;
      st = Strip{};
      return;
    }
    const Layer& L = layers_[regions_.of(k)];
    const Creepages& c = pb_.creepages;
    const double y = g_.y(j) - pb_.ref_y;
    // The layer's rigid slip: translational creepages and the extra slip as they are, the spin scaled per axis.
    const double wx = c.xi - L.spin_x * y + (extra_ ? pb_.extra_x[k] : 0.0);
    const double wy = c.eta + L.spin_y * x + (extra_ ? pb_.extra_y[k] : 0.0);
    // The stick traction: the upstream displacement less the step's slip (trapezoidal), through the layer.
    const double qx = (st.ux - half_ * (wx + st.wx_up)) * L.inv_lx, qy = (st.uy - half_ * (wy + st.wy_up)) * L.inv_ly;
    double px = qx, py = qy, sx = 0, sy = 0;
    const double gp = pb_.friction_scale.empty() ? pn : pn * pb_.friction_scale[k];
    bool sliding = st.sliding;
    if constexpr (kFalling) {
      const double mus = pb_.friction.static_coefficient;
      const FallingSlip fs{L.lx, L.ly, inv_dx_, pb_.speed, pb_.friction};
      sliding = (sliding || qx * qx + qy * qy > mus * mus * gp * gp) && fs.solve(qx, qy, gp, px, py, sx, sy) > 0;
      if (!sliding) px = qx, py = qy;
    } else {  // a sliding upstream point slides on while its stick traction passes the kinetic bound
      const double muk = pb_.friction.kinetic_coefficient;
      const double bound = (sliding ? muk : pb_.friction.static_coefficient) * gp;
      sliding = qx * qx + qy * qy > bound * bound;
      if (sliding) {
        project(L.lx, L.ly, qx, qy, muk * gp, px, py);
        sx = L.lx * (px - qx) * inv_dx_, sy = L.ly * (py - qy) * inv_dx_;
      }
    }
    out_.state[k] = sliding ? kSlip : kAdhesion;
    out_.sx[k] = sx;
    out_.sy[k] = sy;
    out_.px[k] = px, out_.py[k] = py;
    st = {L.lx * px, L.ly * py, wx, wy, sliding};
  }

  const TangentialProblem& pb_;
  const Grid& g_;
  const Regions& regions_;
  std::span<const Layer> layers_;
  TangentialSolution& out_;
  double half_, inv_dx_;  // half an element's length along the rows, and the inverse of the length
  bool extra_;            // the problem has the extra rigid slip
};

// The forces, moment, power and areas of the marched solution, row by row along the rolling direction as the march
// went before its rows were interleaved (the same order of additions: the same bits).
void sum_solution(const TangentialProblem& pb, TangentialSolution& out) {
  const Grid& g = pb.grid;
  double fx = 0, fy = 0, mz = 0, power = 0, contact = 0, adhesion = 0;
  for (int j = 0; j < g.ny; ++j) {
    const double y = g.y(j) - pb.ref_y;
    for (int step = 0; step < g.nx; ++step) {
      const int i = pb.direction > 0 ? g.nx - 1 - step : step;
      const auto k = static_cast<std::size_t>(g.index(i, j));
      if (out.state[k] == kExterior) continue;
      const double x = g.x(i) - pb.ref_x, px = out.px[k], py = out.py[k];
      if (out.state[k] == kSlip) power -= px * out.sx[k] + py * out.sy[k];
      else adhesion += 1;
      contact += 1;
      fx += px;
      fy += py;
      mz += x * py - y * px;
    }
  }
  const double dA = g.element_area();
  if (!(std::isfinite(fx) && std::isfinite(fy) && std::isfinite(mz) && std::isfinite(power))) [[unlikely]] {
    validate(pb, "solve_fastsim");  // (with ProblemCheck::sizes the grids' values were not checked: the culprit named)
    fail("solve_fastsim: the tangential forces are not finite (Fx = {}, Fy = {}, Mz = {})", fx * dA, fy * dA, mz * dA);
  }
  out.fx = fx * dA;
  out.fy = fy * dA;
  out.mz = mz * dA;
  out.power_per_speed = power * dA;
  out.contact_area = contact * dA;
  out.adhesion_area = adhesion * dA;
}

}  // namespace

TangentialSolution solve_fastsim(const Material& material, const TangentialProblem& pb, ProblemCheck check) {
  TangentialSolution out;
  solve_fastsim(material, pb, out, check);
  return out;
}

void solve_fastsim(const Material& material, const TangentialProblem& pb, TangentialSolution& out,
                   ProblemCheck check) {
  validate(pb, "solve_fastsim", check);
  validate(material, "solve_fastsim");
  const auto n = static_cast<std::size_t>(pb.grid.size());
  out = TangentialSolution{pb.grid, std::move(out.px), std::move(out.py), std::move(out.sx), std::move(out.sy),
                           std::move(out.state)};
  for (auto* v : {&out.px, &out.py, &out.sx, &out.sy}) v->resize(n);  // every element is written by the march
  out.state.resize(n);
  const Regions regions(pb);
  const std::vector<Layer> layers = region_layers(regions, material, pb.creepages.phi);
  const March march(pb, regions, layers, out);
  if (pb.friction.slip_dependent()) march.rows<true>();
  else march.rows<false>();
  sum_solution(pb, out);
}

namespace {

// The derivative of project()'s traction p (on |p| = g, nearest to q in the layer's norm: p_i (l_i + lambda) = l_i q_i)
// for dq, dg and the flexibilities' dl: dp_i = (l_i dq_i + dl_i (q_i - p_i) - p_i dlambda) / (l_i + lambda), dlambda
// from p . dp = g dg. lambda is recovered from p and q (least squares over the two components).
void project_derivative(double lx, double ly, double qx, double qy, double px, double py, double g, double dqx,
                        double dqy, double dg, double dlx, double dly, double& dpx, double& dpy) {
  const double lam = std::max(0.0, (lx * (qx - px) * px + ly * (qy - py) * py) / (px * px + py * py));
  const double ax = 1 / (lx + lam), ay = 1 / (ly + lam);
  const double rx = lx * dqx + dlx * (qx - px), ry = ly * dqy + dly * (qy - py);
  const double num = px * rx * ax + py * ry * ay - g * dg, den = px * px * ax + py * py * ay;
  const double dlam = num / den;
  dpx = (rx - px * dlam) * ax;
  dpy = (ry - py * dlam) * ay;
}

// The change of Kalker's flexibilities for a change (da, db) of the ellipse (a, b): a central difference over a
// relative change of 1e-6 of the semi-axes (they are smooth in a and b).
Flexibilities flexibility_change(const EquivalentEllipse& e, const EllipseChange& d, const Material& m) {
  const double scale = std::max(std::abs(d.da) / e.a, std::abs(d.db) / e.b);
  if (!(scale > 0)) return {0, 0, 0};
  const double h = 1e-6 / scale;
  const Flexibilities up = kalker_flexibilities(e.a + h * d.da, e.b + h * d.db, m);
  const Flexibilities down = kalker_flexibilities(e.a - h * d.da, e.b - h * d.db, m);
  return {(up.x - down.x) / (2 * h), (up.y - down.y) / (2 * h), (up.spin - down.spin) / (2 * h)};
}

}  // namespace

std::vector<TangentialDerivative> linearise_fastsim(const Material& material, const TangentialProblem& pb,
                                                    const TangentialSolution& sol,
                                                    std::span<const TangentialChange> changes) {
  detail::check_linearisation(pb, sol, changes, "linearise_fastsim");
  validate(material, "linearise_fastsim");
  const Grid& g = pb.grid;
  const Regions regions(pb);
  std::vector<Flexibilities> flex;
  for (const EquivalentEllipse& e : regions.ellipses()) flex.push_back(kalker_flexibilities(e.a, e.b, material));
  const Creepages& c = pb.creepages;
  const double half = 0.5 * g.dx, muk = pb.friction.kinetic_coefficient;
  std::vector<TangentialDerivative> out;
  for (const TangentialChange& ch : changes) {
    TangentialDerivative& d = out.emplace_back();
    d.grid = g;
    d.px.assign(pb.pressure.size(), 0.0);
    d.py.assign(pb.pressure.size(), 0.0);
    const Creepages& dc = ch.creepages;
    // The flexibilities change with the pressure through the ellipses (their edge elements' weights).
    std::vector<Flexibilities> dflex(flex.size(), Flexibilities{0, 0, 0});
    if (!ch.pressure.empty()) {
      const std::vector<EllipseChange> de = ellipse_changes(g, pb.pressure, ch.pressure);
      for (std::size_t r = 0; r < flex.size(); ++r)
        dflex[r] = flexibility_change(regions.ellipses()[r], de[r], material);
    }
    for (int j = 0; j < g.ny; ++j) {
      const double y = g.y(j) - pb.ref_y;
      // upstream element's layer displacement, rigid slip and their derivatives (0 outside the contact)
      double ux = 0, uy = 0, wxu = 0, wyu = 0, dux = 0, duy = 0, dwxu = 0, dwyu = 0;
      for (int step = 0; step < g.nx; ++step) {
        const int i = pb.direction > 0 ? g.nx - 1 - step : step;
        const auto k = static_cast<std::size_t>(g.index(i, j));
        if (sol.state[k] == kExterior) {
          ux = uy = wxu = wyu = dux = duy = dwxu = dwyu = 0;
          continue;
        }
        const std::size_t r = regions.of(k);
        const Flexibilities &L = flex[r], &dL = dflex[r];
        const double x = g.x(i) - pb.ref_x, sx = L.x / L.spin, sy = L.y / L.spin;
        const double dsx = (dL.x - sx * dL.spin) / L.spin, dsy = (dL.y - sy * dL.spin) / L.spin;
        // the march's rigid slip (the spin scaled per axis) and its change (the reference point moving too)
        const double wx = c.xi - c.phi * sx * y + (pb.extra_x.empty() ? 0.0 : pb.extra_x[k]);
        const double wy = c.eta + c.phi * sy * x + (pb.extra_y.empty() ? 0.0 : pb.extra_y[k]);
        const double dwx = dc.xi - (dc.phi * sx + c.phi * dsx) * y + c.phi * sx * ch.ref_y +
                           (ch.extra_x.empty() ? 0.0 : ch.extra_x[k]);
        const double dwy = dc.eta + (dc.phi * sy + c.phi * dsy) * x - c.phi * sy * ch.ref_x +
                           (ch.extra_y.empty() ? 0.0 : ch.extra_y[k]);
        const double qx = (ux - half * (wx + wxu)) / L.x, qy = (uy - half * (wy + wyu)) / L.y;
        const double dqx = (dux - half * (dwx + dwxu) - qx * dL.x) / L.x;
        const double dqy = (duy - half * (dwy + dwyu) - qy * dL.y) / L.y;
        double dpx = dqx, dpy = dqy;
        if (sol.state[k] == kSlip) {
          const double gp = pb.friction_scale.empty() ? 1.0 : pb.friction_scale[k];
          const double dg = ch.pressure.empty() ? 0.0 : muk * gp * ch.pressure[k];
          project_derivative(L.x, L.y, qx, qy, sol.px[k], sol.py[k], muk * gp * pb.pressure[k], dqx, dqy, dg, dL.x,
                             dL.y, dpx, dpy);
        }
        d.px[k] = dpx;
        d.py[k] = dpy;
        ux = L.x * sol.px[k], uy = L.y * sol.py[k], wxu = wx, wyu = wy;
        dux = L.x * dpx + dL.x * sol.px[k], duy = L.y * dpy + dL.y * sol.py[k], dwxu = dwx, dwyu = dwy;
      }
    }
    detail::summarise(d, pb, sol, ch);
  }
  return out;
}

}  // namespace wrc::halfspace
