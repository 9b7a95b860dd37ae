// The planar surface's undeformed distance h under yaw against brute force, at the S1002 flange root on 60E1 (the
// paper's wheelset), the twin of test_conformal_yaw.cpp: the same poses, the same rail lines and their h, laid out on
// one plane per area instead of along the rail's profile.
#include "wheelset/exact_depth.hpp"
#include "wheelset/paper_profiles.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

using wrc::test::exact_depth;
using wrc::test::paper_profiles;
using namespace wrc;

namespace {

// The rail's surface under a row of a planar area (plane coordinate v), taken as flat between neighbouring rail lines:
// they run along the track, so each projects onto the plane at one v and the surface under the row is the chords
// between the lines whose v bracket v (usually one).
struct RailUnderRow {
  const RailLines& rail;
  const PatchContact& pc;
  std::vector<int> chords;  // r: the chord from line r to line r + 1
  RailUnderRow(const RailLines& rail_, const PatchContact& pc_, double v) : rail(rail_), pc(pc_) {
    for (int r = 0; r + 1 < rail.count(); ++r) {
      const double va = v_of(r), vb = v_of(r + 1);
      if (va != vb && std::min(va, vb) <= v && v <= std::max(va, vb)) chords.push_back(r);
    }
  }
  double v_of(int r) const { return (Eigen::Vector3d(0, rail.y[r], rail.z[r]) - pc.origin).dot(pc.t2); }
  // Line r's point whose plane coordinate u is u.
  Eigen::Vector3d on_line(int r, double u) const {
    const Eigen::Vector3d d(0, rail.y[r], rail.z[r]);
    return d + (u - (d - pc.origin).dot(pc.t1)) / pc.t1.x() * Eigen::Vector3d::UnitX();
  }
  // The rail point under the plane point (u, v) along the plane's normal (of several chords the one nearest the
  // plane) and its chord's angle to the horizontal (rad); none when no chord lies under the row.
  std::optional<std::pair<Eigen::Vector3d, double>> under(double u, double v) const {
    std::optional<std::pair<Eigen::Vector3d, double>> best;
    double gap = INFINITY;
    for (int r : chords) {
      const Eigen::Vector3d a = on_line(r, u), b = on_line(r + 1, u);
      const double va = v_of(r), vb = v_of(r + 1);
      const Eigen::Vector3d p = a + (v - va) / (vb - va) * (b - a);
      const double s = std::abs((p - pc.origin).dot(pc.normal));
      if (s < gap) gap = s, best = {p, std::atan2(std::abs(b.z() - a.z()), std::abs(b.y() - a.y()))};
    }
    return best;
  }
};

}  // namespace

// h at an element is its two bracketing rail lines' h (the same arcs, corrections and normal_depth's bend as on the
// conformal surface) linear between them; its reference is the exact depth (closest point, brute force) of the rail
// point under the element along the plane's normal. The bound is the conformal surface's: every element within 1 % of
// the deepest h, each row's deepest h within 1 % of the row's deepest exact depth. Measured here: the worst element
// 0.35 % of the deepest h at yaw 0, 0.76 % at 0.2 deg (the samples phased in, fit_bend), 0.59 % at 1 deg; the worst
// row 0.56 %. It fails for a wrong bend: fitted at each line's deepest point alone (not following the yawed line) the
// worst element at 1 deg is 2.6 %, with the samples on the wrong side of the deepest point 3.4 %, and without the bend
// (h the radial depth turned onto the normal) 3.7 % of the deepest h and rows 4.3 % deep at yaw 0 already.
TEST_CASE("planar h under yaw: every element and every row against the brute-force depth") {
  WheelsetParams params;
  params.contact.surface = ContactSurface::planar;
  const auto wheelset = build_wheelset(paper_profiles(), params);
  const ContactModel& model = wheelset->contact_model();
  const auto work = wheelset->make_workspace();
  const WheelCones& wheel = model.geometry().side[kLeft].wheel;
  const RailLines& rail = model.geometry().side[kLeft].rail;
  fmt::print("planar h under yaw against the brute-force depth: worst element / deepest h, worst row / its depth\n");
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
        REQUIRE(!pc.conformal);
        const halfspace::Grid& g = pc.solution.grid;
        const double hmax = *std::max_element(pc.h.begin(), pc.h.end());
        for (int j = 0; j < g.ny; ++j) {
          const RailUnderRow under(rail, pc, g.y(j));
          double row_h = -INFINITY, row_d = -INFINITY, worst = 0, row_angle = 0;
          for (int i = 0; i < g.nx; ++i) {
            const auto p = under.under(g.x(i), g.y(j));
            REQUIRE(p);
            const Eigen::Vector3d q = f.to_wheelset(p->first);
            const double h = pc.h[static_cast<std::size_t>(g.index(i, j))];
            const double exact = exact_depth(wheel, q.y(), std::hypot(q.x(), q.z()));
            if (h > 0 || exact > 0) worst = std::max(worst, std::abs(h - exact));
            row_h = std::max(row_h, h);
            if (exact > row_d) row_d = exact, row_angle = p->second;
          }
          CAPTURE(j);
          CHECK(worst <= 0.01 * hmax);
          worst_element = std::max(worst_element, worst / hmax);
          if (row_d < 0.02e-3) continue;
          CHECK(std::abs(row_h - row_d) <= 0.01 * row_d);
          worst_row = std::max(worst_row, std::abs(row_h - row_d) / row_d);
          steep_rows += row_angle > 60 * std::numbers::pi / 180;
        }
      }
      fmt::print("  yaw {:3.1f} deg, y {:3.1f} mm: {:5.2f} %, {:5.2f} %\n", yaw_deg, y * 1e3, 100 * worst_element,
                 100 * worst_row);
      CHECK(steep_rows >= 5);  // the check reached the flank
    }
}
