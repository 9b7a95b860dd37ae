// The call layer's operation table (wrc/api/operations.hpp): every option documented, and the documented keys the
// ones the readers really accept.
#include "wrc/api/calls.hpp"
#include "wrc/api/operations.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>

using namespace wrc;

namespace {

OptionValue numbers(std::initializer_list<double> v) {
  std::vector<OptionValue> a;
  for (double x : v) a.push_back(OptionValue::of(x));
  return OptionValue::of(std::move(a));
}

// The smallest table each operation reads without complaint (its required keys).
OptionTable minimal(const std::string& op) {
  OptionTable t;
  if (op == "wheel" || op == "trajectory_wheel") t.set("side", OptionValue::of(std::string("left"))).set("Fz", OptionValue::of(5e4));
  if (op == "equilibrium") t.set("y", OptionValue::of(0.0)).set("Q", OptionValue::of(1e5));
  if (op == "rigid") t.set("y", OptionValue::of(0.0));
  if (op == "sweep") t.set("y", numbers({0.0})).set("Q", OptionValue::of(1e5));
  if (op == "geometry_table") t.set("y", numbers({0.0}));
  if (op == "wheelset_conicity") t.set("yhat", numbers({3e-3}));
  if (op == "subsurface") t.set("z", numbers({1e-3}));
  if (op == "conicity") t.set("y", numbers({-1e-3, 0, 1e-3})).set("dr", numbers({-1e-4, 0, 1e-4})).set("yhat", numbers({5e-4}));
  return t;
}

// The keys a reader knows, as its unknown-key message lists them ("expected one of: a, b, c)").
std::set<std::string> known_keys(const std::string& op) {
  OptionTable t = minimal(op);
  t.set("not_a_key_of_any_operation", OptionValue::of(1.0));
  std::string message;
  try {
    const auto read = [&](auto tag) { api::read<decltype(tag)>(t, op); };
    if (op == "contact") read(api::ContactCall{});
    else if (op == "wheel") read(api::WheelCall{});
    else if (op == "equilibrium") read(api::EquilibriumCall{});
    else if (op == "rigid") read(api::RigidCall{});
    else if (op == "sweep") read(api::SweepCall{});
    else if (op == "geometry_table") read(api::GeometryTableCall{});
    else if (op == "wheelset_conicity") read(api::WheelsetConicityCall{});
    else if (op == "conicity") read(api::ConicityCall{});
    else if (op == "flange_measures") read(api::FlangeMeasuresCall{});
    else if (op == "trajectory") read(api::TrajectoryCall{});
    else if (op == "trajectory_contact") read(api::TrajectoryContactCall{});
    else if (op == "trajectory_wheel") read(api::TrajectoryWheelCall{});
    else if (op == "check_strategy") read(api::StrategyCheckCall{});
    else if (op == "subsurface") read(api::SubsurfaceCall{});
    else if (op == "wheelset") {
      OptionReader r(t, op);
      read_wheelset_params(r);
      r.finish();
    } else if (op == "profile_load") {  // every other key passes on to the reader plugin: the keys of its own
      return {load_option_keys().begin(), load_option_keys().end()};
    }
    else FAIL("no reader for ", op);
  } catch (const Error& e) {
    message = e.what();
  }
  REQUIRE_MESSAGE(message.find("unknown key 'not_a_key_of_any_operation'") != std::string::npos, op, ": ", message);
  const std::string list = message.substr(message.find("expected one of: ") + 17);
  std::set<std::string> keys;
  std::stringstream ss(list.substr(0, list.rfind(')')));
  for (std::string k; std::getline(ss, k, ',');) keys.insert(k.substr(k.find_first_not_of(' ')));
  return keys;
}

}  // namespace

TEST_CASE("every option of every operation has a unit (or \"-\") and a help text") {
  CHECK(api::operations().size() >= 15);
  for (const api::Operation& op : api::operations()) {
    CAPTURE(op.name);
    CHECK(!op.options.empty());
    CHECK(!op.lua.empty());
    for (const OptionInfo& o : op.options) {
      CAPTURE(o.key);
      CHECK(!o.unit.empty());
      CHECK(o.help.size() >= 8);
      CHECK(!o.type.empty());
    }
  }
}

TEST_CASE("the documented keys of an operation are the keys its reader accepts") {
  for (const api::Operation& op : api::operations()) {
    CAPTURE(op.name);
    std::set<std::string> documented;
    for (const OptionInfo& o : op.options)
      if (o.key.find('.') == std::string::npos) documented.insert(o.key);
    CHECK(documented == known_keys(op.name));
  }
}

TEST_CASE("operations: the keys Lua and C give, with units, defaults and required keys") {
  auto find = [](const api::Operation& op, const std::string& key) -> const OptionInfo& {
    const auto it = std::find_if(op.options.begin(), op.options.end(), [&](const OptionInfo& o) { return o.key == key; });
    REQUIRE_MESSAGE(it != op.options.end(), op.name, " has no option ", key);
    return *it;
  };
  const api::Operation& contact = api::operation("contact");
  CHECK(contact.c == "wrc_contact");
  for (const char* key : {"y", "z", "roll", "yaw", "grids", "sensitivity", "max_penetration", "search", "V", "omega",
                          "vy", "yaw_rate", "creepage", "creepage.xi", "creepage.eta", "creepage.phi", "mu",
                          "mu_static", "mu_kinetic", "method", "rolling_tolerance"})
    find(contact, key);
  CHECK(find(contact, "z").unit == "m");
  CHECK(find(contact, "yaw_rate").unit == "rad/s");
  CHECK(find(contact, "creepage.phi").unit == "1/m");
  CHECK(find(contact, "grids").fallback == "true");
  CHECK(find(contact, "search").choices == std::vector<std::string>{"strategy", "brute"});
  const api::Operation& eq = api::operation("equilibrium");
  CHECK(find(eq, "Q").required);
  CHECK(find(eq, "Q").unit == "N");
  CHECK(find(eq, "start.z").required);
  CHECK(find(eq, "on_failure").fallback == "\"error\"");
  CHECK(find(api::operation("wheel"), "Fz").unit == "N");
  // The flange measures' default tape offset is the track's: one constant.
  CHECK(find(api::operation("flange_measures"), "tape_offset").fallback == fmt::format("{}", TrackParams{}.tape_offset));
  CHECK_THROWS_WITH_AS(api::operation("contcat"), doctest::Contains("the operations: profile_load, wheelset, contact"),
                       Error);
  // A profile's load options and a wheelset's parameters, as wrc.profile.load and wrc.wheelset take them.
  CHECK(find(api::operation("profile_load"), "smooth").unit == "m");
  CHECK(find(api::operation("profile_load"), "shift.y").unit == "m");
  CHECK(find(api::operation("wheelset"), "radius").unit == "m");
  CHECK(find(api::operation("wheelset"), "tape_offset").fallback == fmt::format("{}", TrackParams{}.tape_offset));
}

TEST_CASE("a request's validate() names the key, the value, the unit and the range (the engine's checks and its own)") {
  OptionTable t;
  t.set("y", OptionValue::of(1e-3)).set("Q", OptionValue::of(1e5));
  api::EquilibriumCall e = api::read<api::EquilibriumCall>(t, "test");
  CHECK_NOTHROW(e.validate());
  e.equilibrium.Q = -5;  // a C++ caller's request: no reader saw it
  CHECK_THROWS_WITH_AS(e.validate(), doctest::Contains("equilibrium: Q = -5 N must be a positive number"), Error);
  e.equilibrium.Q = 1e5;
  e.options.moment_tolerance = 2;
  CHECK_THROWS_WITH_AS(e.validate(), doctest::Contains("moment_tolerance = 2 must be in ]0, 0.1]"), Error);
  e.options.moment_tolerance = 1e-6;
  e.starts.push_back(Start{std::nan(""), 0, std::nullopt, false});
  CHECK_THROWS_WITH_AS(e.validate(), doctest::Contains("start = {z = NaN m, roll = 0 rad} must be finite"), Error);

  api::WheelCall w;
  w.wheel.Fz = 5e4;
  CHECK_NOTHROW(w.validate());
  w.options.limits.max_penetration = 0;
  CHECK_THROWS_WITH_AS(w.validate(), doctest::Contains("wheel: max_penetration = 0 m must be a positive number"), Error);
  api::ContactCall c;
  c.request.tolerance = 1;
  CHECK_THROWS_WITH_AS(c.validate(), doctest::Contains("contact: tolerance = 1 must be in [0, 1e-2]"), Error);
}
