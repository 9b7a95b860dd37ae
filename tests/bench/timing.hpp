// The benchmarks' clocks: this thread's CPU time (not disturbed by other processes' load), the median of repeats, and
// for benchmarks on several threads the process's CPU time, the wall time and the machine's load.
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace wrc::bench {

// This thread's CPU time, ms.
inline double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// This thread's CPU time, s.
inline double thread_cpu_s() { return cpu_ms() * 1e-3; }

// The CPU time of all the process's threads (user and system), s.
inline double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// A steady wall clock, s.
inline double wall_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The load averages of /proc/loadavg ("0.52 0.58 0.59"), "?" where there is none.
inline std::string loadavg() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a.empty() ? std::string("?") : a + " " + b + " " + c;
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
