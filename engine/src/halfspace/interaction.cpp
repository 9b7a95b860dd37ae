// The patch interaction criterion (see interaction.hpp for the derivation).
#include "wrc/halfspace/interaction.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wrc::halfspace {
namespace {

void check(const PatchFootprint& p, const char* which) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    fail("patch interaction: {} patch centre ({}, {}) m is not finite", which, p.x, p.y);
  if (!std::isfinite(p.half_length) || !(p.half_length > 0) || !std::isfinite(p.half_width) || !(p.half_width > 0))
    fail("patch interaction: {} patch half-extents {} x {} m must be finite and positive", which, p.half_length,
         p.half_width);
  if (!std::isfinite(p.penetration) || !(p.penetration > 0))
    fail("patch interaction: {} patch penetration {} m must be finite and positive", which, p.penetration);
  if (!std::isfinite(p.force) || p.force < 0)
    fail("patch interaction: {} patch force {} N must be finite and >= 0 (0: estimate)", which, p.force);
}

double contact_radius(const PatchFootprint& p) { return std::sqrt(0.5 * p.half_length * p.half_width); }

// Displacement at distance s of a Hertz pressure of radius a and total force F, over the point-load
// value F / (pi E* s): [(2a^2 - s^2) asin(a/s) + a sqrt(s^2 - a^2)] 3 s / (4 a^3) outside (-> 1 far
// away, 3 pi / 8 at the edge); inside, the edge value (the patches then overlap: merged anyway).
double near_field_factor(double s, double a) {
  if (s <= a) return 3.0 * std::numbers::pi / 8.0;
  const double t = a / s;
  if (t < 1e-3) return 1.0 + 0.1 * t * t;  // series: avoids cancellation far away
  return ((2 * a * a - s * s) * std::asin(t) + a * std::sqrt(s * s - a * a)) * 3.0 * s / (4.0 * a * a * a);
}

}  // namespace

double estimated_force(const Material& material, const PatchFootprint& patch) {
  validate(material, "patch interaction");
  check(patch, "the");
  return 4.0 / 3.0 * material.combined_modulus() * contact_radius(patch) * patch.penetration;
}

double interaction_ratio(const Material& material, const PatchFootprint& source, const PatchFootprint& target) {
  validate(material, "patch interaction");
  check(source, "source");
  check(target, "target");
  const double F = source.force > 0 ? source.force : estimated_force(material, source);
  const double s = std::hypot(target.x - source.x, target.y - source.y);
  const double a = contact_radius(source);
  const double r = std::max(s, a);  // overlapping patches: at least the edge value (they merge anyway)
  const double w = F * material.pair_compliance() / r * near_field_factor(r, a);
  return 1.5 * w / target.penetration;
}

PatchInteraction patch_interaction(const Material& material, const PatchFootprint& a, const PatchFootprint& b) {
  const double rho_ab = interaction_ratio(material, a, b) / 1.5;  // w at b from a's separate force, over delta_b
  const double rho_ba = interaction_ratio(material, b, a) / 1.5;
  const auto kept = [](double rho) { return rho < 1 ? std::pow(1 - rho, 1.5) : 0.0; };  // F'/F at w = rho delta
  // fa = kept(rho_ba fb), fb = kept(rho_ab fa): fa -> kept(rho_ba kept(rho_ab fa)) is increasing, so
  // iterating from 1 decreases monotonically to the largest fixed point.
  double fa = 1, fb = 1;
  for (int it = 0; it < 1000; ++it) {
    fb = kept(rho_ab * fa);
    const double next = kept(rho_ba * fb);
    const bool done = std::abs(next - fa) < 1e-14;
    fa = next;
    if (done) break;
  }
  fb = kept(rho_ab * fa);
  return {1 - fa, 1 - fb};
}

bool patches_interact(const Material& material, const PatchFootprint& a, const PatchFootprint& b, double tolerance) {
  if (!std::isfinite(tolerance) || !(tolerance > 0))
    fail("patch interaction: tolerance {} must be finite and positive", tolerance);
  const PatchInteraction i = patch_interaction(material, a, b);
  const bool overlap = std::abs(a.x - b.x) < a.half_length + b.half_length && std::abs(a.y - b.y) < a.half_width + b.half_width;
  return overlap || std::max(i.change_a, i.change_b) > tolerance;
}

}  // namespace wrc::halfspace
