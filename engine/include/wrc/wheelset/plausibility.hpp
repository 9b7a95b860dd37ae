// Plausibility of a wheelset set-up (docs/guide/robustness.md): the profiles' sizes and shapes for their kind and the
// flanges against the gauge, checked when the wheelset is built. Results past flange climb are flagged by the
// definitions of geometry/flange.hpp.
#pragma once

#include "wrc/geometry/flange.hpp"
#include "wrc/geometry/track.hpp"

#include <string>

namespace wrc {

// Throws wrc::Error when a set-up cannot be what the user meant: a profile far too wide or tall for its kind (wrong
// units), a "wheel" whose radius grows by more than 10 mm toward the field side (a rail profile, or a wheel with
// reversed y), a "rail" that does not fall by 0.1 mm on the field side of its highest point or rises again there by
// more than 1 mm (a wheel profile: its tread rises toward the field side), flanges that do not fit between the rails
// (back_to_back + both flange thicknesses >= gauge).
void check_setup(const Track& track);

}  // namespace wrc
