// The C API (wrc/wrc.h) through libwrc alone: results agree with the engine's own checks (the equilibrium's
// residuals), bad input gets a status and a message (never a crash: this suite runs under ASan/UBSan), handles are
// independent, and one wheelset serves several threads at once with the results of sequential calls.
#include "wrc/wrc.h"
#include "approx.hpp"
#include "halfspace/hertz_reference.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

using wrc::test::within_rel;
namespace {

std::string last() { return wrc_last_error(); }

// The S1002 wheel and the 60E1 rail canted 1:40 as files (tests/data/profile/samples, every 0.5 mm), read by the
// reader plugins; a coarse grid keeps the tests fast.
struct Fixture {
  wrc_profile *wheel = nullptr, *rail = nullptr;
  wrc_wheelset* ws = nullptr;
  Fixture() {
    REQUIRE_MESSAGE(wrc_profile_load(WRC_SAMPLES "/s1002.prw", nullptr, &wheel) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_profile_load(WRC_SAMPLES "/60e1_canted.prr", nullptr, &rail) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_wheelset_new(wheel, rail, "cant=0 grid=0.5e-3 strategy=uniform+coarse+topology", &ws) == WRC_OK,
                    last());
  }
  ~Fixture() {
    wrc_wheelset_free(ws);
    wrc_profile_free(wheel);
    wrc_profile_free(rail);
  }
};

double number(const wrc_result* r, const char* path) {
  double v = NAN;
  REQUIRE_MESSAGE(wrc_result_number(r, path, &v) == WRC_OK, last());
  return v;
}

}  // namespace

TEST_CASE("version and ABI") {
  CHECK(wrc_abi_version() == WRC_ABI_VERSION);
  CHECK(std::strlen(wrc_version()) > 0);
}

TEST_CASE("an equilibrium through the C API carries Q with no roll moment, and its fields read back") {
  Fixture f;
  wrc_result* e = nullptr;
  REQUIRE_MESSAGE(wrc_equilibrium(f.ws, 2e-3, 0.0, 100e3, nullptr, &e) == WRC_OK, last());
  CHECK(number(e, "converged") == 1);
  CHECK(std::abs(number(e, "left.force.z") + number(e, "right.force.z") - 100e3) <= 1e-6 * 100e3);
  CHECK(std::abs(number(e, "residual.force")) <= 1e-6 * 100e3);
  CHECK(number(e, "Y") == within_rel(-(number(e, "left.force.y") + number(e, "right.force.y")), 1e-5));
  size_t n = 0;
  REQUIRE(wrc_result_count(e, "left.patches", &n) == WRC_OK);
  REQUIRE(n >= 1);
  // The pressure grid integrates to the patch's pressure integral (its normal force on a plane).
  const double nx = number(e, "left.patches.1.grid.nx"), ny = number(e, "left.patches.1.grid.ny");
  const double dA = number(e, "left.patches.1.grid.dx") * number(e, "left.patches.1.grid.dy");
  size_t count = 0;
  CHECK(wrc_result_numbers(e, "left.patches.1.pressure", nullptr, 0, &count) == WRC_TOO_SMALL);
  CHECK(count == static_cast<size_t>(nx * ny));
  std::vector<double> p(count);
  REQUIRE(wrc_result_numbers(e, "left.patches.1.pressure", p.data(), p.size(), &count) == WRC_OK);
  double sum = 0;
  for (double v : p) sum += v * dA;
  CHECK(sum == within_rel(number(e, "left.patches.1.pressure_integral"), 1e-9));
  CHECK(number(e, "left.patches.1.normal_force") <= sum * (1 + 1e-12));  // the resultant of a turning surface
  // Enumeration lists the same paths.
  size_t fields = 0;
  REQUIRE(wrc_result_fields(e, &fields) == WRC_OK);
  bool seen = false;
  for (size_t i = 0; i < fields; ++i) {
    const char* path = nullptr;
    REQUIRE(wrc_result_field(e, i, &path) == WRC_OK);
    seen = seen || std::string(path) == "left.patches.1.pmax";
  }
  CHECK(seen);
  CHECK(wrc_result_free(e) == WRC_OK);
}

TEST_CASE("grids=false is accepted alike by wrc_contact, wrc_equilibrium and wrc_wheel, and drops the grids") {
  Fixture f;
  for (const char* options : {"grids=false", "grids=true"}) {
    const bool kept = std::string(options) == "grids=true";
    wrc_result *c = nullptr, *e = nullptr, *w = nullptr;
    REQUIRE_MESSAGE(wrc_contact(f.ws, 2e-3, -0.05e-3, 0, 0, options, &c) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_equilibrium(f.ws, 2e-3, 0.0, 100e3, options, &e) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_wheel(f.ws, 0, 2e-3, 0, 0, 50e3, options, &w) == WRC_OK, last());
    for (auto [r, prefix] : {std::pair{c, "left."}, {e, "left."}, {w, ""}}) {
      CAPTURE(options);
      CAPTURE(prefix);
      const std::string patch = std::string(prefix) + "patches.1.";
      CHECK(number(r, (patch + "normal_force").c_str()) > 0);  // the area is there, with or without its grids
      size_t count = 0;
      CHECK((wrc_result_numbers(r, (patch + "pressure").c_str(), nullptr, 0, &count) != WRC_NOT_FOUND) == kept);
    }
    for (wrc_result* r : {c, e, w}) wrc_result_free(r);
  }
}

TEST_CASE("an error names the C function once (was 'wrc_wheel: wrc_wheel: unknown key')") {
  Fixture f;
  wrc_result* r = nullptr;
  wrc_wheelset* w2 = nullptr;
  CHECK(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 1e5, "raduis=1", &r) == WRC_ERROR);
  CHECK(last().rfind("wrc_wheel: unknown key 'raduis'", 0) == 0);
  CHECK(wrc_equilibrium(f.ws, 0, 0, 2e5, "raduis=1", &r) == WRC_ERROR);
  CHECK(last().rfind("wrc_equilibrium: unknown key 'raduis'", 0) == 0);
  CHECK(wrc_contact(f.ws, 0, 0, 0, 0, "raduis=1", &r) == WRC_ERROR);
  CHECK(last().rfind("wrc_contact: unknown key 'raduis'", 0) == 0);
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "raduis=0.45", &w2) == WRC_ERROR);
  CHECK(last().rfind("wrc_wheelset_new: ", 0) == 0);
  CHECK(last().find("wrc_wheelset_new: wrc_wheelset_new") == std::string::npos);
}

TEST_CASE("implausible magnitudes are refused with their unit, as in Lua, unless check_setup=false") {
  Fixture f;
  wrc_result* r = nullptr;
  CHECK(wrc_equilibrium(f.ws, 0, 0, 200, nullptr, &r) == WRC_ERROR);  // kN meant
  CHECK(last().find("Q = 200 N is implausible for a wheelset load") != std::string::npos);
  // The way out in no one front end's words: C's option text says check_setup=false, not Lua's "= false".
  CHECK(last().find("set the wheelset's option check_setup to false to accept it") != std::string::npos);
  CHECK(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 100, nullptr, &r) == WRC_ERROR);
  CHECK(last().find("Fz = 100 N is implausible for a wheel load") != std::string::npos);
  CHECK(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "V=300 mu=0.3", &r) == WRC_ERROR);  // km/h meant
  CHECK(last().find("V = 300 m/s is implausible") != std::string::npos);
  wrc_wheelset* w2 = nullptr;
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "cant=0 E=210", &w2) == WRC_ERROR);  // GPa meant
  CHECK(last().find("E = 210 Pa is implausible") != std::string::npos);
  REQUIRE(wrc_wheelset_new(f.wheel, f.rail, "cant=0 grid=1e-3 check_setup=false", &w2) == WRC_OK);
  CHECK(wrc_contact(w2, 0, -0.05e-3, 0, 0, "V=300 mu=0.3 grids=false", &r) == WRC_OK);
  wrc_result_free(r);
  wrc_wheelset_free(w2);
}

TEST_CASE("wrc_closest_name: the option readers' suggestion for a front end's own names") {
  const char* names[] = {"y", "z", "roll", "yaw", "side"};
  CHECK(wrc_closest_name("yy", names, 5) == names[0]);     // one insertion from y, two from yaw
  CHECK(wrc_closest_name("rol", names, 5) == names[2]);    // one deletion
  CHECK(wrc_closest_name("Side", names, 5) == names[4]);   // the same letters in another case
  CHECK(wrc_closest_name("Fz", names, 5) == names[1]);     // one deletion from z: short names are near many words
  CHECK(wrc_closest_name("grids", names, 5) == nullptr);   // no name within max(2, 5 / 3) = 2 edits
  CHECK(wrc_closest_name("yy", names, 0) == nullptr);
  CHECK(wrc_closest_name(nullptr, names, 5) == nullptr);
  CHECK(wrc_closest_name("yy", nullptr, 5) == nullptr);
}

TEST_CASE("bad input: a status and a message that names what is wrong") {
  Fixture f;
  wrc_result* r = nullptr;
  CHECK(wrc_equilibrium(nullptr, 0, 0, 1e5, nullptr, &r) == WRC_INVALID_ARGUMENT);
  CHECK(last().find("wheelset is NULL") != std::string::npos);
  CHECK(wrc_equilibrium(f.ws, NAN, 0, 1e5, nullptr, &r) == WRC_INVALID_ARGUMENT);
  CHECK(last().find("y = NaN") != std::string::npos);
  CHECK(r == nullptr);
  CHECK(wrc_equilibrium(f.ws, 0, 0, 1e5, "max_evaluatons=3", &r) == WRC_ERROR);
  CHECK(last().find("did you mean 'max_evaluations'") != std::string::npos);
  CHECK(wrc_equilibrium(f.ws, 0, 0, -5, nullptr, &r) == WRC_ERROR);
  CHECK(last().find("Q = -5") != std::string::npos);
  CHECK(wrc_wheel(f.ws, 2, 0, 0, 0, 5e4, nullptr, &r) == WRC_INVALID_ARGUMENT);
  CHECK(last().find("WRC_LEFT") != std::string::npos);
  CHECK(wrc_contact(f.ws, 0, 0, 0, 0, nullptr, nullptr) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_wheelset_new(f.wheel, f.wheel, nullptr, nullptr) == WRC_INVALID_ARGUMENT);
  wrc_wheelset* w2 = nullptr;
  CHECK(wrc_wheelset_new(f.wheel, f.wheel, nullptr, &w2) == WRC_ERROR);  // a wheel as the rail
  CHECK(w2 == nullptr);
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "raduis=0.45", &w2) == WRC_ERROR);
  CHECK(last().find("did you mean 'radius'") != std::string::npos);
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "strategy=fastest", &w2) == WRC_ERROR);
  CHECK(last().find("unknown strategy 'fastest'") != std::string::npos);
  wrc_profile* p = nullptr;
  CHECK(wrc_profile_load("no/such/file.prr", nullptr, &p) == WRC_ERROR);
  CHECK(last().find("no such file") != std::string::npos);
  const double y[2] = {0, 1e-3}, z[2] = {0, 0};
  CHECK(wrc_profile_from_points("rail", y, z, 2, nullptr, &p) == WRC_ERROR);  // fewer than 3 points
  CHECK(wrc_profile_from_points("tyre", y, z, 2, nullptr, &p) == WRC_ERROR);
  CHECK(wrc_profile_from_points("rail", nullptr, z, 2, nullptr, &p) == WRC_INVALID_ARGUMENT);
  // Result paths and sizes.
  REQUIRE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, nullptr, &r) == WRC_OK);
  double v = 0;
  CHECK(wrc_result_number(r, "left.nosuch", &v) == WRC_NOT_FOUND);
  CHECK(wrc_result_number(r, "left.patches", &v) == WRC_INVALID_ARGUMENT);  // a list, not a number
  CHECK(wrc_result_number(r, nullptr, &v) == WRC_INVALID_ARGUMENT);
  char buf[4];
  size_t len = 0;
  CHECK(wrc_result_string(r, "left.patches.1.side", buf, sizeof buf, &len) == WRC_OK);
  CHECK(std::string(buf) == "lef");  // truncated, NUL-terminated
  CHECK(len == 4);
  size_t n = 0;
  CHECK(wrc_profile_points(f.rail, nullptr, nullptr, 0, &n) == WRC_TOO_SMALL);
  CHECK(n > 3);
  // A number is not a list or array of none: counting it said n = 0 (an empty array, to a caller) with WRC_OK.
  n = 7;
  CHECK(wrc_result_count(r, "force.z", &n) == WRC_INVALID_ARGUMENT);
  CHECK(last().find("'force.z' is a number, not a list or array") != std::string::npos);
  CHECK(wrc_result_numbers(r, "force.z", nullptr, 0, &n) == WRC_INVALID_ARGUMENT);
  CHECK(n == 7);
  // A table is no field; its fields are named (it said "the result has no field 'force'").
  CHECK(wrc_result_number(r, "force", &v) == WRC_NOT_FOUND);
  CHECK(last().find("'force' is a table, not a field: its fields are force.x, force.y, force.z") != std::string::npos);
  wrc_result_free(r);
}

TEST_CASE("issue 14's options through the C API: check_strategy, max_elements, max_penetration, flange_climb") {
  Fixture f;
  wrc_wheelset* w2 = nullptr;
  const char* checked = "cant=0 grid=0.5e-3 strategy=uniform+coarse+topology check_strategy=4";
  REQUIRE_MESSAGE(wrc_wheelset_new(f.wheel, f.rail, checked, &w2) == WRC_OK, last());
  wrc_wheelset_free(w2);
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "cant=0 grid=0.5e-3 max_elements=100", &w2) == WRC_ERROR);
  CHECK(last().find("is too fine for max_elements = 100") != std::string::npos);
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "cant=0 gauge=1.42", &w2) == WRC_ERROR);
  CHECK(last().find("the flanges do not fit between the rails") != std::string::npos);
  wrc_result* r = nullptr;
  CHECK(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 1e9, "max_penetration=1e-3", &r) == WRC_ERROR);
  CHECK(last().find("Fz = 1e+09 N is implausible for a wheel load") != std::string::npos);
  // Without the set-up checks the load reaches the solver, which stops: out of reach within max_penetration.
  REQUIRE(wrc_wheelset_new(f.wheel, f.rail, "cant=0 grid=0.5e-3 check_setup=false", &w2) == WRC_OK);
  CHECK(wrc_wheel(w2, WRC_LEFT, 0, 0, 0, 1e9, "max_penetration=1e-3", &r) == WRC_NOT_CONVERGED);
  wrc_wheelset_free(w2);
  char msg[512];
  size_t len = 0;
  REQUIRE(wrc_result_string(r, "error", msg, sizeof msg, &len) == WRC_OK);
  CHECK(std::string(msg).find("the load is out of reach: Fz = 1e+09 N") != std::string::npos);
  wrc_result_free(r);
  REQUIRE_MESSAGE(wrc_equilibrium(f.ws, 2e-3, 0.0, 100e3, nullptr, &r) == WRC_OK, last());
  CHECK(number(r, "flange_climb") == 0);
  CHECK(number(r, "left.flange_climb") == 0);
  wrc_result_free(r);
}

// Input a C caller may pass that the engine cannot honour: an error status and a message that names the value (never
// OK with numbers, never "internal error", never a NaN or a Lua traceback in the message).
TEST_CASE("poses far too deep: an error naming the depth, max_penetration and the option") {
  Fixture f;
  wrc_result* r = nullptr;
  // 17.5 mm of inter-penetration at y = 20 mm, z = 0 (was OK with 120 MN), and poses through the rails.
  CHECK(wrc_contact(f.ws, 20e-3, 0, 0, 0, nullptr, &r) == WRC_ERROR);
  CHECK(last().find("more than max_penetration = 1 mm") != std::string::npos);
  CHECK(last().find("option max_penetration") != std::string::npos);
  CHECK(r == nullptr);
  for (double z : {-0.3, -0.5, -1.0, -1e308}) {
    CAPTURE(z);
    CHECK(wrc_contact(f.ws, 0, z, 0, 0, nullptr, &r) == WRC_ERROR);
    CHECK(last().find("nan") == std::string::npos);
    CHECK(last().find("NaN") == std::string::npos);
  }
  CHECK(wrc_contact(f.ws, 0, -1e308, 0, 0, nullptr, &r) == WRC_ERROR);
  CHECK(last().find("z = -1e+308 m is more than the wheels' largest radius") != std::string::npos);
  REQUIRE_MESSAGE(wrc_contact(f.ws, 0, -2e-3, 0, 0, "grids=false max_penetration=3e-3", &r) == WRC_OK, last());
  CHECK(number(r, "left.force.z") > 0);
  wrc_result_free(r);
  wrc_trajectory* tr = nullptr;
  REQUIRE(wrc_trajectory_new(f.ws, "max_penetration=0.5e-3", &tr) == WRC_OK);
  CHECK(wrc_trajectory_contact(tr, 0, -1e-3, 0, 0, &r) == WRC_ERROR);
  CHECK(last().find("more than max_penetration = 0.5 mm") != std::string::npos);
  wrc_trajectory_free(tr);
}

TEST_CASE("grid sizes out of range are refused with the range (1e-30 overflowed the element count)") {
  Fixture f;
  // grid = 1e-30 overflowed the element count and solved to 1.2e-22 N.
  wrc_wheelset* w2 = nullptr;
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "cant=0 grid=1e-30", &w2) == WRC_ERROR);
  CHECK(last().find("grid = 1e-30 m must be in [1e-06, 0.01] m") != std::string::npos);
  CHECK(w2 == nullptr);
  CHECK(wrc_wheelset_new(f.wheel, f.rail, "cant=0 grid=1e-6", &w2) == WRC_ERROR);  // 1 um: in range, too fine for the cap
  CHECK(last().find("grid = 0.001 mm is too fine for max_elements = 4194304") != std::string::npos);
}

TEST_CASE("loads and friction coefficients beyond any wheel: a range, no NaN, no internal error") {
  Fixture f;
  wrc_result* r = nullptr;
  CHECK(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 1e308, nullptr, &r) == WRC_ERROR);
  CHECK(last().find("Fz = 1e+308 N must be a positive number of at most") != std::string::npos);
  CHECK(last().find("nan") == std::string::npos);
  CHECK(last().find("NaN") == std::string::npos);
  CHECK(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "creepage.xi=1e-3 mu=1e-300", &r) == WRC_ERROR);
  CHECK(last().find("mu = 1e-300 must be in") != std::string::npos);
  CHECK(last().find("internal error") == std::string::npos);
}

TEST_CASE("array sizes no caller can have: WRC_INVALID_ARGUMENT, not an internal error") {
  wrc_result* r = nullptr;
  const double y[3] = {0, 1e-3, 2e-3}, z[3] = {0, 0, 0};
  wrc_profile* p = nullptr;
  CHECK(wrc_profile_from_points("rail", y, z, SIZE_MAX, nullptr, &p) == WRC_INVALID_ARGUMENT);
  CHECK(last().find("n = 18446744073709551615 points is more than any profile") != std::string::npos);
  CHECK(wrc_conicity(y, z, SIZE_MAX, nullptr, &r) == WRC_INVALID_ARGUMENT);
}

TEST_CASE("an error inside a Lua profile definition: its message, without the Lua traceback") {
  wrc_profile* p = nullptr;
  const std::string path = (std::filesystem::temp_directory_path() / "wrc_capi_failing_definition.lua").string();
  {
    std::ofstream out(path);
    out << "local opt = ...\nerror(\"my_wheel: this definition fails on purpose\")\n";
  }
  CHECK(wrc_profile_load(path.c_str(), nullptr, &p) == WRC_ERROR);
  CHECK(last().find("this definition fails on purpose") != std::string::npos);
  CHECK(last().find("stack traceback") == std::string::npos);
  CHECK(last().find('\n') == std::string::npos);
  std::filesystem::remove(path);
  // A file no reader takes: the loader's own error, which passes through Lua too.
  CHECK(wrc_profile_load(WRC_SAMPLES "/README.md", nullptr, &p) == WRC_ERROR);
  CHECK(last().find("no reader for the extension '.md'") != std::string::npos);
  CHECK(last().find("stack traceback") == std::string::npos);
}

TEST_CASE("freed handles are refused, and handles are independent") {
  wrc_result* r = nullptr;
  wrc_wheelset* ws = nullptr;
  {
    Fixture f;
    REQUIRE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "grids=false", &r) == WRC_OK);
    ws = f.ws;
    // Freeing the profiles leaves the wheelset working.
    REQUIRE(wrc_profile_free(f.wheel) == WRC_OK);
    REQUIRE(wrc_profile_free(f.rail) == WRC_OK);
    wrc_result* r2 = nullptr;
    CHECK(wrc_contact(f.ws, 1e-3, -0.05e-3, 0, 0, nullptr, &r2) == WRC_OK);
    wrc_result_free(r2);
    CHECK(wrc_profile_free(f.wheel) == WRC_INVALID_ARGUMENT);  // double free
    CHECK(last().find("not a live profile") != std::string::npos);
    f.wheel = f.rail = nullptr;
  }  // the fixture frees the wheelset
  CHECK(number(r, "left.force.z") > 0);  // the result outlives its wheelset
  wrc_result* r3 = nullptr;
  CHECK(wrc_contact(ws, 0, 0, 0, 0, nullptr, &r3) == WRC_INVALID_ARGUMENT);
  CHECK(last().find("not a live wheelset") != std::string::npos);
  // A handle of another type.
  CHECK(wrc_wheelset_free(reinterpret_cast<wrc_wheelset*>(r)) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_result_free(r) == WRC_OK);
  CHECK(wrc_result_free(r) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_result_free(nullptr) == WRC_OK);
}

TEST_CASE("one wheelset from several threads at once gives the results of sequential calls") {
  Fixture f;
  const std::vector<double> ys = {-3e-3, -1e-3, 0.0, 1e-3, 2e-3, 3e-3};
  std::vector<double> seq(ys.size()), par(ys.size());
  auto solve = [&](std::size_t i, std::vector<double>& out) {
    wrc_result* e = nullptr;
    if (wrc_equilibrium(f.ws, ys[i], 0.0, 100e3, "grids=false", &e) != WRC_OK) return;
    wrc_result_number(e, "z", &out[i]);
    wrc_result_free(e);
  };
  for (std::size_t i = 0; i < ys.size(); ++i) solve(i, seq);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < ys.size(); ++i) threads.emplace_back([&, i] { solve(i, par); });
  for (auto& t : threads) t.join();
  for (std::size_t i = 0; i < ys.size(); ++i) CHECK(par[i] == seq[i]);
}

TEST_CASE("a trajectory follows a motion warm-started, with the forces of cold evaluations at its poses") {
  Fixture f;
  wrc_trajectory* tr = nullptr;
  REQUIRE_MESSAGE(wrc_trajectory_new(f.ws, "tolerance=1e-6", &tr) == WRC_OK, last());
  for (int k = 0; k < 10; ++k) {
    const double y = 3e-3 * std::sin(0.3 * k), z = -0.03e-3;
    wrc_result *a = nullptr, *b = nullptr;
    REQUIRE_MESSAGE(wrc_trajectory_contact(tr, y, z, 0.0, 0.0, &a) == WRC_OK, last());
    REQUIRE(wrc_contact(f.ws, y, z, 0.0, 0.0, "grids=false", &b) == WRC_OK);
    for (const char* path : {"left.force.y", "left.force.z", "right.force.y", "right.force.z"})
      CHECK(std::abs(number(a, path) - number(b, path)) <= 1e-5 * std::max(1.0, std::abs(number(b, "left.force.z"))));
    wrc_result_free(a);
    wrc_result_free(b);
  }
  wrc_result* w = nullptr;
  REQUIRE(wrc_trajectory_wheel(tr, WRC_LEFT, 1e-3, 0, 0, 80e3, &w) == WRC_OK);
  CHECK(std::abs(number(w, "force.z") - 80e3) <= 1e-6 * 80e3);
  wrc_result_free(w);
  CHECK(wrc_trajectory_reset(tr) == WRC_OK);
  CHECK(wrc_trajectory_wheel(tr, 3, 0, 0, 0, 80e3, &w) == WRC_INVALID_ARGUMENT);
  wrc_trajectory* bad = tr;
  CHECK(wrc_trajectory_new(f.ws, "tolerence=1e-6", &bad) == WRC_ERROR);
  CHECK(last().find("did you mean 'tolerance'") != std::string::npos);
  CHECK(bad == nullptr);  // *out is reset on failure
  CHECK(wrc_trajectory_free(tr) == WRC_OK);
  CHECK(wrc_trajectory_free(tr) == WRC_INVALID_ARGUMENT);
}

TEST_CASE("a trajectory with rolling options: the creep forces of wrc_contact at its poses, bad options refused") {
  Fixture f;
  wrc_trajectory* tr = nullptr;
  REQUIRE_MESSAGE(wrc_trajectory_new(f.ws, "tolerance=1e-6", &tr) == WRC_OK, last());
  const std::string opts = "V=27.78 vy=0.01 mu=0.3 method=fastsim";
  for (int k = 0; k < 5; ++k) {
    const double y = 1e-3 * k, z = -0.03e-3;
    wrc_result *a = nullptr, *b = nullptr;
    REQUIRE_MESSAGE(wrc_trajectory_contact_with(tr, y, z, 0.0, 0.0, opts.c_str(), &a) == WRC_OK, last());
    REQUIRE_MESSAGE(wrc_contact(f.ws, y, z, 0.0, 0.0, (opts + " grids=false").c_str(), &b) == WRC_OK, last());
    // The creep forces follow the pressures, within the trajectory's tolerance (1e-6 of the gap) of a cold solve.
    const double scale = 0.3 * number(b, "left.force.z");
    for (const char* path : {"left.creep_force.x", "left.creep_force.y", "left.creep_moment.z"}) {  // the left wheel carries the load
      CAPTURE(path);
      CHECK(std::abs(number(a, path) - number(b, path)) <= 1e-4 * scale);
    }
    CHECK(std::abs(number(a, "left.creep_force.y")) > 1e-3 * scale);  // a lateral slip: a lateral creep force
    wrc_result_free(a);
    wrc_result_free(b);
  }
  wrc_result* w = nullptr;
  REQUIRE_MESSAGE(wrc_trajectory_wheel_with(tr, WRC_LEFT, 1e-3, 0, 0, 80e3, opts.c_str(), &w) == WRC_OK, last());
  CHECK(std::abs(number(w, "force.z") - 80e3) <= 1e-6 * 80e3);  // the creep forces' vertical part included
  wrc_result_free(w);
  CHECK(wrc_trajectory_contact_with(tr, 0, 0, 0, 0, "mu=0.3", &w) == WRC_ERROR);  // friction needs V or creepage
  CHECK(last().find("neither V") != std::string::npos);
  CHECK(wrc_trajectory_wheel_with(tr, WRC_LEFT, 0, 0, 0, 80e3, "V=0 mu=0.3", &w) == WRC_ERROR);
  CHECK(w == nullptr);
  CHECK(wrc_trajectory_contact_with(tr, 0, -0.03e-3, 0, 0, "", &w) == WRC_OK);  // no options: frictionless
  double v = 0;
  CHECK(wrc_result_number(w, "left.creep_force.x", &v) == WRC_NOT_FOUND);
  wrc_result_free(w);
  CHECK(wrc_trajectory_free(tr) == WRC_OK);
}

TEST_CASE("the contact ellipses and Kalker's coefficients read by path: rigid points, tables and elastic patches") {
  Fixture f;
  const double Es = 2.1e11 / (2 * (1 - 0.3 * 0.3));  // the wheelset's default steel
  // A rigid touching point's Hertz ellipse for the load given: the tests' own Hertz solution for the curvatures the
  // result reports (cos(angle) / r along the track, wheel + rail across).
  wrc_result* g = nullptr;
  REQUIRE_MESSAGE(wrc_rigid_contact(f.ws, 0.0, 0.0, "hertz_load=80e3", &g) == WRC_OK, last());
  const char* c = "left.contacts.1.";
  const auto at = [&](const wrc_result* r, const std::string& p) { return number(r, p.c_str()); };
  const double kx = std::cos(at(g, std::string(c) + "angle")) / at(g, std::string(c) + "rolling_radius");
  const double ky = at(g, std::string(c) + "wheel_curvature") + at(g, std::string(c) + "rail_curvature");
  const wrc::test::HertzReference ref = wrc::test::hertz_from_force(kx / 2, ky / 2, Es, 80e3);
  CHECK(at(g, std::string(c) + "hertz.a") == within_rel(ref.a, 1e-6));
  CHECK(at(g, std::string(c) + "hertz.b") == within_rel(ref.b, 1e-6));
  CHECK(at(g, std::string(c) + "hertz.load") == 80e3);
  CHECK(at(g, std::string(c) + "kalker.C11") > 3);  // S1002/60E1 at the centre: a/b near 1, C11 near 3.8 (nu 0.3)
  wrc_result_free(g);
  CHECK(wrc_rigid_contact(f.ws, 0.0, 0.0, "hertz_load=-5", &g) == WRC_ERROR);
  CHECK(last().find("hertz_load = -5 N must be a positive number") != std::string::npos);
  // A table row carries them too.
  wrc_result* t = nullptr;
  REQUIRE_MESSAGE(wrc_geometry_table(f.ws, "y=0,1e-3 progress=false", &t) == WRC_OK, last());
  CHECK(number(t, "rows.1.left.contacts.1.hertz.a") == within_rel(ref.a * std::cbrt(100.0 / 80.0), 1e-6));  // a ~ F^(1/3)
  CHECK(number(t, "hertz_load") == 100e3);  // the default
  wrc_result_free(t);
  // An elastic patch: Hertz for its own normal force, FASTSIM's ellipse, Kalker's coefficients.
  wrc_result* e = nullptr;
  REQUIRE_MESSAGE(wrc_equilibrium(f.ws, 0.0, 0.0, 200e3, nullptr, &e) == WRC_OK, last());
  CHECK(number(e, "left.patches.1.hertz.load") == within_rel(number(e, "left.patches.1.normal_force"), 1e-15));
  CHECK(number(e, "left.patches.1.ellipse.a") > 0);
  CHECK(number(e, "left.patches.1.kalker.C22") > 0);
  wrc_result_free(e);
}

TEST_CASE("rigid contact geometry, tables, conicity and flange measures through the C API") {
  Fixture f;
  // The rigid contact, roll fixed: Δr from the touching points' radii.
  wrc_result* g = nullptr;
  REQUIRE_MESSAGE(wrc_rigid_contact(f.ws, 3e-3, 0.0, "roll=fixed", &g) == WRC_OK, last());
  CHECK(number(g, "roll") == 0);
  CHECK(number(g, "rolling_radius_difference") ==
        within_rel(number(g, "left.contacts.1.rolling_radius") - number(g, "right.contacts.1.rolling_radius"), 1e-15));
  CHECK(number(g, "left.lifted") == 0);
  wrc_result_free(g);
  CHECK(wrc_rigid_contact(f.ws, 0.0, 0.0, "roll=sideways", &g) == WRC_ERROR);
  CHECK(last().find("'roll' must be") != std::string::npos);
  // A table with its jumps.
  wrc_result* t = nullptr;
  REQUIRE_MESSAGE(wrc_geometry_table(f.ws, "y.from=-8e-3 y.to=8e-3 y.step=0.1e-3 progress=false", &t) == WRC_OK, last());
  size_t rows = 0, jumps = 0;
  REQUIRE(wrc_result_count(t, "rows", &rows) == WRC_OK);
  REQUIRE(wrc_result_count(t, "jumps", &jumps) == WRC_OK);
  CHECK(rows == 161);
  CHECK(jumps >= 2);
  CHECK(number(t, "rows.81.y") == doctest::Approx(0).scale(1e-3));
  wrc_result_free(t);
  // The wheelset's conicity is the conicity of its own Δr table.
  wrc_result* c = nullptr;
  REQUIRE_MESSAGE(wrc_wheelset_conicity(f.ws, "yhat=0.002,0.003", &c) == WRC_OK, last());
  size_t n = 0;
  REQUIRE(wrc_result_count(c, "dr.y", &n) == WRC_OK);
  std::vector<double> y(n), dr(n), tg(2);
  REQUIRE(wrc_result_numbers(c, "dr.y", y.data(), n, &n) == WRC_OK);
  REQUIRE(wrc_result_numbers(c, "dr.dr", dr.data(), n, &n) == WRC_OK);
  REQUIRE(wrc_result_numbers(c, "tan_gamma", tg.data(), 2, &n) == WRC_OK);
  wrc_result* d = nullptr;
  REQUIRE_MESSAGE(wrc_conicity(y.data(), dr.data(), y.size(), "yhat=0.002,0.003", &d) == WRC_OK, last());
  std::vector<double> tg2(2);
  REQUIRE(wrc_result_numbers(d, "tan_gamma", tg2.data(), 2, &n) == WRC_OK);
  CHECK(tg2[0] == tg[0]);
  CHECK(tg2[1] == tg[1]);
  wrc_result_free(c);
  wrc_result_free(d);
  // Bad tables: an error naming it.
  std::swap(y[3], y[4]);
  CHECK(wrc_conicity(y.data(), dr.data(), y.size(), "yhat=0.002", &d) == WRC_ERROR);
  CHECK(last().find("y must increase strictly") != std::string::npos);
  CHECK(wrc_conicity(nullptr, dr.data(), 3, "yhat=0.002", &d) == WRC_INVALID_ARGUMENT);
  // Flange measures of the sampled S1002 (every 0.5 mm).
  wrc_result* m = nullptr;
  REQUIRE_MESSAGE(wrc_profile_flange_measures(f.wheel, nullptr, &m) == WRC_OK, last());
  CHECK(number(m, "Sh") == within_rel(0.028, 1e-4));
  CHECK(number(m, "Sd") == within_rel(0.0325, 1e-4));
  wrc_result_free(m);
  CHECK(wrc_profile_flange_measures(f.rail, nullptr, &m) == WRC_ERROR);
}

namespace {

// What `call` writes to stderr (file descriptor 2, redirected to a temporary file while it runs).
std::string stderr_of(const std::function<void()>& call) {
  std::fflush(stderr);
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  const int saved = dup(2);
  REQUIRE(dup2(fileno(f), 2) == 2);
  call();
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  std::string text(static_cast<std::size_t>(std::ftell(f)), '\0');
  std::rewind(f);
  REQUIRE(std::fread(text.data(), 1, text.size(), f) == text.size());
  std::fclose(f);
  return text;
}

}  // namespace

TEST_CASE("the C API prints nothing unless asked: a capped thread count is a field, progress=true draws a line") {
  Fixture f;
  wrc_result* t = nullptr;
  // 3 rows make one chunk: 4 threads asked for, 1 used -- said in the result, not on the caller's stderr.
  CHECK(stderr_of([&] { REQUIRE(wrc_geometry_table(f.ws, "y=0,1e-3,2e-3 threads=4", &t) == WRC_OK); }).empty());
  char note[256];
  size_t length = 0;
  REQUIRE(wrc_result_string(t, "threads_note", note, sizeof note, &length) == WRC_OK);
  CHECK(std::string(note).find("threads = 4 asked for, 1 used") != std::string::npos);
  CHECK(number(t, "threads") == 1);
  wrc_result_free(t);
  const std::string drawn = stderr_of([&] { REQUIRE(wrc_geometry_table(f.ws, "y=0,1e-3,2e-3 progress=true", &t) == WRC_OK); });
  CHECK(drawn.find("\rwrc geometry table: 3 / 3 rows, ") != std::string::npos);
  CHECK(drawn.back() == '\n');
  wrc_result_free(t);
}

TEST_CASE("rolling contact through the C API: creep forces, grids and the options' errors") {
  Fixture f;
  wrc_result* c = nullptr;
  REQUIRE_MESSAGE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "V=27.78 mu=0.3 omega=61.6 method=exact", &c) == WRC_OK, last());
  const double fx = number(c, "left.patches.1.Fx"), fy = number(c, "left.patches.1.Fy");
  // Braking (omega below V / r0 = 61.73 rad/s): positive longitudinal creepage, the rail pulls the wheel back.
  CHECK(number(c, "left.patches.1.creepage.xi") > 0);
  CHECK(fx < 0);
  CHECK(number(c, "left.patches.1.creep_force.x") == within_rel(fx * number(c, "left.patches.1.frame.t1.x") +
                                                                      fy * number(c, "left.patches.1.frame.t2.x"), 1e-5));
  CHECK(number(c, "left.creep_force.x") + number(c, "right.creep_force.x") == within_rel(number(c, "creep_force.x"), 1e-5));
  CHECK(number(c, "power") > 0);
  size_t n = 0, nx = static_cast<size_t>(number(c, "left.patches.1.grid.nx"));
  REQUIRE(wrc_result_count(c, "left.patches.1.adhesion_map", &n) == WRC_OK);
  CHECK(n == nx * static_cast<size_t>(number(c, "left.patches.1.grid.ny")));
  std::vector<double> px(n);
  REQUIRE(wrc_result_numbers(c, "left.patches.1.px", px.data(), px.size(), &n) == WRC_OK);
  double sum = 0;
  for (double v : px) sum += v;
  CHECK(sum * std::pow(number(c, "left.patches.1.grid.dx"), 2) == within_rel(fx, 1e-5));
  wrc_result_free(c);
  // Prescribed creepages, FASTSIM, and one wheel with its vertical force.
  REQUIRE_MESSAGE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "creepage.xi=1e-3 mu=0.3 method=fastsim", &c) == WRC_OK, last());
  CHECK(number(c, "left.patches.1.creepage.xi") == 1e-3);
  CHECK(number(c, "right.patches.1.Fx") < 0);
  wrc_result_free(c);
  REQUIRE_MESSAGE(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 80e3, "V=27.78 mu=0.3 yaw_rate=0.05", &c) == WRC_OK, last());
  CHECK(number(c, "force.z") == within_rel(80e3, 1e-6));
  CHECK(number(c, "creep_force.y") != 0);
  wrc_result_free(c);
  // Bad input: a status and a message.
  for (const char* bad : {"V=27.78 mu=0", "V=0 mu=0.3", "V=27.78", "mu=0.3", "creepage.xi=1e-3 vy=1 mu=0.3",
                          "V=27.78 mu=0.3 method=polach", "V=27.78 mu_static=0.2 mu_kinetic=0.3"}) {
    CAPTURE(bad);
    c = nullptr;
    CHECK(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, bad, &c) == WRC_ERROR);
    CHECK(c == nullptr);
    CHECK(last().find("wrc_contact") != std::string::npos);
  }
  CHECK(last().find("mu_kinetic") != std::string::npos);
}

TEST_CASE("the C API's Jacobian (sensitivity=true): paths, and its xi and z columns against differences of wrc_contact") {
  Fixture f;
  const double z = -0.05e-3;
  const auto force = [&](double zz, const char* options, std::array<double, 6>& F) {
    wrc_result* r = nullptr;
    REQUIRE_MESSAGE(wrc_contact(f.ws, 0, zz, 0, 0, options, &r) == WRC_OK, last());
    const char* paths[6] = {"left.force.x", "left.force.y", "left.force.z", "left.moment.x", "left.moment.y", "left.moment.z"};
    for (int i = 0; i < 6; ++i) F[static_cast<std::size_t>(i)] = number(r, paths[i]);
    wrc_result_free(r);
  };
  wrc_result* c = nullptr;
  REQUIRE_MESSAGE(wrc_contact(f.ws, 0, z, 0, 0, "creepage.xi=1e-3 creepage.phi=0.2 mu=0.3 sensitivity=true", &c) == WRC_OK,
                  last());
  std::array<double, 6> jxi{}, jz{}, a{}, b{};
  size_t n = 0;
  REQUIRE(wrc_result_numbers(c, "left.jacobian.xi", jxi.data(), 6, &n) == WRC_OK);
  CHECK(n == 6);
  REQUIRE(wrc_result_numbers(c, "left.jacobian.z", jz.data(), 6, &n) == WRC_OK);
  for (const char* col : {"eta", "phi", "y", "roll", "yaw"}) {
    CAPTURE(col);
    CHECK(wrc_result_count(c, (std::string("left.jacobian.") + col).c_str(), &n) == WRC_OK);
    CHECK(n == 6);
  }
  wrc_result_free(c);
  const double h = 2e-6;  // 0.2 % of xi
  force(z, "creepage.xi=0.001002 creepage.phi=0.2 mu=0.3", a);
  force(z, "creepage.xi=0.000998 creepage.phi=0.2 mu=0.3", b);
  CHECK(jxi[0] == within_rel((a[0] - b[0]) / (2 * h), 0.01));  // dFx/dxi
  const double hz = 1e-7;
  force(z + hz, "creepage.xi=1e-3 creepage.phi=0.2 mu=0.3", a);
  force(z - hz, "creepage.xi=1e-3 creepage.phi=0.2 mu=0.3", b);
  CHECK(jz[2] == within_rel((a[2] - b[2]) / (2 * hz), 0.01));  // dFz/dz
  CHECK(jz[0] == within_rel((a[0] - b[0]) / (2 * hz), 0.02));  // dFx/dz: the bound's change through the pressure
  // Without the option: no jacobian.
  REQUIRE(wrc_contact(f.ws, 0, z, 0, 0, "creepage.xi=1e-3 mu=0.3", &c) == WRC_OK);
  CHECK(wrc_result_count(c, "left.jacobian.xi", &n) != WRC_OK);
  wrc_result_free(c);
}

TEST_CASE("rolling contact through the C API: a falling friction law and a friction profile as option text") {
  Fixture f;
  wrc_result* c = nullptr;
  // Full sliding at w = V xi = 1 m/s: |Fx| = mu(1 m/s) sum p dA, Polach's mu written out.
  const double mu = 0.4 * (0.6 * std::exp(-0.6) + 0.4);
  REQUIRE_MESSAGE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0,
                              "creepage.xi=0.05 V=20 friction.law=polach friction.mu0=0.4 friction.A=0.4 friction.B=0.6",
                              &c) == WRC_OK, last());
  std::size_t n = 0;
  REQUIRE(wrc_result_count(c, "left.patches.1.pressure", &n) == WRC_OK);
  std::vector<double> p(n);
  REQUIRE(wrc_result_numbers(c, "left.patches.1.pressure", p.data(), p.size(), &n) == WRC_OK);
  double N = 0;
  for (double v : p) N += v;
  N *= std::pow(number(c, "left.patches.1.grid.dx"), 2);
  CHECK(-number(c, "left.patches.1.Fx") == within_rel(mu * N, 0.01));
  wrc_result_free(c);
  // A profile of mu across the left rail (lists), the right rail's plain mu: the left tread's friction is 0.2.
  REQUIRE_MESSAGE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0,
                              "creepage.xi=0.05 V=20 mu=0.3 friction_profile.left.y=-0.1,0.1 "
                              "friction_profile.left.mu=0.2,0.2", &c) == WRC_OK, last());
  wrc_result* d = nullptr;
  REQUIRE(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "creepage.xi=0.05 V=20 mu=0.2", &d) == WRC_OK);
  CHECK(number(c, "left.patches.1.Fx") == within_rel(number(d, "left.patches.1.Fx"), 1e-9));
  CHECK(number(c, "right.patches.1.Fx") == within_rel(number(d, "right.patches.1.Fx") * 1.5, 1e-3));
  wrc_result_free(c);
  wrc_result_free(d);
  for (const char* bad : {"creepage.xi=1e-3 friction.preset=polach_dry", "V=20 friction.law=polach friction.mu0=0.4",
                          "V=20 mu=0.3 friction_profile.y=0,-0.01 friction_profile.mu=0.3,0.3"}) {
    CAPTURE(bad);
    CHECK(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, bad, &c) == WRC_ERROR);
    CHECK(last().find("wrc_contact") != std::string::npos);
  }
}

TEST_CASE("wrc_profile_write: each format read back by wrc_profile_load gives the points, bad calls a status") {
  Fixture f;
  const auto dir = std::filesystem::temp_directory_path() / ("wrc_capi_write_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::size_t n = 0;
  REQUIRE(wrc_profile_points(f.wheel, nullptr, nullptr, 0, &n) == WRC_TOO_SMALL);
  std::vector<double> y(n), z(n), y2(n), z2(n);
  REQUIRE(wrc_profile_points(f.wheel, y.data(), z.data(), n, &n) == WRC_OK);
  for (const char* ext : {".txt", ".csv", ".prw", ".whl", ".whe"}) {
    const std::string path = (dir / (std::string("wheel") + ext)).string();
    REQUIRE_MESSAGE(wrc_profile_write(f.wheel, path.c_str(), nullptr) == WRC_OK, last());
    wrc_profile* back = nullptr;
    const char* options = std::strcmp(ext, ".txt") == 0 || std::strcmp(ext, ".csv") == 0 ? "kind=wheel" : nullptr;
    REQUIRE_MESSAGE(wrc_profile_load(path.c_str(), options, &back) == WRC_OK, last());
    std::size_t m = 0;
    REQUIRE(wrc_profile_points(back, y2.data(), z2.data(), n, &m) == WRC_OK);
    CHECK(m == n);
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) worst = std::max({worst, std::abs(y2[i] - y[i]), std::abs(z2[i] - z[i])});
    CHECK_MESSAGE(worst <= 0.51e-9, std::string(ext) << ": largest difference " << worst << " m (6 decimals of a mm)");
    wrc_profile_free(back);
  }
  // A VAMPIRE wheel with the flange backs 1.435 m apart and the tape circle 72 mm from the flange back.
  const std::string custom = (dir / "custom.whe").string();
  REQUIRE_MESSAGE(wrc_profile_write(f.wheel, custom.c_str(), "flange_back=1.435 tape_offset=0.072") == WRC_OK, last());
  std::ifstream in(custom);
  std::string l1, l2, l3, l4;
  std::getline(in, l1), std::getline(in, l2), std::getline(in, l3), std::getline(in, l4);
  CHECK(l3 == "TREADDATUM CUSTOM 72.000000");
  CHECK(l4 == "FLANGEBACK 1435.000000");

  const std::string bad = (dir / "bad.whe").string();
  CHECK(wrc_profile_write(f.wheel, nullptr, nullptr) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_profile_write(nullptr, bad.c_str(), nullptr) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_profile_write(f.wheel, bad.c_str(), "format=gensys") == WRC_ERROR);
  CHECK_MESSAGE(last().find("unknown format 'gensys'; the formats are: text (.txt .dat), csv") != std::string::npos, last());
  CHECK(wrc_profile_write(f.rail, bad.c_str(), nullptr) == WRC_ERROR);
  CHECK_MESSAGE(last().find("a rail profile is written as .rai, not .whe") != std::string::npos, last());
  CHECK_FALSE(std::filesystem::exists(bad));
  std::filesystem::remove_all(dir);
}

TEST_CASE("wrc_profile_warnings: a loaded profile's warnings (those printed on stderr), bad calls a status") {
  Fixture f;
  std::size_t n = 99;
  REQUIRE(wrc_profile_warnings(f.wheel, &n) == WRC_OK);
  CHECK(n == 0);  // the sample S1002, the right way round, its points on the curve
  // The same file read mirrored: its flange on the field side, which the orientation check names, on stderr too.
  wrc_profile* mirrored = nullptr;
  const std::string printed = stderr_of([&] {
    REQUIRE_MESSAGE(wrc_profile_load(WRC_SAMPLES "/s1002.prw", "mirror_y=true", &mirrored) == WRC_OK, last());
  });
  CHECK_MESSAGE(
      (printed.rfind("wrc.profile.load: warning: ", 0) == 0 && printed.find("looks mirrored") != std::string::npos),
      printed);
  REQUIRE(wrc_profile_warnings(mirrored, &n) == WRC_OK);
  REQUIRE(n == 1);
  const char* text = nullptr;
  REQUIRE(wrc_profile_warning(mirrored, 0, &text) == WRC_OK);
  CHECK_MESSAGE(std::string(text).find("the wheel profile looks mirrored") != std::string::npos, text);
  CHECK(wrc_profile_warning(mirrored, 1, &text) == WRC_INVALID_ARGUMENT);
  CHECK_MESSAGE(last().find("index 1 is past the profile's 1 warnings") != std::string::npos, last());
  CHECK(wrc_profile_warning(mirrored, 0, nullptr) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_profile_warnings(mirrored, nullptr) == WRC_INVALID_ARGUMENT);
  CHECK(wrc_profile_warnings(nullptr, &n) == WRC_INVALID_ARGUMENT);
  wrc_profile_free(mirrored);
  CHECK(wrc_profile_warnings(mirrored, &n) == WRC_INVALID_ARGUMENT);  // freed
}

TEST_CASE("wrc_set_profile_warnings_printed: a caller that shows the warnings itself keeps them off stderr") {
  wrc_profile* mirrored = nullptr;
  REQUIRE(wrc_set_profile_warnings_printed(0) == WRC_OK);
  const std::string quiet = stderr_of([&] {
    REQUIRE_MESSAGE(wrc_profile_load(WRC_SAMPLES "/s1002.prw", "mirror_y=true", &mirrored) == WRC_OK, last());
  });
  CHECK_MESSAGE(quiet.empty(), quiet);
  std::size_t n = 0;
  REQUIRE(wrc_profile_warnings(mirrored, &n) == WRC_OK);
  CHECK(n == 1);  // still in the profile
  wrc_profile_free(mirrored);
  // Points given as arrays that scatter as measurement noise (2 um on a circle of 0.5 m): kept off stderr too.
  std::vector<double> y, z;
  for (int i = 0; i <= 600; ++i) {
    y.push_back(-30e-3 + 1e-4 * i);
    z.push_back(0.5 - std::sqrt(0.25 - y.back() * y.back()) + 2e-6 * (i % 2 ? 1 : -1));
  }
  wrc_profile* points = nullptr;
  const std::string quiet_points = stderr_of([&] {
    REQUIRE_MESSAGE(wrc_profile_from_points("rail", y.data(), z.data(), y.size(), nullptr, &points) == WRC_OK, last());
  });
  CHECK_MESSAGE(quiet_points.empty(), quiet_points);
  REQUIRE(wrc_profile_warnings(points, &n) == WRC_OK);
  CHECK(n == 1);
  wrc_profile_free(points);
  // Per thread, as the option dialect: another thread still prints.
  const std::string other = stderr_of([&] {
    std::thread([&] {
      wrc_profile* p = nullptr;
      wrc_profile_load(WRC_SAMPLES "/s1002.prw", "mirror_y=true", &p);
      wrc_profile_free(p);
    }).join();
  });
  CHECK_MESSAGE(
      (other.rfind("wrc.profile.load: warning: ", 0) == 0 && other.find("looks mirrored") != std::string::npos), other);
  CHECK(wrc_set_profile_warnings_printed(2) == WRC_INVALID_ARGUMENT);
  CHECK_MESSAGE(last().find("printed = 2 must be 0 or 1") != std::string::npos, last());
  REQUIRE(wrc_set_profile_warnings_printed(1) == WRC_OK);
  const std::string again = stderr_of([&] {
    wrc_profile* p = nullptr;
    REQUIRE(wrc_profile_from_points("rail", y.data(), z.data(), y.size(), nullptr, &p) == WRC_OK);
    wrc_profile_free(p);
  });
  CHECK_MESSAGE(again.find("wrc: warning: ") != std::string::npos, again);
}

TEST_CASE("the C API reads its arguments and options as one request: search, arguments given twice, on_failure") {
  Fixture f;
  wrc_result *a = nullptr, *b = nullptr;
  // search = "brute" (every rail line against every cone): the same contact as the strategy's.
  REQUIRE_MESSAGE(wrc_contact(f.ws, 3e-3, -0.1e-3, 0, 1e-3, "grids=false", &a) == WRC_OK, last());
  REQUIRE_MESSAGE(wrc_contact(f.ws, 3e-3, -0.1e-3, 0, 1e-3, "grids=false search=brute", &b) == WRC_OK, last());
  for (const char* path : {"left.force.z", "right.force.z", "left.force.y", "right.patches.1.pmax"})
    CHECK(number(a, path) == within_rel(number(b, path), 1e-9));
  wrc_result_free(a);
  wrc_result_free(b);
  wrc_result* r = nullptr;
  CHECK(wrc_contact(f.ws, 0, 0, 0, 0, "search=fastest", &r) == WRC_ERROR);
  CHECK(last().find("'search' must be one of \"strategy\", \"brute\"") != std::string::npos);
  // A number passed as an argument is not an option as well.
  CHECK(wrc_contact(f.ws, 0, -0.1e-3, 0, 0, "z=-1e-3", &r) == WRC_ERROR);
  CHECK(last().find("wrc_contact: 'z' is an argument of wrc_contact, not an option") != std::string::npos);
  CHECK(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 5e4, "side=right", &r) == WRC_ERROR);
  CHECK(wrc_equilibrium(f.ws, 0, 0, 1e5, "Q=2e5", &r) == WRC_ERROR);
  CHECK(last().find("'Q' is an argument") != std::string::npos);
  CHECK(wrc_conicity(nullptr, nullptr, 0, "y=1,2,3", &r) == WRC_ERROR);
  CHECK(last().find("'y' is an argument") != std::string::npos);
  // The status reports a failed solve: on_failure is Lua's.
  CHECK(wrc_wheel(f.ws, WRC_LEFT, 0, 0, 0, 5e4, "on_failure=return", &r) == WRC_ERROR);
  CHECK(last().find("'on_failure' is not an option of the C API") != std::string::npos);
  CHECK(r == nullptr);
  // The rigid contact with Q alone (wrc_rigid) is the rigid contact call with that Q.
  REQUIRE_MESSAGE(wrc_rigid(f.ws, 2e-3, 0, 1e5, &a) == WRC_OK, last());
  REQUIRE_MESSAGE(wrc_rigid_contact(f.ws, 2e-3, 0, "Q=1e5", &b) == WRC_OK, last());
  CHECK(number(a, "z") == number(b, "z"));
  CHECK(number(a, "left.normal_force") == number(b, "left.normal_force"));
  wrc_result_free(a);
  wrc_result_free(b);
}

TEST_CASE("option types in the C API's words (MATLAB's when its gateway asks), positions as ordinals") {
  Fixture f;
  const auto npos = std::string::npos;
  wrc_result* c = nullptr;
  // creepage is a table (creepage.xi=...): a number there is named in the words of option text.
  CHECK(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "creepage=0.001 mu=0.3", &c) == WRC_ERROR);
  CHECK(c == nullptr);
  CHECK(last().find("'creepage' must be a table (dotted keys: key.name=value), got number") != npos);
  // MATLAB's words, on the calling thread only: another thread keeps the C API's.
  REQUIRE(wrc_set_option_dialect("matlab") == WRC_OK);
  CHECK(wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "creepage=0.001 mu=0.3", &c) == WRC_ERROR);
  CHECK(last().find("'creepage' must be a struct, got number") != npos);
  std::string other;
  std::thread([&] {
    wrc_result* r = nullptr;
    wrc_contact(f.ws, 0, -0.05e-3, 0, 0, "creepage=0.001 mu=0.3", &r);
    other = wrc_last_error();
  }).join();
  CHECK(other.find("must be a table (dotted keys") != npos);
  REQUIRE(wrc_set_option_dialect("c") == WRC_OK);
  CHECK(wrc_set_option_dialect("python") == WRC_INVALID_ARGUMENT);
  CHECK(last().find("\"c\" or \"matlab\"") != npos);
  CHECK(wrc_set_option_dialect(nullptr) == WRC_INVALID_ARGUMENT);
  // A C array counts from 0: the NaN planted at dr[bad] is named by its ordinal, the (bad + 1)th point.
  std::vector<double> y, dr;
  for (int i = -10; i <= 10; ++i) {
    y.push_back(i * 1e-3);
    dr.push_back(0.04 * i * 1e-3);
  }
  const std::size_t bad = 2;
  dr[bad] = NAN;
  CHECK(wrc_conicity(y.data(), dr.data(), y.size(), "yhat=2e-3", &c) == WRC_ERROR);
  CHECK(last().find("the 3rd point is not a finite number") != npos);
}
