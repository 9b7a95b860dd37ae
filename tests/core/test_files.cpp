// Atomic files, folder listings and content hashes (wrc/core/files.hpp).
#include "wrc/core/error.hpp"
#include "wrc/core/files.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace wrc;

namespace {

// A fresh folder under WRC_TEST_TMP (or the system's temporary folder).
fs::path fresh_folder(const std::string& name) {
  const char* tmp = std::getenv("WRC_TEST_TMP");
  const fs::path dir = fs::path(tmp ? tmp : fs::temp_directory_path().string()) / ("core_files_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("files: an atomic file appears whole at commit, and a discarded one leaves the old file") {
  const fs::path dir = fresh_folder("atomic");
  const std::string target = (dir / "table.csv").string();
  write_file_atomic(target, "old\n");
  {
    AtomicFile f(target);
    f.write("new ");
    f.write("content\n");
    CHECK(read(target) == "old\n");  // not visible before commit
    const auto names = list_folder(dir.string());
    REQUIRE(names.size() == 2);      // the target and one temporary file
    CHECK(is_temporary_name(names[0]));
    CHECK(names[1] == "table.csv");
    f.commit();
  }
  CHECK(read(target) == "new content\n");
  CHECK(list_folder(dir.string()) == std::vector<std::string>{"table.csv"});
  {
    AtomicFile f(target);
    f.write("never committed");
  }  // destroyed: discarded
  CHECK(read(target) == "new content\n");
  CHECK(list_folder(dir.string()) == std::vector<std::string>{"table.csv"});
  AtomicFile g(target);
  g.commit();
  CHECK_THROWS_WITH_AS(g.write("x"), doctest::Contains("already committed"), Error);
  CHECK(read(target).empty());
  CHECK_THROWS_WITH_AS(AtomicFile((dir / "no_such_folder" / "x.csv").string()), doctest::Contains("no_such_folder"), Error);
}

TEST_CASE("files: temporary names, sorted listings, writable folders") {
  CHECK(is_temporary_name(".sweep.csv.tmp.host.12.0"));
  CHECK_FALSE(is_temporary_name("sweep.csv"));
  CHECK_FALSE(is_temporary_name(".hidden"));
  const fs::path dir = fresh_folder("list");
  for (const char* n : {"b", "a", "C", "a2"}) write_file_atomic((dir / n).string(), n);
  CHECK(list_folder(dir.string()) == std::vector<std::string>{"C", "a", "a2", "b"});  // bytewise
  CHECK_THROWS_WITH_AS(list_folder((dir / "missing").string()), doctest::Contains("cannot list folder"), Error);
  CHECK_NOTHROW(check_writable(dir.string()));
  CHECK(list_folder(dir.string()).size() == 4);  // the probe is gone
  // /proc refuses new files even to root (CI runs as root, for whom permissions do not stop a write).
  CHECK_THROWS_WITH_AS(check_writable("/proc"), doctest::Contains("output folder '/proc' is not writable"), Error);
  CHECK_THROWS_WITH_AS(check_writable((dir / "a").string()), doctest::Contains("is not a folder"), Error);
}

TEST_CASE("files: FNV-1a 64 against its published test vectors, of text and of files") {
  // Fowler, Noll, Vo: the offset basis for "", and the vectors of "a" and "foobar".
  CHECK(hash_text("") == "cbf29ce484222325");
  CHECK(hash_text("a") == "af63dc4c8601ec8c");
  CHECK(hash_text("foobar") == "85944171f73967e8");
  const fs::path dir = fresh_folder("hash");
  std::string big(200000, 'x');
  big[123456] = 'y';
  write_file_atomic((dir / "big").string(), big);
  CHECK(hash_file((dir / "big").string()) == hash_text(big));  // read in blocks: the same as at once
  ContentHash h;
  h.add("foo");
  h.add("bar");
  CHECK(h.hex() == hash_text("foobar"));
  CHECK_THROWS_AS(hash_file((dir / "missing").string()), Error);
  CHECK(available_cores() >= 1);
}
