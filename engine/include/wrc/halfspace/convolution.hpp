// Fast products with the influence matrix of a regular grid. On a regular grid the coefficient between
// two elements depends only on their offset, so the matrix is Toeplitz-block-Toeplitz and u = I * p is a
// linear convolution: computed by FFT as a circular convolution on a zero-padded periodic grid of
// Mx x My >= (2 nx - 2) x (2 ny - 2) points, with the kernel's spectrum computed once per shape.
//
// Threads: an InfluenceCache may be shared by any number of threads (it locks while it builds); the
// spectra it hands out are immutable; each thread brings its own ConvolutionWorkspace. FFTW's planner is
// not thread-safe, so every plan creation and destruction in wrc goes through one process-wide mutex;
// execution uses FFTW's new-array interface, which is safe from several threads at once.
#pragma once

#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/influence.hpp"

#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

namespace wrc::halfspace {

// The smallest size >= n among 7-smooth sizes up to 16 and 2^a {1, 9/8, 5/4, 3/2, 7/4} above (fft_shape's sizes
// beyond its table).
int fft_size(int n);
// The periodic size of the normal solver's FFT products: Mx >= min_x and My >= min_y that cost least by FFTW's
// measured speed per length (the table in convolution.cpp, from bench_fft_sizes): rows(My) row transforms of length
// Mx and Mx/2 + 1 column transforms of length My (pruned and cheaper so: two of length My/2, split_columns), with
// rows(My) = My/2 + 1 when the rows beyond are pruned (the linear product), else My. Deterministic (a fixed table), so
// results do not depend on the machine's timing.
struct FftShape {
  int Mx, My;
};
FftShape fft_shape(int min_x, int min_y, bool pruned);
// Whether a PrunedFft of My rows, `rows` of them holding data, runs its columns as two transforms of length My / 2
// (the first radix-2 stage by hand, which the zero rows make cheaper) instead of one of length My: My even, the
// transform pruned (rows < My), and the two shorter ones cheaper by the table of fft_shape (FFTW's cost per length is
// far from smooth: two 128-point columns cost less than half a 256-point one).
bool split_columns(int My, int rows);

// How hard FFTW's planner works: `measure` times candidate algorithms once per size (slower to build,
// faster to run), `estimate` picks one by heuristics.
enum class FftPlanning { estimate, measure };

struct FftPlans;  // a set of FFTW plans (convolution.cpp), shared through the process-wide plan cache

// The FFTW plans of the 2-D real transforms of an Mx x My periodic grid, pruned: at most the first `rows` rows
// are transformed along x (the input is zero beyond them, and the output is not needed there), so the 2-D
// transform runs as row transforms (one plan, run on each row that holds data) and batched column transforms.
// Immutable once built; execution is thread-safe (FFTW's new-array interface on buffers aligned like the
// workspace's). The plans come from a process-wide cache keyed by (Mx, My, rows, planning): a new model of the same
// grids (each step of the wear loop builds new wheelsets) plans nothing again, and the same plans give the same bits.
class PrunedFft {
 public:
  PrunedFft(int Mx, int My, int rows, FftPlanning planning);
  ~PrunedFft();
  PrunedFft(const PrunedFft&) = delete;
  PrunedFft& operator=(const PrunedFft&) = delete;
  int Mx() const { return Mx_; }
  int My() const { return My_; }
  int rows() const { return rows_; }
  int complex_size() const { return My_ * (Mx_ / 2 + 1); }
  // Forward (real -> spectrum, the input rows from `rows` on taken as zero) and backward transforms
  // (unnormalised; the output rows from `rows` on are left undefined); rows <= rows(), -1 for rows().
  void forward(double* in, void* spectrum, int rows = -1) const;
  void backward(void* spectrum, double* out, int rows = -1) const;
  // Split columns (split_columns): the spectrum's rows hold the even frequencies (row k: frequency 2k) and then the
  // odd ones (row m + k: 2k + 1, m = My / 2). arrange puts a spectrum in FFTW's order (real_spectrum's) into this one.
  bool split() const;
  void arrange(std::vector<double>& spectrum) const;
  // Whether both run the same FFTW plans (the cache's sharing, for the tests).
  bool shares_plans(const PrunedFft& other) const { return plans_ == other.plans_; }

 private:
  int row_count(int rows) const;
  int Mx_, My_, rows_;
  std::shared_ptr<const FftPlans> plans_;  // a row r2c, columns forward, columns backward, a row c2r
};

// The process-wide cache of FFTW plans (PrunedFft's and real_spectrum's): it keeps the most recently used
// kFftPlanCacheSize sets (least recently used dropped first; sets in use stay alive through their owners).
inline constexpr std::size_t kFftPlanCacheSize = 256;
struct FftPlanStats {
  std::size_t cached;  // plan sets held by the cache
  std::size_t built;   // plan sets built since the process started (one dropped and needed again counts again)
};
FftPlanStats fft_plan_stats();

// FFTW's planner is not thread-safe: every plan creation and destruction in wrc holds this lock.
std::mutex& fftw_planner_mutex();

// The spectrum (Mx/2 + 1 columns by My rows, FFTW's r2c layout, unnormalised) of a real kernel given on the
// Mx x My periodic grid (index k + Mx l) that is even, or odd in both directions, so that its spectrum is real.
std::vector<double> real_spectrum(const std::vector<double>& kernel, int Mx, int My);

// Spectrum of the influence kernel of elements dx x dy on an Mx x My periodic grid, and its FFTW plans.
// The kernel is embedded centred (slot s holds offset s for s <= M/2 and s - M above).
//  - linear: Mx, My >= 2 nx - 2, 2 ny - 2 (fft_shape); the circular convolution restricted to the grid is exactly
//    the product with the influence matrix. Serves grids with nx - 1 <= Mx/2 and ny - 1 <= My/2. The
//    transforms are pruned: rows beyond the grid's are known to be zero on the way in and are not needed
//    on the way out, so the 2-D transform runs as row transforms of the grid's rows and column transforms.
//  - periodic: Mx, My >= nx, ny (fft_shape); the grid itself made periodic. Its circulant inverse is the
//    preconditioner of the normal solver (cheap: no padding). Serves grids with nx <= Mx, ny <= My.
// Immutable once built.
class InfluenceSpectrum {
 public:
  enum class Kind { linear, periodic };
  InfluenceSpectrum(Kind kind, double dx, double dy, int Mx, int My, FftPlanning planning = FftPlanning::estimate);
  ~InfluenceSpectrum();
  InfluenceSpectrum(const InfluenceSpectrum&) = delete;
  InfluenceSpectrum& operator=(const InfluenceSpectrum&) = delete;

  Kind kind() const { return kind_; }
  int Mx() const { return Mx_; }
  int My() const { return My_; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }
  bool serves(const Grid& grid) const;
  int complex_size() const { return fft_.complex_size(); }
  int pruned_rows() const { return fft_.rows(); }  // rows transformed along x (My/2 + 1 linear, My periodic)
  const PrunedFft& fft() const { return fft_; }
  // Eigenvalues of the circulant (m), times 1/(Mx My) for FFTW's unnormalised round trip; real because
  // the kernel is even. `inverse` holds their reciprocals (times the same factor; clamped positive).
  const std::vector<double>& eigenvalues() const { return eigen_; }
  const std::vector<double>& inverse() const { return inverse_; }
  double min_eigenvalue() const { return min_eigen_; }  // before clamping, unscaled (m)
  // The coefficients I for offsets 0..Mx/2, 0..My/2 (for direct sums of a few elements).
  const InfluenceTable& table() const { return table_; }

  // Forward (real -> spectrum) and backward transforms of the workspace buffers, of the first `rows` rows.
  void forward(double* in, void* spectrum, int rows = -1) const { fft_.forward(in, spectrum, rows); }
  void backward(void* spectrum, double* out, int rows = -1) const { fft_.backward(spectrum, out, rows); }

 private:
  Kind kind_;
  double dx_, dy_;
  int Mx_, My_;
  PrunedFft fft_;
  InfluenceTable table_;
  std::vector<double> eigen_, inverse_;
  double min_eigen_ = 0;
};

// Buffers of one thread for the FFT round trips (FFTW-aligned). Grows on demand; not shareable.
class ConvolutionWorkspace {
 public:
  ConvolutionWorkspace() = default;
  ~ConvolutionWorkspace();
  ConvolutionWorkspace(const ConvolutionWorkspace&) = delete;
  ConvolutionWorkspace& operator=(const ConvolutionWorkspace&) = delete;
  ConvolutionWorkspace(ConvolutionWorkspace&& other) noexcept;
  ConvolutionWorkspace& operator=(ConvolutionWorkspace&& other) noexcept;

  // Makes room for a spectrum's transforms on `grid` and makes sure the input buffer is zero outside the
  // grid's window (the first ny rows' first nx values, rows of Mx). Callers write the window alone until they
  // prepare again: only the last window is cleared then.
  void prepare(const InfluenceSpectrum& spectrum, const Grid& grid) { prepare(spectrum.fft(), grid); }
  void prepare(const PrunedFft& fft, const Grid& grid);
  double* input() { return in_; }
  double* output() { return out_; }
  void* spectrum_buffer() { return spec_; }

 private:
  void release();
  double* in_ = nullptr;
  double* out_ = nullptr;
  void* spec_ = nullptr;
  std::size_t real_capacity_ = 0, complex_capacity_ = 0;
  int Mx_ = 0, My_ = 0;  // shape of the data in `in_`: zero outside the nx_ x ny_ window
  int nx_ = 0, ny_ = 0;
};

// u = scale * I * p: the 1/r integrals of the pressure field p over the grid at every element centre (units of p
// times m); p and u are grid vectors (index i + nx j), u may alias p. Needs a linear spectrum serving the
// grid (exact); with a periodic one it is the periodic approximation.
void convolve(const InfluenceSpectrum& spectrum, const Grid& grid, const double* p, double* u,
              ConvolutionWorkspace& workspace, double scale = 1.0);
// z = scale * C^-1 r: the inverse of the spectrum's circulant applied to r, read back on the grid (the FFT
// preconditioner of the normal solver); r and z grid vectors (z may alias r).
void deconvolve(const InfluenceSpectrum& spectrum, const Grid& grid, const double* r, double* z,
                ConvolutionWorkspace& workspace, double scale = 1.0);

// Thread-safe store of spectra keyed by (kind, dx, dy, Mx, My), built on first use. Logically part of
// an immutable model: get() is const. Keeps the most recently used spectra up to max_bytes of their memory
// (least recently used evicted first; spectra in use stay alive through their shared owners): a sweep meets a few
// hundred shapes (grids and their windows, both kinds, the coarse levels), each built once (a few ms) if it stays.
class InfluenceCache {
 public:
  explicit InfluenceCache(FftPlanning planning = FftPlanning::estimate, std::size_t max_bytes = std::size_t{256} << 20)
      : planning_(planning), max_bytes_(max_bytes) {}
  // The spectrum of the given kind for the grid's element size and shape (validates the grid).
  std::shared_ptr<const InfluenceSpectrum> get(const Grid& grid,
                                               InfluenceSpectrum::Kind kind = InfluenceSpectrum::Kind::linear) const;
  std::size_t size() const;
  std::size_t built() const;  // spectra built so far (one evicted and needed again counts again)
  FftPlanning planning() const { return planning_; }

 private:
  using Key = std::tuple<int, double, double, int, int>;
  struct Entry {
    std::shared_ptr<const InfluenceSpectrum> spectrum;
    std::size_t bytes = 0;
    std::list<Key>::iterator use;  // position in uses_ (front: most recent)
  };
  FftPlanning planning_;
  std::size_t max_bytes_;
  mutable std::mutex mutex_;
  mutable std::map<Key, Entry> entries_;
  mutable std::list<Key> uses_;
  mutable std::size_t bytes_ = 0, built_ = 0;
};

}  // namespace wrc::halfspace
