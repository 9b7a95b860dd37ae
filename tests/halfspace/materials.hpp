// The steels of the half-space suites, E = 210 GPa: nu = 0.3 in the normal problem's cases, nu = 0.28 in the rolling
// (tangential) ones.
#pragma once

#include "wrc/halfspace/material.hpp"

namespace wrc::test {

inline const halfspace::Material steel{2.1e11, 0.3};
inline const halfspace::Material rolling_steel{2.1e11, 0.28};

}  // namespace wrc::test
