// Does a profile look the right way round for its kind? (docs/design.md, section 2: LEFT-side frames, z up, the
// track centre toward -y.) A reader or an option can leave a profile mirrored or upside down (a MiniProf rail
// measured with the track centre on +X and read without mirror_y, a Simpack profile without its inversion key);
// the engine would then compute contact on a backwards shape without complaint. These checks look at the shape
// only where it is unambiguous and return warnings (p.warnings), not errors: a test shape may be unusual on purpose.
//
//  - wheel with a flange (the lowest point more than 10 mm below the tape circle): the flange must lie toward -y
//    (the track centre) and point down (-z);
//  - rail head: the highest point must be an interior point with the head falling away on both sides; where the
//    head reaches 14 mm below its top on both sides, a top lying more than 3 mm toward -y of the head's centre
//    means a head leaning outward: a rail canted toward the track centre has its top toward the field side (+y),
//    so such a profile is probably mirrored.
#pragma once

#include "wrc/profile/profile.hpp"

#include <string>
#include <vector>

namespace wrc {

std::vector<std::string> orientation_warnings(const Profile& p);

}  // namespace wrc
