// The Python module wrc._wrc (docs/python.md): a front end beside the Lua binding and the C API. Each binding file
// converts keyword arguments into an OptionTable (convert.hpp), reads the request of the call layer
// (wrc/api/calls.hpp) from it, runs it with the GIL released and converts the result it recorded
// (wrc/core/field_record.hpp).
// No default, check or option list of its own: the engine's readers and api::operations() are the one source.
#pragma once

#include "wrc/core/error.hpp"
#include "wrc/profile/profile.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <pybind11/pybind11.h>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace wrc::python {

namespace py = pybind11;

// Errors the translator (errors.cpp) raises as the Python classes of wrc._errors: an engine error while reading a
// call's keys (OptionError, also a ValueError), while loading a profile (ProfileError), and an object used after
// close() (Error). Any other wrc::Error becomes wrc.Error.
struct OptionFailure : Error {
  using Error::Error;
};
struct ProfileFailure : Error {
  using Error::Error;
};

// Runs f, turning a wrc::Error it throws into an OptionFailure (the reading of a call's keys and its validate()).
template <class F>
auto reading(F&& f) {
  try {
    return f();
  } catch (const OptionFailure&) {
    throw;
  } catch (const Error& e) {
    throw OptionFailure(e.what());
  }
}

// The exception class wrc._errors.<name> (python/wrc/_errors.py: Error, OptionError, ProfileError, NotConverged).
py::object error_class(const char* name);

// Raises wrc.NotConverged(message, result).
[[noreturn]] void raise_not_converged(const std::string& message, py::object result);

// A profile as Python holds it: close() drops it.
struct PyProfile {
  std::shared_ptr<const Profile> profile;
  const Profile& get(const char* context) const;  // wrc.Error after close()
};

// A wheelset and its pool of workspaces (one taken per call: calls from several Python threads run at once).
struct PyWheelset {
  std::shared_ptr<const Wheelset> model;
  // Whether a result's under-resolved contact area was shown (once per wheelset, its trajectories and sweeps included)
  std::shared_ptr<std::atomic<bool>> resolution_shown = std::make_shared<std::atomic<bool>>(false);
  std::mutex pool_mutex;
  std::vector<std::unique_ptr<ContactWorkspace>> pool;
  std::shared_ptr<const Wheelset> get(const char* context) const;  // wrc.Error after close()
  // Drops the model and the idle workspaces; a call in progress keeps its own reference and drops its workspace
  // when it ends (Lease), before the model it was made from.
  void close();
};

// A workspace of the wheelset's pool for one call, started cold (a result does not depend on earlier calls).
class Lease {
 public:
  Lease(PyWheelset& w, std::shared_ptr<const Wheelset> model);
  ~Lease();
  Lease(const Lease&) = delete;
  Lease& operator=(const Lease&) = delete;
  ContactWorkspace& operator*() { return *ws_; }

 private:
  PyWheelset& w_;
  std::unique_ptr<ContactWorkspace> ws_;
};

// Runs work(stop) -- a long call of worker threads: a batch, a sweep -- on a thread of its own while the calling thread
// (holding the GIL on entry) waits without it, waking every 50 ms to let Python run its signal handlers. When one
// raises (Ctrl-C: KeyboardInterrupt), `stop` turns true, work is waited for -- it must begin nothing more, let its
// workers finish what they are doing and return or throw -- and the exception propagates; work's own error otherwise
// (interrupt.cpp).
void run_interruptible(const std::function<void(const std::atomic<bool>& stop)>& work);

// A batch call (batch_binding.cpp) when an argument of `operation` that batches holds an array, or threads= is
// given: the wrc.Batch of the elements. None for a one-by-one call.
py::object batch_call(PyWheelset& self, const char* operation, const char* context, const py::kwargs& kw);

void register_batch(py::module_& m);
void register_errors(py::module_& m);
void register_profile(py::module_& m);
void register_wheelset(py::module_& m);
void register_track(py::module_& m);  // after register_wheelset: properties of wrc.Wheelset

}  // namespace wrc::python
