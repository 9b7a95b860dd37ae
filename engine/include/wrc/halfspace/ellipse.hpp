// What multibody tables carry per contact (docs/guide/rolling.md "Ellipses and Kalker's coefficients"): the
// contact ellipse of Hertz's theory from the curvatures at the contact point and a normal load, the equivalent
// ellipse FASTSIM gives each contact region of a solved pressure (rolling.hpp), and Kalker's creep coefficients
// (creep.hpp) for the Hertz ellipse. Semi-axes: a along x (the rolling direction), b along y.
#pragma once

#include "wrc/core/fields.hpp"
#include "wrc/halfspace/creep.hpp"
#include "wrc/halfspace/grid.hpp"
#include "wrc/halfspace/material.hpp"

#include <optional>
#include <span>
#include <vector>

namespace wrc::halfspace {

// Hertz's elliptic contact of two bodies of the material `m` whose undeformed gap near the first point of contact
// is h = (kx x^2 + ky y^2) / 2: kx, ky (1/m) are the relative curvatures along x and y, the sums of the two bodies'
// principal curvatures there (> 0 convex), the principal axes along x and y (Johnson, Contact Mechanics, 1985,
// sections 3.6 and 4.2).
struct HertzContact {
  double a = 0, b = 0;    // semi-axes along x and y (m)
  double p0 = 0;          // peak pressure (Pa)
  double approach = 0;    // approach of the two bodies (m)
  double force = 0;       // the normal load (N)
  double kx = 0, ky = 0;  // the relative curvatures it was solved for (1/m)
};

// Hertz's contact for the load `force` (N). nullopt when kx or ky is not > 0 (a concave or conformal pair: no
// Hertz ellipse) or force is not > 0. Throws wrc::Error on a non-finite argument or a bad material.
std::optional<HertzContact> hertz_contact(double kx, double ky, double force, const Material& m);

// The relative curvatures at a wheel-rail contact point: along the track the wheel's cos(angle) / rolling_radius
// (Meusnier: the wheel's circle seen along a normal tilted by the contact angle), the rail straight along the track;
// across it the wheel's and the rail's lateral profile curvatures summed (1/m, > 0 convex). The wheelset's roll and
// yaw are left out (cos of a few mrad).
struct RelativeCurvature {
  double kx = 0, ky = 0;  // 1/m
};
RelativeCurvature wheel_rail_curvature(double rolling_radius, double angle, double wheel_curvature,
                                       double rail_curvature);

// The equivalent ellipse of one contact region of a pressure grid, as FASTSIM uses it (fastsim.cpp): the region's
// extent along x and y (element edges included) gives a/b, its area pi a b. An element with less than 5 % of the
// region's largest pressure counts with a weight rising smoothly from 0 to 1 with its pressure (to the area, and to
// the extent of its row and column), so that the ellipse grows continuously as the contact does.
struct EquivalentEllipse {
  double a = 0, b = 0;  // semi-axes along grid x and y (m)
  double force = 0;     // sum p dA of the region (N)
};

// The contact regions of `pressure` (p > 0, 8-connected) and their equivalent ellipses, in order of first element
// (x fastest); `label` gets each element's region (-1 outside).
std::vector<EquivalentEllipse> equivalent_ellipses(const Grid& grid, std::span<const double> pressure,
                                                   std::vector<int>& label);

// How many elements each of `regions` (equivalent_ellipses' numbering in `label`, -1 outside) spans, in that order:
// its most elements in one grid row (x) and in one grid column (y); a region absent from `label` spans none. What a
// contact's resolution is judged by (wheelset/contact.hpp, kMinSpan).
struct RegionSpan {
  int x = 0, y = 0;  // elements
};
std::vector<RegionSpan> region_spans(const Grid& grid, std::span<const int> label, std::span<const int> regions);

// The first-order change of each region's semi-axes (m per unit of the parameter, in equivalent_ellipses' order) for
// a change dp of the pressure (Pa per unit) that keeps the contact (the elements with p > 0): through the weights of
// the elements below 5 % of the region's largest pressure, which change with their pressure and with that largest.
struct EllipseChange {
  double da = 0, db = 0;
};
std::vector<EllipseChange> ellipse_changes(const Grid& grid, std::span<const double> pressure,
                                           std::span<const double> dp);

// The fields of a contact that multibody tables carry. `ellipse`: of the region carrying the largest normal force
// (elastic results); `hertz`: when the relative curvatures are convex; `kalker` (Kalker's coefficients for hertz's
// a/b and the material's nu): with hertz, when nu lies within Kalker's table (0 .. 0.5).
struct ContactEllipses {
  std::optional<EquivalentEllipse> ellipse;
  std::optional<HertzContact> hertz;
  std::optional<CreepCoefficients> kalker;
};

// Hertz and Kalker for the curvatures and load (N) with the material: `ellipse` left empty.
ContactEllipses hertz_ellipses(const RelativeCurvature& k, double load, const Material& m);
// FASTSIM's ellipse of the region of `pressure` that carries the largest force (none without contact).
std::optional<EquivalentEllipse> fastsim_ellipse(const Grid& grid, std::span<const double> pressure);

// ellipse = {a, b}, hertz = {a, b, p0, approach, load, kx, ky} and kalker = {C11, C22, C23, C33, tabulated}, each
// when set.
void describe(const ContactEllipses& e, FieldSink& out);

}  // namespace wrc::halfspace
