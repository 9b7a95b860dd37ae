// Fast products with the pair's tangential influence matrix of a regular grid (influence.hpp): the displacement
// difference u = B q of a two-component traction field q = (q_x, q_y), each component constant on its element.
// As for the normal problem (convolution.hpp), B is a two-by-two block Toeplitz-block-Toeplitz matrix, so u is a
// linear convolution computed by zero-padded FFTs; its periodic counterpart, inverted frequency by frequency, is
// the preconditioner of the rolling solver.
//
// Threads: a ShearCache may be shared by any number of threads (it locks while it builds); the spectra are
// immutable; each thread brings its own ShearWorkspace.
#pragma once

#include "wrc/halfspace/convolution.hpp"
#include "wrc/halfspace/material.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

namespace wrc::halfspace {

// The three kernels' spectra of one grid shape (element dx x dy, m), and their FFT plans.
//  - linear: Mx, My >= 2n - 1 (fft_shape), so that every offset -(n-1)..n-1 has its own slot even for the odd B_xy;
//    the circular convolution restricted to the grid is exactly the product with B. Serves grids with
//    2 nx - 1 <= Mx and 2 ny - 1 <= My.
//  - periodic: Mx, My >= n (fft_shape): the grid made periodic; holds the INVERSE of the 2 x 2 symbol at every
//    frequency (B_xy's Nyquist offsets, which an odd kernel cannot have, are set to zero). Serves nx <= Mx, ny <= My.
// Both scaled by 1/(Mx My) for FFTW's unnormalised round trip. Immutable once built.
class ShearSpectrum {
 public:
  enum class Kind { linear, periodic };
  ShearSpectrum(Kind kind, const Material& material, double dx, double dy, int Mx, int My,
                FftPlanning planning = FftPlanning::estimate);
  Kind kind() const { return kind_; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }
  const PrunedFft& fft() const { return fft_; }
  bool serves(const Grid& grid) const;
  // The symbol (linear) or its inverse (periodic) at each frequency of the r2c layout: [xx xy; xy yy].
  const std::vector<double>& xx() const { return xx_; }
  const std::vector<double>& xy() const { return xy_; }
  const std::vector<double>& yy() const { return yy_; }

 private:
  Kind kind_;
  double dx_, dy_;
  PrunedFft fft_;
  std::vector<double> xx_, xy_, yy_;
};

// Buffers of one thread: one round-trip workspace per component.
struct ShearWorkspace {
  ConvolutionWorkspace x, y;
};

// (u_x, u_y) = B (q_x, q_y) on the grid (grid vectors, index i + nx j; m from Pa): needs a linear spectrum serving
// the grid. The outputs may alias the inputs.
void shear_convolve(const ShearSpectrum& spectrum, const Grid& grid, const double* qx, const double* qy, double* ux,
                    double* uy, ShearWorkspace& workspace);
// (q_x, q_y) = C^-1 (u_x, u_y), the inverse of the periodic circulant (Pa from m): needs a periodic spectrum.
void shear_deconvolve(const ShearSpectrum& spectrum, const Grid& grid, const double* ux, const double* uy, double* qx,
                      double* qy, ShearWorkspace& workspace);

// Thread-safe store of the spectra of one material, keyed by (kind, dx, dy, Mx, My), built on first use. Holds at
// most max_entries (then starts afresh; spectra in use stay alive through their shared owners).
class ShearCache {
 public:
  explicit ShearCache(const Material& material, FftPlanning planning = FftPlanning::estimate,
                      std::size_t max_entries = 64);
  std::shared_ptr<const ShearSpectrum> get(const Grid& grid, ShearSpectrum::Kind kind) const;
  const Material& material() const { return material_; }

 private:
  Material material_;
  FftPlanning planning_;
  std::size_t max_entries_;
  mutable std::mutex mutex_;
  mutable std::map<std::tuple<int, double, double, int, int>, std::shared_ptr<const ShearSpectrum>> entries_;
};

}  // namespace wrc::halfspace
