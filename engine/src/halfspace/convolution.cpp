// FFT convolution with the influence kernel (FFTW3, double precision).
#include "wrc/halfspace/convolution.hpp"

#include "wrc/halfspace/influence.hpp"
#include "wrc/core/error.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <type_traits>

namespace wrc::halfspace {
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
    {1, 9, 0}, {2, 10, 2}, {3, 13, 3}, {4, 13, 3}, {5, 14, 6}, {6, 14, 6},
    {7, 19, 8}, {8, 16, 7}, {9, 23, 12}, {10, 20, 11}, {12, 21, 12}, {14, 48, 17},
    {15, 36, 21}, {16, 35, 16}, {18, 66, 96}, {20, 68, 25}, {24, 86, 100}, {28, 91, 116},
    {30, 103, 354}, {32, 105, 44}, {36, 106, 225}, {40, 119, 256}, {42, 133, 201}, {48, 133, 174},
    {50, 142, 297}, {54, 180, 343}, {56, 121, 225}, {60, 204, 328}, {64, 163, 104}, {70, 170, 415},
    {72, 154, 277}, {80, 251, 390}, {84, 184, 462}, {90, 202, 584}, {96, 306, 472}, {98, 256, 441},
    {100, 219, 513}, {108, 362, 761}, {112, 241, 479}, {120, 253, 567}, {126, 413, 583}, {128, 217, 241},
    {140, 336, 606}, {144, 259, 932}, {150, 314, 741}, {160, 378, 745}, {162, 538, 1109}, {168, 431, 944},
    {180, 334, 1495}, {192, 378, 1485}, {196, 532, 1015}, {200, 402, 956}, {210, 596, 1907}, {216, 622, 1446},
    {224, 519, 1556}, {240, 503, 1862}, {250, 592, 1467}, {252, 829, 1395}, {256, 589, 1048}, {270, 908, 2424},
    {280, 816, 1988}, {288, 803, 2022}, {294, 1121, 1962}, {300, 623, 1960}, {320, 609, 1605}, {324, 1081, 2608},
    {336, 855, 2545}, {350, 1034, 2978}, {360, 1057, 3361}, {378, 1759, 2666}, {384, 770, 1750}, {392, 1085, 3090},
    {400, 797, 1983}, {420, 1473, 3293}, {432, 1314, 3583}, {448, 969, 2593}, {450, 1184, 3842}, {480, 998, 3236},
    {486, 1874, 4276}, {490, 1404, 4121}, {500, 1270, 3701}, {504, 1262, 3444}, {512, 1026, 2666}, {540, 1921, 4725},
    {560, 1592, 3911}, {576, 1232, 4147}, {588, 1666, 4460}, {600, 1739, 4344}, {630, 1688, 5509}, {640, 1289, 4492},
    {648, 1906, 5385}, {672, 2371, 5989}, {686, 2249, 4793}, {700, 2216, 5094}, {720, 2264, 5066}, {750, 2075, 6315},
    {756, 2232, 5985}, {768, 1673, 4100}, {784, 2294, 6190}, {800, 2241, 6170}, {810, 2222, 6910}, {840, 2848, 7563},
    {864, 2583, 7384}, {882, 3640, 6419}, {896, 2551, 5066}, {900, 2503, 8924}, {960, 2690, 6755}, {972, 3590, 9230},
    {980, 3098, 7840}, {1000, 2841, 7300}, {1008, 2966, 7071}, {1024, 2092, 6198}, {1050, 3025, 8907}, {1080, 3996, 11473},
    {1120, 3704, 8517}, {1134, 4840, 8563}, {1152, 2721, 9121}, {1176, 4955, 8218}, {1200, 3515, 8907}, {1250, 4092, 11732},
    {1260, 3620, 10193}, {1280, 3066, 10688}, {1296, 4736, 12095}, {1344, 4831, 12615}, {1350, 3998, 12289}, {1372, 4975, 10738},
    {1400, 4096, 11252}, {1440, 3618, 9249}, {1458, 6228, 14401}, {1470, 6368, 16825}, {1500, 4678, 13733}, {1512, 6603, 12993},
    {1536, 3340, 13657}, {1568, 5068, 14153}, {1600, 4245, 12060}, {1620, 4847, 18460}, {1680, 6750, 15761}, {1728, 5511, 15949},
    {1750, 5870, 17036}, {1764, 7656, 14450}, {1792, 5132, 15540}, {1800, 6075, 18736}, {1890, 8365, 22593}, {1920, 5010, 22335},
    {1944, 7711, 20302}, {1960, 5807, 17623}, {2000, 5211, 15822}, {2016, 7450, 15432}, {2048, 4447, 13464},
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

// The table's column cost of a length, or NaN when it has none (the table ascends by length).
double column_cost(int length) {
  const auto* c = std::lower_bound(std::begin(kLengthCosts), std::end(kLengthCosts), length,
                                   [](const LengthCost& e, int n) { return e.length < n; });
  return c != std::end(kLengthCosts) && c->length == length ? c->column : NAN;
}

// The cost of a column's two transforms split in two of half the length (PrunedFft::forward, backward): theirs and
// the hand-made stage's pass over the column each way; NaN when the table lacks the half length.
double split_cost(int length) { return length % 2 ? NAN : 2 * column_cost(length / 2) + 2 * kPointCost * length; }

}  // namespace

bool split_columns(int My, int rows) { return rows < My && split_cost(My) < column_cost(My); }  // NaN: no

FftShape fft_shape(int min_x, int min_y, bool pruned) {
  if (min_x < 1 || min_y < 1) fail("fft_shape: least size {} x {}, expected at least 1 x 1", min_x, min_y);
  const std::vector<LengthCost> xs = candidates(min_x), ys = candidates(min_y);
  FftShape best{xs.front().length, ys.front().length};
  double least = INFINITY;
  for (const LengthCost& y : ys) {
    const double rows = pruned ? y.length / 2 + 1 : y.length;
    const double column = pruned && split_columns(y.length, y.length / 2 + 1) ? split_cost(y.length) : y.column;
    for (const LengthCost& x : xs) {
      const double columns = x.length / 2 + 1;
      const double cost = rows * x.row + columns * column + kPointCost * columns * y.length;
      if (cost < least || (cost == least && x.length < best.Mx)) least = cost, best = {x.length, y.length};
    }
  }
  return best;
}

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

// A set of FFTW plans; destroyed under the planner lock.
struct FftPlans {
  fftw_plan plan[4] = {nullptr, nullptr, nullptr, nullptr};
  // Split columns (split_columns): exp(-i pi n / m) for n < m = My / 2, as (cos, sin) pairs; empty otherwise.
  std::vector<double> twiddle;
  FftPlans() = default;
  FftPlans(const FftPlans&) = delete;
  FftPlans& operator=(const FftPlans&) = delete;
  ~FftPlans() {
    std::lock_guard lock(fftw_planner_mutex());
    for (fftw_plan p : plan)
      if (p) fftw_destroy_plan(p);
  }
};

namespace {

// What a plan set transforms: PrunedFft's (rows > 0) or real_spectrum's plain 2-D r2c (rows = 0).
using PlanKey = std::tuple<int, int, int, int>;  // Mx, My, rows, planning

// PrunedFft's plans: one row transform (length Mx), run on each row that holds data, and the column transforms
// (length My, stride H) of all H columns, in place in the complex buffer. FFTW's new-array execution needs arrays
// aligned as the plan's: if the rows do not all start so (an odd Mx with FFTW's 16-byte SIMD alignment), the row
// plans are made unaligned. Called under the planner lock.
void plan_pruned(FftPlans& p, int Mx, int My, int rows, unsigned flags, double* in, double* out,
                 fftw_complex* spec) {
  const int H = Mx / 2 + 1;
  const bool rows_aligned = fftw_alignment_of(in + Mx) == fftw_alignment_of(in) &&
                            fftw_alignment_of(out + Mx) == fftw_alignment_of(out) &&
                            fftw_alignment_of(spec[H]) == fftw_alignment_of(spec[0]);
  const unsigned row_flags = flags | (rows_aligned ? 0u : FFTW_UNALIGNED);
  p.plan[0] = fftw_plan_dft_r2c_1d(Mx, in, spec, row_flags);
  p.plan[3] = fftw_plan_dft_c2r_1d(Mx, spec, out, row_flags);
  if (!split_columns(My, rows)) {
    int ny = My;
    p.plan[1] = fftw_plan_many_dft(1, &ny, H, spec, nullptr, H, 1, spec, nullptr, H, 1, FFTW_FORWARD, flags);
    p.plan[2] = fftw_plan_many_dft(1, &ny, H, spec, nullptr, H, 1, spec, nullptr, H, 1, FFTW_BACKWARD, flags);
    return;
  }
  // Columns of length m in both halves of the buffer: H columns (stride H) in each of 2 blocks of m rows.
  const int m = My / 2;
  const fftw_iodim column{m, H, H}, loops[2] = {{2, m * H, m * H}, {H, 1, 1}};
  p.plan[1] = fftw_plan_guru_dft(1, &column, 2, loops, spec, spec, FFTW_FORWARD, flags);
  p.plan[2] = fftw_plan_guru_dft(1, &column, 2, loops, spec, spec, FFTW_BACKWARD, flags);
  p.twiddle.resize(2 * static_cast<std::size_t>(m));
  for (int n = 0; n < m; ++n) {
    const double angle = std::numbers::pi * n / m;
    p.twiddle[2 * static_cast<std::size_t>(n)] = std::cos(angle);
    p.twiddle[2 * static_cast<std::size_t>(n) + 1] = -std::sin(angle);
  }
}

// Builds a plan set on scratch buffers allocated as the workspaces' (fftw_alloc: FFTW's SIMD alignment).
std::shared_ptr<const FftPlans> build_plans(const PlanKey& key, const char* who) {
  const auto [Mx, My, rows, planning] = key;
  const std::size_t nreal = static_cast<std::size_t>(Mx) * My;
  const std::size_t ncomplex = static_cast<std::size_t>(My) * (Mx / 2 + 1);
  double* in = fftw_alloc_real(nreal);
  double* out = fftw_alloc_real(nreal);
  fftw_complex* spec = fftw_alloc_complex(ncomplex);
  auto plans = std::make_shared<FftPlans>();
  bool planned = false;
  if (in && out && spec) {
    std::lock_guard lock(fftw_planner_mutex());
    const unsigned flags = planning == static_cast<int>(FftPlanning::measure) ? FFTW_MEASURE : FFTW_ESTIMATE;
    if (rows > 0) {
      plan_pruned(*plans, Mx, My, rows, flags, in, out, spec);
      planned = plans->plan[0] && plans->plan[1] && plans->plan[2] && plans->plan[3];
    } else {
      plans->plan[0] = fftw_plan_dft_r2c_2d(My, Mx, in, spec, flags);
      planned = plans->plan[0] != nullptr;
    }
  }
  fftw_free(in);
  fftw_free(out);
  fftw_free(spec);
  if (!planned) fail("{}: FFTW could not allocate or plan a {} x {} transform", who, Mx, My);  // ~FftPlans frees any made
  return plans;
}

// The process-wide store of plan sets: the most recently used kFftPlanCacheSize kept.
class PlanCache {
 public:
  std::shared_ptr<const FftPlans> get(const PlanKey& key, const char* who) {
    std::lock_guard lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      uses_.splice(uses_.begin(), uses_, it->second.use);
      return it->second.plans;
    }
    // Built under the cache's lock (the planner's lock serialises planning anyway); the lock order is always the
    // cache's, then the planner's.
    auto plans = build_plans(key, who);
    if (entries_.size() >= kFftPlanCacheSize) {  // drop the least recently used
      entries_.erase(uses_.back());
      uses_.pop_back();
    }
    uses_.push_front(key);
    entries_.emplace(key, Entry{plans, uses_.begin()});
    ++built_;
    return plans;
  }
  FftPlanStats stats() {
    std::lock_guard lock(mutex_);
    return {entries_.size(), built_};
  }

 private:
  struct Entry {
    std::shared_ptr<const FftPlans> plans;
    std::list<PlanKey>::iterator use;  // position in uses_ (front: most recent)
  };
  std::mutex mutex_;
  std::map<PlanKey, Entry> entries_;
  std::list<PlanKey> uses_;
  std::size_t built_ = 0;
};

PlanCache& plan_cache() {
  // Never destroyed: plans may still be released by other static objects at exit (their destructor takes the
  // planner's lock, made first so that it outlives them).
  static PlanCache* cache = (fftw_planner_mutex(), new PlanCache);
  return *cache;
}

std::shared_ptr<const FftPlans> cached_plans(const char* who, int Mx, int My, int rows, FftPlanning planning) {
  return plan_cache().get(PlanKey{Mx, My, rows, static_cast<int>(planning)}, who);
}

}  // namespace

FftPlanStats fft_plan_stats() { return plan_cache().stats(); }

PrunedFft::PrunedFft(int Mx, int My, int rows, FftPlanning planning) : Mx_(Mx), My_(My), rows_(rows) {
  if (Mx < 1 || My < 1 || rows < 1 || rows > My)
    fail("PrunedFft: periodic size {} x {} with {} rows is not valid", Mx, My, rows);
  plans_ = cached_plans("PrunedFft", Mx, My, rows, planning);
}

PrunedFft::~PrunedFft() = default;

int PrunedFft::row_count(int rows) const {
  if (rows < 0) return rows_;
  if (rows > rows_) fail("PrunedFft: {} rows of data, the transform holds {}", rows, rows_);
  return rows;
}

bool PrunedFft::split() const { return !plans_->twiddle.empty(); }

namespace {

// The hand-made radix-2 stage of split columns (split_columns), shared by forward and backward: rows n < m = My / 2
// that hold data (forward) or are needed (backward), each with row n + m; butterfly(a, b, c, s, both) on each element
// pair (a of row n, b of row n + m) with the twiddle w^n = c + i s. both is std::true_type where row n + m holds data
// or is needed too, else std::false_type: each case its own loop, without a test per element.
template <class Butterfly>
void row_pairs(fftw_complex* spec, std::size_t H, int m, int rows, const double* twiddle, Butterfly butterfly) {
  for (int n = 0; n < std::min(rows, m); ++n) {
    fftw_complex* a = spec + H * static_cast<std::size_t>(n);
    fftw_complex* b = a + H * static_cast<std::size_t>(m);
    const double c = twiddle[2 * n], s = twiddle[2 * n + 1];
    if (n + m < rows) {
      for (std::size_t q = 0; q < H; ++q) butterfly(a[q], b[q], c, s, std::true_type{});
    } else {
      for (std::size_t q = 0; q < H; ++q) butterfly(a[q], b[q], c, s, std::false_type{});
    }
  }
}

}  // namespace

void PrunedFft::forward(double* in, void* spectrum, int rows) const {
  rows = row_count(rows);
  auto* spec = static_cast<fftw_complex*>(spectrum);
  const std::size_t H = Mx_ / 2 + 1;
  const fftw_plan r2c = plans_->plan[0];
  for (int j = 0; j < rows; ++j) fftw_execute_dft_r2c(r2c, in + static_cast<std::size_t>(Mx_) * j, spec + H * j);
  if (!split()) {
    // The other rows of the input are zero, so are their row transforms.
    std::memset(static_cast<void*>(spec + H * rows), 0, sizeof(fftw_complex) * H * (My_ - rows));
    fftw_execute_dft(plans_->plan[1], spec, spec);
    return;
  }
  // The first radix-2 stage by hand: rows n and n + m become x_n + x_{n+m} and (x_n - x_{n+m}) w^n, whose length-m
  // transforms are the even and the odd frequencies; rows from `rows` on are zero.
  const int m = My_ / 2;
  row_pairs(spec, H, m, rows, plans_->twiddle.data(), [](double* a, double* b, double c, double s, auto both) {
    if constexpr (decltype(both)::value) {
      const double dr = a[0] - b[0], di = a[1] - b[1];
      a[0] += b[0], a[1] += b[1];
      b[0] = dr * c - di * s, b[1] = dr * s + di * c;
    } else {
      b[0] = a[0] * c - a[1] * s, b[1] = a[0] * s + a[1] * c;
    }
  });
  if (rows < m) {
    const std::size_t zero = sizeof(fftw_complex) * H * static_cast<std::size_t>(m - rows);
    std::memset(static_cast<void*>(spec + H * rows), 0, zero);
    std::memset(static_cast<void*>(spec + H * static_cast<std::size_t>(m + rows)), 0, zero);
  }
  fftw_execute_dft(plans_->plan[1], spec, spec);
}

void PrunedFft::backward(void* spectrum, double* out, int rows) const {
  rows = row_count(rows);
  auto* spec = static_cast<fftw_complex*>(spectrum);
  const std::size_t H = Mx_ / 2 + 1;
  fftw_execute_dft(plans_->plan[2], spec, spec);
  if (split()) {  // the last stage: rows n and n + m are e_n + w^-n o_n and e_n - w^-n o_n (those needed)
    row_pairs(spec, H, My_ / 2, rows, plans_->twiddle.data(), [](double* a, double* b, double c, double s, auto both) {
      const double br = b[0] * c + b[1] * s, bi = b[1] * c - b[0] * s;
      if constexpr (decltype(both)::value) b[0] = a[0] - br, b[1] = a[1] - bi;
      a[0] += br, a[1] += bi;
    });
  }
  const fftw_plan c2r = plans_->plan[3];
  for (int j = 0; j < rows; ++j) fftw_execute_dft_c2r(c2r, spec + H * j, out + static_cast<std::size_t>(Mx_) * j);
}

void PrunedFft::arrange(std::vector<double>& spectrum) const {
  if (!split()) return;
  const std::size_t H = Mx_ / 2 + 1, m = My_ / 2;
  if (spectrum.size() != H * My_) fail("PrunedFft: a spectrum of {} values for {} x {}", spectrum.size(), H, My_);
  std::vector<double> natural = spectrum;
  for (std::size_t k = 0; k < static_cast<std::size_t>(My_); ++k)  // frequency k to row k / 2 (even), m + k / 2 (odd)
    std::copy_n(natural.begin() + static_cast<std::ptrdiff_t>(H * k), H,
                spectrum.begin() + static_cast<std::ptrdiff_t>(H * (k % 2 ? m + k / 2 : k / 2)));
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
  std::vector<double> spectrum = real_spectrum(kernel, Mx, My);
  fft_.arrange(spectrum);
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
  // The plain 2-D transform (FFTW_ESTIMATE, from the plan cache), on buffers aligned as at planning.
  const auto plans = cached_plans("real_spectrum", Mx, My, 0, FftPlanning::estimate);
  double* in = fftw_alloc_real(nreal);
  fftw_complex* spec = fftw_alloc_complex(ncomplex);
  if (!in || !spec) {
    fftw_free(in);
    fftw_free(spec);
    fail("real_spectrum: cannot allocate FFT buffers for {} x {}", Mx, My);
  }
  std::copy(kernel.begin(), kernel.end(), in);
  fftw_execute_dft_r2c(plans->plan[0], in, spec);
  std::vector<double> out(ncomplex);
  for (std::size_t q = 0; q < ncomplex; ++q) out[q] = spec[q][0];
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
    std::memset(in_, 0, nreal * sizeof(double));
    Mx_ = My_ = nx_ = ny_ = 0;
  }
  // The input buffer is zero but for the last window (rows of Mx_): a window at least as large in the same layout
  // overwrites it; otherwise that window alone is cleared (the shear products alternate two layouts in one buffer).
  if (Mx_ != s.Mx() || My_ != s.My() || grid.nx < nx_ || grid.ny < ny_) {
    for (int j = 0; j < ny_; ++j) std::memset(in_ + static_cast<std::size_t>(Mx_) * j, 0, nx_ * sizeof(double));
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
  s.forward(in, spec, ny);
  const double* f = factor.data();
  const int nc = s.complex_size();
  for (int q = 0; q < nc; ++q) {
    const double fq = scale * f[q];
    spec[q][0] *= fq;
    spec[q][1] *= fq;
  }
  double* out = ws.output();
  s.backward(spec, out, ny);
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

}  // namespace wrc::halfspace
