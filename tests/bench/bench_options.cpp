// Benchmark of parse_option_text (core/options: the C API's "key=value ..." strings) on large inputs: N distinct
// flat keys, N keys of one nested table ("t.kI=I"), N dotted keys of 8 levels, and one key nested N levels deep
// (refused past the depth limit). Prints the CPU time of each and its time per key, so that a quadratic parse
// shows as a time per key that grows with N.
//
//   bench_options [n=40000]
#include "wrc/core/options.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void run(const char* what, const std::string& text, std::size_t keys) {
  const double t0 = cpu_seconds();
  std::string outcome;
  try {
    const wrc::OptionTable t = wrc::parse_option_text(text, "bench");
    outcome = fmt::format("{} top-level entries", t.entries.size());
  } catch (const std::exception& e) {
    outcome = fmt::format("refused: {:.90}", e.what());
  }
  const double dt = cpu_seconds() - t0;
  fmt::print("{:<34} {:>9} bytes {:>10.4f} s CPU {:>9.3f} us/key   {}\n", what, text.size(), dt, 1e6 * dt / keys, outcome);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 40000;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "n=", 2) == 0) n = std::strtoul(argv[i] + 2, nullptr, 10);
  for (std::size_t m : {n / 4, n / 2, n}) {
    std::string flat, nested, deep8;
    for (std::size_t i = 0; i < m; ++i) {
      flat += fmt::format("k{}={} ", i, i);
      nested += fmt::format("t.k{}={} ", i, i);
      deep8 += fmt::format("a.b.c.d.e.f.g.k{}={} ", i, i);
    }
    fmt::print("-- {} keys\n", m);
    std::fflush(stdout);
    run("flat keys", flat, m);
    run("keys of one nested table", nested, m);
    run("keys 8 levels deep", deep8, m);
  }
  std::string deep;
  for (std::size_t i = 0; i < 30000; ++i) deep += "a.";
  deep += "a=1";
  run("one key 30001 levels deep", deep, 1);
  return 0;
}
