// Crossings of one line, sorted by x: the clean-up shared by the segment assembly (location.cpp) and the coarse
// pre-search (search.cpp). See location.cpp for the rule at shared circles.
#pragma once

#include "wrc/geometry/location.hpp"

#include <vector>

namespace wrc::detail {

// v[a, b) are the crossings of one line sorted by x. Drops repeated crossings (the same root of the same cone),
// merges a crossing seen by both cones of a shared circle, and drops a graze at a shared circle if the count is odd
// (counted in `grazes`). Erases from v and updates b. Returns false if the count stays odd.
bool clean_line(std::vector<Crossing>& v, std::size_t a, std::size_t& b, int& grazes);

}  // namespace wrc::detail
