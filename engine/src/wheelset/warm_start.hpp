// The warm start of an area's normal problem from the workspace's last evaluations (area.cpp). Internal.
#pragma once

#include "segments.hpp"

#include "wrc/halfspace/normal.hpp"
#include "wrc/wheelset/contact.hpp"

#include <vector>

namespace wrc::areas {

// Start pressures for an area in the plane pl (AreaLayout::frame) from the workspace's last evaluation of that side:
// the old pressure at each new element centre (bilinear), extrapolated linearly in time with the evaluation before
// it where both were in contact and the workspace extrapolates. Without extrapolation, on a grid that is the old one
// shifted by whole elements and carries all of the old pressure, also the old displacements (NaN where the grids do
// not overlap; else empty). False when there is no old area (or warm starts are off).
bool warm_start(const ContactWorkspace& ws, int side, const Plane& pl, const halfspace::Grid& grid,
                std::vector<double>& start, std::vector<double>& displacement);

}  // namespace wrc::areas
