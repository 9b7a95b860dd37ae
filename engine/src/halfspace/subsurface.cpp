// Subsurface stresses under a patch (subsurface.hpp): the corner functions of a uniformly loaded rectangle, their
// kernels on the grid, the convolution by FFT or direct sum, and the derived measures.
#include "wrc/halfspace/subsurface.hpp"

#include "wrc/halfspace/convolution.hpp"
#include "wrc/core/error.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

namespace wrc::halfspace {
namespace {

constexpr int kLoads = 3;       // pressure, traction x, traction y
constexpr int kComponents = 6;  // xx, yy, zz, xy, xz, yz
using Components = std::array<double, kComponents>;

// Parities of the corner functions g(X, Y) of each load and component: +1 even, -1 odd in X (first) and Y (second).
// A kernel K(m) = g(m + 1/2) - g(m - 1/2) has the opposite parity.
constexpr int kParityX[kLoads][kComponents] = {{-1, -1, -1, 1, 1, -1}, {1, 1, 1, -1, -1, 1}, {-1, -1, -1, 1, 1, -1}};
constexpr int kParityY[kLoads][kComponents] = {{-1, -1, -1, 1, -1, 1}, {-1, -1, -1, 1, -1, 1}, {1, 1, 1, -1, 1, -1}};

// The corner terms of a traction q_x (times 2 pi): sigma = sum over corners of s_a s_b g(X_a, Y_b) / (2 pi).
// ln(rho + Y) is written asinh(Y / sqrt(X^2 + z^2)), which differs by a function of X alone (it cancels between the
// corners), and is odd in Y with no cancellation where Y < 0.
Components cerruti_corner(double X, double Y, double z, double rho, double T, double LX, double LY, double nu) {
  const double rz = rho + z, Xz = X * X + z * z;
  return {2 * LY + 2 * nu * Y / rz - z * Y * (z * rho - X * X) / (rho * rz * Xz),
          2 * nu * LY - 2 * nu * Y / rz - z * Y / (rho * rz),
          z * z * Y / (Xz * rho),
          LX - 2 * nu * X / rz - z * X / (rho * rz),
          -T + z * X * Y / (Xz * rho),
          -z / rho};
}

// The corner functions of the three unit loads at (X, Y, z), z > 0 (Pa per Pa).
std::array<Components, kLoads> stress_corners(double X, double Y, double z, double nu) {
  const double X2 = X * X, Y2 = Y * Y, Xz = X2 + z * z, Yz = Y2 + z * z;
  const double rho = std::sqrt(X2 + Y2 + z * z), rz = rho + z;
  const double T = std::atan(X * Y / (z * rho));  // the solid-angle term
  const double LX = std::asinh(X / std::sqrt(Yz)), LY = std::asinh(Y / std::sqrt(Xz));
  // int X / (rho (rho + z)) dY = atan(Y / X) - atan(z Y / (X rho)), as one continuous atan.
  const double XY = X * Y * (X2 + Y2);
  const double Axy = std::atan2(XY, rz * (X2 * rho + z * Y2)), Ayx = std::atan2(XY, rz * (Y2 * rho + z * X2));
  const double c = 1 - 2 * nu;
  std::array<Components, kLoads> g;
  g[0] = {-c * Axy + z * X * Y / (Xz * rho) - 2 * nu * T,
          -c * Ayx + z * X * Y / (Yz * rho) - 2 * nu * T,
          -T - z * X * Y / rho * (1 / Xz + 1 / Yz),
          -c * std::log(rz) - z / rho,
          z * z * Y / (Xz * rho),
          z * z * X / (Yz * rho)};
  g[1] = cerruti_corner(X, Y, z, rho, T, LX, LY, nu);
  // q_y: q_x's terms with x and y exchanged (xx <-> yy, xz <-> yz).
  const Components s = cerruti_corner(Y, X, z, rho, T, LY, LX, nu);
  g[2] = {s[1], s[0], s[2], s[3], s[5], s[4]};
  for (Components& l : g)
    for (double& v : l) v *= 0.5 / std::numbers::pi;
  return g;
}

// The kernels of one depth: K[load][component](m, n) for offsets m, n >= 0 (nx x ny each, index m + nx n), the stress
// at an element centre per unit load on the element (m, n) elements away; other signs by parity. G holds the corner
// functions at (k + 1/2) dx, (l + 1/2) dy for k, l >= 0 (the corners at -1/2 follow by parity). Built in place, so
// that the depths of a call reuse the storage.
struct Kernels {
  int nx = 0, ny = 0;
  std::array<std::array<std::vector<double>, kComponents>, kLoads> G, K;
  // K at a signed offset.
  double at(int load, int c, int m, int n) const {
    double v = K[load][c][static_cast<std::size_t>(std::abs(m)) + static_cast<std::size_t>(nx) * std::abs(n)];
    if (m < 0) v *= -kParityX[load][c];
    if (n < 0) v *= -kParityY[load][c];
    return v;
  }
  void build(const Grid& grid, double z, double nu, const std::array<bool, kLoads>& active);
};

void Kernels::build(const Grid& grid, double z, double nu, const std::array<bool, kLoads>& active) {
  nx = grid.nx;
  ny = grid.ny;
  const std::size_t N = static_cast<std::size_t>(nx) * ny;
  for (int L = 0; L < kLoads; ++L)
    for (int c = 0; c < kComponents; ++c) {
      G[L][c].resize(active[L] ? N : 0);
      K[L][c].resize(active[L] ? N : 0);
    }
  for (int l = 0; l < ny; ++l)
    for (int k = 0; k < nx; ++k) {
      const auto g = stress_corners((k + 0.5) * grid.dx, (l + 0.5) * grid.dy, z, nu);
      for (int L = 0; L < kLoads; ++L)
        if (active[L])
          for (int c = 0; c < kComponents; ++c) G[L][c][k + static_cast<std::size_t>(nx) * l] = g[L][c];
    }
  for (int L = 0; L < kLoads; ++L) {
    if (!active[L]) continue;
    for (int c = 0; c < kComponents; ++c) {
      const std::vector<double>& g = G[L][c];
      const int px = kParityX[L][c], py = kParityY[L][c];
      const auto at = [&](int k, int l) {  // k, l >= -1
        const double s = (k < 0 ? px : 1) * (l < 0 ? py : 1);
        return s * g[static_cast<std::size_t>(std::max(k, 0)) + static_cast<std::size_t>(nx) * std::max(l, 0)];
      };
      std::vector<double>& out = K[L][c];
      for (int n = 0; n < ny; ++n)
        for (int m = 0; m < nx; ++m)
          out[m + static_cast<std::size_t>(nx) * n] = at(m, n) - at(m - 1, n) - at(m, n - 1) + at(m - 1, n - 1);
    }
  }
}

// The loads as the stressed body carries them: the traction reversed for the rail.
struct Loads {
  std::array<std::vector<double>, kLoads> v;
  std::array<bool, kLoads> active{};
  std::vector<int> loaded;  // elements with any load
};

Loads gather(const SurfaceLoad& load, StressedBody body) {
  const std::size_t N = static_cast<std::size_t>(load.grid.size());
  Loads out;
  const double sign = body == StressedBody::rail ? -1.0 : 1.0;
  out.v[0].assign(load.pressure.begin(), load.pressure.end());
  for (int L = 1; L < kLoads; ++L) {
    const std::span<const double> q = L == 1 ? load.px : load.py;
    out.v[L].assign(N, 0.0);
    for (std::size_t k = 0; k < q.size(); ++k) out.v[L][k] = sign * q[k];
  }
  for (int L = 0; L < kLoads; ++L)
    out.active[L] = std::any_of(out.v[L].begin(), out.v[L].end(), [](double x) { return x != 0; });
  for (std::size_t k = 0; k < N; ++k)
    if (out.v[0][k] != 0 || out.v[1][k] != 0 || out.v[2][k] != 0) out.loaded.push_back(static_cast<int>(k));
  return out;
}

using Fields = std::array<std::vector<double>, kComponents>;

// The direct sum over the loaded elements.
void convolve_direct(const Grid& grid, const Kernels& K, const Loads& loads, Fields& s) {
  const int nx = grid.nx, ny = grid.ny;
  for (int e : loads.loaded) {
    const int i0 = e % nx, j0 = e / nx;
    for (int L = 0; L < kLoads; ++L) {
      const double w = loads.v[L][e];
      if (w == 0) continue;
      for (int c = 0; c < kComponents; ++c) {
        const double* k = K.K[L][c].data();
        const double wx = -kParityX[L][c] * w;  // the kernel's sign at negative x offsets, times the load
        for (int j = 0; j < ny; ++j) {
          const int n = j - j0;
          const double sy = n < 0 ? -kParityY[L][c] : 1.0;
          const double* row = k + static_cast<std::size_t>(nx) * std::abs(n);
          double* out = s[c].data() + static_cast<std::size_t>(nx) * j;
          for (int i = 0; i < i0; ++i) out[i] += sy * wx * row[i0 - i];
          const double wp = sy * w;
          for (int i = i0; i < nx; ++i) out[i] += wp * row[i - i0];
        }
      }
    }
  }
}

// The FFT convolution of one call: the plans and buffers of its grid, reused across depths.
class FftConvolution {
 public:
  explicit FftConvolution(const Grid& grid) : grid_(grid), shape_(shape(grid)), fft_(shape_.Mx, shape_.My, shape_.My,
                                                                                     FftPlanning::estimate) {
    for (ConvolutionWorkspace* w : {&kernel_, &out_}) w->prepare(fft_, grid);
    for (ConvolutionWorkspace& w : load_) w.prepare(fft_, grid);
  }

  // The spectra of the loads (once per call).
  void set_loads(const Loads& loads) {
    active_ = loads.active;
    for (int L = 0; L < kLoads; ++L) {
      if (!active_[L]) continue;
      copy_in(loads.v[L].data(), load_[L].input());
      fft_.forward(load_[L].input(), load_[L].spectrum_buffer(), grid_.ny);
    }
  }

  void convolve(const Kernels& K, Fields& s) {
    const std::size_t nc = static_cast<std::size_t>(fft_.complex_size());
    auto* acc = static_cast<fftw_complex*>(out_.spectrum_buffer());
    auto* kspec = static_cast<fftw_complex*>(kernel_.spectrum_buffer());
    const double scale = 1.0 / (static_cast<double>(shape_.Mx) * shape_.My);
    for (int c = 0; c < kComponents; ++c) {
      std::memset(static_cast<void*>(acc), 0, nc * sizeof(fftw_complex));
      for (int L = 0; L < kLoads; ++L) {
        if (!active_[L]) continue;
        embed(K, L, c, kernel_.input());
        fft_.forward(kernel_.input(), kspec);
        const auto* f = static_cast<const fftw_complex*>(load_[L].spectrum_buffer());
        for (std::size_t q = 0; q < nc; ++q) {
          acc[q][0] += kspec[q][0] * f[q][0] - kspec[q][1] * f[q][1];
          acc[q][1] += kspec[q][0] * f[q][1] + kspec[q][1] * f[q][0];
        }
      }
      fft_.backward(acc, out_.output(), grid_.ny);
      for (int j = 0; j < grid_.ny; ++j)
        for (int i = 0; i < grid_.nx; ++i)
          s[c][i + static_cast<std::size_t>(grid_.nx) * j] =
              scale * out_.output()[i + static_cast<std::size_t>(shape_.Mx) * j];
    }
  }

  // Every offset -(n - 1)..n - 1 needs its own periodic slot (odd kernels): M >= 2 n - 1.
  static FftShape shape(const Grid& g) { return fft_shape(2 * g.nx - 1, 2 * g.ny - 1, true); }

 private:
  void copy_in(const double* v, double* in) const {
    for (int j = 0; j < grid_.ny; ++j)
      std::memcpy(in + static_cast<std::size_t>(shape_.Mx) * j, v + static_cast<std::size_t>(grid_.nx) * j,
                  sizeof(double) * grid_.nx);
  }
  // The kernel at slot (m mod Mx, n mod My) of every offset (m, n), zero elsewhere.
  void embed(const Kernels& K, int L, int c, double* in) const {
    const int Mx = shape_.Mx, My = shape_.My, nx = grid_.nx, ny = grid_.ny;
    std::memset(in, 0, sizeof(double) * static_cast<std::size_t>(Mx) * My);
    for (int n = -(ny - 1); n < ny; ++n) {
      double* row = in + static_cast<std::size_t>(Mx) * (n < 0 ? n + My : n);
      for (int m = -(nx - 1); m < nx; ++m) row[m < 0 ? m + Mx : m] = K.at(L, c, m, n);
    }
  }
  Grid grid_;
  FftShape shape_;
  PrunedFft fft_;
  ConvolutionWorkspace kernel_, out_;
  std::array<ConvolutionWorkspace, kLoads> load_;
  std::array<bool, kLoads> active_{};
};

// The cheaper method by an operation count: per depth, the direct sum's multiply-adds against M log2 M per transform
// of the M-point periodic grid (a kernel's per load and component, and one back per component); by bench_subsurface a
// multiply-add costs about twice such a unit (direct wins below ~10 x 10 elements).
SubsurfaceMethod choose(const Grid& grid, const Loads& loads) {
  int n_loads = 0;
  for (bool a : loads.active) n_loads += a;
  const FftShape s = FftConvolution::shape(grid);
  const double M = static_cast<double>(s.Mx) * s.My;
  const double fft = M * std::log2(M) * (kComponents * n_loads + kComponents + n_loads);
  const double direct = static_cast<double>(loads.loaded.size()) * grid.size() * kComponents * n_loads;
  return direct < 0.5 * fft ? SubsurfaceMethod::direct : SubsurfaceMethod::fft;
}

void keep_max(StressMaximum& m, double v, double x, double y, double z) {
  if (v > m.value) m = {v, x, y, z};
}

// The derived measures of one depth, its maxima, and (with fields) its grids.
void derive(const Grid& grid, const Fields& s, bool fields, SubsurfaceDepth& d) {
  const std::size_t N = static_cast<std::size_t>(grid.size());
  if (fields) {
    d.sxx = s[0];
    d.syy = s[1];
    d.szz = s[2];
    d.sxy = s[3];
    d.sxz = s[4];
    d.syz = s[5];
    for (auto* v : {&d.s1, &d.s2, &d.s3, &d.von_mises, &d.tresca}) v->resize(N);
  }
  for (std::size_t k = 0; k < N; ++k) {
    const Stress t{s[0][k], s[1][k], s[2][k], s[3][k], s[4][k], s[5][k]};
    const PrincipalStresses p = principal_stresses(t);
    const double vm = von_mises(t), tr = p.s1 - p.s3;
    // Loads or sizes beyond any contact (1e300 Pa, depths of 1e160 m) could overflow the closed forms: refused here.
    if (!std::isfinite(vm) || !std::isfinite(tr))
      fail("subsurface: the stress at element {} at depth z = {} m is not finite (loads or sizes out of range)", k,
           d.z);
    const double x = grid.x(static_cast<int>(k % grid.nx)), y = grid.y(static_cast<int>(k / grid.nx));
    keep_max(d.von_mises_max, vm, x, y, d.z);
    keep_max(d.tresca_max, tr, x, y, d.z);
    if (!fields) continue;
    d.s1[k] = p.s1;
    d.s2[k] = p.s2;
    d.s3[k] = p.s3;
    d.von_mises[k] = vm;
    d.tresca[k] = tr;
  }
}

ShakedownPoint shakedown(const SurfaceLoad& load, const SubsurfaceRequest& request, double von_mises_max) {
  ShakedownPoint sd;
  double fn = 0, fx = 0, fy = 0;
  for (std::size_t k = 0; k < load.pressure.size(); ++k) {
    sd.p0 = std::max(sd.p0, load.pressure[k]);
    fn += load.pressure[k];
    if (!load.px.empty()) fx += load.px[k];
    if (!load.py.empty()) fy += load.py[k];
  }
  const double inf = std::numeric_limits<double>::infinity();
  sd.shear_yield = request.shear_yield;
  sd.load_factor = sd.p0 / sd.shear_yield;
  sd.traction_coefficient = fn > 0 ? std::hypot(fx, fy) / fn : 0.0;
  sd.elastic_limit = von_mises_max > 0 ? std::numbers::sqrt3 * sd.p0 / von_mises_max : inf;
  sd.map = request.map;
  sd.subsurface_limit = request.map == ShakedownMap::point ? kPointShakedownLimit : kLineShakedownLimit;
  sd.surface_limit = sd.traction_coefficient > 0 ? 1 / sd.traction_coefficient : inf;
  const double lambda = sd.load_factor;
  if (lambda <= sd.elastic_limit) sd.regime = ShakedownRegime::elastic;
  else if (lambda > sd.surface_limit) sd.regime = ShakedownRegime::ratchetting;
  else if (lambda > sd.subsurface_limit) sd.regime = ShakedownRegime::plastic_shakedown;
  else sd.regime = ShakedownRegime::elastic_shakedown;
  return sd;
}

void check_values(std::span<const double> v, std::size_t n, bool nonnegative, std::string_view what) {
  if (v.size() != n) fail("subsurface: {} has {} values, the grid {} elements", what, v.size(), n);
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(v[k]) || (nonnegative && v[k] < 0))
      fail("subsurface: {} of element {} is {} (expected a finite{} value, Pa)", what, k, v[k],
           nonnegative ? ", non-negative" : "");
}

void check_input(const Material& material, const SurfaceLoad& load, const SubsurfaceRequest& r) {
  validate(material, "subsurface");
  validate(load.grid, "subsurface");
  const std::size_t N = static_cast<std::size_t>(load.grid.size());
  check_values(load.pressure, N, true, "pressure");
  if (!load.px.empty()) check_values(load.px, N, false, "traction px");
  if (!load.py.empty()) check_values(load.py, N, false, "traction py");
  if (r.z.empty()) fail("subsurface: no depth z given (expected depths below the surface, m)");
  if (r.z.size() > kMaxSubsurfaceDepths)
    fail("subsurface: {} depths, at most {} per call", r.z.size(), kMaxSubsurfaceDepths);
  for (std::size_t d = 0; d < r.z.size(); ++d)
    if (!(std::isfinite(r.z[d]) && r.z[d] > 0))
      fail("subsurface: {} (= {}) must be a finite depth > 0 below the surface (m)", value_at(d, "z"), r.z[d]);
    else if (r.z[d] > kMaxSubsurfaceDepth)
      fail("subsurface: {} (= {} m) is deeper than {:g} m, below any wheel rim or rail head: is it in mm? (1 mm is "
           "z = 1e-3)", value_at(d, "z"), r.z[d], kMaxSubsurfaceDepth);
  if (r.fields && static_cast<double>(r.z.size()) * static_cast<double>(N) * 11 > kMaxSubsurfaceFieldValues)
    fail("subsurface: {} depths of {} elements make {} field values, more than {} (ask for fields = false: the "
         "maxima only)", r.z.size(), N, r.z.size() * N * 11, kMaxSubsurfaceFieldValues);
  check_shear_yield("subsurface", r.shear_yield);
  if (r.method != SubsurfaceMethod::automatic && r.method != SubsurfaceMethod::fft &&
      r.method != SubsurfaceMethod::direct)
    fail("subsurface: unknown method {}", static_cast<int>(r.method));
}

}  // namespace

void check_shear_yield(std::string_view context, double k) {
  if (std::isfinite(k) && k >= kMinShearYield && k <= kMaxShearYield) return;
  fail("{}: shear_yield = {} Pa must be in [{:g}, {:g}] Pa (the shear yield stress k; wheel steel ER7: {:.0f}e6): is it "
       "in MPa?", context, k, kMinShearYield, kMaxShearYield, kDefaultShearYield / 1e6);
}

PrincipalStresses principal_stresses(const Stress& s) {
  const double q = (s.xx + s.yy + s.zz) / 3;
  const double a = s.xx - q, b = s.yy - q, c = s.zz - q;
  const double off = s.xy * s.xy + s.xz * s.xz + s.yz * s.yz;
  const double p2 = (a * a + b * b + c * c + 2 * off) / 6;
  if (!(p2 > 0)) return {q, q, q};
  const double p = std::sqrt(p2);
  // det of the deviator over p^3, halved: cos(3 phi) of the eigenvalues q + 2 p cos(phi + 2 pi k / 3).
  const double det = a * (b * c - s.yz * s.yz) - s.xy * (s.xy * c - s.yz * s.xz) + s.xz * (s.xy * s.yz - b * s.xz);
  const double r = std::clamp(det / (2 * p * p2), -1.0, 1.0);
  const double phi = std::acos(r) / 3;
  const double s1 = q + 2 * p * std::cos(phi), s3 = q + 2 * p * std::cos(phi + 2 * std::numbers::pi / 3);
  return {s1, 3 * q - s1 - s3, s3};
}

double von_mises(const Stress& s) {
  const double d1 = s.xx - s.yy, d2 = s.yy - s.zz, d3 = s.zz - s.xx;
  return std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz));
}

double tresca(const Stress& s) {
  const PrincipalStresses p = principal_stresses(s);
  return p.s1 - p.s3;
}

Stress rectangle_stress(double nu, double x, double y, double z, double a, double b, double p, double qx, double qy) {
  if (!(z > 0) || !(a > 0) || !(b > 0))
    fail("rectangle_stress: z = {}, a = {}, b = {} (expected all > 0, m)", z, a, b);
  Components sum{};
  const double w[kLoads] = {p, qx, qy};
  for (int ia = 0; ia < 2; ++ia)
    for (int ib = 0; ib < 2; ++ib) {
      const double sign = (ia == 0 ? 1 : -1) * (ib == 0 ? 1 : -1);  // + at the lower bounds of xi and eta
      const auto g = stress_corners(x - (ia == 0 ? -a : a), y - (ib == 0 ? -b : b), z, nu);
      for (int L = 0; L < kLoads; ++L)
        for (int c = 0; c < kComponents; ++c) sum[c] += sign * w[L] * g[L][c];
    }
  return {sum[0], sum[1], sum[2], sum[3], sum[4], sum[5]};
}

SubsurfaceResult compute_subsurface(const Material& material, const SurfaceLoad& load,
                                    const SubsurfaceRequest& request) {
  check_input(material, load, request);
  const Grid& grid = load.grid;
  const Loads loads = gather(load, request.body);
  SubsurfaceResult r;
  r.grid = grid;
  r.nu = material.nu;
  r.body = request.body;
  r.method = request.method == SubsurfaceMethod::automatic ? choose(grid, loads) : request.method;
  std::unique_ptr<FftConvolution> fft;
  if (r.method == SubsurfaceMethod::fft && !loads.loaded.empty()) {
    fft = std::make_unique<FftConvolution>(grid);
    fft->set_loads(loads);
  }
  Fields s;
  Kernels K;
  for (double z : request.z) {
    for (auto& c : s) c.assign(static_cast<std::size_t>(grid.size()), 0.0);
    if (!loads.loaded.empty()) {
      K.build(grid, z, material.nu, loads.active);
      if (fft) fft->convolve(K, s);
      else convolve_direct(grid, K, loads, s);
    }
    SubsurfaceDepth& d = r.depths.emplace_back();
    d.z = z;
    derive(grid, s, request.fields, d);
    if (d.von_mises_max.value > r.von_mises_max.value) r.von_mises_max = d.von_mises_max;
    if (d.tresca_max.value > r.tresca_max.value) r.tresca_max = d.tresca_max;
  }
  r.shakedown = shakedown(load, request, r.von_mises_max.value);
  return r;
}

SubsurfaceRequest read_subsurface_request(OptionReader& o) {
  SubsurfaceRequest r;
  const auto z = o.number_list("z", {"m", "depths below the surface (required; > 0): an array or {from, to, step}"},
                               kMaxSubsurfaceDepths);
  if (!z && !o.documenting()) fail("{}: 'z' is required: the depths below the surface (m)", o.context());
  r.z = z.value_or(std::vector<double>{});
  const auto m = o.choice("method", {"auto", "fft", "direct"},
                          {"-", "per depth: zero-padded FFT, the direct sum, or the cheaper (auto)"}, "auto");
  r.method = m == "fft" ? SubsurfaceMethod::fft : m == "direct" ? SubsurfaceMethod::direct : SubsurfaceMethod::automatic;
  r.body = o.choice("body", {"wheel", "rail"}, {"-", "the stressed body (rail: the same pressure, the traction reversed)"},
                    body_name(r.body)) == "rail"
               ? StressedBody::rail
               : StressedBody::wheel;
  r.fields = o.boolean("fields", {"-", "keep every depth's stress grids (false: the maxima alone)"}, r.fields);
  r.shear_yield = o.number("shear_yield", {"Pa", "k of the shakedown point's load factor p0 / k"}, r.shear_yield);
  r.map = o.choice("shakedown_map", {"point", "line"},
                   {"-", "the subsurface limit of Johnson's map: point contact (4.7) or line contact (4.0)"},
                   map_name(r.map)) == "line"
              ? ShakedownMap::line
              : ShakedownMap::point;
  return r;
}

const char* method_name(SubsurfaceMethod m) {
  return m == SubsurfaceMethod::fft ? "fft" : m == SubsurfaceMethod::direct ? "direct" : "auto";
}
const char* body_name(StressedBody b) { return b == StressedBody::rail ? "rail" : "wheel"; }
const char* map_name(ShakedownMap m) { return m == ShakedownMap::line ? "line" : "point"; }
const char* regime_name(ShakedownRegime r) {
  switch (r) {
    case ShakedownRegime::elastic: return "elastic";
    case ShakedownRegime::elastic_shakedown: return "elastic shakedown";
    case ShakedownRegime::plastic_shakedown: return "plastic shakedown";
    case ShakedownRegime::ratchetting: return "ratchetting";
  }
  return "?";
}

namespace {

// The keys of a maximum: its value, its place (x, y in the grid's frame) and its depth (over all depths).
struct MaxKeys {
  const char *value, *x, *y, *z;
};
constexpr MaxKeys kVonMises{"von_mises_max", "von_mises_max_x", "von_mises_max_y", "von_mises_max_z"};
constexpr MaxKeys kTresca{"tresca_max", "tresca_max_x", "tresca_max_y", "tresca_max_z"};

// `what` names the stress; the depth only for the maximum over all depths (with_z).
void describe_max(FieldSink& out, const MaxKeys& k, const StressMaximum& m, bool with_z, std::string_view what) {
  const char* where = with_z ? "over all depths" : "at this depth";
  out.number(k.value, m.value, {"Pa", fmt::format("largest {} {}", what, where).c_str()});
  out.number(k.x, m.x, {"m", fmt::format("x of the largest {} (grid frame, along t1)", what).c_str()});
  out.number(k.y, m.y, {"m", fmt::format("y of the largest {} (grid frame, along t2)", what).c_str()});
  if (with_z) out.number(k.z, m.z, {"m", fmt::format("depth of the largest {}", what).c_str()});
}

void describe(const SubsurfaceDepth& d, const Grid& g, FieldSink& out) {
  out.number("z", d.z, {"m", "depth below the surface, into the stressed body"});
  describe_max(out, kVonMises, d.von_mises_max, false, "von Mises stress");
  describe_max(out, kTresca, d.tresca_max, false, "Tresca stress");
  if (d.sxx.empty()) return;
  // Stresses per element of the load's grid, tension positive; x along t1, y along t2, z the depth.
  const std::tuple<const char*, const std::vector<double>*, const char*> grids[] = {
      {"sigma_xx", &d.sxx, "normal stress along x, tension positive (x along t1, y along t2, z the depth)"},
      {"sigma_yy", &d.syy, "normal stress along y, tension positive"},
      {"sigma_zz", &d.szz, "normal stress along the depth z, tension positive (-p at the surface)"},
      {"sigma_xy", &d.sxy, "shear stress xy"},
      {"sigma_xz", &d.sxz, "shear stress xz"},
      {"sigma_yz", &d.syz, "shear stress yz"},
      {"sigma_1", &d.s1, "largest principal stress"},
      {"sigma_2", &d.s2, "middle principal stress"},
      {"sigma_3", &d.s3, "smallest principal stress"},
      {"von_mises", &d.von_mises, "von Mises stress"},
      {"tresca", &d.tresca, "Tresca stress sigma_1 - sigma_3"}};
  for (const auto& [name, v, meaning] : grids) out.grid(name, v->data(), g.nx, g.ny, {"Pa", meaning});
  std::vector<double> tau(d.tresca.size());
  for (std::size_t k = 0; k < tau.size(); ++k) tau[k] = 0.5 * d.tresca[k];
  out.grid("max_shear", tau.data(), g.nx, g.ny, {"Pa", "maximum shear stress tau_1 = (sigma_1 - sigma_3) / 2"});
}

}  // namespace

void describe(const SubsurfaceResult& r, FieldSink& out) {
  out.string("body", body_name(r.body), {"", "the stressed body: wheel (the tractions as solved) or rail (reversed)"});
  out.string("method", method_name(r.method), {"", "the method used: fft or direct"});
  out.number("nu", r.nu, {"-", "Poisson's ratio"});
  describe_max(out, kVonMises, r.von_mises_max, true, "von Mises stress");
  describe_max(out, kTresca, r.tresca_max, true, "Tresca stress");
  out.number("tau1_max", 0.5 * r.tresca_max.value, {"Pa", "largest maximum shear stress tau_1 (at tresca_max's place)"});
  const ShakedownPoint& s = r.shakedown;
  out.begin("shakedown", {"", "the patch's point on Johnson's shakedown map"});
  out.number("p0", s.p0, {"Pa", "the patch's peak pressure"});
  out.number("shear_yield", s.shear_yield, {"Pa", "shear yield stress k"});
  out.number("load_factor", s.load_factor, {"-", "p0 / k"});
  out.number("traction_coefficient", s.traction_coefficient, {"-", "mu = |(Fx, Fy)| / Fn of the tractions (0 without load)"});
  if (std::isfinite(s.elastic_limit))
    out.number("elastic_limit", s.elastic_limit, {"-", "p0 / k at first yield, sqrt(3) p0 / von_mises_max (absent without stress)"});
  out.number("subsurface_limit", s.subsurface_limit, {"-", "the map's subsurface shakedown limit of p0 / k"});
  if (std::isfinite(s.surface_limit))
    out.number("surface_limit", s.surface_limit, {"-", "the surface limit 1 / mu (absent for mu = 0)"});
  out.string("map", map_name(s.map), {"", "which of Johnson's maps: point or line contact"});
  out.string("regime", regime_name(s.regime), {"", "elastic, elastic shakedown, plastic shakedown or ratchetting"});
  out.end();
  out.begin_list("depths", r.depths.size(), {"", "one entry per requested depth, in the request's order"});
  for (const SubsurfaceDepth& d : r.depths) {
    out.item();
    describe(d, r.grid, out);
    out.end();
  }
  out.end();
}

}  // namespace wrc::halfspace
