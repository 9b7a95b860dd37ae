// Benchmark of the study runner (wrc.study, issue 13): peak memory against the number of cases. Runs
// tests/data/study/rigid_cases.lua -- one rigid-contact reference of the paper's wheelset per case -- as a separate
// `wrc run` process for 10^3, 10^4 and 10^5 cases, and prints for each its peak resident set (getrusage of the child,
// ru_maxrss), CPU and wall time, the CPU time per case, and the size of the table it wrote. Rows are streamed into the
// part files and merged line by line, so the peak stays flat while the table grows. `work=none` runs the same study
// without the engine (the runner alone).
//
//   bench_study_memory [max=100000] [work=rigid|none] [out=/tmp/wrc_bench_study]
#include "wrc/core/paths.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct Run {
  long max_rss_kb = 0;
  double cpu = 0, wall = 0;
  int status = -1;
};

// Runs `argv` and waits for it, with the child's own resource usage.
Run spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    execv(argv[0], argv.data());
    std::perror("execv");
    _exit(127);
  }
  Run r;
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.max_rss_kb = ru.ru_maxrss;
  r.cpu = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
          1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  return r;
}

std::string arg_value(int argc, char** argv, const std::string& key, const std::string& fallback) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind(key + "=", 0) == 0) return a.substr(key.size() + 1);
  }
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  const long max_cases = std::stol(arg_value(argc, argv, "max", "100000"));
  const std::string work = arg_value(argc, argv, "work", "rigid");
  const std::string out = arg_value(argc, argv, "out", "/tmp/wrc_bench_study");
  const std::filesystem::path self = std::filesystem::canonical("/proc/self/exe").parent_path();
  const char* env_bin = std::getenv("WRC_BIN");
  const std::string wrc = env_bin ? env_bin : (self / "wrc").string();
  const std::string study = wrc::paths().root + "/tests/data/study/rigid_cases.lua";
  double load[3] = {0, 0, 0};
  getloadavg(load, 3);
  fmt::print("study runner, peak memory against cases: {} ({} per case), load average {:.2f}\n", study, work, load[0]);
  fmt::print("{:>8} {:>12} {:>9} {:>9} {:>12} {:>12}\n", "cases", "peak RSS MB", "cpu s", "wall s", "cpu ms/case",
             "table MB");
  for (long n = 1000; n <= max_cases; n *= 10) {
    const std::string dir = fmt::format("{}/n{}", out, n);
    std::filesystem::remove_all(dir);
    const Run r = spawn({wrc, "run", study, fmt::format("cases={}", n), "batch=1000", "work=" + work, "out=" + dir});
    if (r.status != 0) {
      fmt::print(stderr, "wrc exited with {} for {} cases\n", r.status, n);
      return 1;
    }
    const double table_mb = static_cast<double>(std::filesystem::file_size(dir + "/rigid.csv")) / 1e6;
    fmt::print("{:>8} {:>12.1f} {:>9.2f} {:>9.2f} {:>12.4f} {:>12.2f}\n", n, r.max_rss_kb / 1024.0, r.cpu, r.wall,
               1e3 * r.cpu / static_cast<double>(n), table_mb);
    std::fflush(stdout);
  }
  std::filesystem::remove_all(out);
  return 0;
}
