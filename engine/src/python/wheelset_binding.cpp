// wrc.wheelset, the wrc.Wheelset methods, wrc.Trajectory and wrc.conicity: each reads its request of the call layer
// from the keyword arguments, runs it with the GIL released and converts the result the engine describes. Lua's
// twins: engine/src/lua/wheelset_binding.cpp and kinematics_binding.cpp.
#include "python/bindings.hpp"
#include "python/convert.hpp"
#include "python/docs.hpp"
#include "wrc/api/calls.hpp"
#include "wrc/host/terminal.hpp"

#include <pybind11/stl.h>

namespace wrc::python {

std::shared_ptr<const Wheelset> PyWheelset::get(const char* context) const {
  if (!model) fail("{}: the wrc.Wheelset was closed (close() releases it)", context);
  return model;
}

Lease::Lease(PyWheelset& w, std::shared_ptr<const Wheelset> model) : w_(w) {
  {
    std::lock_guard lock(w.pool_mutex);
    if (!w.pool.empty()) {
      ws_ = std::move(w.pool.back());
      w.pool.pop_back();
    }
  }
  if (!ws_) ws_ = model->make_workspace();
  ws_->forget();
}

Lease::~Lease() {
  std::lock_guard lock(w_.pool_mutex);
  if (w_.model) w_.pool.push_back(std::move(ws_));  // after close(): dropped here, while the call holds its model
}

void PyWheelset::close() {
  std::lock_guard lock(pool_mutex);
  pool.clear();
  model.reset();
}

namespace {

// A trajectory: its steps one at a time (a Python thread may call while another waits without the GIL).
struct PyTrajectory {
  std::unique_ptr<Trajectory> trajectory;
  std::mutex mutex;
  std::shared_ptr<std::atomic<bool>> resolution_shown;  // the wheelset's
  Trajectory& get(const char* context) const {
    if (!trajectory) fail("{}: the wrc.Trajectory was closed (close() releases it)", context);
    return *trajectory;
  }
};

// A result's contact area that spans too few elements for its peak pressure (a coarse grid gives a plausible-looking
// pmax; wheelset/contact.hpp, kMinSpan) as a wrc.ResolutionWarning, once per wheelset: each area's `resolved` says it
// every time. `note` is resolution_note's (empty: none); with the GIL.
void warn_resolution(std::atomic<bool>& shown, const char* ctx, const std::string& note) {
  if (note.empty() || shown.exchange(true)) return;
  const std::string text = fmt::format("{}: {} (shown once per wheelset; each area's `resolved` says it)", ctx, note);
  if (PyErr_WarnEx(error_class("ResolutionWarning").ptr(), text.c_str(), 1) < 0) throw py::error_already_set();
}

// A function of wrc._results (python/wrc/_results.py) that wraps a result tree.
py::object results_function(const char* name) { return py::module_::import("wrc._results").attr(name); }

// A list of names ("coarse", "topology") is the strategy "coarse+topology", as Lua's list form.
py::kwargs strategy_as_name(const py::kwargs& kw) {
  py::kwargs out;
  for (auto [k, v] : kw) {
    if (k.cast<std::string>() == "strategy" && (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)))
      out[k] = py::str("+").attr("join")(v);
    else out[k] = v;
  }
  return out;
}

PyWheelset* make_wheelset(const py::kwargs& given) {
  const char* ctx = "wrc.wheelset";
  const OptionTable t = to_options(strategy_as_name(given), ctx);
  WheelsetParams params;
  WheelsetProfiles profiles;
  OptionTable strategy_options;
  reading([&] {
    OptionReader r(t, ctx);
    r.allow({"wheel", "rail", "left_wheel", "right_wheel", "left_rail", "right_rail"});
    params = read_wheelset_params(r);
    if (const OptionValue* v = r.value("strategy_options")) {
      if (v->type != OptionValue::Type::table)
        fail("{}: 'strategy_options' must be a mapping, got {}", ctx, r.type_name(*v));
      strategy_options = *v->table;
    }
    r.finish();  // a misspelt key first: it may be why a profile seems missing
    profiles = read_wheelset_profiles(r);
    return 0;
  });
  auto w = std::make_unique<PyWheelset>();
  // Ctrl-C: the strategy check of check_strategy = N begins no pose after it; KeyboardInterrupt, no wheelset.
  run_interruptible([&](const std::atomic<bool>& stop) {
    w->model = build_wheelset(profiles, params,
                              native_strategy(params.strategy, strategy_options, params.contact.element), &stop);
  });
  return w.release();
}

template <class Result>
py::object converted(const Result& r) {
  return to_python(record_fields(r));
}

py::object contact(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.contact";
  if (py::object batch = batch_call(self, "contact", ctx, kw); !batch.is_none()) return batch;
  const auto model = self.get(ctx);
  const auto call = read_call<api::ContactCall>(kw, ctx);
  FieldRecord tree;
  std::string note;
  {
    py::gil_scoped_release release;
    Lease ws(self, model);
    const ContactResult r = call.run(*model, *ws);
    note = resolution_note(r);
    tree = record_fields(r, call.request.sensitivity);
  }
  warn_resolution(*self.resolution_shown, ctx, note);
  return to_python(std::move(tree));
}

py::object wheel(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.wheel";
  if (py::object batch = batch_call(self, "wheel", ctx, kw); !batch.is_none()) return batch;
  const auto model = self.get(ctx);
  const auto call = read_call<api::WheelCall>(kw, ctx);
  FieldRecord tree;
  std::string failure, note;
  {
    py::gil_scoped_release release;
    Lease ws(self, model);
    const WheelResult r = call.run(*model, *ws);
    if (!r.converged) failure = failure_message(r);
    note = resolution_note(r.wheel);
    tree = record_fields(r);
  }
  warn_resolution(*self.resolution_shown, ctx, note);
  py::object result = to_python(std::move(tree));
  if (!failure.empty() && !call.on_failure.returns)
    raise_not_converged(fmt::format("{}: {} (on_failure = \"return\" gives the result)", ctx, failure), result);
  return result;
}

py::object equilibrium(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.equilibrium";
  if (py::object batch = batch_call(self, "equilibrium", ctx, kw); !batch.is_none()) return batch;
  const auto model = self.get(ctx);
  const auto call = read_call<api::EquilibriumCall>(kw, ctx);
  FieldRecord tree;
  std::string failure, note;
  {
    py::gil_scoped_release release;
    Lease ws(self, model);
    const EquilibriumResult e = call.run(*model, *ws);
    if (!e.converged) failure = failure_message(e);
    note = resolution_note(e.contact);
    tree = record_fields(e);
  }
  warn_resolution(*self.resolution_shown, ctx, note);
  py::object result = to_python(std::move(tree));
  if (!failure.empty() && !call.on_failure.returns)
    raise_not_converged(fmt::format("{}: {} (on_failure = \"return\" gives the result)", ctx, failure), result);
  return result;
}

py::object rigid(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.rigid";
  if (py::object batch = batch_call(self, "rigid", ctx, kw); !batch.is_none()) return batch;
  const auto model = self.get(ctx);
  const auto call = read_call<api::RigidCall>(kw, ctx);
  FieldRecord tree;
  {
    py::gil_scoped_release release;
    tree = record_fields(call.run(*model));
  }
  return to_python(std::move(tree));
}

// The sweep's entries as `rows` (each what Wheelset.equilibrium returns, with `case` and `rigid`), the run's
// seconds, threads and failed count; wrc._results.with_table adds `table`, a DataFrame of the rows.
py::object sweep(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.sweep";
  const auto model = self.get(ctx);
  auto call = read_call<api::SweepCall>(kw, ctx);
  if (call.progress.on(false)) call.options.progress = host::progress_line("sweep", "cases");
  call.options.notice = host::note_printer("sweep");
  SweepResult r;  // Ctrl-C: no case begins after it, KeyboardInterrupt is raised and nothing returned
  run_interruptible([&](const std::atomic<bool>& stop) {
    call.options.stop = &stop;
    r = call.run(*model, [&] { return model->make_workspace(); });
  });
  FieldRecord tree;
  {
    py::gil_scoped_release release;
    FieldRecorder t;
    long long failed = 0;
    t.begin_list("rows", r.cases.size(), {"", "one entry per case, in the order of the plan"});
    for (std::size_t i = 0; i < r.cases.size(); ++i) {
      t.item();
      describe_case(r, i, t);
      t.end();
      if (!r.elastic[i].converged) ++failed;
    }
    t.end();
    t.number("seconds", r.seconds, {"s", "wall time"});
    t.integer("threads", r.threads, {"-", "worker threads used"});
    if (!r.threads_note.empty()) t.string("threads_note", r.threads_note, {"", "why fewer threads ran than asked for"});
    t.integer("failed", failed, {"-", "cases that did not converge"});
    tree = t.take();
  }
  for (std::size_t i = 0; i < r.cases.size(); ++i)
    if (std::string note = resolution_note(r.elastic[i].contact); !note.empty()) {
      warn_resolution(*self.resolution_shown, ctx,
                      fmt::format("at y = {:.4f} mm, yaw = {:.4g} rad: {}", r.cases[i].y * 1e3, r.cases[i].yaw, note));
      break;
    }
  return results_function("with_table")(to_python(std::move(tree)), "rows");
}

py::object geometry_table(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.geometry_table";
  const auto model = self.get(ctx);
  auto call = read_call<api::GeometryTableCall>(kw, ctx);
  if (call.progress.on(false)) call.options.progress = host::progress_line("geometry table", "rows");
  call.options.notice = host::note_printer("geometry table");
  FieldRecord tree;  // Ctrl-C: no row begins after it, KeyboardInterrupt is raised, no file written
  run_interruptible([&](const std::atomic<bool>& stop) {
    call.options.stop = &stop;
    tree = record_fields(call.run(*model));
  });
  return results_function("rows_frame")(to_python(std::move(tree)), "rows");
}

py::object wheelset_conicity(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.conicity";
  const auto model = self.get(ctx);
  auto call = read_call<api::WheelsetConicityCall>(kw, ctx);
  FieldRecord tree;  // Ctrl-C: its geometry table begins no row after it; KeyboardInterrupt
  run_interruptible([&](const std::atomic<bool>& stop) {
    call.options.table.stop = &stop;
    tree = record_fields(call.run(*model));
  });
  return to_python(std::move(tree));
}

// wrc.conicity(table, **options): the Δr table's keys (y, dr, flange) from `table`, the options from the keywords;
// without a table, all of them from the keywords (the documentation's one-table form).
py::object conicity(py::object table, const py::kwargs& kw) {
  const char* ctx = "wrc.conicity";
  const OptionTable options = to_options(kw, ctx);
  OptionTable dr_table;
  if (!table.is_none()) {
    if (!is_mapping(table))
      throw py::type_error(fmt::format("{}: the table must be a mapping (y=, dr=, flange=) or a pandas.DataFrame, got {}",
                                       ctx, py::str(py::type::of(table).attr("__name__")).cast<std::string>()));
    dr_table = mapping_options(table, std::string(ctx) + ": table");
  }
  const auto call = reading([&] {
    if (table.is_none()) return api::read<api::ConicityCall>(options, ctx);
    const std::string dr_ctx = std::string(ctx) + ": Δr table";
    OptionReader dr(dr_table, dr_ctx), o(options, ctx);
    try {
      auto c = api::ConicityCall::read(dr, o);
      dr.finish();
      o.finish();
      return c;
    } catch (const Error&) {  // a misspelt key first, as api::read reports it
      std::vector<OptionInfo> documented;
      OptionReader all = OptionReader::documenting(ctx, documented);
      api::ConicityCall::read(all);
      api::unknown_key_first(dr_table, dr_ctx, dr, documented);
      api::unknown_key_first(options, ctx, o, documented);
      throw;
    }
  });
  FieldRecord tree;
  {
    py::gil_scoped_release release;
    tree = record_fields(call.run());
  }
  return to_python(std::move(tree));
}

PyTrajectory* trajectory(PyWheelset& self, const py::kwargs& kw) {
  const char* ctx = "Wheelset.trajectory";
  const auto model = self.get(ctx);
  const auto call = read_call<api::TrajectoryCall>(kw, ctx);
  auto t = std::make_unique<PyTrajectory>();
  t->trajectory = call.run(model);
  t->resolution_shown = self.resolution_shown;
  return t.release();
}

py::object trajectory_contact(PyTrajectory& self, const py::kwargs& kw) {
  const char* ctx = "Trajectory.contact";
  self.get(ctx);
  const auto call = read_call<api::TrajectoryContactCall>(kw, ctx);
  FieldRecord tree;
  std::string note;
  {
    py::gil_scoped_release release;
    std::lock_guard lock(self.mutex);
    const ContactResult r = call.run(self.get(ctx));
    note = resolution_note(r);
    tree = record_fields(r);
  }
  warn_resolution(*self.resolution_shown, ctx, note);
  return to_python(std::move(tree));
}

// A step that fails is an error (Lua's tr:wheel has no on_failure): wrc.NotConverged with the result.
py::object trajectory_wheel(PyTrajectory& self, const py::kwargs& kw) {
  const char* ctx = "Trajectory.wheel";
  self.get(ctx);
  const auto call = read_call<api::TrajectoryWheelCall>(kw, ctx);
  FieldRecord tree;
  std::string failure, note;
  {
    py::gil_scoped_release release;
    std::lock_guard lock(self.mutex);
    const WheelResult r = call.run(self.get(ctx));
    if (!r.converged) failure = failure_message(r);
    note = resolution_note(r.wheel);
    tree = record_fields(r);
  }
  warn_resolution(*self.resolution_shown, ctx, note);
  py::object result = to_python(std::move(tree));
  if (!failure.empty()) raise_not_converged(fmt::format("{}: {}", ctx, failure), result);
  return result;
}

void close_trajectory(PyTrajectory& self) {
  py::gil_scoped_release release;
  std::lock_guard lock(self.mutex);  // a step in progress on another thread ends first
  self.trajectory.reset();
}

const char* doc(const char* python) {
  static std::vector<std::unique_ptr<std::string>> kept;  // pybind11 keeps the pointer
  kept.push_back(std::make_unique<std::string>(docstring(python_entry(python))));
  return kept.back()->c_str();
}

}  // namespace

void register_wheelset(py::module_& m) {
  py::class_<PyTrajectory>(m, "Trajectory", "Contact calls that start from the previous step: Wheelset.trajectory.")
      .def("contact", trajectory_contact, doc("Trajectory.contact"))
      .def("wheel", trajectory_wheel, doc("Trajectory.wheel"))
      .def("reset", [](PyTrajectory& t) {
        Trajectory& tr = t.get("Trajectory.reset");
        py::gil_scoped_release release;
        std::lock_guard lock(t.mutex);
        tr.reset();
      }, "Forgets the previous steps.")
      .def("close", close_trajectory, "Releases the trajectory; using it afterwards is an error.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](PyTrajectory& t, py::args) { close_trajectory(t); })
      .def("__repr__", [](const PyTrajectory& t) {
        return std::string(t.trajectory ? "<wrc.Trajectory>" : "<wrc.Trajectory (closed)>");
      });

  py::class_<PyWheelset>(m, "Wheelset", "A wheelset on its track: wrc.wheelset(wheel=, rail=, **params).")
      .def("contact", contact, doc("Wheelset.contact"))
      .def("wheel", wheel, doc("Wheelset.wheel"))
      .def("equilibrium", equilibrium, doc("Wheelset.equilibrium"))
      .def("rigid", rigid, doc("Wheelset.rigid"))
      .def("sweep", sweep, doc("Wheelset.sweep"))
      .def("geometry_table", geometry_table, doc("Wheelset.geometry_table"))
      .def("conicity", wheelset_conicity, doc("Wheelset.conicity"))
      .def("trajectory", trajectory, doc("Wheelset.trajectory"))
      .def_property_readonly("params", [](const PyWheelset& w) { return converted(w.get("Wheelset.params")->params()); },
                             "the wheelset's parameters (every default filled in)")
      .def("close", &PyWheelset::close, "Releases the wheelset; using it afterwards is an error.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](PyWheelset& w, py::args) { w.close(); })
      .def("__repr__", [](const PyWheelset& w) {
        if (!w.model) return std::string("<wrc.Wheelset (closed)>");
        return fmt::format("<wrc.Wheelset strategy '{}'>", w.model->params().strategy);
      });

  m.def("wheelset", make_wheelset, doc("wheelset"), py::return_value_policy::take_ownership);
  m.def("conicity", conicity, py::arg("table") = py::none(), doc("conicity"));
}

}  // namespace wrc::python
