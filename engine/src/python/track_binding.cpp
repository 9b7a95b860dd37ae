// The wheelset's placed profiles and reference points as properties of wrc.Wheelset, with the names of the Lua
// wheelset's fields (engine/src/lua/wheelset_binding.cpp, wheelset_index): left_wheel, right_wheel, left_rail,
// right_rail, gauge_points, tape_points, rail_top. They are what a drawing of the profile pair needs
// (wrc.plots.profile_pair). Each is described into a FieldRecorder like a result, so it arrives as a wrc.Result.
#include "python/bindings.hpp"
#include "python/convert.hpp"
#include "wrc/core/conventions.hpp"

#include <string>

namespace wrc::python {
namespace {

// Placed points ordered by increasing track y on both sides: the profile's own order on the left, reversed on the
// right (its field side first); `reversed` says which (as Lua's push_placed).
py::object placed(const std::vector<double>& y, const std::vector<double>& z, const char* kind, const char* frame,
                  int side) {
  FieldRecorder t;
  t.numbers("y", y.data(), y.size(), {"m", "lateral coordinate of each point, increasing"});
  t.numbers("z", z.data(), z.size(), {"m", "vertical coordinate of each point"});
  t.string("kind", kind, {"", "wheel or rail"});
  t.string("frame", frame, {"", "the frame of the points: wheelset (wheels) or track (rails)"});
  t.string("order", "increasing y", {"", "the order of the points"});
  t.boolean("reversed", side == kRight, {"", "the profile's own order reversed (the right side)"});
  return to_python(t.take());
}

py::object side_points(const std::array<Eigen::Vector2d, 2>& pts, const char* frame) {
  FieldRecorder t;
  for (int s : {kLeft, kRight}) {
    t.begin(side_name(s), {"", frame});
    t.number("y", pts[s].x(), {"m", "lateral coordinate"});
    t.number("z", pts[s].y(), {"m", "vertical coordinate"});
    t.end();
  }
  return to_python(t.take());
}

const Track& track_of(const PyWheelset& w, const char* context) { return w.get(context)->track(); }

}  // namespace

void register_track(py::module_& m) {
  auto cls = py::reinterpret_borrow<py::class_<PyWheelset>>(m.attr("Wheelset"));
  for (int s : {kLeft, kRight}) {
    const std::string side = side_name(s);
    cls.def_property_readonly(
        (side + "_wheel").c_str(),
        [s](const PyWheelset& w) {
          const Track& t = track_of(w, s == kLeft ? "Wheelset.left_wheel" : "Wheelset.right_wheel");
          return placed(t.wheel_y[s], t.wheel_z[s], "wheel", "wheelset", s);
        },
        ("the " + side + " wheel's profile placed in the wheelset frame: y, z (m), by increasing y").c_str());
    cls.def_property_readonly(
        (side + "_rail").c_str(),
        [s](const PyWheelset& w) {
          const Track& t = track_of(w, s == kLeft ? "Wheelset.left_rail" : "Wheelset.right_rail");
          return placed(t.rail_y[s], t.rail_z[s], "rail", "track", s);
        },
        ("the " + side + " rail's profile placed in the track frame: y, z (m), by increasing y").c_str());
  }
  cls.def_property_readonly(
      "gauge_points",
      [](const PyWheelset& w) {
        return side_points(track_of(w, "Wheelset.gauge_points").gauge_point, "the gauge point (track frame)");
      },
      "the rails' gauge points, left and right: y, z (m, track frame)");
  cls.def_property_readonly(
      "tape_points",
      [](const PyWheelset& w) {
        return side_points(track_of(w, "Wheelset.tape_points").tape_point,
                           "the tape circle's lowest point (wheelset frame)");
      },
      "the wheels' tape circle points, left and right: y, z (m, wheelset frame)");
  cls.def_property_readonly(
      "rail_top",
      [](const PyWheelset& w) {
        const Track& t = track_of(w, "Wheelset.rail_top");
        FieldRecorder tree;
        tree.number("left", t.rail_top[kLeft], {"m", "z of the left rail's highest point (track frame)"});
        tree.number("right", t.rail_top[kRight], {"m", "z of the right rail's highest point (track frame)"});
        return to_python(tree.take());
      },
      "z of each placed rail's highest point: left, right (m, track frame)");
}

}  // namespace wrc::python
