// The result-field reference (docs/reference/fields.md) covers every path that wrc_result_fields lists for a wheel,
// a rolling contact, an equilibrium and a geometry table made through the C API: each path matches a C path of the
// page's section for that result, with <side> = left or right and N = a list index.
#include "wrc/wrc.h"

#include <doctest/doctest.h>

#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

std::string last() { return wrc_last_error(); }

// The C paths of one section ("## Wheel") of the reference, as patterns.
std::vector<std::regex> section_patterns(const std::string& title) {
  std::ifstream in(WRC_DOCS "/reference/fields.md");
  REQUIRE_MESSAGE(in, "cannot read " WRC_DOCS "/reference/fields.md");
  std::vector<std::regex> out;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) inside = line == "## " + title;
    if (!inside || line.rfind("| `", 0) != 0) continue;
    // | `lua` | `c` | kind | unit | meaning |
    const std::size_t a = line.find("| `", 2), b = line.find('`', a + 3);
    std::string c = line.substr(a + 3, b - a - 3), re;
    std::size_t start = 0;
    while (start <= c.size()) {
      const std::size_t dot = std::min(c.find('.', start), c.size());
      const std::string part = c.substr(start, dot - start);
      re += part == "N" ? "[0-9]+" : part == "<side>" ? "(left|right)" : part;
      if (dot < c.size()) re += "\\.";
      start = dot + 1;
    }
    out.emplace_back(re);
  }
  return out;
}

std::vector<std::string> paths(const wrc_result* r) {
  size_t n = 0;
  REQUIRE(wrc_result_fields(r, &n) == WRC_OK);
  std::vector<std::string> out;
  for (size_t i = 0; i < n; ++i) {
    const char* p = nullptr;
    REQUIRE(wrc_result_field(r, i, &p) == WRC_OK);
    out.emplace_back(p);
  }
  return out;
}

bool covered(const std::string& path, const std::vector<std::regex>& patterns) {
  for (const std::regex& re : patterns)
    if (std::regex_match(path, re)) return true;
  return false;
}

// Every listed path of the result is in the section; frees the result.
void check_covered(wrc_result* r, const std::string& section, std::size_t at_least) {
  const std::vector<std::regex> patterns = section_patterns(section);
  REQUIRE_MESSAGE(patterns.size() > 10, "the reference has no section \"", section, "\"");
  const std::vector<std::string> listed = paths(r);
  CHECK(listed.size() >= at_least);
  for (const std::string& p : listed) CHECK_MESSAGE(covered(p, patterns), section, ": ", p, " is not in the reference");
  CHECK(!covered("left.patches.1.no_such_field", patterns));  // the match can fail
  wrc_result_free(r);
}

struct Fixture {
  wrc_profile *wheel = nullptr, *rail = nullptr;
  wrc_wheelset* ws = nullptr;
  Fixture() {
    REQUIRE_MESSAGE(wrc_profile_load(WRC_SAMPLES "/s1002.prw", nullptr, &wheel) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_profile_load(WRC_SAMPLES "/60e1_canted.prr", nullptr, &rail) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_wheelset_new(wheel, rail, "cant=0 grid=0.5e-3", &ws) == WRC_OK, last());
  }
  ~Fixture() {
    wrc_wheelset_free(ws);
    wrc_profile_free(wheel);
    wrc_profile_free(rail);
  }
};

}  // namespace

TEST_CASE("field reference: every path of a wheel result (exact and FASTSIM rolling) is documented") {
  Fixture f;
  for (const char* options : {"V=20 vy=0.01 mu=0.3", "V=20 mu=0.3 method=fastsim", ""}) {
    wrc_result* r = nullptr;
    REQUIRE_MESSAGE(wrc_wheel(f.ws, WRC_LEFT, 2e-3, 0, 0, 100e3, options, &r) == WRC_OK, last());
    check_covered(r, "Wheel", 100);
  }
}

TEST_CASE("field reference: every path of a rolling contact result is documented") {
  Fixture f;
  for (const char* options : {"sensitivity=true V=20 vy=0.01 mu=0.3", "creepage.xi=1e-3 creepage.phi=0.1 mu=0.3"}) {
    wrc_result* r = nullptr;
    REQUIRE_MESSAGE(wrc_contact(f.ws, 2e-3, -0.1e-3, 0, 0, options, &r) == WRC_OK, last());
    check_covered(r, "Contact", 200);
  }
}

TEST_CASE("field reference: every path of an equilibrium result is documented") {
  Fixture f;
  wrc_result* r = nullptr;
  REQUIRE_MESSAGE(wrc_equilibrium(f.ws, 2e-3, 0, 100e3, nullptr, &r) == WRC_OK, last());
  check_covered(r, "Equilibrium", 200);
}

TEST_CASE("field reference: every path of a geometry table result is documented") {
  Fixture f;
  wrc_result* r = nullptr;
  REQUIRE_MESSAGE(wrc_geometry_table(f.ws, "y.from=0 y.to=10e-3 y.step=1e-3 threads=1", &r) == WRC_OK, last());
  size_t jumps = 0;
  REQUIRE(wrc_result_count(r, "jumps", &jumps) == WRC_OK);
  CHECK(jumps >= 1);  // the jump's fields are listed too
  check_covered(r, "Geometry table", 300);
}
