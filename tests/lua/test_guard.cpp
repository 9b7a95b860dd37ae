// The exception -> Lua error boundary (engine/src/lua/guard.hpp): a C++ exception thrown inside an engine
// call made from Lua reaches Lua as an error message, and the C++ objects of that call are destroyed
// before lua_error longjmps.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "wrc/core/error.hpp"
#include "wrc/lua/host.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace {

int g_alive = 0;      // live Sentinel objects
int g_destroyed = 0;  // Sentinel destructors run

struct Sentinel {
  std::vector<double> payload = std::vector<double>(1000, 1.0);  // owns heap memory (ASan sees a leak)
  Sentinel() { ++g_alive; }
  ~Sentinel() {
    --g_alive;
    ++g_destroyed;
  }
};

int throwing_call(lua_State* L) {
  Sentinel a;
  std::string label = "a heap string that would leak if its destructor were skipped";
  Sentinel b;
  const double x = wrc::lua::check_number(L, 1, "throwing_call");
  if (x > 0) wrc::fail("throwing_call: x = {} must not be positive ({})", x, label.size());
  lua_pushnumber(L, -x);
  return 1;
}

int throwing_unknown(lua_State*) {
  Sentinel a;
  throw 42;  // not a std::exception
}

}  // namespace

TEST_CASE("a C++ exception reaches Lua as an error after the call's objects are destroyed") {
  wrc::lua::Session s;
  auto* L = static_cast<lua_State*>(s.state());
  lua_register(L, "throwing_call", wrc::lua::guarded<throwing_call>);
  lua_register(L, "throwing_unknown", wrc::lua::guarded<throwing_unknown>);

  g_alive = g_destroyed = 0;
  auto err = s.run(
      "local ok, msg = pcall(function() return throwing_call(2) end)\n"
      "assert(not ok)\n"
      "error(msg, 0)\n",
      "=study.lua");
  REQUIRE(err.has_value());
  // Message of the exception, prefixed with the Lua line that made the call.
  CHECK(err->find("study.lua:1: throwing_call: x = 2 must not be positive") != std::string::npos);
  CHECK(g_destroyed == 2);
  CHECK(g_alive == 0);

  SUBCASE("an argument error from a check_ helper is an exception too") {
    g_alive = g_destroyed = 0;
    auto e = s.run("throwing_call('abc')", "=study.lua");
    REQUIRE(e.has_value());
    CHECK(e->find("throwing_call: argument 1 must be a number, got string") != std::string::npos);
    CHECK(e->find("stack traceback") != std::string::npos);
    CHECK(g_destroyed == 2);
    CHECK(g_alive == 0);
  }

  SUBCASE("a non-standard exception becomes a generic error") {
    g_alive = g_destroyed = 0;
    auto e = s.run("throwing_unknown()", "=study.lua");
    REQUIRE(e.has_value());
    CHECK(e->find("unknown C++ exception") != std::string::npos);
    CHECK(g_destroyed == 1);
    CHECK(g_alive == 0);
  }

  SUBCASE("no exception: the call returns normally") {
    g_alive = g_destroyed = 0;
    auto e = s.run("assert(throwing_call(-3) == 3)");
    CHECK_FALSE(e.has_value());
    CHECK(g_destroyed == 2);
  }
}

TEST_CASE("the wrc module and its Lua library are loaded in every state") {
  wrc::lua::Session s;
  CHECK_FALSE(s.run("assert(type(wrc) == 'table' and type(wrc.version) == 'string')").has_value());
  CHECK_FALSE(s.run("local c = require 'wrc.check'; c.near(1.0, 1.0, 0, 'one')").has_value());
  auto e = s.run("require 'wrc.no_such_module'");
  REQUIRE(e.has_value());
  CHECK(e->find("no_such_module") != std::string::npos);
}
