// Files written whole or not at all, folder listings and content hashes: the mechanics under study outputs
// (scripts/study/), which must never leave a file that looks complete and is not.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace wrc {

// A file written under a temporary name in its own folder (temporary_path) and renamed over
// `path` by commit(), after its data reached the disk (fsync): a reader, or a run killed at any moment, sees the
// old file or the new one, never a part. Destroyed without commit(), it removes the temporary file.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);  // throws wrc::Error naming the path and the system's reason
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view text);
  void commit();   // flush, fsync, rename; throws on any failure (the temporary file is removed)
  void discard();  // removes the temporary file; the target is untouched
  bool open() const { return file_ != nullptr; }
  const std::string& path() const { return path_; }

 private:
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  int tracked_ = -1;  // its slot among the tracked temporaries
};

// Throws wrc::Error "<context>: the path '...' holds a NUL character ..." when `path` does: the system reads a path up
// to its first NUL, so "w.txt\0.csv" would read or write w.txt, a file the caller did not name (Lua and Python strings
// may hold NUL; a C string cannot).
void check_path_text(std::string_view path, std::string_view context);

// Writes `content` to `path` through an AtomicFile.
void write_file_atomic(const std::string& path, std::string_view content);

// A fresh temporary name next to `path`: "<folder>/.<name>.wrc-tmp-<16 hex digits>-<pid>-<n>", the hex digits
// random: unique across the processes and hosts writing into one shared folder, and a pattern that a user's file
// does not match by chance (".notes.tmp.txt" does not).
std::string temporary_path(const std::string& path);

// ---- The temporary files of this process that exist or are about to: a fixed table a signal handler may read, so
// that a run stopped by SIGINT or SIGTERM removes them before it ends (the wrc executable, host/interrupt.hpp).
// AtomicFile tracks its own; a script that writes a temporary itself tracks it through wrc.fs.temporary_name.

// Enters `path` (as given: relative to the working directory, which the host never changes) and returns its slot.
// Throws wrc::Error when kMaxTracked paths are tracked already, or the path is longer than the system takes.
inline constexpr int kMaxTracked = 256;
int track_temporary(const std::string& path);
void untrack_temporary(int slot);                // a slot track_temporary gave; -1 does nothing
bool untrack_temporary(const std::string& path);  // false when that path is not tracked
// unlink()s every tracked path; only async-signal-safe calls (atomic loads of lock-free atomics, unlink).
void remove_tracked_temporaries() noexcept;

// True for a name that temporary_path gives, exactly (a run killed before commit() leaves such files behind).
bool is_temporary_name(std::string_view name);

// The names in a folder (no "." or ".."), sorted bytewise. Throws when it is not a readable folder.
std::vector<std::string> list_folder(const std::string& folder);

// Creates a probe file in `folder` and removes it: throws wrc::Error "output folder '...' is not writable: <reason>"
// before a study computes anything it could not save.
void check_writable(const std::string& folder);

// FNV-1a, 64 bits, as 16 hex digits: a fingerprint of a study's inputs and outputs (change detection, not security).
class ContentHash {
 public:
  void add(std::string_view bytes);
  std::string hex() const;

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};
std::string hash_text(std::string_view bytes);
std::string hash_file(const std::string& path);  // throws when the file cannot be read

// The hash of a file's first `limit` bytes (all when shorter), the bytes read and the line breaks among them.
struct FileDigest {
  std::string hash;
  std::uint64_t bytes = 0, lines = 0;
};
FileDigest digest_file(const std::string& path, std::uint64_t limit = UINT64_MAX);  // throws when unreadable

// ---- Inside an output folder (files_inside.cpp). A study's output folder may come from someone else, so what a run
// creates, locks and removes in it is reached without following any symbolic link below the folder the user named
// (folders opened one by one with O_NOFOLLOW, files removed with unlinkat in the last one): a link planted there,
// even while the run goes on, leads nowhere outside it.

// Why `name` cannot name an entry inside a folder, or "" when it can: a relative path of '/'-separated components,
// none empty, "." or "..", with no control character (manifests list one name per line).
std::string inside_name_problem(std::string_view name);

// mkdir -p of `name` under `root`, as real folders: throws naming the component that is a symbolic link or not a
// folder. `root` itself may be a link (the user named it).
void make_folders_inside(const std::string& root, std::string_view name);

// What remove_file_inside did; `why` says why a file was refused (left in place).
enum class Removal { removed, missing, refused };
struct RemoveResult {
  Removal what;
  std::string why;
};

// Removes `name` under `root` if it is a regular file reached through real folders; with `hash` (FNV-1a, as
// hash_file gives it) only if its content still has that hash. Refuses (does not throw) an unsafe name, a link, a
// folder, a changed file, or a removal the system denies.
RemoveResult remove_file_inside(const std::string& root, std::string_view name, std::string_view hash = {});

// Removes the folder `name` under `root` with everything in it: a symbolic link inside is removed, never followed;
// nothing when missing. Throws when the name is unsafe, a folder on the way is a link, or a removal fails.
void remove_tree_inside(const std::string& root, std::string_view name);

// An exclusive lock (flock) on a file, held until release(), destruction or the end of the process, however it ends
// (kill -9 too: the lock belongs to the open file). It serialises the runs that write one part of an output folder.
class FileLock {
 public:
  // Takes the lock on `path` (created if missing; a symbolic link is refused) without waiting, and writes the holder's
  // note into the file ("pid 12 on host h since 2024-05-01 10:00:00"). When another process holds it, returns null
  // and sets `holder` to that process's note. On a file system without locks it returns a FileLock whose locked() is
  // false, `holder` saying why. Throws when the file cannot be opened.
  static std::unique_ptr<FileLock> try_acquire(const std::string& path, std::string& holder);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool locked() const { return locked_; }
  void release();

 private:
  FileLock(int fd, bool locked) : fd_(fd), locked_(locked) {}
  int fd_ = -1;
  bool locked_ = false;
};

}  // namespace wrc
