// Inside an output folder: folders made, files and trees removed, locks taken without following a symbolic link
// below the folder the user named (files.hpp). Every step below `root` goes through an open folder descriptor
// (openat with O_NOFOLLOW, unlinkat), so a link swapped in at any moment makes the call fail, never act elsewhere.
#include "wrc/core/error.hpp"
#include "wrc/core/files.hpp"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace wrc {
namespace {

// An open descriptor, closed when it goes out of scope.
class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(Fd&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  Fd& operator=(Fd&& o) noexcept {
    std::swap(fd_, o.fd_);
    return *this;
  }
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

constexpr int kFolderFlags = O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC;
constexpr int kMaxDepth = 64;  // folders below a removed tree; deeper is not a study's

std::string why_errno() { return std::strerror(errno); }

std::vector<std::string> components(std::string_view name) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto slash = name.find('/', start);
    parts.emplace_back(name.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
    if (slash == std::string_view::npos) return parts;
    start = slash + 1;
  }
}

std::string joined(const std::string& root, const std::vector<std::string>& parts, std::size_t count) {
  std::string s = root;
  for (std::size_t i = 0; i < count; ++i) s += "/" + parts[i];
  return s;
}

// Why the entry `name` of the folder `dir` could not be opened as a folder (after openat failed with errno).
std::string not_a_folder(int dir, const std::string& name, const std::string& shown) {
  const int err = errno;
  struct stat st {};
  if (fstatat(dir, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode))
    return fmt::format("'{}' is a symbolic link (wrc follows no link inside an output folder)", shown);
  if (err == ENOTDIR) return fmt::format("'{}' is not a folder", shown);
  return fmt::format("'{}': {}", shown, std::strerror(err));
}

// The folder root/parts[0]/.../parts[count-1], each below root opened without following a link; with `create`,
// missing ones are made. Returns an invalid Fd when one is missing (and not created), with `why` set on any failure.
Fd open_inside(const std::string& root, const std::vector<std::string>& parts, std::size_t count, bool create,
               std::string& why) {
  Fd dir(::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.get() < 0) {
    why = fmt::format("'{}': {}", root, why_errno());
    return Fd();
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (create && mkdirat(dir.get(), parts[i].c_str(), 0777) != 0 && errno != EEXIST) {
      why = fmt::format("cannot create '{}': {}", joined(root, parts, i + 1), why_errno());
      return Fd();
    }
    Fd next(openat(dir.get(), parts[i].c_str(), kFolderFlags));
    if (next.get() < 0) {
      if (errno == ENOENT && !create) return Fd();
      why = not_a_folder(dir.get(), parts[i], joined(root, parts, i + 1));
      return Fd();
    }
    dir = std::move(next);
  }
  return dir;
}

// Removes the entry `name` of the folder `dir`: a folder with its content, anything else (a link too) unlinked.
void remove_entry(int dir, const std::string& name, const std::string& shown, int depth) {
  struct stat st {};
  if (fstatat(dir, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
    if (errno == ENOENT) return;
    fail("cannot remove '{}': {}", shown, why_errno());
  }
  if (S_ISDIR(st.st_mode)) {
    if (depth > kMaxDepth) fail("cannot remove '{}': folders nested deeper than {}", shown, kMaxDepth);
    Fd sub(openat(dir, name.c_str(), kFolderFlags));
    if (sub.get() < 0) fail("cannot remove {}", not_a_folder(dir, name, shown));
    std::vector<std::string> entries;
    DIR* d = fdopendir(sub.get());
    if (d == nullptr) fail("cannot list '{}': {}", shown, why_errno());
    const int fd = sub.release();  // owned by d now
    while (const dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") entries.push_back(n);
    }
    try {
      for (const std::string& n : entries) remove_entry(fd, n, shown + "/" + n, depth + 1);
    } catch (...) {
      closedir(d);
      throw;
    }
    closedir(d);
  }
  if (unlinkat(dir, name.c_str(), S_ISDIR(st.st_mode) ? AT_REMOVEDIR : 0) != 0 && errno != ENOENT)
    fail("cannot remove '{}': {}", shown, why_errno());
}

// Whether the open regular file `fd` has the FNV-1a hash `hash`.
bool has_hash(int fd, std::string_view hash) {
  ContentHash h;
  char buf[1 << 16];
  ssize_t n = 0;
  while ((n = ::read(fd, buf, sizeof buf)) > 0) h.add(std::string_view(buf, static_cast<std::size_t>(n)));
  return n == 0 && h.hex() == hash;
}

std::string lock_note() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "?");
  const std::time_t now = std::time(nullptr);
  char when[32] = {};
  std::tm tm{};
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", localtime_r(&now, &tm));
  return fmt::format("pid {} on host {} since {}", getpid(), host, when);
}

}  // namespace

std::string inside_name_problem(std::string_view name) {
  if (name.empty()) return "an empty name";
  for (const unsigned char c : name)
    if (c < 0x20 || c == 0x7f) return "a control character (a line break?) in the name";
  if (name.front() == '/') return "an absolute path";
  for (const std::string& part : components(name)) {
    if (part.empty()) return "an empty component ('//' or a trailing '/')";
    if (part == "." || part == "..") return "a '" + part + "' component";
  }
  return "";
}

void make_folders_inside(const std::string& root, std::string_view name) {
  if (const std::string why = inside_name_problem(name); !why.empty())
    fail("cannot create '{}/{}': {}", root, name, why);
  const std::vector<std::string> parts = components(name);
  std::string why;
  if (open_inside(root, parts, parts.size(), true, why).get() < 0) fail("{}", why);
}

RemoveResult remove_file_inside(const std::string& root, std::string_view name, std::string_view hash) {
  if (std::string why = inside_name_problem(name); !why.empty()) return {Removal::refused, why};
  const std::vector<std::string> parts = components(name);
  std::string why;
  const Fd dir = open_inside(root, parts, parts.size() - 1, false, why);
  if (dir.get() < 0) return {why.empty() ? Removal::missing : Removal::refused, why};
  const std::string& leaf = parts.back();
  struct stat st {};
  if (fstatat(dir.get(), leaf.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
    return errno == ENOENT ? RemoveResult{Removal::missing, ""} : RemoveResult{Removal::refused, why_errno()};
  if (!S_ISREG(st.st_mode))
    return {Removal::refused,
            S_ISLNK(st.st_mode) ? "a symbolic link" : S_ISDIR(st.st_mode) ? "a folder" : "not a plain file"};
  if (!hash.empty()) {
    const Fd file(openat(dir.get(), leaf.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
    if (file.get() < 0) return {Removal::refused, why_errno()};
    if (!has_hash(file.get(), hash)) return {Removal::refused, "changed since the run that wrote it"};
  }
  if (unlinkat(dir.get(), leaf.c_str(), 0) != 0)
    return errno == ENOENT ? RemoveResult{Removal::missing, ""} : RemoveResult{Removal::refused, why_errno()};
  return {Removal::removed, ""};
}

void remove_tree_inside(const std::string& root, std::string_view name) {
  if (const std::string why = inside_name_problem(name); !why.empty())
    fail("cannot remove '{}/{}': {}", root, name, why);
  const std::vector<std::string> parts = components(name);
  std::string why;
  const Fd dir = open_inside(root, parts, parts.size() - 1, false, why);
  if (dir.get() < 0) {
    if (why.empty()) return;  // a folder on the way is missing: so is the tree
    fail("cannot remove '{}/{}': {}", root, name, why);
  }
  remove_entry(dir.get(), parts.back(), root + "/" + std::string(name), 0);
}

std::unique_ptr<FileLock> FileLock::try_acquire(const std::string& path, std::string& holder) {
  Fd fd(::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644));
  if (fd.get() < 0)
    fail("cannot open the lock file '{}': {}", path, errno == ELOOP ? "it is a symbolic link" : why_errno());
  if (flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK) {
      holder = fmt::format("the file system does not lock '{}': {}", path, why_errno());
      return std::unique_ptr<FileLock>(new FileLock(fd.release(), false));
    }
    char note[256] = {};
    const ssize_t n = pread(fd.get(), note, sizeof note - 1, 0);
    holder = n > 0 ? std::string(note, static_cast<std::size_t>(n)) : "a process that has not written its note yet";
    while (!holder.empty() && holder.back() == '\n') holder.pop_back();
    for (char& c : holder)  // the note is the file's text: shown on one line, whatever it holds
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    return nullptr;
  }
  const std::string note = lock_note() + "\n";
  if (ftruncate(fd.get(), 0) != 0 || pwrite(fd.get(), note.data(), note.size(), 0) != static_cast<ssize_t>(note.size()))
    fail("cannot write the lock file '{}': {}", path, why_errno());
  return std::unique_ptr<FileLock>(new FileLock(fd.release(), true));
}

FileLock::~FileLock() { release(); }

void FileLock::release() {
  if (fd_ < 0) return;
  ::close(fd_);  // drops the flock
  fd_ = -1;
  locked_ = false;
}

}  // namespace wrc
