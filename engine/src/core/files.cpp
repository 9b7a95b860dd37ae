// Atomic files, folder listings, content hashes (files.hpp).
#include "wrc/core/files.hpp"

#include "wrc/core/error.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

namespace wrc {
namespace {

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "host";
  std::string h(buf);
  std::replace(h.begin(), h.end(), '/', '_');
  return h.empty() ? "host" : h;
}

// "<folder>/.<name>.tmp.<host>.<pid>.<n>": unique across processes and hosts writing to one shared folder.
std::string temporary_name(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path p(path);
  const std::string name = "." + p.filename().string() + ".tmp." + host_name() + "." + std::to_string(getpid()) +
                           "." + std::to_string(counter.fetch_add(1));
  return (p.parent_path() / name).string();
}

std::string reason() { return std::strerror(errno); }

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty() || std::filesystem::path(path_).filename().empty())
    fail("cannot write '{}': not a file name", path_);
  temp_ = temporary_name(path_);
  file_ = std::fopen(temp_.c_str(), "wb");
  if (file_ == nullptr) fail("cannot write '{}': {}", path_, reason());
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
  const bool ok = std::fflush(file_) == 0 && fsync(fileno(file_)) == 0;
  const std::string why = ok ? std::string() : reason();
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok || !closed) {
    std::remove(temp_.c_str());
    fail("cannot write '{}': {}", path_, ok ? reason() : why);
  }
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const std::string r = reason();
    std::remove(temp_.c_str());
    fail("cannot write '{}': {}", path_, r);
  }
}

void AtomicFile::discard() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  file_ = nullptr;
  std::remove(temp_.c_str());
}

void write_file_atomic(const std::string& path, std::string_view content) {
  AtomicFile f(path);
  f.write(content);
  f.commit();
}

bool is_temporary_name(std::string_view name) {
  return name.size() > 1 && name.front() == '.' && name.find(".tmp.") != std::string_view::npos;
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
  const std::string probe = temporary_name((std::filesystem::path(folder) / "wrc-writable").string());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) fail("output folder '{}' is not writable: {}", folder, reason());
  const bool ok = ::write(fd, "x", 1) == 1;
  const std::string why = ok ? std::string() : reason();
  ::close(fd);
  ::unlink(probe.c_str());
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

std::string hash_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read '{}': {}", path, reason());
  ContentHash h;
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    h.add(std::string_view(buf, static_cast<std::size_t>(in.gcount())));
  }
  if (in.bad()) fail("cannot read '{}': {}", path, reason());
  return h.hex();
}

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace wrc
