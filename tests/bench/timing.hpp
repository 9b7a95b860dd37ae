// The benchmarks' clock: this thread's CPU time (not disturbed by other processes' load), and the median of repeats.
#pragma once

#include <algorithm>
#include <ctime>
#include <functional>
#include <vector>

namespace wrc::bench {

// This thread's CPU time, ms.
inline double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// The median CPU time of `reps` calls of f, ms.
inline double median_ms(int reps, const std::function<void()>& f) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const double t0 = cpu_ms();
    f();
    t.push_back(cpu_ms() - t0);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace wrc::bench
