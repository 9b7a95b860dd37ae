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

// The frame of a solved area as its warm starts know it (AreaLayout::frame): its plane, or on a conformal area the
// unrolled surface's (x, s) coordinates.
Plane area_frame(const PatchContact& area);

// Start tractions (Pa) and split (halfspace::ElementState) of the exact tangential solver for an area in the frame pl
// from the workspace's last tangential solution of that side (ContactWorkspace::tangential): per new element the
// nearest old element's where that was in contact (on the conformal lattice a copy), none elsewhere (exterior, 0);
// with the solution of the step before (ContactWorkspace::tangential_before) the tractions extrapolated linearly in
// time where both were in contact (the split the last's: the solver clips the tractions to it). False when there is
// none (or warm starts are off).
bool tangential_start(const ContactWorkspace& ws, int side, const Plane& pl, const halfspace::Grid& grid,
                      std::vector<double>& px, std::vector<double>& py, std::vector<unsigned char>& state);

}  // namespace wrc::areas
