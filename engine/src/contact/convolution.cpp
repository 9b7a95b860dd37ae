// FFT convolution with the influence kernel (FFTW3, double precision).
#include "wrc/contact/convolution.hpp"

#include "wrc/contact/influence.hpp"
#include "wrc/core/error.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace wrc::contact {
int fft_size(int n) {
  if (n < 1) fail("fft_size: {} points, expected at least 1", n);
  for (long m = n; m <= 16; ++m) {
    long r = m;
    for (long f : {2, 3, 5, 7})
      while (r % f == 0) r /= f;
    if (r == 1) return static_cast<int>(m);
  }
  for (long base = 16;; base *= 2) {
    for (long num : {8, 9, 10, 12, 14}) {  // 2^a {1, 9/8, 5/4, 3/2, 7/4}
      const long m = base * num / 8;
      if (m >= n) return static_cast<int>(m);
    }
  }
}

int padded_size(int n) {
  if (n < 1) fail("padded_size: {} elements, expected at least 1", n);
  return fft_size(std::max(1, 2 * n - 2));  // M >= 2n - 2 gives floor(M/2) >= n - 1
}

namespace {

// FFTW's cost per length, as PrunedFft runs its transforms: ns per real row of that length (r2c + c2r) and per
// complex column (forward + backward, batched and strided). Measured by bench_fft_sizes (FFTW 3.3.10 of Debian 12,
// FFTW_ESTIMATE plans, AVX codelets). It is far from smooth: lengths with a direct SIMD codelet (<= 16, 20, 32, 64,
// 128) are 2-4x cheaper per point than their neighbours, so that a 128-point column costs half a 112-point one.
struct LengthCost {
  int length;
  double row, column;
};
constexpr LengthCost kLengthCosts[] = {
    {1, 1, 0}, {2, 2, 2}, {3, 3, 3}, {4, 4, 3}, {5, 6, 5}, {6, 6, 5},
    {7, 10, 8}, {8, 8, 8}, {9, 13, 12}, {10, 12, 11}, {12, 13, 12}, {14, 40, 17},
    {15, 30, 19}, {16, 30, 16}, {18, 66, 97}, {20, 36, 24}, {24, 88, 98}, {28, 93, 119},
    {30, 103, 340}, {32, 71, 39}, {36, 106, 227}, {40, 122, 267}, {42, 114, 201}, {48, 129, 175},
    {50, 142, 295}, {54, 176, 343}, {56, 121, 221}, {60, 201, 329}, {64, 173, 98}, {70, 170, 409},
    {72, 155, 277}, {80, 246, 393}, {84, 184, 457}, {90, 202, 578}, {96, 300, 444}, {98, 254, 433},
    {100, 219, 482}, {108, 360, 765}, {112, 241, 473}, {120, 254, 562}, {126, 412, 577}, {128, 412, 240},
    {140, 341, 588}, {144, 260, 935}, {150, 312, 742}, {160, 367, 722}, {162, 537, 1101}, {168, 435, 943},
    {180, 335, 1494}, {192, 371, 1466}, {196, 523, 1007}, {200, 397, 963}, {210, 596, 1848}, {216, 625, 1427},
    {224, 518, 1589}, {240, 498, 1959}, {250, 582, 1467}, {252, 832, 1383}, {256, 588, 1053}, {270, 907, 2393},
    {280, 814, 1951}, {288, 805, 2035}, {294, 1113, 1943}, {300, 622, 1928}, {320, 596, 1577}, {324, 1079, 2595},
    {336, 853, 2522}, {350, 1031, 2886}, {360, 1056, 3365}, {378, 1257, 2649}, {384, 747, 1771}, {392, 1077, 3114},
    {400, 792, 1980}, {420, 1460, 3243}, {432, 1325, 3569}, {448, 971, 2562}, {450, 1172, 3818}, {480, 986, 3190},
    {486, 1866, 4233}, {490, 1376, 4010}, {500, 1259, 3701}, {504, 1270, 3422}, {512, 1013, 2615}, {540, 1918, 4727},
    {560, 1607, 3984}, {576, 1213, 4012}, {588, 1654, 4417}, {600, 1724, 4408}, {630, 1660, 5585}, {640, 1257, 4442},
    {648, 1911, 5406}, {672, 2374, 6136}, {686, 2282, 4735}, {700, 2210, 5067}, {720, 2270, 5034}, {750, 2061, 6333},
    {756, 2214, 5873}, {768, 1628, 4117}, {784, 2285, 6217}, {800, 2230, 6183}, {810, 2204, 6904}, {840, 2850, 7558},
    {864, 2579, 7354}, {882, 3637, 6415}, {896, 2540, 5134}, {900, 2518, 8917}, {960, 2672, 6798}, {972, 3541, 9151},
    {980, 3038, 7782}, {1000, 2827, 7340}, {1008, 2947, 7009}, {1024, 2065, 6111}, {1050, 2969, 9008}, {1080, 3988, 11300},
    {1120, 3721, 8561}, {1134, 4794, 8536}, {1152, 2710, 8877}, {1176, 4949, 8314}, {1200, 3483, 8748}, {1250, 4112, 11775},
    {1260, 3647, 10071}, {1280, 2998, 10427}, {1296, 4670, 12105}, {1344, 4750, 12730}, {1350, 3965, 11971}, {1372, 5061, 10814},
    {1400, 4098, 11328}, {1440, 3573, 9232}, {1458, 6176, 14230}, {1470, 6302, 16671}, {1500, 4573, 13492}, {1512, 6535, 12861},
    {1536, 3278, 13675}, {1568, 5020, 14039}, {1600, 4168, 11785}, {1620, 4755, 17161}, {1680, 6313, 15636}, {1728, 5430, 15985},
    {1750, 5850, 16246}, {1764, 7584, 14386}, {1792, 5046, 15647}, {1800, 5918, 18621}, {1890, 8299, 21845}, {1920, 4958, 21487},
    {1944, 7626, 20259}, {1960, 5788, 17546}, {2000, 5212, 15621}, {2016, 7396, 15235}, {2048, 4419, 13363},
};
// Per complex point of the spectrum: the product with the kernel's spectrum and the buffers' traffic.
constexpr double kPointCost = 0.5;

// The table's lengths from `least` up to 2 least + 16 (a longer one never pays), else fft_size(least) alone.
std::vector<LengthCost> candidates(int least) {
  std::vector<LengthCost> out;
  for (const LengthCost& c : kLengthCosts)
    if (c.length >= least && c.length <= 2 * least + 16) out.push_back(c);
  if (out.empty()) out.push_back({fft_size(least), 0, 0});  // beyond the table: one size, nothing to compare
  return out;
}

}  // namespace

FftShape fft_shape(int min_x, int min_y, bool pruned) {
  if (min_x < 1 || min_y < 1) fail("fft_shape: least size {} x {}, expected at least 1 x 1", min_x, min_y);
  const std::vector<LengthCost> xs = candidates(min_x), ys = candidates(min_y);
  FftShape best{xs.front().length, ys.front().length};
  double least = INFINITY;
  for (const LengthCost& x : xs)
    for (const LengthCost& y : ys) {
      const double rows = pruned ? y.length / 2 + 1 : y.length, columns = x.length / 2 + 1;
      const double cost = rows * x.row + columns * y.column + kPointCost * columns * y.length;
      if (cost < least) least = cost, best = {x.length, y.length};
    }
  return best;
}

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

PrunedFft::PrunedFft(int Mx, int My, int rows, FftPlanning planning) : Mx_(Mx), My_(My), rows_(rows) {
  if (Mx < 1 || My < 1 || rows < 1 || rows > My)
    fail("PrunedFft: periodic size {} x {} with {} rows is not valid", Mx, My, rows);
  const int H = Mx / 2 + 1;  // complex values per row of the r2c transform
  const std::size_t nreal = static_cast<std::size_t>(Mx) * My;
  const std::size_t ncomplex = static_cast<std::size_t>(My) * H;
  double* in = fftw_alloc_real(nreal);
  double* out = fftw_alloc_real(nreal);
  fftw_complex* spec = fftw_alloc_complex(ncomplex);
  bool planned = false;
  if (in && out && spec) {
    // Row transforms (length Mx, contiguous) of the first rows_ rows, and column transforms (length My,
    // stride H) of all H columns, in place in the complex buffer.
    std::lock_guard lock(fftw_planner_mutex());
    const unsigned flags = planning == FftPlanning::measure ? FFTW_MEASURE : FFTW_ESTIMATE;
    int nx = Mx, ny = My;
    plans_[0] = fftw_plan_many_dft_r2c(1, &nx, rows_, in, nullptr, 1, Mx, spec, nullptr, 1, H, flags);
    plans_[1] = fftw_plan_many_dft(1, &ny, H, spec, nullptr, H, 1, spec, nullptr, H, 1, FFTW_FORWARD, flags);
    plans_[2] = fftw_plan_many_dft(1, &ny, H, spec, nullptr, H, 1, spec, nullptr, H, 1, FFTW_BACKWARD, flags);
    plans_[3] = fftw_plan_many_dft_c2r(1, &nx, rows_, spec, nullptr, 1, H, out, nullptr, 1, Mx, flags);
    planned = plans_[0] && plans_[1] && plans_[2] && plans_[3];
  }
  fftw_free(in);
  fftw_free(out);
  fftw_free(spec);
  if (!planned) {
    {
      std::lock_guard lock(fftw_planner_mutex());
      for (void*& plan : plans_)
        if (plan) fftw_destroy_plan(static_cast<fftw_plan>(plan)), plan = nullptr;
    }
    fail("PrunedFft: FFTW could not allocate or plan a {} x {} transform", Mx, My);
  }
}

PrunedFft::~PrunedFft() {
  std::lock_guard lock(fftw_planner_mutex());
  for (void* plan : plans_)
    if (plan) fftw_destroy_plan(static_cast<fftw_plan>(plan));
}

void PrunedFft::forward(double* in, void* spectrum) const {
  auto* spec = static_cast<fftw_complex*>(spectrum);
  fftw_execute_dft_r2c(static_cast<fftw_plan>(plans_[0]), in, spec);
  // Rows rows_..My-1 of the input are zero, so are their row transforms.
  const std::size_t H = Mx_ / 2 + 1;
  std::memset(static_cast<void*>(spec + H * rows_), 0, sizeof(fftw_complex) * H * (My_ - rows_));
  fftw_execute_dft(static_cast<fftw_plan>(plans_[1]), spec, spec);
}

void PrunedFft::backward(void* spectrum, double* out) const {
  auto* spec = static_cast<fftw_complex*>(spectrum);
  fftw_execute_dft(static_cast<fftw_plan>(plans_[2]), spec, spec);
  fftw_execute_dft_c2r(static_cast<fftw_plan>(plans_[3]), spec, out);  // rows >= rows_ are not needed
}

InfluenceSpectrum::InfluenceSpectrum(Kind kind, double dx, double dy, int Mx, int My, FftPlanning planning)
    : kind_(kind), dx_(dx), dy_(dy), Mx_(Mx), My_(My), fft_(Mx, My, kind == Kind::linear ? My / 2 + 1 : My, planning),
      table_(dx, dy, std::max(1, Mx / 2 + 1), std::max(1, My / 2 + 1)) {
  const int H = Mx / 2 + 1;
  const InfluenceTable& table = table_;
  const std::size_t nreal = static_cast<std::size_t>(Mx) * My;
  const std::size_t ncomplex = static_cast<std::size_t>(My) * H;
  std::vector<double> kernel(nreal);
  for (int l = 0; l < My; ++l) {
    const int n = std::min(l, My - l);
    for (int k = 0; k < Mx; ++k) kernel[k + static_cast<std::size_t>(Mx) * l] = table(std::min(k, Mx - k), n);
  }
  const std::vector<double> spectrum = real_spectrum(kernel, Mx, My);
  const double scale = 1.0 / static_cast<double>(nreal);
  eigen_.resize(ncomplex);
  inverse_.resize(ncomplex);
  double largest = 0;
  min_eigen_ = INFINITY;
  for (double v : spectrum) {
    largest = std::max(largest, v);
    min_eigen_ = std::min(min_eigen_, v);
  }
  // The circulant of this positive, decreasing kernel is positive definite (checked in the tests); the
  // clamp only guards the preconditioner against a tiny high-frequency eigenvalue.
  const double floor = 1e-12 * largest;
  for (std::size_t q = 0; q < ncomplex; ++q) {
    eigen_[q] = spectrum[q] * scale;
    inverse_[q] = scale / std::max(spectrum[q], floor);
  }
}

InfluenceSpectrum::~InfluenceSpectrum() = default;

bool InfluenceSpectrum::serves(const Grid& grid) const {
  if (grid.dx != dx_ || grid.dy != dy_) return false;
  if (kind_ == Kind::linear) return grid.nx - 1 <= Mx_ / 2 && grid.ny - 1 <= My_ / 2;
  return grid.nx <= Mx_ && grid.ny <= My_;
}

std::vector<double> real_spectrum(const std::vector<double>& kernel, int Mx, int My) {
  const int H = Mx / 2 + 1;
  const std::size_t nreal = static_cast<std::size_t>(Mx) * My;
  const std::size_t ncomplex = static_cast<std::size_t>(My) * H;
  if (kernel.size() != nreal) fail("real_spectrum: {} values for a {} x {} grid", kernel.size(), Mx, My);
  double* in = fftw_alloc_real(nreal);
  fftw_complex* spec = fftw_alloc_complex(ncomplex);
  fftw_plan full = nullptr;  // plain 2-D transform, once per kernel
  if (in && spec) {
    std::lock_guard lock(fftw_planner_mutex());
    full = fftw_plan_dft_r2c_2d(My, Mx, in, spec, FFTW_ESTIMATE);
  }
  if (!full) {
    fftw_free(in);
    fftw_free(spec);
    fail("real_spectrum: FFTW could not allocate or plan a {} x {} transform", Mx, My);
  }
  std::copy(kernel.begin(), kernel.end(), in);
  fftw_execute(full);
  std::vector<double> out(ncomplex);
  for (std::size_t q = 0; q < ncomplex; ++q) out[q] = spec[q][0];
  {
    std::lock_guard lock(fftw_planner_mutex());
    fftw_destroy_plan(full);
  }
  fftw_free(in);
  fftw_free(spec);
  return out;
}

ConvolutionWorkspace::~ConvolutionWorkspace() { release(); }

ConvolutionWorkspace::ConvolutionWorkspace(ConvolutionWorkspace&& o) noexcept
    : in_(o.in_), out_(o.out_), spec_(o.spec_), real_capacity_(o.real_capacity_),
      complex_capacity_(o.complex_capacity_), Mx_(o.Mx_), My_(o.My_), nx_(o.nx_), ny_(o.ny_) {
  o.in_ = o.out_ = nullptr;
  o.spec_ = nullptr;
  o.real_capacity_ = o.complex_capacity_ = 0;
  o.Mx_ = o.My_ = o.nx_ = o.ny_ = 0;
}

ConvolutionWorkspace& ConvolutionWorkspace::operator=(ConvolutionWorkspace&& o) noexcept {
  if (this != &o) {
    release();
    std::swap(in_, o.in_);
    std::swap(out_, o.out_);
    std::swap(spec_, o.spec_);
    std::swap(real_capacity_, o.real_capacity_);
    std::swap(complex_capacity_, o.complex_capacity_);
    std::swap(Mx_, o.Mx_);
    std::swap(My_, o.My_);
    std::swap(nx_, o.nx_);
    std::swap(ny_, o.ny_);
  }
  return *this;
}

void ConvolutionWorkspace::release() {
  fftw_free(in_);
  fftw_free(out_);
  fftw_free(spec_);
  in_ = out_ = nullptr;
  spec_ = nullptr;
  real_capacity_ = complex_capacity_ = 0;
  Mx_ = My_ = nx_ = ny_ = 0;
}

void ConvolutionWorkspace::prepare(const PrunedFft& s, const Grid& grid) {
  const std::size_t nreal = static_cast<std::size_t>(s.Mx()) * s.My();
  const std::size_t ncomplex = static_cast<std::size_t>(s.complex_size());
  if (nreal > real_capacity_ || ncomplex > complex_capacity_) {
    release();
    // fftw_alloc gives FFTW's SIMD alignment, the same as the buffers the plans were made with, as the
    // new-array execute functions require.
    in_ = fftw_alloc_real(nreal);
    out_ = fftw_alloc_real(nreal);
    spec_ = fftw_alloc_complex(ncomplex);
    if (!in_ || !out_ || !spec_) {
      release();
      fail("ConvolutionWorkspace: cannot allocate FFT buffers for {} x {}", s.Mx(), s.My());
    }
    real_capacity_ = nreal;
    complex_capacity_ = ncomplex;
  }
  if (Mx_ != s.Mx() || My_ != s.My() || grid.nx < nx_ || grid.ny < ny_) {
    std::memset(in_, 0, nreal * sizeof(double));  // then only windows at least as large are written
    Mx_ = s.Mx();
    My_ = s.My();
  }
  nx_ = grid.nx;
  ny_ = grid.ny;
}

namespace {

// One round trip: window of `src` -> spectrum -> multiplied by `factor` -> window of `dst`.
void round_trip(const InfluenceSpectrum& s, const Grid& grid, const double* src, double* dst,
                const std::vector<double>& factor, double scale, ConvolutionWorkspace& ws) {
  if (!s.serves(grid))
    fail("convolve: spectrum {} x {} of {} x {} m elements does not serve a {} x {} grid of {} x {} m", s.Mx(),
         s.My(), s.dx(), s.dy(), grid.nx, grid.ny, grid.dx, grid.dy);
  ws.prepare(s, grid);
  const int Mx = s.Mx(), nx = grid.nx, ny = grid.ny;
  double* in = ws.input();
  for (int j = 0; j < ny; ++j)
    std::memcpy(in + static_cast<std::size_t>(Mx) * j, src + static_cast<std::size_t>(nx) * j, nx * sizeof(double));
  auto* spec = static_cast<fftw_complex*>(ws.spectrum_buffer());
  s.forward(in, spec);
  const double* f = factor.data();
  const int nc = s.complex_size();
  for (int q = 0; q < nc; ++q) {
    const double fq = scale * f[q];
    spec[q][0] *= fq;
    spec[q][1] *= fq;
  }
  double* out = ws.output();
  s.backward(spec, out);
  for (int j = 0; j < ny; ++j)
    std::memcpy(dst + static_cast<std::size_t>(nx) * j, out + static_cast<std::size_t>(Mx) * j, nx * sizeof(double));
}

}  // namespace

void convolve(const InfluenceSpectrum& s, const Grid& grid, const double* p, double* u, ConvolutionWorkspace& ws,
              double scale) {
  round_trip(s, grid, p, u, s.eigenvalues(), scale, ws);
}

void deconvolve(const InfluenceSpectrum& s, const Grid& grid, const double* r, double* z, ConvolutionWorkspace& ws,
                double scale) {
  round_trip(s, grid, r, z, s.inverse(), scale, ws);
}

std::shared_ptr<const InfluenceSpectrum> InfluenceCache::get(const Grid& grid, InfluenceSpectrum::Kind kind) const {
  validate(grid, "InfluenceCache");
  const bool linear = kind == InfluenceSpectrum::Kind::linear;
  // Linear: M >= 2n - 2 gives floor(M/2) >= n - 1, a slot for every offset; its rows beyond My/2 + 1 are pruned.
  const FftShape shape = linear ? fft_shape(std::max(1, 2 * grid.nx - 2), std::max(1, 2 * grid.ny - 2), true)
                                : fft_shape(grid.nx, grid.ny, false);
  const Key key = std::make_tuple(static_cast<int>(kind), grid.dx, grid.dy, shape.Mx, shape.My);
  {
    std::lock_guard lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      uses_.splice(uses_.begin(), uses_, it->second.use);
      return it->second.spectrum;
    }
  }
  // Built outside the lock (a few ms: other threads go on with the spectra they need); a thread that built the
  // same one meanwhile wins.
  auto spectrum = std::make_shared<const InfluenceSpectrum>(kind, grid.dx, grid.dy, std::get<3>(key),
                                                            std::get<4>(key), planning_);
  std::lock_guard lock(mutex_);
  if (auto it = entries_.find(key); it != entries_.end()) return it->second.spectrum;
  const std::size_t bytes = sizeof(double) * (2 * static_cast<std::size_t>(spectrum->complex_size()) +
                                              static_cast<std::size_t>(spectrum->table().mx()) * spectrum->table().my());
  while (!uses_.empty() && bytes_ + bytes > max_bytes_) {  // evict the least recently used
    const auto old = entries_.find(uses_.back());
    bytes_ -= old->second.bytes;
    entries_.erase(old);
    uses_.pop_back();
  }
  uses_.push_front(key);
  entries_.emplace(key, Entry{spectrum, bytes, uses_.begin()});
  bytes_ += bytes;
  ++built_;
  return spectrum;
}

std::size_t InfluenceCache::built() const {
  std::lock_guard lock(mutex_);
  return built_;
}

std::size_t InfluenceCache::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace wrc::contact
