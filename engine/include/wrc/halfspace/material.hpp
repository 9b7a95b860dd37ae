// Elastic material of the two bodies of a contact (docs/design.md, section 2: both bodies have the same E and nu,
// hence the factor 2 of eq. 2 of the paper, 2 D p = h). Identical bodies are "quasi-identical" in Kalker's sense:
// a tangential traction displaces the two surfaces normally by equal amounts in the same direction, so the normal
// and tangential problems decouple (the normal one is solved first, the tangential one on its pressure).
#pragma once

#include <string_view>

namespace wrc::halfspace {

struct Material {
  double E = 2.1e11;  // Young's modulus of each body (Pa)
  double nu = 0.3;    // Poisson's ratio of each body, in ]-1, 0.5[

  // Hertz's combined modulus E* of the pair: 1/E* = 2 (1 - nu^2) / E (Pa).
  double combined_modulus() const { return E / (2.0 * (1.0 - nu * nu)); }
  // Displacement of ONE body's surface per unit of the 1/r integral of the pressure: (1 - nu^2) / (pi E)
  // (1/Pa). The pair's approach is twice this (both bodies deform).
  double compliance() const;
  // The pair's approach per unit of the 1/r integral of the pressure, 1 / (pi E*) (1/Pa): twice compliance(), the
  // factor of the influence matrix 2 D of eq. 2 (both bodies deform) and of Boussinesq's far field F / (pi E* r).
  double pair_compliance() const;
  // Shear modulus G = E / (2 (1 + nu)) of each body (Pa): the scale of the tangential problem and of Kalker's creep
  // coefficients.
  double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }
};

// Throws wrc::Error naming `context` when E is not finite and > 0 or nu is not in ]-1, 0.5[.
void validate(const Material& material, std::string_view context);

}  // namespace wrc::halfspace
