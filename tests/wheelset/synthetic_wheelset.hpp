// A wheelset on the synthetic profiles of tests/geometry/geometry_fixtures.hpp (the same pair on both sides), with
// coarse 0.5 mm elements: fast tests of the solvers above the geometry.
#pragma once

#include "geometry/geometry_fixtures.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <memory>

namespace wrc::test {

inline WheelsetProfiles synthetic_profiles() {
  WheelsetProfiles p;
  const Profile wheel = synthetic_wheel(0.5e-3), rail = synthetic_rail(0.5e-3);
  p.wheel = {wheel, wheel};
  p.rail = {rail, rail};
  return p;
}

inline WheelsetParams synthetic_params() {
  WheelsetParams params;
  params.contact.element = 0.5e-3;  // coarse: fast tests
  params.check_setup = false;       // a synthetic pair
  return params;
}

inline std::shared_ptr<const Wheelset> synthetic_wheelset() {
  return build_wheelset(synthetic_profiles(), synthetic_params());
}

// One wheelset of synthetic_wheelset() for the whole process (built on first use): the suites that only read it.
inline const Wheelset& shared_synthetic_wheelset() {
  static const std::shared_ptr<const Wheelset> ws = synthetic_wheelset();
  return *ws;
}

}  // namespace wrc::test
