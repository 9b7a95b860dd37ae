// The sandbox of profile definitions (engine/src/lua/sandbox.hpp) with small budgets: each limit stops a definition
// with a message naming the definition and the budget, a nested load of a shipped profile spends the same budget, a
// definition within its budgets gives the profile the study would get, and a definition that would write a file
// through the C API's loader cannot. tests/scripts/profile_sandbox.lua runs the same at the default budgets.
#include "lua/sandbox.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/lua/host.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using wrc::lua::SandboxLimits;

namespace {

fs::path folder() {
  const char* tmp = std::getenv("WRC_TEST_TMP");
  const fs::path dir = fs::path(tmp ? tmp : fs::temp_directory_path().string()) / "lua_sandbox";
  fs::create_directories(dir);
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = folder() / name;
  std::ofstream(p) << text;
  return p.string();
}

// The message of loading `path` with `limits` ("" when it loads).
std::string error_of(const std::string& path, const SandboxLimits& limits) {
  try {
    wrc::lua::load_definition(path, {}, limits);
  } catch (const wrc::Error& e) {
    return e.what();
  }
  return "";
}

SandboxLimits small(std::uint64_t instructions, std::size_t memory, double points) {
  SandboxLimits l;
  l.instructions = instructions;
  l.memory = memory;
  l.points = points;
  return l;
}

}  // namespace

TEST_CASE("sandbox: each budget stops a definition, pcall or not, naming the definition and the budget") {
  const SandboxLimits limits = small(100'000, 2u << 20, 10'000);
  const std::string loop = write("loop.lua", "while true do pcall(function() while true do end end) end");
  CHECK(error_of(loop, limits) ==
        "wrc.profile.load: the profile definition " + loop + " exceeded its CPU budget (100000 Lua instructions)");
  const std::string table = write("table.lua", "local t = {} for i = 1, 1e9 do pcall(function() t[i] = {i} end) end");
  CHECK(error_of(table, small(1'000'000'000, 2u << 20, 10'000)) ==
        "wrc.profile.load: the profile definition " + table + " exceeded its memory budget (2 MB)");
  const std::string points = write("points.lua",
                                   "local p = wrc.profile.points{kind = 'rail', y = {-0.01, 0, 0.01}, z = {-1e-3, 0, -1e-3}}\n"
                                   "for i = 1, 100 do pcall(p.resample, p, {step = 1e-5}) end");
  CHECK(error_of(points, limits) ==
        "wrc.profile.load: the profile definition " + points + " made more profile points than its budget (10000 in all)");
}

TEST_CASE("sandbox: a shipped profile loaded by a definition spends the definition's budget") {
  const std::string worn = wrc::paths().profiles + "/worn_s1002.lua";
  // The S1002 that worn_s1002.lua loads runs some 3e5 instructions at its default step.
  CHECK(error_of(worn, small(50'000, 256u << 20, 1e7)).find("the profile definition " + worn + " exceeded its CPU budget") !=
        std::string::npos);
  CHECK(error_of(worn, SandboxLimits{}).empty());
}

TEST_CASE("sandbox: within its budgets a definition gives the profile a study gets") {
  const std::string s1002 = wrc::paths().profiles + "/s1002.lua";
  const wrc::Profile p = wrc::lua::load_definition(s1002, {});
  const auto q = wrc::lua::load_profile("profiles/s1002.lua", {});
  CHECK(p.y == q->y);
  CHECK(p.z == q->z);
  CHECK(p.source == s1002);
}

TEST_CASE("sandbox: the C++ loader of the C API runs a definition sandboxed") {
  const fs::path marker = folder() / "MARKER";
  fs::remove(marker);
  const std::string hostile = write("hostile.lua", "io.open('" + marker.string() + "', 'w'):write('x')");
  std::string msg;
  try {
    wrc::lua::load_profile(hostile, {});
  } catch (const wrc::Error& e) {
    msg = e.what();
  }
  CHECK(msg.find(hostile + ":1: 'io' is not available in a profile definition") != std::string::npos);
  CHECK_FALSE(fs::exists(marker));
}
