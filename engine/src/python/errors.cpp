// Engine errors as the exceptions of wrc._errors (python/wrc/_errors.py): the engine's message, without the Lua
// traceback an error inside a Lua profile definition carries (its frames name the host's internals).
#include "python/bindings.hpp"

#include <new>

namespace wrc::python {

namespace {

std::string without_traceback(std::string message) {
  const std::size_t at = message.find("\nstack traceback:");
  if (at != std::string::npos) message.erase(at);
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return message;
}

void set_error(const char* cls, const char* message) {
  PyErr_SetObject(error_class(cls).ptr(), py::str(without_traceback(message)).ptr());
}

}  // namespace

py::object error_class(const char* name) { return py::module_::import("wrc._errors").attr(name); }

void raise_not_converged(const std::string& message, py::object result) {
  PyErr_SetObject(error_class("NotConverged").ptr(), py::make_tuple(message, std::move(result)).ptr());
  throw py::error_already_set();
}

void register_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const OptionFailure& e) {
      set_error("OptionError", e.what());
    } catch (const ProfileFailure& e) {
      set_error("ProfileError", e.what());
    } catch (const Error& e) {
      set_error("Error", e.what());
    }
  });
}

}  // namespace wrc::python
