// Does a profile look the right way round for its kind? (docs/design.md, section 2: LEFT-side frames, z up, the
// track centre toward -y.) A reader or an option can leave a profile mirrored or upside down (a MiniProf rail
// measured with the track centre on +X and read without mirror_y, a Simpack profile without its inversion key);
// the engine would then compute contact on a backwards shape without complaint. These checks look at the shape
// only where it is unambiguous and return warnings (p.warnings): a test shape may be unusual on purpose. One case
// is refused: a rail head that leans outward by two independent measures (below).
//
//  - wheel with a flange (the lowest point more than 10 mm below the tape circle): the flange must lie toward -y
//    (the track centre) and point down (-z);
//  - rail head: the highest point must be an interior point with the head falling away on both sides; where the
//    head reaches 14 mm below its top on both sides, a top lying more than 3 mm toward -y of the head's centre
//    means a head leaning outward: a rail canted toward the track centre has its top toward the field side (+y),
//    so such a profile is probably mirrored. A worn high rail can show the same (its worn gauge face moves the
//    head's centre toward the field side), so this alone is a warning. When the head's shoulders also tilt outward,
//    by the same slope near the crown and near the corners (a rigid tilt: wear lowers one corner, and the gauge one),
//    the profile is refused.
//
// A warning says how to turn the profile round: the option mirror_y or mirror_z, or, when a step on the way in
// reversed that direction (a file's own key, such as Simpack's rotate = 180, or the option itself), that step.
#pragma once

#include "wrc/profile/profile.hpp"

#include <string>
#include <vector>

namespace wrc {

// The steps between the file and the profile that reversed its lateral (y) or vertical (z) direction, each
// described with how to undo it ("rotate = 180 (line 27) turned the points over: set rotate = 0 ...").
struct Reversals {
  std::vector<std::string> y, z;
};

// The warnings about p's orientation; throws wrc::Error (naming p.source) for a rail that is mirrored beyond doubt.
std::vector<std::string> orientation_warnings(const Profile& p, const Reversals& reversed = {});

}  // namespace wrc
