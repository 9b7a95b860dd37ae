// The tangential step of the patch pipeline (wheelset/tangential.hpp), called after the normal solve of an area; kept
// apart from the normal problem's code (contact.cpp) so that each can change without the other.
#pragma once

#include "wrc/wheelset/contact.hpp"

namespace wrc {

// Solves the area's tangential problem (its pressure and h grids must be there) and adds the creep force and
// moment to the area's force and moment (replacing an earlier tangential solution). The exact solver starts from the
// workspace's last solution of the same area (workspace.tangential) and appends its own to `next`.
void solve_area_rolling(const ContactModel& model, const Pose& pose, PatchContact& area, const RollingRequest& request,
                        ContactWorkspace& workspace, std::vector<ContactWorkspace::Previous>& next);
// Accumulates an area's (or a wheel's) creep totals.
void add_creep(CreepTotals& total, const PatchContact& area);
void add_creep(CreepTotals& total, const CreepTotals& part);
// Releases the tangential grids.
void drop_grids(PatchRolling& rolling);

}  // namespace wrc
