// Cost of FFTW's transforms per length, as the normal solver's FFT products run them (PrunedFft: real row transforms
// r2c + c2r, one plan run on each row, and batched complex column transforms forward + backward, strided across the
// columns; FFTW_ESTIMATE plans). Prints one line per length: the length, ns per row (both directions), ns per column (both
// directions), in the form of the table kLengthCosts in engine/src/halfspace/convolution.cpp, which chooses the
// periodic sizes of the FFT products by these costs.
//
// FFTW's speed is far from smooth in the length: lengths with a direct SIMD codelet (up to 16, 20, 25, 32, 64, 128)
// cost 1-2 ns per point and column, the others 4-9 (a 112-point column costs twice a 128-point one). The table is
// the machine's measure of that; re-run this on another machine to compare.
//
//   bench_fft_sizes [from=1] [to=2048] [batch=65]
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

using Clock = std::chrono::steady_clock;

// Best of five means over >= 20 ms each, in ns.
template <class F>
double time_ns(F f) {
  double best = 1e300;
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = Clock::now();
    int n = 0;
    double elapsed = 0;
    do {
      f();
      ++n;
      elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
    } while (elapsed < 0.02);
    best = std::min(best, 1e9 * elapsed / n);
  }
  return best;
}

// The lengths the table holds: 7-smooth up to 16, even 7-smooth above.
bool candidate(int n) {
  if (n > 16 && n % 2) return false;
  for (int f : {2, 3, 5, 7})
    while (n % f == 0) n /= f;
  return n == 1;
}

}  // namespace

int main(int argc, char** argv) {
  int from = 1, to = 2048, batch = 65;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "from=", 5) == 0) from = std::max(1, std::atoi(argv[i] + 5));
    if (std::strncmp(argv[i], "to=", 3) == 0) to = std::atoi(argv[i] + 3);
    if (std::strncmp(argv[i], "batch=", 6) == 0) batch = std::max(1, std::atoi(argv[i] + 6));
  }
  std::printf("// length, ns per row (r2c + c2r), ns per column (forward + backward); batches of %d\n", batch);
  for (int M = from; M <= to; ++M) {
    if (!candidate(M)) continue;
    const int H = M / 2 + 1, K = batch;
    double* real = fftw_alloc_real(static_cast<std::size_t>(M) * K);
    fftw_complex* rows = fftw_alloc_complex(static_cast<std::size_t>(H) * K);
    fftw_complex* cols = fftw_alloc_complex(static_cast<std::size_t>(M) * K);
    for (int i = 0; i < M * K; ++i) real[i] = i % 5, cols[i][0] = i % 3, cols[i][1] = 0;
    int n = M;
    // Rows: K real rows of length M, contiguous, one row plan run on each (PrunedFft's plans 0 and 3).
    const unsigned row_flags = FFTW_ESTIMATE | (fftw_alignment_of(real + M) == fftw_alignment_of(real) ? 0u : FFTW_UNALIGNED);
    fftw_plan r2c = fftw_plan_dft_r2c_1d(M, real, rows, row_flags);
    fftw_plan c2r = fftw_plan_dft_c2r_1d(M, rows, real, row_flags);
    // Columns: K complex columns of length M, stride K, in place (PrunedFft's plans 1 and 2).
    fftw_plan fwd = fftw_plan_many_dft(1, &n, K, cols, nullptr, K, 1, cols, nullptr, K, 1, FFTW_FORWARD, FFTW_ESTIMATE);
    fftw_plan bwd = fftw_plan_many_dft(1, &n, K, cols, nullptr, K, 1, cols, nullptr, K, 1, FFTW_BACKWARD, FFTW_ESTIMATE);
    const double row = time_ns([&] {
                         for (int k = 0; k < K; ++k) fftw_execute_dft_r2c(r2c, real + M * k, rows + H * k);
                         for (int k = 0; k < K; ++k) fftw_execute_dft_c2r(c2r, rows + H * k, real + M * k);
                       }) / K;
    const double column = time_ns([&] { fftw_execute(fwd), fftw_execute(bwd); }) / K;
    std::printf("{%d, %.0f, %.0f},\n", M, row, column);
    for (fftw_plan p : {r2c, c2r, fwd, bwd}) fftw_destroy_plan(p);
    fftw_free(real);
    fftw_free(rows);
    fftw_free(cols);
  }
  return 0;
}
