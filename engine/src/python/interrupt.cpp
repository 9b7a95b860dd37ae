// Ctrl-C during a long call (bindings.hpp, run_interruptible). Python runs signal handlers on the main thread only
// when it holds the GIL, and a call of worker threads releases it for its whole run: so the call runs on a thread of
// its own and the calling thread polls PyErr_CheckSignals between waits. 50 ms is below what a person notices and
// costs nothing beside solves of milliseconds to seconds.
#include "python/bindings.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <thread>

namespace wrc::python {

void run_interruptible(const std::function<void(const std::atomic<bool>& stop)>& work) {
  constexpr auto kPoll = std::chrono::milliseconds(50);
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  bool done = false, interrupted = false;
  std::mutex mutex;
  std::condition_variable finished;
  {
    py::gil_scoped_release release;
    std::thread runner([&] {
      try {
        work(stop);
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, kPoll, [&] { return done; })) {
      if (interrupted) continue;  // stopped: waiting for the workers to end
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        interrupted = PyErr_CheckSignals() != 0;  // the handler's exception stays set for this thread
      }
      if (interrupted) stop = true;
      lock.lock();
    }
    lock.unlock();
    runner.join();
  }
  if (interrupted) throw py::error_already_set();
  if (error) std::rethrow_exception(error);
}

}  // namespace wrc::python
