// FFT products with the tangential influence matrix (shear.hpp).
#include "wrc/halfspace/shear.hpp"

#include "wrc/halfspace/influence.hpp"
#include "wrc/core/error.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace wrc::halfspace {
namespace {

// Signed offset of periodic slot s of M: s up to M/2, s - M above; the Nyquist slot of an even M is flagged.
int offset_of(int s, int M, bool& nyquist) {
  nyquist = (M % 2 == 0) && s == M / 2;
  return s <= M / 2 ? s : s - M;
}

// The kernels of one component pair embedded centred on the Mx x My periodic grid.
std::vector<double> embed(const ShearInfluenceTable& t, int Mx, int My, int which) {
  std::vector<double> k(static_cast<std::size_t>(Mx) * My);
  for (int l = 0; l < My; ++l)
    for (int c = 0; c < Mx; ++c) {
      bool nx_ = false, ny_ = false;
      const int m = offset_of(c, Mx, nx_), n = offset_of(l, My, ny_);
      double v = which == 0 ? t.xx(m, n) : which == 2 ? t.yy(m, n) : t.xy(m, n);
      if (which == 1 && (nx_ || ny_)) v = 0;  // an odd kernel has no value at the Nyquist offset
      k[static_cast<std::size_t>(c) + static_cast<std::size_t>(Mx) * l] = v;
    }
  return k;
}

}  // namespace

ShearSpectrum::ShearSpectrum(Kind kind, const Material& material, double dx, double dy, int Mx, int My,
                             FftPlanning planning)
    : kind_(kind), dx_(dx), dy_(dy), fft_(Mx, My, kind == Kind::linear ? My / 2 + 1 : My, planning) {
  const ShearInfluenceTable table(material, dx, dy, Mx / 2 + 1, My / 2 + 1);
  xx_ = real_spectrum(embed(table, Mx, My, 0), Mx, My);
  xy_ = real_spectrum(embed(table, Mx, My, 1), Mx, My);
  yy_ = real_spectrum(embed(table, Mx, My, 2), Mx, My);
  for (auto* v : {&xx_, &xy_, &yy_}) fft_.arrange(*v);
  const double scale = 1.0 / (static_cast<double>(Mx) * My);
  if (kind == Kind::linear) {
    for (auto* v : {&xx_, &xy_, &yy_})
      for (double& x : *v) x *= scale;
    return;
  }
  // The symbol of the Cerruti kernel is positive definite; its periodic truncation stays so in practice. The floor
  // on the determinant only guards the preconditioner against a near-singular high frequency.
  double largest = 0;
  for (std::size_t q = 0; q < xx_.size(); ++q) largest = std::max(largest, xx_[q] * yy_[q]);
  for (std::size_t q = 0; q < xx_.size(); ++q) {
    const double a = xx_[q], b = xy_[q], c = yy_[q];
    const double det = std::max(a * c - b * b, 1e-12 * largest);
    xx_[q] = scale * c / det;
    xy_[q] = -scale * b / det;
    yy_[q] = scale * a / det;
  }
}

bool ShearSpectrum::serves(const Grid& grid) const {
  if (grid.dx != dx_ || grid.dy != dy_) return false;
  if (kind_ == Kind::linear) return 2 * grid.nx - 1 <= fft_.Mx() && 2 * grid.ny - 1 <= fft_.My();
  return grid.nx <= fft_.Mx() && grid.ny <= fft_.My();
}

namespace {

// One two-component round trip: windows of (sx, sy) -> spectra -> the 2 x 2 symbol -> windows of (dx_, dy_).
void shear_round_trip(const ShearSpectrum& s, const Grid& grid, const double* sx, const double* sy, double* ox,
                      double* oy, ShearWorkspace& ws) {
  if (!s.serves(grid))
    fail("shear_convolve: spectrum {} x {} of {} x {} m elements does not serve a {} x {} grid of {} x {} m",
         s.fft().Mx(), s.fft().My(), s.dx(), s.dy(), grid.nx, grid.ny, grid.dx, grid.dy);
  const PrunedFft& f = s.fft();
  ws.x.prepare(f, grid);
  ws.y.prepare(f, grid);
  const int Mx = f.Mx(), nx = grid.nx, ny = grid.ny;
  for (int j = 0; j < ny; ++j) {
    std::memcpy(ws.x.input() + static_cast<std::size_t>(Mx) * j, sx + static_cast<std::size_t>(nx) * j, nx * sizeof(double));
    std::memcpy(ws.y.input() + static_cast<std::size_t>(Mx) * j, sy + static_cast<std::size_t>(nx) * j, nx * sizeof(double));
  }
  auto* X = static_cast<fftw_complex*>(ws.x.spectrum_buffer());
  auto* Y = static_cast<fftw_complex*>(ws.y.spectrum_buffer());
  f.forward(ws.x.input(), X, ny);
  f.forward(ws.y.input(), Y, ny);
  const double *a = s.xx().data(), *b = s.xy().data(), *c = s.yy().data();
  const int nc = f.complex_size();
  for (int q = 0; q < nc; ++q) {
    const double xr = X[q][0], xi = X[q][1], yr = Y[q][0], yi = Y[q][1];
    X[q][0] = a[q] * xr + b[q] * yr;
    X[q][1] = a[q] * xi + b[q] * yi;
    Y[q][0] = b[q] * xr + c[q] * yr;
    Y[q][1] = b[q] * xi + c[q] * yi;
  }
  f.backward(X, ws.x.output(), ny);
  f.backward(Y, ws.y.output(), ny);
  for (int j = 0; j < ny; ++j) {
    std::memcpy(ox + static_cast<std::size_t>(nx) * j, ws.x.output() + static_cast<std::size_t>(Mx) * j, nx * sizeof(double));
    std::memcpy(oy + static_cast<std::size_t>(nx) * j, ws.y.output() + static_cast<std::size_t>(Mx) * j, nx * sizeof(double));
  }
}

}  // namespace

void shear_convolve(const ShearSpectrum& s, const Grid& grid, const double* qx, const double* qy, double* ux,
                    double* uy, ShearWorkspace& ws) {
  if (s.kind() != ShearSpectrum::Kind::linear) fail("shear_convolve: needs a linear spectrum");
  shear_round_trip(s, grid, qx, qy, ux, uy, ws);
}

void shear_deconvolve(const ShearSpectrum& s, const Grid& grid, const double* ux, const double* uy, double* qx,
                      double* qy, ShearWorkspace& ws) {
  if (s.kind() != ShearSpectrum::Kind::periodic) fail("shear_deconvolve: needs a periodic spectrum");
  shear_round_trip(s, grid, ux, uy, qx, qy, ws);
}

ShearCache::ShearCache(const Material& material, FftPlanning planning, std::size_t max_entries)
    : material_(material), planning_(planning), max_entries_(max_entries) {
  validate(material, "ShearCache");
}

std::shared_ptr<const ShearSpectrum> ShearCache::get(const Grid& grid, ShearSpectrum::Kind kind) const {
  validate(grid, "ShearCache");
  const bool linear = kind == ShearSpectrum::Kind::linear;
  // The sizes of least cost (fft_shape, as the normal products); linear: every offset -(n-1)..n-1 its own slot.
  const FftShape shape = linear ? fft_shape(2 * grid.nx - 1, 2 * grid.ny - 1, true) : fft_shape(grid.nx, grid.ny, false);
  const auto key = std::make_tuple(static_cast<int>(kind), grid.dx, grid.dy, shape.Mx, shape.My);
  std::lock_guard lock(mutex_);
  if (auto it = entries_.find(key); it != entries_.end()) return it->second;
  if (entries_.size() >= max_entries_) entries_.clear();
  auto s = std::make_shared<const ShearSpectrum>(kind, material_, grid.dx, grid.dy, std::get<3>(key),
                                                 std::get<4>(key), planning_);
  entries_.emplace(key, s);
  return s;
}

}  // namespace wrc::halfspace
