// Option texts (parse_option_text, wrc/core/options.hpp), as the C API receives them from any caller: nested tables
// from dotted keys, and hostile input (keys nested thousands of levels, very long keys and texts, tens of thousands
// of keys) refused with a message or parsed, never a crash. The time of large parses is printed by
// tests/bench/bench_options.
#include "wrc/core/error.hpp"
#include "wrc/core/options.hpp"

#include <doctest/doctest.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace wrc;

namespace {

// The message of the error parse_option_text throws for `text` ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    parse_option_text(text, "ctx");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// `levels` names joined by dots ("a.a.a").
std::string dotted(int levels) {
  std::string key = "a";
  for (int i = 1; i < levels; ++i) key += ".a";
  return key;
}

}  // namespace

TEST_CASE("option text: values, lists and dotted keys make nested tables in the order given") {
  const OptionTable t = parse_option_text("grid=0.5e-3; crop.y=-0.07,0.06 check_setup=false crop.z=1 name=w1", "ctx");
  REQUIRE(t.entries.size() == 4);
  CHECK(t.entries[0].first == "grid");
  CHECK(t.entries[0].second.number == 0.5e-3);
  CHECK(t.entries[1].first == "crop");
  REQUIRE(t.entries[1].second.type == OptionValue::Type::table);
  const OptionTable& crop = *t.entries[1].second.table;
  REQUIRE(crop.entries.size() == 2);
  CHECK(crop.entries[0].first == "y");
  REQUIRE(crop.entries[0].second.array.size() == 2);
  CHECK(crop.entries[0].second.array[1].number == 0.06);
  CHECK(crop.entries[1].first == "z");
  CHECK(t.entries[2].second.type == OptionValue::Type::boolean);
  CHECK(t.entries[3].second.string == "w1");
}

TEST_CASE("option text: a key 30000 levels deep is refused with the limit, not a stack overflow") {
  const std::string msg = error_of(dotted(30000) + "=1");
  CHECK(msg.find("ctx: the key 'a.a.a.a") != std::string::npos);
  CHECK(msg.find("characters long (at most 256)") != std::string::npos);
  // Within the length, the depth is the bound: 16 levels parse, 17 do not.
  const OptionTable t = parse_option_text(dotted(kMaxOptionDepth) + "=7", "ctx");
  const OptionTable* level = &t;
  for (int i = 1; i < kMaxOptionDepth; ++i) {
    REQUIRE(level->entries.size() == 1);
    REQUIRE(level->entries[0].second.type == OptionValue::Type::table);
    level = level->entries[0].second.table.get();
  }
  CHECK(level->entries[0].second.number == 7);
  CHECK(error_of(dotted(kMaxOptionDepth + 1) + "=1").find("nests more than 16 levels") != std::string::npos);
}

TEST_CASE("option text: keys given twice, a name both a value and a table, empty names and oversized text") {
  CHECK(error_of("grid=1 grid=2") == "ctx: 'grid' is given twice");
  CHECK(error_of("crop.y=1 crop.y=2") == "ctx: 'crop.y' is given twice");
  CHECK(error_of("crop=1 crop.y=2") == "ctx: 'crop' is both a value and a table");
  CHECK(error_of("crop.y=2 crop=1") == "ctx: 'crop' is both a value and a table");
  CHECK(error_of("crop.y.z=2 crop.y=1") == "ctx: 'crop.y' is both a value and a table");
  CHECK(error_of("a..b=1") == "ctx: the key 'a..b' has an empty name between its dots");
  CHECK(error_of(".a=1") == "ctx: the key '.a' has an empty name between its dots");
  CHECK(error_of("a.=1") == "ctx: the key 'a.' has an empty name between its dots");
  CHECK(error_of("=1") == "ctx: '=1' is not a key=value pair");
  CHECK(error_of("novalue") == "ctx: 'novalue' is not a key=value pair");
  const std::string big(kMaxOptionTextLength + 1, ' ');
  CHECK(error_of(big) == fmt::format("ctx: the option text is {} bytes long (at most {})", big.size(), kMaxOptionTextLength));
}

TEST_CASE("option text: 40000 keys, flat and in one nested table, all kept in order") {
  std::string flat, nested;
  for (int i = 0; i < 40000; ++i) {
    flat += fmt::format("k{}={} ", i, i);
    nested += fmt::format("t.k{}={};", i, i);
  }
  const OptionTable f = parse_option_text(flat, "ctx");
  REQUIRE(f.entries.size() == 40000);
  const OptionTable n = parse_option_text(nested, "ctx");
  REQUIRE(n.entries.size() == 1);
  const OptionTable& t = *n.entries[0].second.table;
  REQUIRE(t.entries.size() == 40000);
  for (int i = 0; i < 40000; i += 997) {
    CHECK(f.entries[i].first == fmt::format("k{}", i));
    CHECK(f.entries[i].second.number == i);
    CHECK(t.entries[i].first == fmt::format("k{}", i));
    CHECK(t.entries[i].second.number == i);
  }
}

namespace {

// A reading function as the engine writes them: documented keys, defaults from a struct, a nested table, a check of
// what it read that a documenting pass skips.
struct Params {
  double radius = 0.45;
  int margin = 2;
  bool grids = true;
  std::string surface = "conformal";
  std::string name = "S1002";
  std::optional<double> xi;
  double Q = 0;
};

Params read_params(OptionReader& r) {
  Params p;
  p.radius = r.number("radius", {"m", "wheel radius at the tape circle"}, p.radius);
  p.margin = r.integer("margin", 1, 100, {"1", "elements around the area"}, p.margin);
  p.grids = r.boolean("grids", {"", "keep the pressure grids"}, p.grids);
  p.surface = r.choice("surface", {"planar", "conformal"}, {"", "potential contact area"}, p.surface);
  p.name = r.string("name", {"", "profile name"}, p.name);
  p.Q = r.need_number("Q", {"N", "vertical load"});
  if (auto c = r.table("creepage", {"", "creepages at the reference point"})) {
    p.xi = c->number("xi", {"1", "longitudinal creepage"});
    c->finish();
  }
  if (!r.documenting() && p.Q <= 0) fail("{}: 'Q' must be > 0, got {}", r.context(), p.Q);
  return p;
}

}  // namespace

TEST_CASE("option docs: a documenting reader records every key with type, unit, help, default and choices") {
  std::vector<OptionInfo> keys;
  OptionReader r = OptionReader::documenting("call", keys);
  CHECK(r.documenting());
  read_params(r);
  r.finish();  // nothing to refuse
  REQUIRE(keys.size() == 8);
  auto at = [&](const std::string& k) -> const OptionInfo& {
    for (const auto& i : keys)
      if (i.key == k) return i;
    FAIL("no key " << k);
    return keys.front();
  };
  CHECK(keys[0].key == "radius");  // in the order asked
  CHECK(at("radius").type == "number");
  CHECK(at("radius").unit == "m");
  CHECK(at("radius").help == "wheel radius at the tape circle");
  CHECK(at("radius").fallback == "0.45");
  CHECK(!at("radius").required);
  CHECK(at("margin").type == "integer");
  CHECK(at("margin").fallback == "2");
  CHECK(at("grids").fallback == "true");
  CHECK(at("surface").type == "choice");
  CHECK(at("surface").choices == std::vector<std::string>{"planar", "conformal"});
  CHECK(at("surface").fallback == "\"conformal\"");
  CHECK(at("name").fallback == "\"S1002\"");
  CHECK(at("Q").required);
  CHECK(at("Q").unit == "N");
  CHECK(at("creepage").type == "table");
  CHECK(at("creepage.xi").unit == "1");
  CHECK(at("creepage.xi").fallback.empty());
}

TEST_CASE("option docs: documented getters read values, fallbacks and errors as the plain ones") {
  const OptionTable t = parse_option_text("radius=0.46 surface=planar Q=1e5 creepage.xi=0.001", "ctx");
  OptionReader r(t, "call");
  CHECK(!r.documenting());
  const Params p = read_params(r);
  r.finish();
  CHECK(p.radius == 0.46);
  CHECK(p.margin == 2);
  CHECK(p.grids);
  CHECK(p.surface == "planar");
  CHECK(p.name == "S1002");
  CHECK(p.Q == 1e5);
  CHECK(p.xi == 0.001);

  auto error_reading = [](const std::string& text) -> std::string {
    const OptionTable t2 = parse_option_text(text, "ctx");
    OptionReader r2(t2, "call");
    try {
      read_params(r2);
      r2.finish();
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  CHECK(error_reading("Q=1 surface=round").find("'surface' must be one of \"planar\", \"conformal\"") != std::string::npos);
  CHECK(error_reading("Q=1 margin=0").find("'margin' must be a whole number in 1..100") != std::string::npos);
  CHECK(error_reading("radius=1").find("'Q' is required") != std::string::npos);
  CHECK(error_reading("Q=-1").find("'Q' must be > 0") != std::string::npos);
  CHECK(error_reading("Q=1 raduis=1").find("did you mean 'radius'") != std::string::npos);
}

TEST_CASE("positions in messages: ordinals by the rules of English, from a 0-based index") {
  // English: 1st 2nd 3rd, then th; 11th 12th 13th whatever their tens; 21st 22nd 23rd again, and so in each hundred.
  const std::pair<std::size_t, const char*> cases[] = {{1, "1st"},     {2, "2nd"},     {3, "3rd"},     {4, "4th"},
                                                       {10, "10th"},   {11, "11th"},   {12, "12th"},   {13, "13th"},
                                                       {21, "21st"},   {22, "22nd"},   {23, "23rd"},   {101, "101st"},
                                                       {111, "111th"}, {112, "112th"}, {1002, "1002nd"}};
  for (const auto& [n, text] : cases) CHECK(ordinal(n) == text);
  CHECK(value_at(0, "'y'") == "the 1st value of 'y'");
  CHECK(value_at(1, "mu") == "the 2nd value of mu");
}

TEST_CASE("numbers in messages: a NaN of either sign reads NaN, whatever the format, other numbers as fmt writes them") {
  // Lua's 0/0 has its sign bit set, which fmt (as printf) wrote "-nan": the message named a negative that is not one.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const double v : {nan, -nan, std::copysign(nan, -1.0)}) {
    CHECK(format_message("got {}", v) == "got NaN");
    CHECK(format_message("got {:.6f} m", v) == "got NaN m");
    CHECK(format_message("got {:g}", static_cast<float>(v)) == "got NaN");
    CHECK(number_text(v) == "NaN");
    CHECK_THROWS_WITH_AS(fail("'{}' must be finite, got {}", "y", v), "'y' must be finite, got NaN", Error);
  }
  // Everything else as fmt writes it, format specifications and all: the reference is fmt::format itself.
  for (const double v : {inf, -inf, 0.0, -0.0, 1e-300, 0.1, -1.5e308, 1.0 / 3})
    for (const char* spec : {"{}", "{:g}", "{:.3f}", "{:+.2e}", "{:>12.4g}"}) {
      CAPTURE(v);
      CAPTURE(spec);
      CHECK(format_message(fmt::runtime(spec), v) == fmt::format(fmt::runtime(spec), v));
    }
  CHECK(format_message("{} {} {}", inf, -inf, 3) == "inf -inf 3");
  CHECK(format_message("{} of {}", std::string("y"), 'z') == "y of z");
}

namespace {

// The message of reading `key` from `t` as a table (and its key 'inner' as a table) or as numbers ("" when it reads).
std::string reading_error(const OptionTable& t, bool table, const char* key) {
  try {
    OptionReader r(t, "call");
    if (table) {
      auto sub = r.table(key);
      if (sub) sub->table("inner");
    } else {
      r.numbers(key);
    }
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("option types in the words of the front end that built the options, positions the same from all") {
  // 'creepage' given as an array where a table is read, and 'y' holding NaN as its 2nd of three values.
  OptionTable t;
  t.set("creepage", OptionValue::of(std::vector<OptionValue>{OptionValue::of(1e-3)}));
  t.set("y", OptionValue::of(std::vector<OptionValue>{OptionValue::of(0.0), OptionValue::of(std::nan("")),
                                                      OptionValue::of(1.0)}));
  OptionTable holder;  // a table nested in it, built by C++ code (no dialect of its own): its reader keeps the root's
  holder.set("inner", OptionValue::of(true));
  t.set("outer", OptionValue::of(holder));
  const std::pair<OptionDialect, const char*> dialects[] = {{OptionDialect::lua, "must be a table, got array"},
                                                            {OptionDialect::python, "must be a dict, got list"},
                                                            {OptionDialect::matlab, "must be a struct, got numeric array"},
                                                            {OptionDialect::c, "must be a table (dotted keys"}};
  for (const auto& [dialect, words] : dialects) {
    CAPTURE(words);
    t.dialect = dialect;
    CHECK(reading_error(t, true, "creepage").find(std::string("'creepage' ") + words) != std::string::npos);
    CHECK(reading_error(t, false, "y") == "call: the 2nd value of 'y' must be finite, got NaN");
    const std::string nested = reading_error(t, true, "outer");
    CHECK(nested.find(std::string("call: 'outer': 'inner' must be ") + option_words(dialect).a_table + ", got " +
                      option_words(dialect).boolean) != std::string::npos);
  }
  // The C API's text: its tables, nested ones too, carry the dialect it is parsed with.
  const OptionTable m = parse_option_text("creepage=0.001 outer.inner=true", "ctx", OptionDialect::matlab);
  CHECK(reading_error(m, true, "creepage").find("'creepage' must be a struct, got number") != std::string::npos);
  CHECK(reading_error(m, true, "outer").find("'inner' must be a struct, got logical") != std::string::npos);
}

TEST_CASE("a table given as another type: the message shows the table's shape from the key's help") {
  OptionTable t;
  t.set("profile", OptionValue::of(std::vector<OptionValue>{OptionValue::of(0.0), OptionValue::of(0.3)}));
  t.set("bare", OptionValue::of(1.0));
  t.dialect = OptionDialect::python;
  OptionReader r(t, "call");
  CHECK_THROWS_WITH_AS(r.table("profile", {"-", "mu across the rail: {y =, mu =}"}),
                       "call: 'profile' must be a dict, got list (profile: mu across the rail: {y =, mu =})", Error);
  CHECK_THROWS_WITH_AS(r.table("bare"), "call: 'bare' must be a dict, got number", Error);  // no help: as before
}

TEST_CASE("closest name: a key in another case is the one meant, before a key one edit away") {
  // 'q' is one edit from 'y' and from 'Q' alike; only the case tells which was meant.
  CHECK(closest_name("q", {"y", "yaw", "Q"}) == "Q");
  CHECK(closest_name("FZ", {"y", "Fz", "fy"}) == "Fz");
  CHECK(closest_name("yhta", {"yhat", "y"}) == "yhat");  // edits as before
  CHECK(closest_name("xyz", {"Q"}).empty());
}

TEST_CASE("closest name: a short word is not 'meant' by a name that shares none of its letters in place") {
  // Two edits are a typo's allowance, but for a two-letter word they replace it whole.
  CHECK(closest_name("ab", {"mu", "V", "Q"}).empty());
  CHECK(closest_name("x", {"y", "V"}).empty());
  CHECK(closest_name("mv", {"mu", "V"}) == "mu");  // one letter kept
  CHECK(closest_name("yy", {"y", "yaw"}) == "y");
}
