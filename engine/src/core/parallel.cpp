// Worker threads: the thread count, parallel_for, progress (parallel.hpp).
#include "wrc/core/parallel.hpp"

#include "wrc/core/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

#include <sched.h>

namespace wrc {

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

ThreadCount thread_count(int asked, int cap, std::string_view why) {
  ThreadCount t;
  t.threads = std::clamp(asked > 0 ? asked : available_cores(), 1, std::max(1, cap));
  if (asked > t.threads) t.note = fmt::format("threads = {} asked for, {} used: {}", asked, t.threads, why);
  return t;
}

int read_threads(OptionReader& r, int fallback) {
  return r.integer("threads", 0, kMaxThreads, {"-", "worker threads (0: the cores available)"}, fallback);
}

void parallel_for(int count, int workers, const std::function<void(int worker, int task)>& body) {
  workers = std::clamp(workers, 1, std::max(1, count));
  if (workers == 1) {  // in order on the calling thread: the first task that throws is the lowest-numbered one
    for (int t = 0; t < count; ++t) body(0, t);
    return;
  }
  std::atomic<int> next{0};
  std::atomic<int> stop{count};  // the lowest-numbered task that threw (count: none); no task after it begins
  std::exception_ptr error;      // its exception
  std::mutex error_mutex;
  auto fail_at = [&](int task, std::exception_ptr e) {
    std::lock_guard lock(error_mutex);
    if (task < stop.load()) {
      stop = task;
      error = std::move(e);
    }
  };
  auto run = [&](int worker) {
    for (int t; (t = next.fetch_add(1)) < stop.load();) {
      try {
        body(worker, t);
      } catch (...) {
        fail_at(t, std::current_exception());
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  try {
    for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
  } catch (...) {  // a thread that cannot start: stop the ones that did, then report it
    fail_at(-1, std::current_exception());
  }
  run(0);
  for (std::thread& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

void ProgressCount::add(bool failed) {
  if (!report_) return;  // nobody to tell: no lock taken
  std::lock_guard lock(mutex_);
  ++done_;
  if (failed) ++failed_;
  report_(done_, total_, failed_);
}

}  // namespace wrc
