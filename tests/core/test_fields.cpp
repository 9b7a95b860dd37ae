// FieldSink (wrc/core/fields.hpp): a field's documentation reaches the sink's document() just before the value, and
// a sink that ignores documentation receives the same values as from the calls without it.
#include "wrc/core/fields.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace wrc;

namespace {

// Records "document key unit meaning" and "value key" lines in the order of the calls.
class Recorder final : public FieldSink {
 public:
  std::vector<std::string> log;
  void number(std::string_view key, double) override { put("number", key); }
  void integer(std::string_view key, long long) override { put("integer", key); }
  void boolean(std::string_view key, bool) override { put("boolean", key); }
  void string(std::string_view key, std::string_view) override { put("string", key); }
  void numbers(std::string_view key, const double*, std::size_t) override { put("numbers", key); }
  void integers(std::string_view key, const long long*, std::size_t) override { put("integers", key); }
  void grid(std::string_view key, const double*, int, int) override { put("grid", key); }
  void begin(std::string_view key) override { put("begin", key); }
  void begin_list(std::string_view key, std::size_t) override { put("begin_list", key); }
  void item() override { log.push_back("item"); }
  void end() override { log.push_back("end"); }

 protected:
  void document(std::string_view key, FieldDoc doc) override {
    log.push_back("doc " + std::string(key) + " [" + doc.unit + "] " + doc.meaning);
  }

 private:
  void put(const char* kind, std::string_view key) { log.push_back(std::string(kind) + " " + std::string(key)); }
};

void describe_sample(FieldSink& out) {
  out.number("pmax", 1e9, {"Pa", "peak pressure"});
  out.integer("regions", 2);
  out.vec3("force", Eigen::Vector3d(1, 2, 3), {"N", "force on the wheel"});
}

}  // namespace

TEST_CASE("fields: documentation reaches document() before each value, undocumented calls reach only the value") {
  Recorder r;
  describe_sample(r);
  const std::vector<std::string> expected = {
      "doc pmax [Pa] peak pressure", "number pmax", "integer regions", "doc force [N] force on the wheel",
      "begin force", "doc x [N] x component", "number x", "doc y [N] y component", "number y",
      "doc z [N] z component", "number z", "end"};
  CHECK(r.log == expected);
}

// ---- DocSink (wrc/core/field_reference.hpp) ----

#include "wrc/core/field_reference.hpp"

namespace {

// A result with a list and the two wheels' tables, as the engine's descriptions write them.
void describe_wheels(FieldSink& out, bool second_patch_documented) {
  for (const char* side : {"left", "right"}) {
    out.begin(side, {"", "the wheel on that side"});
    out.begin_list("patches", 2, {"", "contact areas"});
    for (int k = 0; k < 2; ++k) {
      out.item();
      if (k == 1 && !second_patch_documented) out.number("pmax", 1.0);
      else out.number("pmax", 1.0, {"Pa", "peak pressure"});
      out.end();
    }
    out.end();
    out.end();
  }
  out.number("Y", 0.0, {"N", "lateral force"});
}

std::vector<std::string> rows(const DocSink& s) {
  std::vector<std::string> out;
  for (const FieldEntry& e : s.entries()) out.push_back(e.lua + " " + e.c + " " + e.kind + " [" + e.unit + "] " + e.meaning);
  return out;
}

}  // namespace

TEST_CASE("fields: DocSink records one pattern per field, list items as N and the wheels as <side>") {
  DocSink s;
  describe_wheels(s, true);
  const std::vector<std::string> expected = {
      "<side> <side> table [] the wheel on that side", "<side>.patches <side>.patches list [] contact areas",
      "<side>.patches[N].pmax <side>.patches.N.pmax number [Pa] peak pressure", "Y Y number [N] lateral force"};
  CHECK(rows(s) == expected);
  CHECK(s.problems().empty());
}

TEST_CASE("fields: DocSink reports a field written without documentation, once") {
  DocSink s;
  describe_wheels(s, false);
  REQUIRE(s.problems().size() == 1);
  CHECK(s.problems()[0] == "<side>.patches.N.pmax: written without a FieldDoc (unit and meaning)");
}

TEST_CASE("fields: DocSink reports a number without a unit, a flag with one, an empty meaning, a path documented twice") {
  DocSink s;
  FieldSink& out = s;
  out.number("a", 1.0, {"", "no unit"});
  out.boolean("b", true, {"m", "a flag with a unit"});
  out.string("c", "x", {"", ""});
  out.number("d", 1.0, {"m", "one way"});
  s.restart();
  out.number("d", 1.0, {"m", "another way"});
  out.integer("e", 3, {"-", "a count"});
  const std::vector<std::string> expected = {
      "a: a number without a unit (\"-\" for a pure number, an index or a count)",
      "b: a boolean with the unit \"m\" (text, flags and lists have none)", "c: no meaning",
      "d: documented two ways: number [m] \"one way\" and number [m] \"another way\""};
  CHECK(s.problems() == expected);
}

TEST_CASE("fields: DocSink places a field first seen in a later description after the field written before it") {
  DocSink s;
  FieldSink& out = s;
  out.boolean("converged", true, {"", "solved"});
  out.number("z", 0.0, {"m", "height"});
  s.restart();
  out.boolean("converged", false, {"", "solved"});
  out.string("error", "why", {"", "why not"});
  out.number("z", 0.0, {"m", "height"});
  REQUIRE(s.entries().size() == 3);
  CHECK(s.entries()[1].c == "error");
  CHECK(s.entries()[2].c == "z");
}
