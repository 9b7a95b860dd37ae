// The C API against hostile input files and option strings (wrc.h, wrc_profile_load; docs/guide/studies.md "What is
// code and what is data"): a Lua profile definition runs sandboxed -- one that would write a file or load a library is
// refused with a message and nothing is written; its CPU and memory budgets hold -- "profiles/NAME" is the shipped
// profile even with a planted ./profiles/NAME in the working directory, and an option string with a key nested 30000
// levels is refused, not a stack overflow.
#include "wrc/wrc.h"

#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string last() { return wrc_last_error(); }

// This process's scratch folder, removed when it exits.
const fs::path& scratch() {
  struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("wrc_capi_trust_" + std::to_string(getpid()));
    ~Scratch() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  };
  static const Scratch s;
  return s.dir;
}

fs::path folder(const std::string& name) {
  const fs::path dir = scratch() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
  return p.string();
}

std::vector<double> points_of(const wrc_profile* p) {
  size_t n = 0;
  REQUIRE(wrc_profile_points(p, nullptr, nullptr, 0, &n) == WRC_TOO_SMALL);
  std::vector<double> yz(2 * n);
  REQUIRE(wrc_profile_points(p, yz.data(), yz.data() + n, n, &n) == WRC_OK);
  return yz;
}

// A definition that would leave `marker` behind (by os.execute, io.open or a C library) and else returns a flat rail.
std::string hostile(const fs::path& marker, const std::string& how) {
  const std::string m = marker.string();
  const std::string action = how == "os"   ? "os.execute(\"touch '" + m + "'\")\n"
                             : how == "io" ? "io.open('" + m + "', 'w'):write('x')\n"
                                           : "package.loadlib('libc.so.6', 'system')(\"touch '" + m + "'\")\n";
  return action + "return wrc.profile.points{kind = 'rail', y = {-0.03, 0, 0.03}, z = {0, 0, 0}}\n";
}

}  // namespace

TEST_CASE("wrc_profile_load: a definition that would reach the system is refused and nothing runs") {
  const fs::path dir = folder("hostile");
  const fs::path marker = dir / "MARKER";
  for (const char* how : {"os", "io", "package"}) {
    const std::string path = write(dir / (std::string(how) + ".lua"), hostile(marker, how));
    wrc_profile* p = nullptr;
    CHECK(wrc_profile_load(path.c_str(), nullptr, &p) == WRC_ERROR);
    CHECK(p == nullptr);
    CHECK_MESSAGE(last().find(path + ":1: '" + how + "' is not available in a profile definition") != std::string::npos,
                  last());
    CHECK_FALSE(fs::exists(marker));
  }
}

TEST_CASE("wrc_profile_load: a definition's CPU and memory budgets hold") {
  const fs::path dir = folder("budgets");
  wrc_profile* p = nullptr;
  const std::string loop = write(dir / "loop.lua", "while true do end\n");
  CHECK(wrc_profile_load(loop.c_str(), nullptr, &p) == WRC_ERROR);
  CHECK_MESSAGE(last().find("the profile definition " + loop + " exceeded its CPU budget") != std::string::npos, last());
  const std::string table = write(dir / "table.lua", "local t = {} for i = 1, 1e10 do t[i] = {i} end\n");
  CHECK(wrc_profile_load(table.c_str(), nullptr, &p) == WRC_ERROR);
  CHECK_MESSAGE(last().find("the profile definition " + table + " exceeded its memory budget") != std::string::npos,
                last());
  CHECK(wrc_profile_load("profiles/s1002.lua", "step=1e-9", &p) == WRC_ERROR);
  CHECK_MESSAGE(last().find("more than a profile may have") != std::string::npos, last());
}

TEST_CASE("wrc_profile_load: profiles/60e1.lua is the shipped rail, not one planted in the working directory") {
  const fs::path dir = folder("planted");
  const fs::path marker = dir / "MARKER";
  write(dir / "profiles" / "60e1.lua", hostile(marker, "io"));
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  wrc_profile *named = nullptr, *shipped = nullptr, *planted = nullptr;
  const wrc_status named_status = wrc_profile_load("profiles/60e1.lua", nullptr, &named);
  const std::string named_error = last();
  const wrc_status planted_status = wrc_profile_load("./profiles/60e1.lua", nullptr, &planted);
  const std::string planted_error = last();
  fs::current_path(before);
  REQUIRE_MESSAGE(named_status == WRC_OK, named_error);
  REQUIRE(wrc_profile_load(WRC_PROFILES "/60e1.lua", nullptr, &shipped) == WRC_OK);
  CHECK(points_of(named) == points_of(shipped));
  CHECK(points_of(named).size() > 100);  // the planted one has 3 points
  CHECK(planted_status == WRC_ERROR);    // named with a path, the file of the working directory: sandboxed
  CHECK(planted_error.find("'io' is not available in a profile definition") != std::string::npos);
  CHECK_FALSE(fs::exists(marker));
  wrc_profile_free(named);
  wrc_profile_free(shipped);
}

TEST_CASE("option strings: a key nested 30000 levels or 17 levels is refused with a message") {
  wrc_profile *wheel = nullptr, *rail = nullptr;
  REQUIRE(wrc_profile_load("profiles/s1002.lua", "step=0.5e-3", &wheel) == WRC_OK);
  REQUIRE(wrc_profile_load("profiles/60e1.lua", "step=0.5e-3", &rail) == WRC_OK);
  std::string deep = "a";
  for (int i = 0; i < 30000; ++i) deep += ".a";
  wrc_wheelset* ws = nullptr;
  CHECK(wrc_wheelset_new(wheel, rail, (deep + "=1").c_str(), &ws) == WRC_ERROR);
  CHECK_MESSAGE(last().find("characters long (at most 256)") != std::string::npos, last());
  CHECK(wrc_wheelset_new(wheel, rail, "a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a=1", &ws) == WRC_ERROR);
  CHECK_MESSAGE(last().find("nests more than 16 levels") != std::string::npos, last());
  CHECK(wrc_wheelset_new(wheel, rail, "grid=0.5e-3 grid=1e-3", &ws) == WRC_ERROR);
  CHECK_MESSAGE(last().find("'grid' is given twice") != std::string::npos, last());
  CHECK(ws == nullptr);
  wrc_profile_free(wheel);
  wrc_profile_free(rail);
}
