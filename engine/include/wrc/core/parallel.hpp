// Work on worker threads, written once for the sweeps, the geometry tables and the strategy checks: how many threads
// run (thread_count), one loop over numbered tasks (parallel_for), the progress it reports (ProgressCount) and the
// front end's stop flag (stop_requested).
//
// Results must not depend on the number of threads: a task writes only its own outputs and keeps its state in the
// workspace of the worker running it (the worker index says which), so the same tasks give the same bytes on 1, 2 or
// 8 threads. parallel_for hands the tasks out in increasing order, and a failure is the lowest-numbered task's.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>

namespace wrc {

// The processors this process may run on (its CPU affinity mask, as a SLURM or taskset allocation restricts it;
// at least 1).
int available_cores();

// The worker threads to run when `asked` were asked for (0: available_cores()) and the work has use for `cap` at most
// (at least 1 runs). When fewer than asked run, `note` says so and why: "threads = 8 asked for, 2 used: <why>".
struct ThreadCount {
  int threads = 1;
  std::string note;  // "" when 0 (all cores) or no more than `cap` were asked for
};
ThreadCount thread_count(int asked, int cap, std::string_view why);

class OptionReader;
// The most worker threads a call may ask for: far beyond any machine this runs on, so that a larger number is a typo.
inline constexpr int kMaxThreads = 256;
// The key "threads" of a call that runs on worker threads (a sweep, a geometry table, a batch, a strategy check):
// a whole number in 0..kMaxThreads, 0 for all the cores available; `fallback` when absent.
int read_threads(OptionReader& r, int fallback);

// Runs body(worker, task) for task = 0 .. count-1 on `workers` threads (fewer when there are fewer tasks; worker in
// 0 .. workers-1, one task at a time each, so that a worker may keep a workspace of its own). Tasks are handed out
// in increasing order, each to the next free worker; worker 0 is the calling thread, and one worker runs everything
// there (a Lua strategy bound to the caller's state stays on it). When tasks throw, the tasks after the
// lowest-numbered one that threw are not begun, and its exception is rethrown on the calling thread once every
// worker has stopped: the same error on any number of workers, when whether a task throws depends on the task alone.
void parallel_for(int count, int workers, const std::function<void(int worker, int task)>& body);

// The stop flag a front end hands a long call (Ctrl-C in Python: SweepOptions, BatchOptions, GeometryTableOptions,
// StrategyCheckOptions): true once it is set; a call without one (nullptr) is never stopped. A task checks it before
// it begins, so the tasks under way finish.
inline bool stop_requested(const std::atomic<bool>* stop) {
  return stop != nullptr && stop->load(std::memory_order_relaxed);
}

// Progress of work counted in units (cases, rows, poses): units done, units in all, units of those done that failed.
using Progress = std::function<void(int done, int total, int failed)>;

// Counts units finished on any worker and reports each count to a Progress, one call at a time, `done` going up by
// one from call to call (1 .. total). An empty Progress is not called.
class ProgressCount {
 public:
  ProgressCount(Progress report, int total) : report_(std::move(report)), total_(total) {}
  void add(bool failed = false);

 private:
  Progress report_;
  std::mutex mutex_;
  int total_ = 0, done_ = 0, failed_ = 0;
};

}  // namespace wrc
