// A wheelset on the synthetic profiles of tests/geometry/geometry_fixtures.hpp (the same pair on both sides), with
// coarse 0.5 mm elements: fast tests of the solvers above the geometry.
#pragma once

#include "geometry/geometry_fixtures.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <memory>

namespace wrc::test {

inline std::shared_ptr<const Wheelset> synthetic_wheelset() {
  WheelsetProfiles p;
  const Profile wheel = synthetic_wheel(0.5e-3), rail = synthetic_rail(0.5e-3);
  p.wheel = {wheel, wheel};
  p.rail = {rail, rail};
  WheelsetParams params;
  params.contact.element = 0.5e-3;  // coarse: fast tests
  params.check_setup = false;       // a synthetic pair
  return build_wheelset(p, params);
}

}  // namespace wrc::test
