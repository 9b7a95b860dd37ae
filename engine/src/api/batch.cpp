// Batch calls (wrc/api/batch.hpp): the elements' tables, one operation per element on parallel_for's workers.
#include "wrc/api/batch.hpp"

#include "wrc/api/calls.hpp"
#include "wrc/api/operations.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>

namespace wrc::api {
namespace {

// Sets `value` under a dotted key ("creepage.xi"), copying the nested tables on the way (they are shared).
void set_dotted(OptionTable& table, std::string_view key, OptionValue value) {
  const std::size_t dot = key.find('.');
  if (dot == std::string_view::npos) {
    table.set(std::string(key), std::move(value));
    return;
  }
  const std::string head(key.substr(0, dot));
  const OptionValue* old = table.find(head);
  OptionTable nested = old && old->type == OptionValue::Type::table && old->table ? *old->table : OptionTable{};
  set_dotted(nested, key.substr(dot + 1), std::move(value));
  table.set(head, OptionValue::of(std::move(nested)));
}

// Reads X from an element's table and validates it: an error here is the element's input's (BatchElement::input).
template <class X>
X read_element(const OptionTable& table, const std::string& context, BatchElement& e) {
  e.input = true;
  X x = read<X>(table, context);
  if constexpr (requires { x.validate(); }) x.validate();
  e.input = false;
  return x;
}

// One element: the call read from its table, run, and its result described; what a one-by-one call of the front
// ends does (the Lua binding's wheelset methods), with a failed solve recorded instead of raised.
void run_element(const Wheelset& wheelset, const std::string& op, const std::string& context,
                 const OptionTable& table, ContactWorkspace* ws, FieldSink& sink, BatchElement& e) {
  auto not_converged = [&](const auto& result, bool returns, std::string_view hint) {
    if (result.converged || returns) return;
    e.status = BatchStatus::not_converged;
    e.message = fmt::format("{}: {}{}", context, failure_message(result), hint);
  };
  e.status = BatchStatus::done;
  if (op == "contact") {
    const auto call = read_element<ContactCall>(table, context, e);
    describe(call.run(wheelset, *ws), sink, call.request.sensitivity);
  } else if (op == "wheel") {
    const auto call = read_element<WheelCall>(table, context, e);
    const WheelResult r = call.run(wheelset, *ws);
    not_converged(r, call.on_failure.returns, " (on_failure = \"return\" gives the result)");
    describe(r, sink);
  } else if (op == "equilibrium") {
    const auto call = read_element<EquilibriumCall>(table, context, e);
    const EquilibriumResult r = call.run(wheelset, *ws);
    not_converged(r, call.on_failure.returns, " (on_failure = \"return\" gives the result)");
    describe(r, sink);
  } else {
    describe(read_element<RigidCall>(table, context, e).run(wheelset), sink);
  }
}

}  // namespace

const std::vector<std::string>& batch_operations() {
  static const std::vector<std::string> ops{"contact", "wheel", "equilibrium", "rigid"};
  return ops;
}

std::vector<std::string> batch_keys(const std::string& operation) {
  const auto& ops = batch_operations();
  if (std::find(ops.begin(), ops.end(), operation) == ops.end())
    fail("'{}' is not an operation of batch calls (they are: contact, wheel, equilibrium, rigid)", operation);
  std::vector<std::string> keys;
  for (const OptionInfo& o : api::operation(operation).options)
    if (o.type == "number") keys.push_back(o.key);
  return keys;
}

BatchOptions read_batch_options(OptionReader& r) {
  BatchOptions o;
  o.threads = read_threads(r, o.threads);
  return o;
}

OptionTable BatchInput::element(std::size_t i) const {
  OptionTable t = shared;
  for (const Column& c : columns) {
    if (c.values.size() != count)
      fail("{}: the batch's column '{}' has {} values for {} elements", context, c.key, c.values.size(), count);
    set_dotted(t, c.key, OptionValue::of(c.values[i]));
  }
  return t;
}

BatchRun run_batch(const Wheelset& wheelset, const BatchInput& input,
                   const std::function<FieldSink&(std::size_t element)>& sink, const BatchOptions& options,
                   const std::function<std::unique_ptr<ContactWorkspace>()>& workspace) {
  batch_keys(input.operation);  // a known operation
  for (const BatchInput::Column& c : input.columns)
    if (c.values.size() != input.count)
      fail("{}: the batch's column '{}' has {} values for {} elements", input.context, c.key, c.values.size(),
           input.count);
  const auto start = std::chrono::steady_clock::now();
  BatchRun run;
  run.elements.resize(input.count);
  const int count = static_cast<int>(std::min<std::size_t>(input.count, 1u << 30));
  if (static_cast<std::size_t>(count) != input.count) fail("{}: a batch of {} elements is too large", input.context, input.count);
  const ThreadCount tc = thread_count(options.threads, count, fmt::format("the batch has {} elements", count));
  run.threads = tc.threads;
  run.threads_note = tc.note;
  std::vector<std::unique_ptr<ContactWorkspace>> workspaces(static_cast<std::size_t>(tc.threads));
  if (input.operation != "rigid")  // the rigid contact needs none
    for (auto& w : workspaces) w = workspace ? workspace() : wheelset.make_workspace();
  std::atomic<bool> halted{false};  // options.done said so
  parallel_for(count, tc.threads, [&](int worker, int task) {
    if (stop_requested(options.stop) || halted.load()) return;  // skipped
    BatchElement& e = run.elements[static_cast<std::size_t>(task)];
    ContactWorkspace* ws = workspaces[static_cast<std::size_t>(worker)].get();
    try {
      if (ws) ws->forget();  // the element starts cold, as a one-by-one call does
      run_element(wheelset, input.operation, input.context, input.element(static_cast<std::size_t>(task)), ws,
                  sink(static_cast<std::size_t>(task)), e);
    } catch (const std::exception& ex) {
      e.status = BatchStatus::failed;
      e.message = ex.what();
    }
    if (options.done && !options.done(static_cast<std::size_t>(task))) halted = true;
  });
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace wrc::api
