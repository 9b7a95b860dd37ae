// The exact tangential solver's start from the workspace's last solutions (areas::tangential_start): the last
// solution's tractions and split copied element by element at the same place of the contact plane, and with the
// solution of the time step before them (ContactWorkspace::tangential_before) the tractions extrapolated linearly in
// time, 2 p_last - p_before, where both were in contact. The expected values are written here from the two old grids.
#include "wheelset/synthetic_wheelset.hpp"
#include "wheelset/warm_start.hpp"

#include <doctest/doctest.h>

using namespace wrc;

namespace {

// An old area on the plane z = 0 (t1 = x, t2 = y) whose grid starts at x0: contact where i is in [1, nx - 2], with
// tractions px = a + i + 10 j, py = -(a + i) and element i = 2 in slip, the others in adhesion.
ContactWorkspace::Previous old_area(double x0, double a) {
  ContactWorkspace::Previous p;
  p.origin = Eigen::Vector3d::Zero();
  p.t1 = Eigen::Vector3d::UnitX();
  p.t2 = Eigen::Vector3d::UnitY();
  p.normal = Eigen::Vector3d::UnitZ();
  p.grid = halfspace::Grid::square(6, 3, 1e-3);
  p.grid.x0 = x0;
  const auto n = static_cast<std::size_t>(p.grid.size());
  p.pressure.assign(n, 0.0);
  p.px.assign(n, 0.0);
  p.py.assign(n, 0.0);
  p.state.assign(n, halfspace::kExterior);
  for (int j = 0; j < p.grid.ny; ++j)
    for (int i = 1; i + 1 < p.grid.nx; ++i) {
      const auto k = static_cast<std::size_t>(p.grid.index(i, j));
      p.pressure[k] = 1e9;
      p.px[k] = a + i + 10 * j;
      p.py[k] = -(a + i);
      p.state[k] = i == 2 ? halfspace::kSlip : halfspace::kAdhesion;
    }
  return p;
}

}  // namespace

TEST_CASE("the tangential start: the last tractions at the same place, extrapolated with the step before's") {
  const auto wheelset = test::synthetic_wheelset();
  auto ws = wheelset->make_workspace();
  const areas::Plane plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                           Eigen::Vector3d::UnitY()};
  // The last area's grid one element further along x than the one before (the patch moving by an element per
  // step); the new grid one element further still.
  const double dx = 1e-3;
  ws->tangential[kLeft] = {old_area(-2.5e-3 + dx, 100)};
  halfspace::Grid grid = ws->tangential[kLeft][0].grid;
  grid.x0 += dx;
  std::vector<double> px, py;
  std::vector<unsigned char> state;
  // Without the step before: a copy of the element at the same x (new i is old i + 1).
  REQUIRE(areas::tangential_start(*ws, kLeft, plane, grid, px, py, state));
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      CAPTURE(i);
      CAPTURE(j);
      const auto k = static_cast<std::size_t>(grid.index(i, j));
      const int o = i + 1;  // the old element at this place
      if (o >= 1 && o + 1 < grid.nx) {
        CHECK(px[k] == 100 + o + 10 * j);
        CHECK(state[k] == (o == 2 ? halfspace::kSlip : halfspace::kAdhesion));
      } else {
        CHECK(px[k] == 0);
      }
    }
  // With the step before (its grid one element back, its tractions 90 + i): 2 p_last - p_before at the same place
  // where both were in contact, the last's elsewhere; the split the last's.
  ws->tangential_before[kLeft] = {old_area(-2.5e-3, 90)};
  REQUIRE(areas::tangential_start(*ws, kLeft, plane, grid, px, py, state));
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      CAPTURE(i);
      CAPTURE(j);
      const auto k = static_cast<std::size_t>(grid.index(i, j));
      const int o = i + 1, b = i + 2;  // the last's and the before's element at this place
      if (!(o >= 1 && o + 1 < grid.nx)) {
        CHECK(px[k] == 0);
        continue;
      }
      const double last_x = 100 + o + 10 * j, last_y = -(100 + o);
      if (b + 1 < grid.nx) {
        CHECK(px[k] == 2 * last_x - (90 + b + 10 * j));
        CHECK(py[k] == 2 * last_y + (90 + b));
      } else {
        CHECK(px[k] == last_x);
        CHECK(py[k] == last_y);
      }
      CHECK(state[k] == (o == 2 ? halfspace::kSlip : halfspace::kAdhesion));
    }
  // Dropped with the rest when the workspace forgets (a cold start).
  ws->forget();
  CHECK(ws->tangential_before[kLeft].empty());
}
