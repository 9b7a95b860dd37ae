// FieldRecorder (wrc/core/field_record.hpp): the tree it records is the description as it was made -- nested tables
// and lists in their order, every kind of value with its unit, NaN and empty arrays kept as they are -- and owns
// its values.
#include "wrc/core/field_record.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace wrc;
using K = FieldNode::Kind;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// A result's description written out by hand: what the test expects is read off these lines.
struct Sample {
  std::vector<double> forces{1.5, nan, -2};
  std::vector<long long> ids{7, -3};
  std::vector<double> grid{1, 2, 3, 4, 5, 6};  // nx = 3, ny = 2
};

void describe(const Sample& s, FieldSink& out) {
  out.object_type("wrc.Sample");
  out.number("pmax", 1e9, {"Pa", "peak pressure"});
  out.number("gap", nan);  // undocumented, NaN
  out.integer("regions", 2, {"-", "number of regions"});
  out.boolean("converged", false, {"", "whether it converged"});
  out.string("method", "fft", {"", "the solver"});
  out.numbers("forces", s.forces.data(), s.forces.size(), {"N", "force per region"});
  out.numbers("empty", nullptr, 0, {"m", "no values"});
  out.integers("ids", s.ids.data(), s.ids.size());
  out.vec3("moment", Eigen::Vector3d(1, 2, 3), {"N m", "moment"});
  out.begin("left", {"", "the left side"});
  out.begin("inner");
  out.grid("pressure", s.grid.data(), 3, 2, {"Pa", "pressure per element"});
  out.integers("none", nullptr, 0);
  out.end();
  out.begin_list("patches", 1, {"", "the contact areas"});  // announces 1, gives 3 (the first with a type)
  for (int i = 0; i < 3; ++i) {
    out.item();
    if (i == 0) out.object_type("wrc.Patch");
    out.number("fz", 10.0 * i, {"N", "vertical force"});
    out.end();
  }
  out.end();
  out.begin_list("nothing", 0);
  out.end();
  out.end();
  out.number("pmax", 2e9);  // repeated: kept as a second field
  out.end();  // one end() too many: the root stays open
  out.string("last", "");
}

// A description with an extra argument (as a contact result's with its sensitivity flag).
struct Scaled {
  double v;
};

void describe(const Scaled& s, FieldSink& out, double factor) { out.number("v", s.v * factor, {"m", "v scaled"}); }

const FieldNode& at(const FieldNode& n, std::size_t i, K kind, const char* key) {
  REQUIRE(i < n.children().size());
  const FieldNode& c = *n.child(i);
  CHECK(c.kind == kind);
  CHECK(c.key == key);
  return c;
}

// The field name "a3" of array 3: a letter with the number appended (GCC 12 mistakes "a" + std::to_string(3), a
// string inserted before, for an overlapping memcpy: -Wrestrict).
std::string field_name(char letter, std::size_t number) {
  std::string s(1, letter);
  s += std::to_string(number);
  return s;
}

}  // namespace

TEST_CASE("field record: the tree is the description, in its order, with units, NaN and empty arrays") {
  auto s = std::make_unique<Sample>();
  FieldRecorder rec;
  describe(*s, rec);
  FieldRecord taken = rec.take();
  s.reset();  // the record owns copies: the source gone, its values stay
  const FieldNode* before = &taken.root();
  const FieldRecord record = std::move(taken);
  const FieldNode& r = record.root();
  CHECK(&r == before);  // moving a record moves no node
  CHECK(r.kind == K::table);
  CHECK(r.object_type == "wrc.Sample");
  REQUIRE(r.children().size() == 12);
  REQUIRE(r.fields == 12);

  const FieldNode& pmax = at(r, 0, K::number, "pmax");
  CHECK(pmax.number == 1e9);
  CHECK(pmax.unit == "Pa");
  CHECK(pmax.documented);
  CHECK(pmax.meaning.empty());  // meanings only when asked for
  const FieldNode& gap = at(r, 1, K::number, "gap");
  CHECK(std::isnan(gap.number));
  CHECK(!gap.documented);
  CHECK(gap.unit.empty());
  CHECK(at(r, 2, K::integer, "regions").integer == 2);
  CHECK(at(r, 3, K::boolean, "converged").integer == 0);
  CHECK(at(r, 4, K::string, "method").text == "fft");

  const FieldNode& forces = at(r, 5, K::numbers, "forces");
  REQUIRE(forces.values.size() == 3);
  CHECK(forces.values[0] == 1.5);
  CHECK(std::isnan(forces.values[1]));
  CHECK(forces.values[2] == -2);
  CHECK(forces.unit == "N");
  const FieldNode& empty = at(r, 6, K::numbers, "empty");
  CHECK(empty.values.empty());
  CHECK(empty.unit == "m");
  const FieldNode& ids = at(r, 7, K::integers, "ids");
  CHECK(std::vector<long long>(ids.integers.begin(), ids.integers.end()) == std::vector<long long>{7, -3});

  const FieldNode& moment = at(r, 8, K::table, "moment");
  CHECK(moment.unit == "N m");
  REQUIRE(moment.children().size() == 3);
  CHECK(at(moment, 2, K::number, "z").number == 3);
  CHECK(moment.child(2)->unit == "N m");
  CHECK(moment.child(3) == nullptr);
  CHECK(r.find("moment") == &moment);
  CHECK(r.find("absent") == nullptr);

  const FieldNode& left = at(r, 9, K::table, "left");
  REQUIRE(left.children().size() == 3);
  const FieldNode& inner = at(left, 0, K::table, "inner");
  REQUIRE(inner.children().size() == 2);
  const FieldNode& grid = at(inner, 0, K::grid, "pressure");
  CHECK(grid.nx == 3);
  CHECK(grid.ny == 2);
  CHECK(std::vector<double>(grid.values.begin(), grid.values.end()) == std::vector<double>{1, 2, 3, 4, 5, 6});
  CHECK(at(inner, 1, K::integers, "none").integers.empty());

  const FieldNode& patches = at(left, 1, K::list, "patches");
  CHECK(patches.count == 1);  // as announced; the items are what came
  REQUIRE(patches.children().size() == 3);
  for (int i = 0; i < 3; ++i) {
    const FieldNode& item = at(patches, i, K::table, "");
    CHECK(!item.documented);
    CHECK(item.object_type == (i == 0 ? "wrc.Patch" : ""));
    REQUIRE(item.children().size() == 1);
    CHECK(at(item, 0, K::number, "fz").number == 10.0 * i);
  }
  const FieldNode& nothing = at(left, 2, K::list, "nothing");
  CHECK(nothing.count == 0);
  CHECK(nothing.children().empty());

  CHECK(at(r, 10, K::number, "pmax").number == 2e9);
  CHECK(r.find("pmax") == &pmax);  // find gives the first
  CHECK(at(r, 11, K::string, "last").text.empty());
}

TEST_CASE("field record: meanings when asked for, and record_fields passes the describe's extra arguments") {
  FieldRecorder rec(true);
  describe(Sample{}, rec);
  const FieldRecord record = rec.take();
  const FieldNode& r = record.root();
  CHECK(r.child(0)->meaning == "peak pressure");
  CHECK(r.find("left")->meaning == "the left side");
  CHECK(r.find("moment")->child(0)->meaning == "x component");
  CHECK(r.find("gap")->meaning.empty());
  CHECK(rec.take().root().children().empty());  // take() leaves an empty record

  const FieldRecord scaled = record_fields(Scaled{2.0}, 3.0);
  REQUIRE(scaled.root().children().size() == 1);
  CHECK(scaled.root().child(0)->number == 6.0);
  CHECK(scaled.root().child(0)->unit == "m");
}

TEST_CASE("field record: take() closes the tables left open") {
  FieldRecorder rec;
  rec.begin("outer");
  rec.begin("inner");
  rec.number("a", 1);
  rec.end();
  rec.number("b", 2);  // outer never closed
  const FieldRecord record = rec.take();
  const FieldNode& r = record.root();
  REQUIRE(r.fields == 1);
  const FieldNode& outer = *r.child(0);
  REQUIRE(outer.fields == 2);
  CHECK(outer.child(0)->child(0)->number == 1);
  CHECK(outer.child(1)->number == 2);
  CHECK(r.below == 4);
}

TEST_CASE("field record: arrays of every size keep their values (small, block-sized, larger than a block)") {
  FieldRecorder rec;
  std::vector<std::vector<double>> arrays;
  for (std::size_t n : {1, 3, 100, 127, 128, 129, 1000, 2047, 2048, 2049, 5000, 20000, 2, 7})
    arrays.emplace_back(n, 0.0);
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    for (std::size_t i = 0; i < arrays[a].size(); ++i) arrays[a][i] = 1e6 * double(a) + double(i);
    rec.numbers(field_name('a', a), arrays[a].data(), arrays[a].size());
    rec.string(field_name('s', a), std::string(arrays[a].size() % 3000, 'x'));
  }
  FieldRecord record = rec.take();
  REQUIRE(record.root().fields == 2 * arrays.size());
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    const FieldNode& n = *record.root().find(field_name('a', a));
    CHECK(std::vector<double>(n.values.begin(), n.values.end()) == arrays[a]);
    CHECK(record.root().find(field_name('s', a))->text == std::string(arrays[a].size() % 3000, 'x'));
  }
  FieldRecord owned = std::move(record);
  for (std::size_t a : {std::size_t{2}, std::size_t{11}})  // 100 values (copied), 20000 (its storage taken)
    CHECK(owned.take_values(*owned.root().find(field_name('a', a))) == arrays[a]);
}

TEST_CASE("field record: storage reused for the next record holds only the next record's fields") {
  FieldRecorder first;
  Sample s;
  describe(s, first);
  FieldRecord used = first.take();
  const FieldNode* root_before = &used.root();
  FieldRecorder second(std::move(used));
  second.number("only", 4.5, {"m", "the one field"});
  FieldRecord record = second.take();
  REQUIRE(record.root().fields == 1);
  CHECK(record.root().child(0)->number == 4.5);
  CHECK(record.root().child(0)->unit == "m");
  CHECK(record.root().object_type.empty());
  CHECK(&record.root() == root_before);  // the same nodes' array

  const FieldRecord elsewhere = std::move(record);
  CHECK(elsewhere.root().fields == 1);
  FieldRecorder third(std::move(record));  // a moved-from record is storage too
  CHECK(third.take().root().fields == 0);
  for (int round = 0; round < 3; ++round) {  // the thread's storage, converted at once, round after round
    double got = 0;
    std::size_t fields = 0;
    record_and_convert(
        [&](const FieldRecord& r) {
          got = r.root().find("pmax")->number;
          fields = r.root().fields;
        },
        s);
    CHECK(got == 1e9);
    CHECK(fields == 12);
  }
}
