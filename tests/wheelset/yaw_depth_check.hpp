// A contact surface's undeformed distance h under yaw against brute force (exact_depth.hpp), at the S1002 flange root
// on 60E1 (the paper's wheelset) where a yawed rail line runs across the steep, curved part of the profile: the poses,
// the solve and the comparison that test_conformal_yaw.cpp and test_planar_yaw.cpp share. Each surface says where its
// elements lie on the rail; the thresholds are the same for both.
#pragma once

#include "wheelset/exact_depth.hpp"
#include "wheelset/paper_profiles.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wrc::test {

// The rail point an element of an area stands for (track frame, m) and the profile's slope there (rad from the
// horizontal).
struct ElementPoint {
  Eigen::Vector3d p;
  double slope;
};

// The left wheel of the paper's wheelset on `surface` at y = 6.6, 6.8, 7.0 mm and yaw 0, 0.2, 1 deg, at its
// equilibrium under 100 kN. row_points(rail, pc, j) gives row j of area pc as a callable i -> ElementPoint (rail: the
// left rail's lines). Each element's h is compared with the exact depth of its rail point in the wheelset's frame:
// every element within 1 % of the area's deepest h (where either is positive), each row's deepest h within 1 % of the
// row's deepest exact depth (rows deeper than 0.02 mm), and at least 5 such rows steeper than 60 deg where the exact
// depth is deepest (the check reached the flank). Prints each pose's worst element and row.
template <class RowPoints>
void check_h_under_yaw(ContactSurface surface, const RowPoints& row_points) {
  WheelsetParams params;
  params.contact.surface = surface;
  const auto wheelset = build_wheelset(paper_profiles(), params);
  const ContactModel& model = wheelset->contact_model();
  const auto work = wheelset->make_workspace();
  const WheelCones& wheel = model.geometry().side[kLeft].wheel;
  const RailLines& rail = model.geometry().side[kLeft].rail;
  const bool conformal = surface == ContactSurface::conformal;
  fmt::print("{} h under yaw against the brute-force depth: worst element / deepest h, worst row / its depth\n",
             conformal ? "conformal" : "planar");
  for (double yaw_deg : {0.0, 0.2, 1.0})
    for (double y : {6.6e-3, 6.8e-3, 7.0e-3}) {
      CAPTURE(yaw_deg);
      CAPTURE(y);
      const double yaw = yaw_deg * std::numbers::pi / 180;
      const WheelResult w = solve_wheel(model, {kLeft, y, yaw, 0.0, 100e3}, *work);
      REQUIRE(w.converged);
      const Pose pose{y, w.z, 0.0, yaw};
      ContactRequest left;
      left.only_side = kLeft;
      const ContactResult c = evaluate_contact(model, pose, *work, left);
      const PoseFrame f(pose);
      int steep_rows = 0;
      double worst_element = 0, worst_row = 0;
      for (const PatchContact& pc : c.wheel[kLeft].patches) {
        REQUIRE(pc.conformal.has_value() == conformal);
        const halfspace::Grid& g = pc.solution.grid;
        const double hmax = *std::max_element(pc.h.begin(), pc.h.end());
        for (int j = 0; j < g.ny; ++j) {
          const auto point = row_points(rail, pc, j);
          double row_h = -INFINITY, row_d = -INFINITY, worst = 0, row_slope = 0;
          for (int i = 0; i < g.nx; ++i) {
            const ElementPoint e = point(i);
            const Eigen::Vector3d q = f.to_wheelset(e.p);
            const double h = pc.h[static_cast<std::size_t>(g.index(i, j))];
            const double exact = exact_depth(wheel, q.y(), std::hypot(q.x(), q.z()));
            if (h > 0 || exact > 0) worst = std::max(worst, std::abs(h - exact));
            row_h = std::max(row_h, h);
            if (exact > row_d) row_d = exact, row_slope = e.slope;
          }
          CAPTURE(j);
          CHECK(worst <= 0.01 * hmax);
          worst_element = std::max(worst_element, worst / hmax);
          if (row_d < 0.02e-3) continue;
          CHECK(std::abs(row_h - row_d) <= 0.01 * row_d);
          worst_row = std::max(worst_row, std::abs(row_h - row_d) / row_d);
          steep_rows += row_slope > 60 * std::numbers::pi / 180;
        }
      }
      fmt::print("  yaw {:3.1f} deg, y {:3.1f} mm: {:5.2f} %, {:5.2f} %\n", yaw_deg, y * 1e3, 100 * worst_element,
                 100 * worst_row);
      CHECK(steep_rows >= 5);  // the check reached the flank
    }
}

}  // namespace wrc::test
