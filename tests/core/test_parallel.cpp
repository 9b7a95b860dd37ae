// wrc::parallel_for, ProgressCount and thread_count (wrc/core/parallel.hpp) against a serial loop: every task once,
// the same results bit for bit on any number of workers, worker indices that name one thread each and never run two
// tasks at once, tasks handed out in increasing order, the lowest-numbered task's exception on the calling thread,
// and progress reports one at a time counting 1 .. total.
#include "wrc/core/parallel.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace wrc;

namespace {

// A task's result that a worker computes in its own workspace (a buffer it reuses and leaves dirty): a sum of a
// few thousand terms, which a changed order of additions would change in its last bits.
double task_value(int task, std::vector<double>& workspace) {
  workspace.resize(2000 + static_cast<std::size_t>(task % 17));
  for (std::size_t k = 0; k < workspace.size(); ++k) workspace[k] = std::sin(0.37 * task + 0.011 * static_cast<double>(k));
  double s = 0;
  for (double v : workspace) s += v / (1.0 + v * v);
  return s;
}

// The message of what parallel_for throws for `body` ("" when nothing).
std::string error_of(int count, int workers, const std::function<void(int, int)>& body) {
  try {
    parallel_for(count, workers, body);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("parallel_for: every task once, results bit for bit those of a serial loop on 1, 2, 3 and 8 workers") {
  const int count = 500;
  std::vector<double> serial(count), scratch;
  for (int t = 0; t < count; ++t) serial[static_cast<std::size_t>(t)] = task_value(t, scratch);
  for (int workers : {1, 2, 3, 8}) {
    CAPTURE(workers);
    std::vector<std::vector<double>> workspaces(static_cast<std::size_t>(workers));
    std::vector<double> out(count, std::nan(""));
    std::vector<std::atomic<int>> runs(count);
    parallel_for(count, workers, [&](int w, int t) {
      ++runs[static_cast<std::size_t>(t)];
      out[static_cast<std::size_t>(t)] = task_value(t, workspaces[static_cast<std::size_t>(w)]);
    });
    for (int t = 0; t < count; ++t) REQUIRE(runs[static_cast<std::size_t>(t)] == 1);
    CHECK(std::memcmp(out.data(), serial.data(), sizeof(double) * count) == 0);
  }
  int calls = 0;
  parallel_for(0, 4, [&](int, int) { ++calls; });  // no tasks: nothing runs
  CHECK(calls == 0);
}

TEST_CASE("parallel_for: worker indices name one thread each, worker 0 the caller's, tasks in increasing order") {
  const std::thread::id caller = std::this_thread::get_id();
  for (int workers : {1, 2, 4, 8}) {
    CAPTURE(workers);
    const int count = 400;
    std::mutex m;
    std::map<int, std::thread::id> thread_of;      // worker -> the thread that ran it
    std::map<int, std::vector<int>> tasks_of;      // worker -> its tasks in the order it ran them
    std::vector<std::atomic<int>> busy(static_cast<std::size_t>(workers));
    std::atomic<int> overlaps{0};
    parallel_for(count, workers, [&](int w, int t) {
      REQUIRE(w >= 0);
      REQUIRE(w < workers);
      if (busy[static_cast<std::size_t>(w)].fetch_add(1) != 0) ++overlaps;
      {
        std::lock_guard lock(m);
        const auto [it, first] = thread_of.emplace(w, std::this_thread::get_id());
        CHECK(it->second == std::this_thread::get_id());
        tasks_of[w].push_back(t);
      }
      std::this_thread::sleep_for(std::chrono::microseconds(20));  // long enough for the workers to interleave
      --busy[static_cast<std::size_t>(w)];
    });
    CHECK(overlaps == 0);
    // Worker 0 is the caller's thread when it ran a task; under load the others may take all tasks before it starts.
    if (const auto it = thread_of.find(0); it != thread_of.end()) CHECK(it->second == caller);
    if (workers == 1) REQUIRE(thread_of.count(0) == 1);
    std::vector<std::thread::id> threads;
    for (const auto& [w, id] : thread_of) threads.push_back(id);
    std::sort(threads.begin(), threads.end());
    CHECK(std::adjacent_find(threads.begin(), threads.end()) == threads.end());  // one thread per worker
    for (const auto& [w, tasks] : tasks_of) CHECK(std::is_sorted(tasks.begin(), tasks.end()));
    if (workers == 1) {
      REQUIRE(tasks_of[0].size() == static_cast<std::size_t>(count));
      for (int t = 0; t < count; ++t) CHECK(tasks_of[0][static_cast<std::size_t>(t)] == t);
    }
  }
  std::atomic<int> most{-1};
  parallel_for(3, 8, [&](int w, int) {  // more workers than tasks: no more workers than tasks
    for (int m = most; w > m && !most.compare_exchange_weak(m, w);) {
    }
  });
  CHECK(most < 3);
}

TEST_CASE("parallel_for: the exception of the lowest-numbered task that threw, rethrown on the calling thread") {
  // Tasks 45, 52, 59, ... throw (45 = the first task >= 40 with t % 7 == 3). A later one may throw first in time.
  auto throws = [](int t) { return t >= 40 && t % 7 == 3; };
  for (int workers : {1, 2, 3, 8}) {
    for (int rep = 0; rep < 20; ++rep) {
      CAPTURE(workers);
      std::vector<std::atomic<int>> runs(200);
      const std::string msg = error_of(200, workers, [&](int, int t) {
        ++runs[static_cast<std::size_t>(t)];
        if (t > 45 && t % 2 == 0) std::this_thread::yield();
        if (throws(t)) throw std::runtime_error("task " + std::to_string(t));
      });
      REQUIRE(msg == "task 45");
      for (int t = 0; t <= 45; ++t) REQUIRE(runs[static_cast<std::size_t>(t)] == 1);  // all before it ran, once
      if (workers == 1)
        for (int t = 46; t < 200; ++t) CHECK(runs[static_cast<std::size_t>(t)] == 0);  // none after it began
    }
  }
  // Tasks after the one that threw are not begun: with 10,000 slow tasks after task 5, far fewer than all run.
  std::atomic<int> ran{0};
  CHECK(error_of(10000, 4, [&](int, int t) {
    ++ran;
    if (t == 5) throw std::runtime_error("five");
    if (t > 5) std::this_thread::sleep_for(std::chrono::microseconds(50));
  }) == "five");
  CHECK(ran < 5000);
  // Any exception type crosses: not only std::exception.
  CHECK_THROWS_AS(parallel_for(10, 2, [](int, int t) {
    if (t == 7) throw 7;
  }), int);
}

TEST_CASE("ProgressCount: reports one at a time, done counting 1 .. total, failures counted, from many workers") {
  const int total = 2000;
  std::vector<int> dones;
  int last_failed = 0, calls_inside = 0, overlaps = 0;
  bool total_ok = true, failed_ok = true;
  ProgressCount progress(
      [&](int done, int all, int failed) {
        if (++calls_inside != 1) ++overlaps;  // a second call while one runs
        dones.push_back(done);
        total_ok = total_ok && all == total;
        failed_ok = failed_ok && failed >= last_failed && failed <= done;
        last_failed = failed;
        std::this_thread::yield();
        --calls_inside;
      },
      total);
  parallel_for(total, 4, [&](int, int t) { progress.add(t % 10 == 0); });
  CHECK(overlaps == 0);
  CHECK(total_ok);
  CHECK(failed_ok);
  CHECK(last_failed == total / 10);
  REQUIRE(dones.size() == static_cast<std::size_t>(total));
  for (int k = 0; k < total; ++k) REQUIRE(dones[static_cast<std::size_t>(k)] == k + 1);
  ProgressCount silent({}, 3);  // no callback: counts, calls nothing
  silent.add();
  silent.add(true);
}

TEST_CASE("thread_count: as asked within the cap, all cores for 0, at least 1, and a note when capped") {
  CHECK(available_cores() >= 1);
  CHECK(thread_count(0, 1000, "x").threads == std::min(available_cores(), 1000));
  CHECK(thread_count(0, 1000, "x").note.empty());  // all cores: nothing was asked that did not happen
  const ThreadCount two = thread_count(2, 8, "x");
  CHECK(two.threads == 2);
  CHECK(two.note.empty());
  const ThreadCount capped = thread_count(8, 3, "the work has 3 chunks");
  CHECK(capped.threads == 3);
  CHECK(capped.note == "threads = 8 asked for, 3 used: the work has 3 chunks");
  CHECK(thread_count(4, 0, "no work").threads == 1);
  CHECK(thread_count(4, 0, "no work").note == "threads = 4 asked for, 1 used: no work");
}
