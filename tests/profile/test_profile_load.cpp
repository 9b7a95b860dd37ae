// wrc::load_profile, the one way every front end loads a profile (profile/load.hpp), from this suite that links the
// profile area alone, without Lua: a .lua definition goes to the DefinitionLoader the caller passes and nowhere else
// (a fake one here, recording its calls), the host's options are applied to what it returns, a file goes to the
// readers (the registry given first, then the reader plugins of <build>/plugins), and without a loader a definition
// is refused with a message naming the file.
#include "wrc/core/error.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/reader.hpp"
#include "approx.hpp"
#include "scratch.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

using wrc::test::within_abs;
using wrc::test::within_rel;
using namespace wrc;

namespace {

using test::tmp_path;
using test::write_tmp;

// A rail head every millimetre from -20 to 20 mm: z = -y^2 / 600 mm (a parabola of 300 mm radius at the top).
struct Head {
  std::vector<double> y_mm, z_mm;
  Head() {
    for (int i = -20; i <= 20; ++i) {
      y_mm.push_back(i);
      z_mm.push_back(-double(i) * i / 600.0);
    }
  }
  std::string text() const {
    std::string s;
    char line[64];
    for (std::size_t i = 0; i < y_mm.size(); ++i) {
      std::snprintf(line, sizeof line, "%.17g %.17g\n", y_mm[i], z_mm[i]);
      s += line;
    }
    return s;
  }
};

// A definition loader that records its calls and returns the head in metres, as a definition would make it.
struct FakeDefinitions {
  std::vector<std::string> paths;
  std::vector<OptionTable> options;
  DefinitionLoader loader() {
    return [this](const std::string& path, const OptionTable& o) {
      paths.push_back(path);
      options.push_back(o);
      const Head h;
      std::vector<double> y, z;
      for (std::size_t i = 0; i < h.y_mm.size(); ++i) {
        y.push_back(h.y_mm[i] * 1e-3);
        z.push_back(h.z_mm[i] * 1e-3);
      }
      return make_profile(ProfileKind::rail, y, z, "head", "(fake definition)");
    };
  }
};

std::string error_of(const std::string& name, const std::string& options, const DefinitionLoader* definitions) {
  try {
    load_profile(name, parse_option_text(options, "test"), definitions);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("load_profile: a .lua definition runs through the loader given, with every option as its arguments") {
  const std::string path = write_tmp("head.lua", "error('the fake loader never runs this')\n");
  FakeDefinitions fake;
  const DefinitionLoader loader = fake.loader();
  const Profile p = load_profile(path, parse_option_text("mirror_y=true shift.z=0.002 step=0.5e-3", "test"), &loader);
  REQUIRE(fake.paths == std::vector<std::string>{path});
  const OptionTable& seen = fake.options.at(0);
  REQUIRE(seen.find("step") != nullptr);  // the definition's own key reaches it
  CHECK(seen.find("step")->number == 0.5e-3);
  CHECK(seen.find("mirror_y") != nullptr);
  // The host applies mirror_y and the shift to what the definition made: each point (y, z) becomes (-y, z + 2 mm).
  const Head h;
  REQUIRE(p.size() == h.y_mm.size());
  for (std::size_t i = 0; i < h.y_mm.size(); ++i) {
    const double y = -h.y_mm[i] * 1e-3, z = h.z_mm[i] * 1e-3 + 0.002;
    const auto at = std::find_if(p.y.begin(), p.y.end(), [&](double v) { return std::abs(v - y) < 1e-15; });
    REQUIRE_MESSAGE(at != p.y.end(), "no point at y = " << y);
    CHECK(p.z[at - p.y.begin()] == within_rel(z, 1e-14));
  }
  CHECK(p.source == path);
  CHECK(p.kind == ProfileKind::rail);
}

TEST_CASE("load_profile: a file never reaches the definition loader, nor does a .lua given to a reader") {
  const Head h;
  const std::string txt = write_tmp("head.txt", h.text());
  FakeDefinitions fake;
  const DefinitionLoader loader = fake.loader();
  const Profile p = load_profile(txt, parse_option_text("kind=rail", "test"), &loader);
  CHECK(fake.paths.empty());
  REQUIRE(p.size() == h.y_mm.size());
  for (std::size_t i = 0; i < h.y_mm.size(); ++i) {
    CHECK(p.y[i] == within_abs(h.y_mm[i] * 1e-3, 1e-15));  // m; the points include y = 0
    CHECK(p.z[i] == within_abs(h.z_mm[i] * 1e-3, 1e-15));
  }
  CHECK(p.transforms.at(0) == "read by 'text'");
  // The same points in a file named .lua, given to the text reader: read, not run.
  const std::string lua = write_tmp("points.lua", h.text());
  const Profile q = load_profile(lua, parse_option_text("kind=rail reader=text", "test"), &loader);
  CHECK(fake.paths.empty());
  CHECK(q.y == p.y);
  CHECK(q.z == p.z);
}

TEST_CASE("load_profile: without a definition loader a definition is refused, and units never apply to one") {
  const std::string path = write_tmp("refused.lua", "return nil\n");
  CHECK(error_of(path, "", nullptr) ==
        "wrc.profile.load: " + path + ": a Lua profile definition, and this program loads no Lua (only files that a "
        "reader reads)");
  FakeDefinitions fake;
  const DefinitionLoader loader = fake.loader();
  CHECK(error_of(path, "units=mm", &loader) ==
        "wrc.profile.load: " + path + ": 'units' does not apply to a Lua definition (it returns metres)");
  CHECK(fake.paths.empty());  // refused before it runs
  CHECK(error_of(path, "mirror_y=3", &loader).find("mirror_y") != std::string::npos);  // options read first
  CHECK(fake.paths.empty());
  CHECK(error_of(tmp_path("missing.lua"), "", &loader).find("no such file") != std::string::npos);
}

TEST_CASE("load_profile: the readers given are looked up before the plugins, by extension and by id") {
  const Head h;
  const std::string txt = write_tmp("mine.txt", h.text());
  ReaderRegistry mine;
  Reader r;
  r.id = "mine";
  r.origin = "test";
  r.extensions = {".txt"};
  r.read = [](const std::string&, std::optional<ProfileKind>, const ReaderOptions&) {
    RawProfile raw;
    raw.y = {-10, 0, 10};  // mm
    raw.z = {-1, 0, -1};
    raw.kind = ProfileKind::rail;
    return raw;
  };
  mine.add(std::move(r));
  const Profile by_extension = load_profile(txt, {}, nullptr, &mine);
  CHECK(by_extension.size() == 3);
  CHECK(by_extension.transforms.at(0) == "read by 'mine'");
  // reader = "text" names the plugin, which the registry given does not hold.
  const Profile by_id = load_profile(txt, parse_option_text("reader=text kind=rail", "test"), nullptr, &mine);
  CHECK(by_id.size() == h.y_mm.size());
  CHECK(by_id.transforms.at(0) == "read by 'text'");
  // Without the registry the plugin claims the extension.
  CHECK(load_profile(txt, parse_option_text("kind=rail", "test"), nullptr).transforms.at(0) == "read by 'text'");
}
