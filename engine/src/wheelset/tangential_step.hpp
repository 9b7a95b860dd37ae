// The tangential step of the patch pipeline (wheelset/tangential.hpp), called after the normal solve of an area; kept
// apart from the normal problem's code (contact.cpp) so that each can change without the other.
#pragma once

#include "area.hpp"

#include "wrc/wheelset/contact.hpp"

#include <array>

namespace wrc {

// Solves the area's tangential problem (its pressure and h grids must be there) and adds the creep force and
// moment to the area's force and moment (replacing an earlier tangential solution). The exact solver starts from the
// workspace's last solution of the same area (workspace.tangential) and appends its own to `next`.
void solve_area_rolling(const ContactModel& model, const Pose& pose, PatchContact& area, const RollingRequest& request,
                        ContactWorkspace& workspace, std::vector<ContactWorkspace::Previous>& next);
// The tolerance of a Jacobian's linear solves (the normal problem's response, the tangential linearisation): the
// Jacobian to ~1e-5 of its scale, well within the 1 % it is checked to, for a third of the cost at 1e-8 / 1e-9.
inline constexpr double kJacobianSolveTolerance = 1e-6;
// The creep force's part of a rolling area's Jacobian (Jacobian; its grids kept): the columns xi, eta, phi from the
// tangential solver's linearisation for a change of the creepages at the reference point (the rest of the rigid slip
// held), the pose columns y, z, roll, yaw for the normal problem's pressure response `normal[c]` (the traction bounds
// of the slip elements), the reference point's motion `dref[c]` (m per unit: grid x and y) and, with kinematics, the
// rigid slip's change; moments about the wheelset centre, its motion included.
Jacobian rolling_jacobian(const ContactModel& model, const Pose& pose, const PatchContact& area,
                          const RollingRequest& request, const std::array<areas::NormalColumn, 4>& normal,
                          const std::array<Eigen::Vector2d, 4>& dref, ContactWorkspace& workspace);
// Accumulates an area's (or a wheel's) creep totals.
void add_creep(CreepTotals& total, const PatchContact& area);
void add_creep(CreepTotals& total, const CreepTotals& part);
// Releases the tangential grids (with keep_rows, not the per-row ones).
void drop_grids(PatchRolling& rolling, bool keep_rows = false);

}  // namespace wrc
