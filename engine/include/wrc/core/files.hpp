// Files written whole or not at all, folder listings and content hashes: the mechanics under study outputs
// (scripts/study/run.lua), which must never leave a file that looks complete and is not.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace wrc {

// A file written under a temporary name in its own folder (".<name>.tmp.<host>.<pid>.<n>") and renamed over
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
};

// Writes `content` to `path` through an AtomicFile.
void write_file_atomic(const std::string& path, std::string_view content);

// True for a name AtomicFile gives its temporary files (a run killed before commit() leaves them behind).
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

// The processors this process may run on (its CPU affinity mask, as a SLURM or taskset allocation restricts it;
// at least 1).
int available_cores();

}  // namespace wrc
