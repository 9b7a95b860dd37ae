// Creepages and Kalker's linear theory of rolling contact (docs/design.md, section 2).
//
// Creepages of a contact patch, at a reference point of its plane, in its frame (x = t1 the rolling direction,
// y = t2, z = n from the rail into the wheel): the rigid slip velocity of body 1 (the wheel: the body n points
// into) relative to body 2 (the rail), divided by the rolling speed |V|:
//   xi  = v_slip . t1 / |V|    longitudinal (-),   > 0: the wheel's surface moves slower through the contact than
//                              the rail's (braking), which makes Fx < 0
//   eta = v_slip . t2 / |V|    lateral (-)
//   phi = (Omega_1 - Omega_2) . n / |V|   spin (1/m), the relative angular velocity about the normal
// so that the rigid slip at a point (x, y) of the plane, relative to the reference point, is
//   w = (xi - phi y, eta + phi x).
// Forces Fx, Fy and the moment Mz (about the reference point, along n) are those the rail exerts on the wheel. This
// is CONTACT's convention (Vollebregt, User guide, "Data units and sign conventions") with body 1 = wheel: CKSI,
// CETA, CPHI, FX, FY, MZ of its basic contact module (module 3) in mm and N mm.
//
// Kalker's linear theory (no slip, vanishing creepage) for an elliptic contact of semi-axes a (along x) and b, c =
// sqrt(a b), identical materials of shear modulus G:
//   Fx = -G c^2 C11 xi,   Fy = -G c^2 C22 eta - G c^3 C23 phi,   Mz = G c^3 C23 eta - G c^4 C33 phi.
// The eta-phi coupling is antisymmetric (C23 and -C23). The coefficients come from Kalker's table, embedded below
// with its source.
#pragma once

#include "wrc/halfspace/material.hpp"

namespace wrc::halfspace {

struct Creepages {
  double xi = 0;   // longitudinal creepage (-)
  double eta = 0;  // lateral creepage (-)
  double phi = 0;  // spin creepage (1/m)
};

struct CreepCoefficients {
  double c11 = 0, c22 = 0, c23 = 0, c33 = 0;  // Kalker's dimensionless coefficients
  // False beyond the table's a/b = 0.1 .. 10: then C11, C22, C23 blend into Kalker's asymptotic expansions and C33
  // is extrapolated (see creep.cpp).
  bool tabulated = true;
};

// Kalker's coefficients for an ellipse of aspect ratio a/b (a along the rolling direction) and Poisson's ratio nu
// (0 <= nu <= 0.5). Source: J.J. Kalker, Three-dimensional elastic bodies in rolling contact (Kluwer, 1990),
// Table E.3 (the values of his 1967 thesis, also in K.L. Johnson, Contact Mechanics, Table 8.1): C11, C22, C23, C33
// at a/b = 0.1 .. 1 and b/a = 1 .. 0.1 in steps of 0.1, nu = 0, 1/4, 1/2. Between the tabulated points: cubic Hermite
// interpolation in ln(a/b) and, in nu, the parabola through the three values of 1/C (1/C11 is exactly linear in nu
// in the limit a/b -> 0). Throws wrc::Error on a/b not finite and > 0 or nu outside [0, 0.5].
CreepCoefficients kalker_coefficients(double a_over_b, double nu);

struct CreepForce {
  double fx = 0, fy = 0;  // N
  double mz = 0;          // N m
};

// Kalker's linear law above for semi-axes a, b (m) and the material's G and nu.
CreepForce linear_creep_force(double a, double b, const Material& material, const Creepages& creepages);

// The flexibilities of Kalker's simplified theory (FASTSIM) that reproduce the linear theory on an ellipse of
// semi-axes a (along x), b (m): L1 = 8 a / (3 C11 G), L2 = 8 a / (3 C22 G) for the longitudinal and lateral
// creepage, L3 = pi a sqrt(a / b) / (4 C23 G) for the spin (m/Pa).
struct Flexibilities {
  double x = 0, y = 0, spin = 0;  // L1, L2, L3 (m/Pa)
};
Flexibilities kalker_flexibilities(double a, double b, const Material& material);

}  // namespace wrc::halfspace
