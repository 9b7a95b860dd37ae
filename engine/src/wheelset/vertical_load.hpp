// An entry point of the contact pipeline for solve_wheel's predictor alone (equilibrium/wheel.cpp): the wheel's area
// solved for a vertical force instead of the pose's penetration. Internal, not installed: such a result is not the
// contact of its pose, so the public ContactRequest does not offer it.
#pragma once

#include "wrc/wheelset/contact.hpp"

namespace wrc::areas {

// The least vertical part of the normals (their cosine to the vertical) over an area solved for a vertical force.
inline constexpr double kVerticalWeightMin = 0.05;

// Each element weighted by the vertical part of its normal (halfspace/normal.hpp's weighted force), the area carries
// `force`; the solution's approach is then the further vertical approach (m, the wheel moving down) that carries it on
// the pose's own grid. A wheel with several areas, or with normals less upright than kVerticalWeightMin, is solved for
// the penetration as usual (its solutions' load says which).
struct VerticalLoad {
  double force = 0;  // N, > 0
  // The normal problems without a warm start only estimated (NormalOptions::estimate: the coarse grid's solution,
  // interpolated): a predictor's cheap first step.
  bool estimate = false;
};

// evaluate_contact with request.only_side's wheel loaded so. Throws as evaluate_contact does, and for a force that is
// not a positive number or a request without only_side or with sensitivities or rolling.
ContactResult evaluate_vertical_load(const ContactModel& model, const Pose& pose, ContactWorkspace& workspace,
                                     const ContactRequest& request, const VerticalLoad& load);

// d(vertical force)/d(approach) (N/m) of a solved area (its grids kept; a predictor's too): its normal problem's
// linearised response (area_sensitivity's z column, to 1e-2) to the wheel moving down; 0 without contact.
double vertical_stiffness(const ContactModel& model, const Pose& pose, const PatchContact& area,
                          ContactWorkspace& workspace);

}  // namespace wrc::areas
