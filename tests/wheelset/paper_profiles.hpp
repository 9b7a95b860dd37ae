// S1002 wheels on 60E1 rails read from the text files the fixture tests/data/profile/write_text_profiles.lua writes
// (17 significant digits), in the folder the test target defines as WRC_TEST_PROFILES.
#pragma once

#include "wrc/profile/reader.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <fmt/format.h>

#include <string>

namespace wrc::test {

inline std::string profile_file(const char* name) { return fmt::format("{}/{}.csv", WRC_TEST_PROFILES, name); }

inline Profile load_text(const char* name, ProfileKind kind) {
  LoadOptions o;
  o.kind = kind;
  return load_profile_file(profile_file(name), o);
}

// The same pair on both sides.
inline WheelsetProfiles paper_profiles() {
  WheelsetProfiles profiles;
  const Profile wheel = load_text("s1002", ProfileKind::wheel), rail = load_text("60e1", ProfileKind::rail);
  profiles.wheel = {wheel, wheel};
  profiles.rail = {rail, rail};
  return profiles;
}

}  // namespace wrc::test
