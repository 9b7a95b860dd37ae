// When are two contact patches close enough to be solved together?
//
// A pressure distribution of total force F_s displaces the half-space surface at a distance s from its
// centre by w = F_s / (pi E* s) (Boussinesq, both bodies, 1/E* = 2 (1 - nu^2) / E), up to ~18 % more
// within a few contact radii (the exact value outside a Hertz pressure is used below). Solving a target
// patch alone ignores that displacement: at a prescribed penetration it overestimates the target's force by
// dF_t = k_t w_bar, with k_t = dF_t/d(approach) the target's contact stiffness and w_bar the displacement
// averaged over the target with the weight dp/d(approach) (exact to first order by the reciprocal
// theorem). For a Hertz-like target k_t = 3/2 F_t / delta_t, so the relative error of solving apart is
//   eps = dF_t / F_t = 3/2 w / delta_t,
// and with the Hertz force of a source of contact radius a_s, F_s = 4/3 E* a_s delta_s,
//   eps = (2 / pi) (a_s / s) (delta_s / delta_t)            (far field).
// It decays only like 1/s: at a 1 % tolerance two equal patches interact out to s ~ 64 contact radii.
// The half-space model itself stops being a good description of the bodies long before that, and it
// only applies to patches in (nearly) one plane; the criterion says when the planar half-space solution
// of the separate patches differs from the joint one by more than a tolerance, nothing more.
#pragma once

#include "wrc/halfspace/material.hpp"

namespace wrc::halfspace {

// What the criterion needs to know of a patch, in a common contact-plane frame (m). From the
// inter-penetration area: its centre, its half-extents along x and y, and its depth max(h). If the
// patch was already solved alone, `force` (N, > 0) replaces the Hertz estimate of its force.
struct PatchFootprint {
  double x = 0, y = 0;          // centre (m)
  double half_length = 0;       // half-extent of the inter-penetration area along x (m), > 0
  double half_width = 0;        // half-extent along y (m), > 0
  double penetration = 0;       // max undeformed inter-penetration delta (m), > 0
  double force = 0;             // N: the patch's normal force when known; 0: estimate it (Hertz-like)
};

// Hertz-like estimate of a patch's normal force (N): contact radius a = sqrt(half_length half_width / 2)
// (the contact of a paraboloid has 1/sqrt(2) the radius of its inter-penetration area), F = 4/3 E* a delta.
double estimated_force(const Material& material, const PatchFootprint& patch);

// First-order relative change of the target's normal force at prescribed penetration caused by the
// source patch's pressure (eps above, >= 0). Conservative: it ignores that the joint solve unloads the
// source too and that F ~ delta^(3/2) flattens. Throws wrc::Error on non-finite or non-positive sizes,
// depth or a negative force.
double interaction_ratio(const Material& material, const PatchFootprint& source, const PatchFootprint& target);

// Predicted relative force changes (>= 0, <= 1) of each patch when the two are solved together instead of
// apart: each patch's approach is reduced by the displacement the other induces, w_t = rho_st delta_t
// (rho_st = 2/3 eps_st, for the other's force in the joint solve), and a Hertz-like patch keeps
// F' / F = (1 - w/delta)^(3/2). The pair of equations is solved by fixed-point iteration (monotone).
struct PatchInteraction {
  double change_a = 0, change_b = 0;
};
PatchInteraction patch_interaction(const Material& material, const PatchFootprint& a, const PatchFootprint& b);

// True when the patches' inter-penetration rectangles overlap, or when solving them apart would change
// either force by more than `tolerance` (relative, e.g. 0.01) according to patch_interaction: then they
// should be merged into one potential contact area and solved together.
bool patches_interact(const Material& material, const PatchFootprint& a, const PatchFootprint& b,
                      double tolerance = 0.01);

}  // namespace wrc::halfspace
