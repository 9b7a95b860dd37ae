// Plugin loading: the test plugins of tests/profile/plugins/test_plugin.c (one folder per variant) are
// accepted or rejected with a message naming the library and the reason.
#include "wrc/core/error.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/profile/reader.hpp"
#include "wrc/reader.h"
#include "approx.hpp"
#include "scratch.hpp"

#include <doctest/doctest.h>

#include <dlfcn.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using wrc::test::within_rel;
using namespace wrc;

namespace {

std::string variant(const std::string& v) { return std::string(WRC_TEST_PLUGIN_ROOT) + "/" + v + "/test_" + v + ".so"; }

using test::tmp_path;

}  // namespace

TEST_CASE("a plain C plugin is accepted and reads through the sink") {
  ReaderRegistry r;
  const auto why = r.load_plugin(variant("good"));
  REQUIRE_MESSAGE(!why, *why);
  const Reader* c = r.find("ctest");
  REQUIRE(c != nullptr);
  CHECK(c->extensions == std::vector<std::string>{".ctest"});
  CHECK(r.find_by_extension(".ctest") == c);
  const std::string path = tmp_path("ok.ctest");
  std::ofstream(path) << "-10 -1\n0 0\n10 -1\n";
  LoadOptions o;
  o.kind = ProfileKind::wheel;
  const Profile p = load_profile_file(path, o, {&r});
  CHECK(p.kind == ProfileKind::wheel);  // the C plugin passes the kind hint back
  REQUIRE(p.size() == 3);
  CHECK(p.y.back() == within_rel(0.010, 1e-5));
  CHECK(p.transforms.at(1) == "ctest: read as given");
  std::ofstream(path) << "-10 -1\n0 zero\n";
  try {
    load_profile_file(path, o, {&r});
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) == path + ":2: expected two numbers `y z`");
  }
}

TEST_CASE("rejected libraries: no entry point, wrong ABI major, NULL descriptor, small struct, not a library") {
  ReaderRegistry r;
  auto reason = [&](const std::string& lib) {
    const auto why = r.load_plugin(lib);
    REQUIRE(why.has_value());
    INFO(*why);
    CHECK(why->rfind(lib + ": ", 0) == 0);
    return *why;
  };
  CHECK(reason(variant("no_entry")).find("does not export the entry point 'wrc_reader_entry'") != std::string::npos);
  CHECK(reason(variant("bad_major")).find("reader ABI version 99.1, but this host implements 1.1") != std::string::npos);
  CHECK(reason(variant("null")).find("returned no descriptor") != std::string::npos);
  CHECK(reason(variant("small_struct")).find("descriptor struct_size 8 is smaller") != std::string::npos);
  const std::string junk = tmp_path("junk.so");
  std::ofstream(junk) << "not an ELF file\n";
  CHECK(reason(junk).find("cannot load the library") != std::string::npos);
  CHECK(r.readers().empty());
}

// ABI 1.1 appended `reversed` to the sink; a host of ABI 1.0 passes the smaller sink, whose struct_size ends before it.
// The project's plugins call it only when the size covers it. A Simpack file turned by rotate = 180 reverses y and z.
TEST_CASE("a sink of ABI 1.0, without `reversed`, is read as before, and one of ABI 1.1 hears of the reversals") {
  void* lib = dlopen((paths().plugin_dirs.at(0) + "/wrc_reader_simpack.so").c_str(), RTLD_NOW | RTLD_LOCAL);
  REQUIRE(lib != nullptr);
  const auto entry = reinterpret_cast<wrc_reader_entry_fn>(dlsym(lib, WRC_READER_ENTRY_NAME));
  const bool exported = entry != nullptr;
  REQUIRE(exported);
  const wrc_reader_descriptor* d = entry();
  const std::string path = tmp_path("turned.prr");
  std::ofstream(path) << "header.begin\nversion = 1\ntype = 0\nheader.end\nspline.begin\nrotate = 180\n"
                         "units.ang.f = 57.29577951308232\npoint.begin\n-10 1\n0 0\n10 1\npoint.end\nspline.end\n";
  struct Seen {
    std::vector<double> y, z;
    int reversed = 0, errors = 0;
  };
  wrc_reader_sink sink{};
  sink.point = [](void* h, double y, double z, int32_t) {
    static_cast<Seen*>(h)->y.push_back(y);
    static_cast<Seen*>(h)->z.push_back(z);
    return 0;
  };
  sink.kind = [](void*, int32_t) {};
  sink.units = [](void*, double, const char*) {};
  sink.transform = [](void*, const char*) {};
  sink.metadata = [](void*, const char*, const char*) {};
  sink.error = [](void* h, int32_t, const char*) { ++static_cast<Seen*>(h)->errors; };
  sink.reversed = [](void* h, int32_t, const char*) { ++static_cast<Seen*>(h)->reversed; };
  wrc_reader_request req{};
  req.struct_size = sizeof(req);
  req.path = path.c_str();
  for (const std::size_t size : {offsetof(wrc_reader_sink, reversed), sizeof(wrc_reader_sink)}) {
    Seen seen;
    sink.struct_size = static_cast<uint32_t>(size);
    sink.host = &seen;
    CHECK(d->read(&req, &sink) == 0);
    CHECK(seen.errors == 0);
    CHECK(seen.reversed == (size == sizeof(wrc_reader_sink) ? 2 : 0));  // y and z, from ABI 1.1 on
    // The file's (y, z down) = (-10, 1) turned by 180 degrees: (10, -1); z up: (10, 1).
    REQUIRE(seen.y.size() == 3);
    CHECK(seen.y.front() == within_rel(10.0, 1e-12));
    CHECK(seen.z.front() == within_rel(1.0, 1e-12));
  }
}

// A copy of a real plugin cut short. dlopen maps a segment that reaches past the end of the file and the loader
// touches it: SIGBUS, which killed the whole process before the host checked the ELF headers.
std::string truncated_copy(const std::string& lib, std::size_t bytes, const std::string& name) {
  std::ifstream in(lib, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(data.size() > bytes);
  const std::string out = tmp_path(name);
  std::ofstream(out, std::ios::binary).write(data.data(), static_cast<std::streamsize>(bytes));
  return out;
}

TEST_CASE("truncated and broken libraries are rejected with a reason, not a crash") {
  ReaderRegistry r;
  const std::string real = paths().plugin_dirs.at(0) + "/wrc_reader_text.so";
  std::ifstream probe(real, std::ios::binary | std::ios::ate);
  const auto size = static_cast<std::size_t>(probe.tellg());
  REQUIRE(size > 20000);
  auto reason = [&](const std::string& lib) {
    const auto why = r.load_plugin(lib);
    REQUIRE(why.has_value());
    INFO(*why);
    CHECK(why->rfind(lib + ": cannot load the library: ", 0) == 0);
    return *why;
  };
  // The case: the first 20,000 bytes.
  CHECK(reason(truncated_copy(real, 20000, "cut20000.so")).find("the file is truncated") != std::string::npos);
  for (std::size_t n : {std::size_t{4}, std::size_t{40}, std::size_t{64}, std::size_t{1000}, size / 2, size - 1})
    CHECK(reason(truncated_copy(real, n, fmt::format("cut{}.so", n))).find("truncated") != std::string::npos);
  // The ELF magic only, and a program header table moved past the end.
  const std::string magic = tmp_path("magic.so");
  std::ofstream(magic, std::ios::binary) << "\x7f" "ELF";
  CHECK(reason(magic).find("truncated") != std::string::npos);
  std::ifstream in(real, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  data[0x20] = '\xff';  // e_phoff (64-bit ELF): a byte of the offset far out
  data[0x25] = '\x7f';
  const std::string moved = tmp_path("moved_phdr.so");
  std::ofstream(moved, std::ios::binary).write(data.data(), static_cast<std::streamsize>(data.size()));
  CHECK(reason(moved).find("program header table") != std::string::npos);
  CHECK(r.readers().empty());
  // The real library itself passes the checks and loads.
  CHECK_FALSE(r.load_plugin(real).has_value());
}

TEST_CASE("a duplicate id is rejected, naming both libraries, and the first keeps the id") {
  ReaderRegistry r;
  r.load_plugin_dir(paths().plugin_dirs.at(0));
  REQUIRE(r.find("text") != nullptr);
  const std::string first = r.find("text")->origin;
  const auto why = r.load_plugin(variant("duplicate_id"));
  REQUIRE(why.has_value());
  INFO(*why);
  CHECK(why->find("duplicate reader id 'text'") != std::string::npos);
  CHECK(why->find(first) != std::string::npos);
  CHECK(why->find(variant("duplicate_id")) != std::string::npos);
  CHECK(r.find("text")->origin == first);
}

TEST_CASE("a plugin folder: every .so loaded in name order, rejections collected") {
  ReaderRegistry r;
  r.load_plugin_dir(std::string(WRC_TEST_PLUGIN_ROOT) + "/bad_major");
  r.load_plugin_dir(std::string(WRC_TEST_PLUGIN_ROOT) + "/good");
  r.load_plugin_dir(std::string(WRC_TEST_PLUGIN_ROOT) + "/no_such_folder");
  CHECK(r.readers().size() == 1);
  REQUIRE(r.rejected().size() == 2);
  CHECK(r.rejected()[0].find("ABI version 99") != std::string::npos);
  CHECK(r.rejected()[1].find("plugin folder does not exist") != std::string::npos);
}

TEST_CASE("readers added in C++ are checked like plugins") {
  ReaderRegistry r;
  Reader bad;
  bad.id = "Bad Id";
  bad.extensions = {".x"};
  bad.read = [](const std::string&, std::optional<ProfileKind>, const ReaderOptions&) { return RawProfile{}; };
  CHECK_THROWS_WITH_AS(r.add(bad), doctest::Contains("reader id 'Bad Id'"), Error);
  bad.id = "ok";
  bad.extensions = {"x"};
  CHECK_THROWS_WITH_AS(r.add(bad), doctest::Contains("extension 'x' must be a dot"), Error);
  bad.extensions = {".X"};
  r.add(bad);
  CHECK(r.find_by_extension(".x") != nullptr);  // extensions are lower-cased
}
