// Atomic files, folder listings, content hashes (files.hpp).
#include "wrc/core/files.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <atomic>
#include <random>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace wrc {
namespace {

// 64 random bits per call: a generator seeded once per process from the system's entropy, stepped by a counter
// (splitmix64), so that two processes -- on one host or on two sharing a folder -- do not draw the same names.
std::uint64_t random_bits() {
  static const std::uint64_t seed = [] {
    std::random_device rd;
    return (std::uint64_t(rd()) << 32) ^ rd() ^ (std::uint64_t(getpid()) << 20);
  }();
  static std::atomic<std::uint64_t> step{0};
  std::uint64_t z = seed + (step.fetch_add(1) + 1) * 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

constexpr std::string_view kTemporaryMark = ".wrc-tmp-";

bool all_of(std::string_view s, bool (*pred)(char)) {
  return !s.empty() && std::all_of(s.begin(), s.end(), pred);
}
bool lower_hex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); }
bool digit(char c) { return c >= '0' && c <= '9'; }

std::string reason() { return std::strerror(errno); }

// The tracked temporaries. A slot goes free -> claimed (by one thread's compare-exchange) -> ready once its path is
// copied, and back to free; a search by name holds a ready slot as compared while it reads the path.
// remove_tracked_temporaries reads ready and compared slots, whose paths are whole: a signal arriving in the middle
// of a copy never sees half a path, nor one in the middle of a search misses a file. 256 slots of PATH_MAX bytes:
// 1 MiB of zero pages, touched only as far as used.
enum : int { kFree = 0, kClaimed = 1, kReady = 2, kCompared = 3 };
struct TrackedSlot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the slots' states");
TrackedSlot g_tracked[kMaxTracked];

}  // namespace

int track_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) fail("cannot write '{}': the path is longer than the system takes", path);
  for (int i = 0; i < kMaxTracked; ++i) {
    int expected = kFree;
    if (!g_tracked[i].state.compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(g_tracked[i].path, path.c_str(), path.size() + 1);
    g_tracked[i].state.store(kReady);
    return i;
  }
  fail("cannot write '{}': {} files are being written at once, the most wrc tracks (to remove them when a run is "
       "interrupted)", path, kMaxTracked);
}

void untrack_temporary(int slot) {
  if (slot < 0 || slot >= kMaxTracked) return;
  // Ready -> free; while another thread's search by name holds the slot, wait for it to hand the slot back.
  for (int expected = kReady; !g_tracked[slot].state.compare_exchange_weak(expected, kFree); expected = kReady)
    if (expected != kReady && expected != kCompared) return;  // freed by a search for its name
}

bool untrack_temporary(const std::string& path) {
  for (TrackedSlot& s : g_tracked) {
    int expected = kReady;
    if (!s.state.compare_exchange_strong(expected, kCompared)) continue;
    const bool same = path == s.path;
    s.state.store(same ? kFree : kReady);
    if (same) return true;
  }
  return false;
}

void remove_tracked_temporaries() noexcept {
  for (TrackedSlot& s : g_tracked)
    if (const int state = s.state.load(); state == kReady || state == kCompared) ::unlink(s.path);
}

std::string temporary_path(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path p(path);
  const std::string name = fmt::format(".{}{}{:016x}-{}-{}", p.filename().string(), kTemporaryMark, random_bits(),
                                       getpid(), counter.fetch_add(1));
  return (p.parent_path() / name).string();
}

void check_path_text(std::string_view path, std::string_view context) {
  const std::size_t nul = path.find('\0');
  if (nul == std::string_view::npos) return;
  std::string shown(path);
  for (std::size_t i = 0; (i = shown.find('\0', i)) != std::string::npos; i += 2) shown.replace(i, 1, "\\0");
  fail("{}: the path '{}' holds a NUL character (after '{}'): the system reads a path up to its first NUL, so it "
       "would name another file than the one given", context, shown, path.substr(0, nul));
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  check_path_text(path_, "cannot write");
  if (path_.empty() || std::filesystem::path(path_).filename().empty())
    fail("cannot write '{}': not a file name", path_);
  temp_ = temporary_path(path_);
  tracked_ = track_temporary(temp_);  // before the file exists: an interrupted run never leaves it untracked
  file_ = std::fopen(temp_.c_str(), "wb");
  if (file_ == nullptr) {
    const std::string why = reason();
    untrack_temporary(std::exchange(tracked_, -1));
    fail("cannot write '{}': {}", path_, why);
  }
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::write(std::string_view text) {
  if (file_ == nullptr) fail("cannot write '{}': the file is already committed or discarded", path_);
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
    const std::string why = reason();
    discard();
    fail("cannot write '{}': {}", path_, why);
  }
}

void AtomicFile::commit() {
  if (file_ == nullptr) fail("cannot write '{}': the file is already committed or discarded", path_);
  std::string why;  // the first failure's reason; empty: renamed
  if (std::fflush(file_) != 0 || fsync(fileno(file_)) != 0) why = reason();
  if (std::fclose(std::exchange(file_, nullptr)) != 0 && why.empty()) why = reason();
  if (why.empty() && std::rename(temp_.c_str(), path_.c_str()) != 0) why = reason();
  if (!why.empty()) std::remove(temp_.c_str());
  untrack_temporary(std::exchange(tracked_, -1));  // the temporary name is gone: renamed or removed
  if (!why.empty()) fail("cannot write '{}': {}", path_, why);
}

void AtomicFile::discard() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  file_ = nullptr;
  std::remove(temp_.c_str());
  untrack_temporary(std::exchange(tracked_, -1));
}

void write_file_atomic(const std::string& path, std::string_view content) {
  AtomicFile f(path);
  f.write(content);
  f.commit();
}

// ".<name>.wrc-tmp-<16 lower hex>-<digits>-<digits>", <name> not empty.
bool is_temporary_name(std::string_view name) {
  const auto mark = name.rfind(kTemporaryMark);
  if (name.size() < 2 || name.front() != '.' || mark == std::string_view::npos || mark < 2) return false;
  const std::string_view tail = name.substr(mark + kTemporaryMark.size());
  const auto dash1 = tail.find('-'), dash2 = tail.rfind('-');
  if (dash1 != 16 || dash2 == dash1) return false;
  return all_of(tail.substr(0, 16), lower_hex) && all_of(tail.substr(dash1 + 1, dash2 - dash1 - 1), digit) &&
         all_of(tail.substr(dash2 + 1), digit);
}

std::vector<std::string> list_folder(const std::string& folder) {
  std::error_code ec;
  std::vector<std::string> names;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  if (ec) fail("cannot list folder '{}': {}", folder, ec.message());
  std::sort(names.begin(), names.end());
  return names;
}

void check_writable(const std::string& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) fail("output folder '{}' does not exist or is not a folder", folder);
  const std::string probe = temporary_path((std::filesystem::path(folder) / "wrc-writable").string());
  const int slot = track_temporary(probe);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    const std::string why = reason();
    untrack_temporary(slot);
    fail("output folder '{}' is not writable: {}", folder, why);
  }
  const bool ok = ::write(fd, "x", 1) == 1;
  const std::string why = ok ? std::string() : reason();
  ::close(fd);
  ::unlink(probe.c_str());
  untrack_temporary(slot);
  if (!ok) fail("output folder '{}' is not writable: {}", folder, why);
}

void ContentHash::add(std::string_view bytes) {
  for (unsigned char c : bytes) {
    h_ ^= c;
    h_ *= 0x100000001b3ull;
  }
}

std::string ContentHash::hex() const { return fmt::format("{:016x}", h_); }

std::string hash_text(std::string_view bytes) {
  ContentHash h;
  h.add(bytes);
  return h.hex();
}

std::string hash_file(const std::string& path) { return digest_file(path).hash; }

FileDigest digest_file(const std::string& path, std::uint64_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read '{}': {}", path, reason());
  ContentHash h;
  FileDigest d;
  char buf[1 << 16];
  while (in && d.bytes < limit) {
    in.read(buf, static_cast<std::streamsize>(std::min<std::uint64_t>(sizeof buf, limit - d.bytes)));
    const std::string_view got(buf, static_cast<std::size_t>(in.gcount()));
    h.add(got);
    d.bytes += got.size();
    d.lines += static_cast<std::uint64_t>(std::count(got.begin(), got.end(), '\n'));
  }
  if (in.bad()) fail("cannot read '{}': {}", path, reason());
  d.hash = h.hex();
  return d;
}

}  // namespace wrc
