// The operations by name (wrc/api/operations.hpp): each request's reader run in documenting mode.
#include "wrc/api/operations.hpp"

#include "wrc/api/calls.hpp"
#include "wrc/core/error.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <functional>

namespace wrc::api {
namespace {

Operation describe_with(std::string name, std::string lua, std::string c, const std::function<void(OptionReader&)>& read) {
  Operation op{std::move(name), std::move(lua), std::move(c), {}};
  OptionReader r = OptionReader::documenting(op.name, op.options);
  read(r);
  return op;
}

template <class X>
Operation describe(std::string name, std::string lua, std::string c) {
  return describe_with(std::move(name), std::move(lua), std::move(c), [](OptionReader& r) { X::read(r); });
}

std::vector<Operation> make_operations() {
  return {
      // A profile's load options (a reader plugin's own keys pass on to it) and a wheelset's parameters (its profiles
      // and strategy are arguments: Lua's wheel, rail, ..., strategy keys; C's profile handles and strategy_options).
      describe_with("profile_load", "wrc.profile.load", "wrc_profile_load",
                    [](OptionReader& r) { read_load_options(r, false); }),
      describe_with("wheelset", "wrc.wheelset", "wrc_wheelset_new", [](OptionReader& r) { read_wheelset_params(r); }),
      describe<ContactCall>("contact", "wheelset:contact", "wrc_contact"),
      describe<WheelCall>("wheel", "wheelset:wheel", "wrc_wheel"),
      describe<EquilibriumCall>("equilibrium", "wheelset:equilibrium", "wrc_equilibrium"),
      describe<RigidCall>("rigid", "wheelset:rigid", "wrc_rigid_contact"),
      describe<SweepCall>("sweep", "wheelset:sweep", ""),
      describe<GeometryTableCall>("geometry_table", "wheelset:geometry_table", "wrc_geometry_table"),
      describe<WheelsetConicityCall>("wheelset_conicity", "wheelset:conicity", "wrc_wheelset_conicity"),
      describe<ConicityCall>("conicity", "wrc.conicity", "wrc_conicity"),
      describe<FlangeMeasuresCall>("flange_measures", "profile:flange_measures", "wrc_profile_flange_measures"),
      describe<TrajectoryCall>("trajectory", "wheelset:trajectory", "wrc_trajectory_new"),
      describe<TrajectoryContactCall>("trajectory_contact", "trajectory:contact", "wrc_trajectory_contact_with"),
      describe<TrajectoryWheelCall>("trajectory_wheel", "trajectory:wheel", "wrc_trajectory_wheel_with"),
      describe<StrategyCheckCall>("check_strategy", "wheelset:check_strategy", ""),
      describe<SubsurfaceCall>("subsurface", "patch:subsurface", "wrc_subsurface"),
  };
}

}  // namespace

const std::vector<Operation>& operations() {
  static const std::vector<Operation> all = make_operations();
  return all;
}

const Operation& operation(const std::string& name) {
  std::string names;
  for (const Operation& op : operations()) {
    if (op.name == name) return op;
    names += (names.empty() ? "" : ", ") + op.name;
  }
  fail("no operation '{}' (the operations: {})", name, names);
}

}  // namespace wrc::api
