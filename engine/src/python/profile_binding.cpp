// wrc.profile.load, wrc.profile.points and the wrc.Profile class: profile/ through the call layer, as the Lua
// binding (engine/src/lua/profile_binding.cpp) does.
#include "python/bindings.hpp"
#include "python/convert.hpp"
#include "python/docs.hpp"
#include "wrc/api/calls.hpp"
#include "wrc/lua/definitions.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/spline.hpp"
#include "wrc/profile/write.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>

namespace wrc::python {

const Profile& PyProfile::get(const char* context) const {
  if (!profile) fail("{}: the wrc.Profile was closed (close() releases it)", context);
  return *profile;
}

namespace {

py::array_t<double> array_of(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

std::string path_text(py::handle path) {
  if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__"))
    throw py::type_error(fmt::format("the path must be a str or os.PathLike, got {}",
                                     py::str(py::type::of(path).attr("__name__")).cast<std::string>()));
  return py::module_::import("os").attr("fsdecode")(path).cast<std::string>();
}

// Shows a loaded profile's warnings, as every front end does (the engine prints nothing); p.warnings keeps them.
// Python's own warnings (wrc.ProfileWarning), not stderr: a notebook shows those, and a filter may silence them or
// make them errors.
void warn(const Profile& p) {
  const py::object category = error_class("ProfileWarning");
  for (const std::string& w : p.warnings)
    if (PyErr_WarnEx(category.ptr(), w.c_str(), 1) < 0) throw py::error_already_set();
}

PyProfile load(py::handle path, const py::kwargs& kwargs) {
  const std::string name = path_text(path);
  const OptionTable options = to_options(kwargs, "wrc.profile.load");
  std::shared_ptr<const Profile> p;
  {
    py::gil_scoped_release release;
    try {
      const DefinitionLoader definitions = lua::definition_loader();
      p = std::make_shared<const Profile>(load_profile(name, options, &definitions));
    } catch (const Error& e) {
      throw ProfileFailure(e.what());
    }
  }
  warn(*p);
  return PyProfile{std::move(p)};
}

// wrc.profile.points(kind=, y=, z=, name=, smooth=): metres, left-side frame; scattered points warned of.
PyProfile points(const py::kwargs& kwargs) {
  const char* ctx = "wrc.profile.points";
  const OptionTable t = to_options(kwargs, ctx);
  PyProfile p = reading([&] {
    OptionReader r(t, ctx);
    return PyProfile{std::make_shared<const Profile>(read_points_profile(r))};
  });
  warn(*p.profile);
  return p;
}

std::string repr(const PyProfile& self) {
  if (!self.profile) return "<wrc.Profile (closed)>";
  const Profile& p = *self.profile;
  return fmt::format("<wrc.Profile {} '{}', {} points, y {:.4f}..{:.4f} m, from {}>", to_string(p.kind), p.name,
                     p.size(), p.y.front(), p.y.back(), p.source);
}

}  // namespace

void register_profile(py::module_& m) {
  py::class_<PyProfile> cls(m, "Profile", "A wheel or rail profile (metres, left-side frame): wrc.profile.load.");
  cls.def_property_readonly("name", [](const PyProfile& s) { return s.get("Profile.name").name; })
      .def_property_readonly("kind", [](const PyProfile& s) { return std::string(to_string(s.get("Profile.kind").kind)); })
      .def_property_readonly("source", [](const PyProfile& s) { return s.get("Profile.source").source; })
      .def_property_readonly("duplicates_dropped",
                             [](const PyProfile& s) { return s.get("Profile.duplicates_dropped").duplicates_dropped; })
      .def_property_readonly("transforms", [](const PyProfile& s) { return s.get("Profile.transforms").transforms; })
      .def_property_readonly("warnings", [](const PyProfile& s) { return s.get("Profile.warnings").warnings; })
      .def_property_readonly("smooth",
                             [](const PyProfile& s) -> py::object {
                               const Profile& p = s.get("Profile.smooth");
                               return p.spline ? py::object(py::float_(p.spline->smoothing)) : py::none();
                             })
      .def_property_readonly("metadata",
                             [](const PyProfile& s) {
                               py::dict d;
                               for (const auto& [k, v] : s.get("Profile.metadata").metadata) d[py::str(k)] = v;
                               return d;
                             })
      .def_property_readonly("y", [](const PyProfile& s) { return array_of(s.get("Profile.y").y); }, "lateral (m)")
      .def_property_readonly("z", [](const PyProfile& s) { return array_of(s.get("Profile.z").z); }, "vertical (m)")
      .def("points", [](const PyProfile& s) {
        const Profile& p = s.get("Profile.points");
        return py::make_tuple(array_of(p.y), array_of(p.z));
      }, "(y, z): two float64 arrays of metres")
      .def("__len__", [](const PyProfile& s) { return s.get("len(Profile)").size(); })
      .def("__repr__", repr)
      .def("flange_measures",
           [](const PyProfile& s, const py::kwargs& kw) {
             const char* ctx = "Profile.flange_measures";
             const Profile& p = s.get(ctx);
             const auto call = reading([&] { return api::read<api::FlangeMeasuresCall>(to_options(kw, ctx), ctx); });
             return to_python(record_fields(call.run(p)));
           },
           docstring(python_entry("Profile.flange_measures")).c_str())
      .def("write",
           [](const PyProfile& s, py::handle path, const py::kwargs& kw) {
             const char* ctx = "Profile.write";
             const Profile& p = s.get(ctx);
             const std::string file = path_text(path);
             const OptionTable t = to_options(kw, ctx);
             py::gil_scoped_release release;
             return write_profile(p, file, t, ctx);
           },
           py::arg("path"), "Writes the profile (format=: text, csv, simpack, miniprof, vampire; default from the "
                            "extension) atomically; returns the format written.")
      .def("arc_length", [](const PyProfile& s) { return arc_length(s.get("Profile.arc_length")); },
           "The profile's length along its points (m).")
      .def("bounds",
           [](const PyProfile& s) {
             const Profile& p = s.get("Profile.bounds");
             const auto [zmin, zmax] = std::minmax_element(p.z.begin(), p.z.end());
             py::dict d;
             d["y_min"] = p.y.front();
             d["y_max"] = p.y.back();
             d["z_min"] = *zmin;
             d["z_max"] = *zmax;
             return d;
           },
           "{y_min, y_max, z_min, z_max} (m)")
      .def("curvature",
           [](const PyProfile& s, double y) {
             const double k = profile_curvature(s.get("Profile.curvature"), y);
             return py::make_tuple(k, k != 0 ? py::object(py::float_(1 / k)) : py::none());
           },
           py::arg("y"), "(curvature 1/m, > 0 convex; lateral radius m, None where the profile is straight) at y")
      .def("transform",
           [](const PyProfile& s, const py::kwargs& kw) {
             const char* ctx = "Profile.transform";
             const Profile& p = s.get(ctx);
             const OptionTable t = to_options(kw, ctx);
             const LoadOptions o = reading([&] {
               OptionReader r(t, ctx);
               return read_load_options(r, true);
             });
             return PyProfile{std::make_shared<const Profile>(transform_profile(p, o))};
           },
           "A new profile: mirror_y=, mirror_z=, crop=, shift=, name= (the load options that change the shape).")
      .def("close", [](PyProfile& s) { s.profile.reset(); }, "Releases the profile; using it afterwards is an error.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](PyProfile& s, py::args) { s.profile.reset(); });

  py::module_ profile = m.def_submodule("profile", "wrc.profile: loading and making profiles");
  profile.def("load", load, py::arg("path"), docstring(python_entry("profile.load")).c_str());
  profile.def("points", points,
              "A profile from points: kind= \"wheel\" or \"rail\", y=, z= (metres, left-side frame), name=, "
              "smooth= (m: a smoothing spline through them; none: the polyline through them, whose scatter is a "
              "wrc.ProfileWarning).");
  profile.attr("max_points") = kMaxProfilePoints;
}

}  // namespace wrc::python
