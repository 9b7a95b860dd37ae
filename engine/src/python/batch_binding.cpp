// Batch calls of Wheelset.contact, .wheel, .equilibrium and .rigid (python/wrc/batch.py, docs/python.md): when an
// argument that batches holds an array, the elements run through the call layer's batch runner (wrc/api/batch.hpp)
// on worker threads with the GIL released, each into its own FieldRecorder, and become a wrc.Batch that reads its
// fields and items from the trees when asked (batch_fields.hpp).
#include "python/batch_fields.hpp"
#include "python/bindings.hpp"
#include "python/convert.hpp"
#include "wrc/api/batch.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <deque>

namespace wrc::python {
namespace {

py::object batch_module() { return py::module_::import("wrc.batch"); }

// The most memory a batch call keeps for its results (bytes). Each element's result is a tree of fields held until the
// Batch is dropped: ws.rigid's takes about 29 KB (100,000 elements: 2.9 GB peak, measured with /usr/bin/time -v), a
// contact with its pressure grids far more; a batch of a million rigid elements asked for 29 GB and was ended by the
// system, not by a message.
constexpr double kBatchMaxBytes = 4e9;
// The elements whose results are averaged before the batch's total is projected from them.
constexpr std::size_t kBatchProbe = 8;

// Refuses a batch whose results would not fit kBatchMaxBytes, naming the size it would reach and the way out.
[[noreturn]] void batch_too_large(const api::BatchInput& input, double count, double per_element, const char* basis) {
  const double most = std::floor(kBatchMaxBytes / per_element);
  const OptionValue* grids = input.shared.find("grids");
  const bool with_grids = input.operation != "rigid" && !(grids && grids->type == OptionValue::Type::boolean &&
                                                          !grids->boolean);
  fail("{}: the batch's results would take about {:.1f} GB ({:.0f} elements of about {:.1f} KB each, {}), more than a "
       "batch call keeps ({:.0f} GB): split it into batches of at most {:.0f} elements{}", input.context,
       count * per_element / 1e9, count, per_element / 1e3, basis, kBatchMaxBytes / 1e9, most,
       with_grids ? " (or grids = False: no grids kept)" : "");
}

// Whether a value may make the call a batch: a list, a tuple, an array of one dimension or more, or a mapping (a
// nested table such as creepage) holding one. The common one-by-one call is decided here without importing numpy.
bool maybe_array(py::handle v, int depth = 0) {
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) return true;
  if (py::hasattr(v, "ndim")) return py::getattr(v, "ndim").cast<long>() > 0;
  if (depth == 0 && py::isinstance<py::dict>(v))
    for (auto item : py::reinterpret_borrow<py::dict>(v))
      if (maybe_array(item.second, 1)) return true;
  return false;
}

// The threads= argument, read by the call layer as every call reads it (0..256, 0: all cores).
int threads_argument(py::handle v, const char* context) {
  py::dict given;
  given["threads"] = v;
  const OptionTable t = mapping_options(given, context);
  return reading([&] {
    OptionReader r(t, context);
    const api::BatchOptions o = api::read_batch_options(r);
    r.finish();
    return o.threads;
  });
}

// An element's exception as a one-by-one call raises it, with .index (its index into the batch).
py::object element_error(const api::BatchElement& e, py::object result, py::tuple index) {
  py::object x = e.status == api::BatchStatus::not_converged ? error_class("NotConverged")(e.message, result)
                 : e.input                                    ? error_class("OptionError")(e.message)
                                                              : error_class("Error")(e.message);
  x.attr("index") = index;
  return x;
}

}  // namespace

py::object batch_call(PyWheelset& self, const char* operation, const char* context, const py::kwargs& kw) {
  bool arrays = false;
  for (auto item : kw) arrays |= item.first.cast<std::string>() == "threads" || maybe_array(item.second);
  if (!arrays) return py::none();  // a one-by-one call
  py::dict given(kw);
  py::object threads_given = given.attr("pop")("threads", py::none());
  const py::object split = batch_module().attr("split_batch")(context, given, api::batch_keys(operation),
                                                              error_class("OptionError"));
  if (split.is_none()) {
    if (threads_given.is_none()) return py::none();
    throw OptionFailure(fmt::format("{}: threads = is an option of batch calls: give an array for one of the keys of "
                                    "type number ({})", context, fmt::join(api::batch_keys(operation), ", ")));
  }
  const int threads = threads_given.is_none() ? 0 : threads_argument(threads_given, context);
  const auto model = self.get(context);
  const py::tuple parts = split.cast<py::tuple>();
  api::BatchInput input;
  input.operation = operation;
  input.context = context;
  input.shared = to_options(parts[0].cast<py::kwargs>(), context);
  const py::tuple shape = parts[3].cast<py::tuple>();
  const auto keys = parts[1].cast<std::vector<std::string>>();
  // What every element holds whatever its result (its recorder, its status, its column values twice: the contiguous
  // copy of the broadcast views and the engine's), checked before any of it is allocated (the count in floating
  // point: a broadcast shape's product may overflow); then each element's result as it is recorded (budget below).
  const double fixed = sizeof(FieldRecorder) + sizeof(api::BatchElement) + 2 * keys.size() * sizeof(double);
  double elements = 1;
  for (auto n : shape) elements *= n.cast<double>();
  if (elements * fixed > kBatchMaxBytes) batch_too_large(input, elements, fixed, "before any result");
  input.count = static_cast<std::size_t>(elements);
  const py::list columns = parts[2].cast<py::list>();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const auto a = columns[k].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
    input.columns.push_back({keys[k], std::vector<double>(a.data(), a.data() + a.size())});
  }

  std::deque<FieldRecorder> trees(input.count);
  // The results' memory, projected to the whole batch from the elements recorded so far (from kBatchProbe on): the
  // batch stops as soon as the projection exceeds kBatchMaxBytes, long before the memory is taken.
  std::atomic<std::size_t> kept_bytes{0}, recorded{0};
  std::atomic<bool> over{false};
  const auto within_budget = [&](std::size_t i) {
    const double bytes = static_cast<double>(kept_bytes += trees[i].bytes());
    const std::size_t n = ++recorded;
    const double total = n >= std::min(input.count, kBatchProbe) ? bytes / n * input.count : bytes;
    if (input.count * fixed + total <= kBatchMaxBytes) return true;
    over = true;
    return false;
  };
  api::BatchRun run;  // Ctrl-C: the elements not begun are skipped, KeyboardInterrupt raised, the results dropped
  run_interruptible([&](const std::atomic<bool>& stop) {
    run = api::run_batch(*model, input, [&](std::size_t i) -> FieldSink& { return trees[i]; },
                         {threads, &stop, within_budget});
  });
  if (over)
    batch_too_large(input, elements, fixed + static_cast<double>(kept_bytes) / recorded,
                    fmt::format("as the first {} took", recorded.load()).c_str());

  // The same bad input for every element is the call's (a misspelt key, a value of the wrong kind, a shared value out
  // of range): the input is wrong as a whole, so it is raised once, as the one-by-one call raises it, with the count
  // and the first element, rather than recorded as n copies of one error. Anything else is an element's, recorded.
  const auto& el = run.elements;
  const py::object unravel = py::module_::import("numpy").attr("unravel_index");
  const auto index_of = [&](std::size_t i) {
    py::list plain;
    for (auto n : py::tuple(unravel(i, shape))) plain.append(n.cast<long long>());
    return py::tuple(plain);
  };
  if (!el.empty() && std::all_of(el.begin(), el.end(), [&](const api::BatchElement& e) {
        return e.status == api::BatchStatus::failed && e.input && e.message == el.front().message;
      })) {
    const py::tuple first = index_of(0);
    py::object x = error_class("OptionError")(fmt::format("{} (every element of the batch fails so: all {}, the first "
                                                          "at index {})", el.front().message, el.size(),
                                                          py::repr(first).cast<std::string>()));
    x.attr("index") = first;
    PyErr_SetObject(error_class("OptionError").ptr(), x.ptr());
    throw py::error_already_set();
  }

  // The results stay in the engine's form (batch_fields.hpp): fields are stacked and items made when first read.
  auto kept = std::make_shared<BatchTrees>();
  kept->records.reserve(el.size());
  for (FieldRecorder& t : trees) kept->records.push_back(t.take());
  std::vector<bool> present(el.size());
  py::list errors;
  for (std::size_t i = 0; i < el.size(); ++i) {
    present[i] = el[i].status == api::BatchStatus::done;
    if (present[i]) continue;
    FieldRecord& record = kept->records[i];
    py::object result = el[i].status == api::BatchStatus::not_converged ? to_python(record.root()) : py::none();
    record = FieldRecord();  // not in the batch's fields: its memory back now
    errors.append(element_error(el[i], result, index_of(i)));
  }
  const py::object nodes = batch_nodes(std::move(kept), present);
  py::object b = batch_module().attr("Batch")(operation, shape, nodes, errors, run.threads, run.seconds);
  if (!run.threads_note.empty()) b.attr("threads_note") = run.threads_note;
  return b;
}

void register_batch(py::module_& m) {
  m.def("batch_keys", &api::batch_keys, py::arg("operation"),
        "The keys of an operation (contact, wheel, equilibrium, rigid) that may be arrays in a batch call: its keys of "
        "type number, from the engine's option table (a nested key as 'creepage.xi').");
  register_batch_fields(m);
}

}  // namespace wrc::python
