// The progress line and notes a front end draws (wrc/host/terminal.hpp): what the line says, when it is redrawn, and
// the option `progress` that turns it on or off.
#include "wrc/core/error.hpp"
#include "wrc/host/terminal.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace wrc;

namespace {

// What `report` wrote to a temporary file for the calls (done, total, failed).
std::string drawn(const std::function<Progress(std::FILE*)>& make, const std::vector<std::array<int, 3>>& calls) {
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  const Progress report = make(f);
  for (const auto& c : calls) report(c[0], c[1], c[2]);
  std::string text(static_cast<std::size_t>(std::ftell(f)), '\0');
  std::rewind(f);
  CHECK(std::fread(text.data(), 1, text.size(), f) == text.size());
  std::fclose(f);
  return text;
}

// The redrawn lines of a text ("\r...").
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t a = text.find('\r'); a != std::string::npos;) {
    const std::size_t b = text.find('\r', a + 1);
    out.push_back(text.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1));
    a = b;
  }
  return out;
}

bool starts_with(const std::string& s, const std::string& head) { return s.rfind(head, 0) == 0; }

}  // namespace

TEST_CASE("progress line: units done of all, failures once there are some, seconds, a newline after the last") {
  const auto every = [](std::FILE* f) { return host::progress_line("sweep", "cases", f, 0.0); };
  const auto l = lines(drawn(every, {{1, 3, 0}, {2, 3, 1}, {3, 3, 1}}));
  REQUIRE(l.size() == 3);
  CHECK(starts_with(l[0], "wrc sweep: 1 / 3 cases, "));
  CHECK(l[0].find("failed") == std::string::npos);
  CHECK(starts_with(l[1], "wrc sweep: 2 / 3 cases, 1 failed, "));
  CHECK(starts_with(l[2], "wrc sweep: 3 / 3 cases, 1 failed, "));
  CHECK(l[1].find('\n') == std::string::npos);
  CHECK(l[2].size() > 3);
  CHECK(l[2].substr(l[2].size() - 3) == " s\n");
}

TEST_CASE("progress line: redrawn at most every interval, but always for the first and the last unit") {
  const auto rarely = [](std::FILE* f) { return host::progress_line("geometry table", "rows", f, 1e6); };
  std::vector<std::array<int, 3>> calls;
  for (int k = 1; k <= 500; ++k) calls.push_back({k, 500, 0});
  const auto l = lines(drawn(rarely, calls));
  REQUIRE(l.size() == 2);
  CHECK(starts_with(l[0], "wrc geometry table: 1 / 500 rows, "));
  CHECK(starts_with(l[1], "wrc geometry table: 500 / 500 rows, "));
}

TEST_CASE("progress option: true draws, false does not, absent takes the front end's default, a bad value names it") {
  for (bool by_default : {false, true}) {
    const OptionTable none = parse_option_text("", "t");
    OptionReader r(none, "t");
    CHECK(static_cast<bool>(host::read_progress_line(r, by_default, "sweep", "cases")) == by_default);
    r.finish();
  }
  for (const char* text : {"progress=true", "progress=false"}) {
    const OptionTable t = parse_option_text(text, "t");
    OptionReader r(t, "t");
    CHECK(static_cast<bool>(host::read_progress_line(r, false, "sweep", "cases")) == (std::string(text) == "progress=true"));
    r.finish();  // the key was read: not an unknown one
  }
  const OptionTable bad = parse_option_text("progress=3", "t");
  OptionReader r(bad, "t");
  CHECK_THROWS_WITH_AS(host::read_progress_line(r, true, "sweep", "cases"), doctest::Contains("progress"), Error);
}
