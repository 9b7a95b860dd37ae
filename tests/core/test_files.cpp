// Atomic files, folder listings, content hashes, and what a run makes, removes and locks inside its output folder
// (wrc/core/files.hpp).
#include "wrc/core/error.hpp"
#include "wrc/core/files.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

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

TEST_CASE("files: an interrupted run removes the temporaries being written, and only those") {
  const fs::path dir = fresh_folder("tracked");
  const std::string target = (dir / "table.csv").string();
  write_file_atomic(target, "old\n");
  AtomicFile open_one(target);  // being written: tracked
  open_one.write("half");
  {
    AtomicFile committed((dir / "done.csv").string());  // committed: untracked, renamed into place
    committed.write("done\n");
    committed.commit();
  }
  const std::string own = temporary_path(target);  // a script's own temporary, tracked by name
  track_temporary(own);
  std::ofstream(own) << "own";
  const std::string forgotten = temporary_path(target);  // tracked, then forgotten: not removed
  track_temporary(forgotten);
  std::ofstream(forgotten) << "kept";
  CHECK(untrack_temporary(forgotten));
  CHECK_FALSE(untrack_temporary(forgotten));
  REQUIRE(list_folder(dir.string()).size() == 5);
  remove_tracked_temporaries();  // what the signal handler does
  const std::string kept = fs::path(forgotten).filename().string();
  CHECK(list_folder(dir.string()) == std::vector<std::string>{kept, "done.csv", "table.csv"});
  CHECK(read(target) == "old\n");
  CHECK(read((dir / "done.csv").string()) == "done\n");
  CHECK(untrack_temporary(own));
  open_one.discard();  // its file is gone already: nothing to remove, and its slot is freed
  fs::remove(forgotten);
  // The table is finite: a path beyond it, or longer than the system takes, is refused before any file exists.
  std::vector<int> slots;
  for (int i = 0; i < kMaxTracked; ++i) slots.push_back(track_temporary((dir / "x").string() + std::to_string(i)));
  CHECK_THROWS_WITH_AS(AtomicFile((dir / "one_more.csv").string()), doctest::Contains("being written at once"), Error);
  for (int slot : slots) untrack_temporary(slot);
  CHECK_THROWS_WITH_AS(track_temporary(std::string(5000, 'a')), doctest::Contains("longer than the system takes"),
                       Error);
  CHECK(list_folder(dir.string()) == std::vector<std::string>{"done.csv", "table.csv"});
}

TEST_CASE("files: temporary names, sorted listings, writable folders") {
  CHECK(is_temporary_name(".sweep.csv.wrc-tmp-0123456789abcdef-12-0"));
  CHECK(is_temporary_name(fs::path(temporary_path("out/sweep.csv")).filename().string()));
  CHECK(fs::path(temporary_path("out/sweep.csv")).parent_path() == "out");
  CHECK(temporary_path("a") != temporary_path("a"));
  CHECK_FALSE(is_temporary_name("sweep.csv"));
  CHECK_FALSE(is_temporary_name(".hidden"));
  // Only the exact pattern: a user's file that looks like a temporary one is not taken for one.
  for (const char* user : {".notes.tmp.txt", ".sweep.csv.tmp.host.12.0", ".x.wrc-tmp-0123456789ABCDEF-1-2",
                           ".x.wrc-tmp-0123456789abcdef-1-2.txt", ".x.wrc-tmp-0123456789abcde-1-2",
                           ".wrc-tmp-0123456789abcdef-1-2", "x.wrc-tmp-0123456789abcdef-1-2",
                           ".x.wrc-tmp-0123456789abcdef--2", ".x.wrc-tmp-0123456789abcdef-1"})
    CHECK_MESSAGE(!is_temporary_name(user), user);
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
}

TEST_CASE("files: a digest of a file's first bytes counts them and their line breaks") {
  const fs::path dir = fresh_folder("digest");
  write_file_atomic((dir / "t").string(), "ab\ncd\nef");
  const FileDigest all = digest_file((dir / "t").string());
  CHECK(all.hash == hash_text("ab\ncd\nef"));
  CHECK(all.bytes == 8);
  CHECK(all.lines == 2);
  const FileDigest head = digest_file((dir / "t").string(), 4);
  CHECK(head.hash == hash_text("ab\nc"));
  CHECK(head.bytes == 4);
  CHECK(head.lines == 1);
  CHECK(digest_file((dir / "t").string(), 100).bytes == 8);
}

TEST_CASE("files: names inside a folder: relative, no '..', no control character") {
  for (const char* ok : {"a", "sweep.csv", "figs/z.png", ".hidden", "a b", "..a", "a..b/c"})
    CHECK_MESSAGE(inside_name_problem(ok).empty(), ok);
  CHECK(inside_name_problem("") == "an empty name");
  CHECK(inside_name_problem("/etc/passwd") == "an absolute path");
  CHECK(inside_name_problem("../victim.txt") == "a '..' component");
  CHECK(inside_name_problem("a/../../b") == "a '..' component");
  CHECK(inside_name_problem("./a") == "a '.' component");
  CHECK(inside_name_problem("a//b").find("empty component") != std::string::npos);
  CHECK(inside_name_problem("a/").find("empty component") != std::string::npos);
  CHECK(inside_name_problem("a\nprevious b").find("control character") != std::string::npos);
  CHECK(inside_name_problem(std::string("a\0b", 3)).find("control character") != std::string::npos);
}

TEST_CASE("files: removing inside a folder follows no symbolic link and removes only what it recorded") {
  const fs::path root = fresh_folder("inside");
  const fs::path out = root / "out", elsewhere = root / "elsewhere";
  fs::create_directories(out / "sub");
  fs::create_directories(elsewhere);
  write_file_atomic((elsewhere / "secret.txt").string(), "secret");
  write_file_atomic((root / "victim.txt").string(), "victim");
  fs::create_directory_symlink("../elsewhere", out / "data");
  fs::create_symlink("../victim.txt", out / "link.txt");
  const std::string o = out.string(), secret = hash_text("secret");
  // Through a link, out of the folder, a link itself, a folder: refused, nothing touched.
  RemoveResult r = remove_file_inside(o, "data/secret.txt", secret);
  CHECK(r.what == Removal::refused);
  CHECK(r.why.find("'" + o + "/data' is a symbolic link") != std::string::npos);
  CHECK(remove_file_inside(o, "../victim.txt").what == Removal::refused);
  CHECK(remove_file_inside(o, (root / "victim.txt").string()).what == Removal::refused);
  r = remove_file_inside(o, "link.txt");
  CHECK(r.what == Removal::refused);
  CHECK(r.why == "a symbolic link");
  CHECK(remove_file_inside(o, "sub").why == "a folder");
  CHECK(read(elsewhere / "secret.txt") == "secret");
  CHECK(read(root / "victim.txt") == "victim");
  CHECK(fs::is_symlink(out / "link.txt"));
  // A plain file: removed when its hash is the recorded one, kept when it changed; a missing one is missing.
  write_file_atomic((out / "sub" / "a.txt").string(), "mine");
  r = remove_file_inside(o, "sub/a.txt", hash_text("old"));
  CHECK(r.what == Removal::refused);
  CHECK(r.why == "changed since the run that wrote it");
  CHECK(fs::exists(out / "sub" / "a.txt"));
  CHECK(remove_file_inside(o, "sub/a.txt", hash_text("mine")).what == Removal::removed);
  CHECK_FALSE(fs::exists(out / "sub" / "a.txt"));
  CHECK(remove_file_inside(o, "sub/a.txt").what == Removal::missing);
  CHECK(remove_file_inside(o, "nothere/a.txt").what == Removal::missing);
}

TEST_CASE("files: folders made and trees removed inside a folder, links never followed") {
  const fs::path root = fresh_folder("trees");
  const fs::path out = root / "out", elsewhere = root / "elsewhere";
  fs::create_directories(out);
  fs::create_directories(elsewhere / "shard-1-of-2");
  write_file_atomic((elsewhere / "shard-1-of-2" / "state.txt").string(), "x");
  const std::string o = out.string();
  make_folders_inside(o, "parts/shard-1-of-1");
  CHECK(fs::is_directory(out / "parts" / "shard-1-of-1"));
  CHECK_NOTHROW(make_folders_inside(o, "parts/shard-1-of-1"));  // exists: fine
  // A tree with a link inside: the link goes, its target stays.
  fs::create_directory_symlink(elsewhere, out / "parts" / "shard-1-of-1" / "inner");
  write_file_atomic((out / "parts" / "shard-1-of-1" / "block.txt").string(), "b");
  remove_tree_inside(o, "parts/shard-1-of-1");
  CHECK_FALSE(fs::exists(out / "parts" / "shard-1-of-1"));
  CHECK(read(elsewhere / "shard-1-of-2" / "state.txt") == "x");
  // A linked folder on the way: refused, for making and for removing.
  fs::remove(out / "parts");
  fs::create_directory_symlink(elsewhere, out / "parts");
  CHECK_THROWS_WITH_AS(make_folders_inside(o, "parts/shard-1-of-2"), doctest::Contains("is a symbolic link"), Error);
  CHECK_THROWS_WITH_AS(remove_tree_inside(o, "parts/shard-1-of-2"), doctest::Contains("is a symbolic link"), Error);
  CHECK(read(elsewhere / "shard-1-of-2" / "state.txt") == "x");
  CHECK_THROWS_WITH_AS(remove_tree_inside(o, "../elsewhere"), doctest::Contains("'..'"), Error);
  remove_tree_inside(o, "parts");  // the link itself is removed, not what it points to
  CHECK_FALSE(fs::exists(fs::symlink_status(out / "parts")));
  CHECK(read(elsewhere / "shard-1-of-2" / "state.txt") == "x");
  CHECK_NOTHROW(remove_tree_inside(o, "missing/x"));
}

TEST_CASE("files: a lock is held by one open file at a time and names its holder") {
  const fs::path dir = fresh_folder("lock");
  const std::string path = (dir / "merge.lock").string();
  std::string holder;
  std::unique_ptr<FileLock> first = FileLock::try_acquire(path, holder);
  REQUIRE(first);
  CHECK(first->locked());
  CHECK(holder.empty());
  // flock belongs to the open file: a second one, in this process too, is refused and told who holds it.
  CHECK_FALSE(FileLock::try_acquire(path, holder));
  CHECK(holder.find("pid " + std::to_string(getpid()) + " on host ") == 0);
  first->release();
  std::unique_ptr<FileLock> second = FileLock::try_acquire(path, holder);
  REQUIRE(second);
  CHECK(second->locked());
  second.reset();  // the destructor releases it
  CHECK(FileLock::try_acquire(path, holder));
  fs::create_symlink(dir / "elsewhere.txt", dir / "link.lock");
  CHECK_THROWS_WITH_AS(FileLock::try_acquire((dir / "link.lock").string(), holder),
                       doctest::Contains("is a symbolic link"), Error);
  CHECK_FALSE(fs::exists(dir / "elsewhere.txt"));
}
