// Batch calls (Python's ws.wheel(y=np.linspace(...), Fz=1e5)): one operation of the call layer (calls.hpp) run
// for every element of a batch on worker threads, each element's result described into its own FieldSink or its
// error recorded, the others going on.
//
// An element's result does not depend on the thread count or on which elements ran before it on the same worker:
// each element is read from its own options table, and its worker's workspace forgets the previous element's areas
// before it (the warm start a Lua or C call never has either), so a batch equals the same calls made one by one,
// bit for bit.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/core/options.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wrc::api {

// The operations a batch runs: "contact", "wheel", "equilibrium", "rigid".
const std::vector<std::string>& batch_operations();

// The keys of `operation` whose value may vary over a batch: its keys of type "number" as api::operations()
// describes them (the pose, loads, creepages -- "creepage.xi" for a nested key --, speeds, friction, tolerances).
// Throws wrc::Error for an operation that is not a batch operation.
std::vector<std::string> batch_keys(const std::string& operation);

// The calls of a batch: the options every element shares, and columns of numbers, element i taking values[i] of
// each column under its key (a dotted key sets a nested table's entry: "creepage.xi").
struct BatchInput {
  std::string operation;  // one of batch_operations()
  std::string context;    // what the messages name, e.g. "ws.wheel"
  OptionTable shared;
  struct Column {
    std::string key;
    std::vector<double> values;  // `count` of them
  };
  std::vector<Column> columns;
  std::size_t count = 0;  // elements
  // Element i's options table. Throws wrc::Error for a column of the wrong length.
  OptionTable element(std::size_t i) const;
};

enum class BatchStatus {
  done,           // described into its sink
  failed,         // an error (bad input, a solver's exception): `message`, nothing described
  not_converged,  // a wheel or equilibrium solve that failed with on_failure = "error": `message` (the error a
                  // one-by-one call raises) and its result, converged = false, described into the sink
  skipped         // not begun: the batch was stopped (BatchOptions::stop)
};

struct BatchElement {
  BatchStatus status = BatchStatus::skipped;
  std::string message;  // the engine's message, for failed and not_converged
  bool input = false;   // failed on reading or validating its options (a front end's bad-argument error)
};

struct BatchOptions {
  int threads = 0;                          // worker threads (0: all cores; thread_count)
  const std::atomic<bool>* stop = nullptr;  // when it turns true, elements not yet begun are skipped
  // Called on the worker after each element ran (whatever its status), with the element's index; false skips the
  // elements not yet begun, as `stop` does (a front end's memory budget for the results it keeps). May be empty.
  std::function<bool(std::size_t element)> done;
};

// The batch's own options, beside its elements' keys: threads (read_threads: a whole number in 0..256, 0 for all
// cores, as a sweep reads it). `stop` is the front end's.
BatchOptions read_batch_options(OptionReader& r);

struct BatchRun {
  std::vector<BatchElement> elements;  // one per element, in order
  int threads = 1;                     // worker threads run
  std::string threads_note;            // why fewer than asked ran ("" otherwise)
  double seconds = 0;                  // wall time of the run
};

// Runs every element of `input` on the wheelset, element i described into sink(i) (called on the worker running
// it, once; the sinks must be distinct objects). Each worker has its own workspace, made by `workspace` (default:
// wheelset.make_workspace()). Throws wrc::Error only for an input that is wrong for every element (an operation
// not batched, a column of the wrong length); an element's own error is recorded in its BatchElement.
BatchRun run_batch(const Wheelset& wheelset, const BatchInput& input,
                   const std::function<FieldSink&(std::size_t element)>& sink, const BatchOptions& options = {},
                   const std::function<std::unique_ptr<ContactWorkspace>()>& workspace = {});

}  // namespace wrc::api
