// Profile readers as the host sees them (docs/design.md, section 6): a plugin loaded from a shared library
// (ABI: engine/include/wrc/reader.h) and a reader registered from Lua look the same, an id, extensions, the
// reader's own option keys and a read function producing a RawProfile.
#pragma once

#include "wrc/profile/load.hpp"

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wrc {

using ReaderOptions = std::vector<std::pair<std::string, std::string>>;

struct Reader {
  std::string id;                       // [a-z0-9_]+, unique within a registry
  std::string description;
  std::string origin;                   // plugin library path, or "Lua (file:line)"
  std::vector<std::string> extensions;  // lower case with the dot
  std::vector<std::string> options;     // keys of the reader's own options
  // Reads `path`: kind_hint is the user's `kind` option, options the reader's own ones. Throws
  // wrc::Error with "path:line: message" on bad input.
  std::function<RawProfile(const std::string& path, std::optional<ProfileKind> kind_hint, const ReaderOptions& options)>
      read;
};

class ReaderRegistry {
 public:
  // Adds a reader. Throws wrc::Error for a malformed id or extension, or an id already present (the
  // message names both origins).
  void add(Reader reader);

  // Loads one plugin library. Returns the reason when it is rejected (not a loadable library, no
  // entry point, wrong ABI major, malformed descriptor, duplicate id); nothing is added then.
  std::optional<std::string> load_plugin(const std::string& library_path);

  // Loads every shared library (*.so) of `dir` in name order; rejections are collected in rejected().
  void load_plugin_dir(const std::string& dir);

  const Reader* find(const std::string& id) const;
  // The first reader (in registration order) that claims the extension (".prw").
  const Reader* find_by_extension(const std::string& extension) const;

  const std::deque<Reader>& readers() const { return readers_; }
  const std::vector<std::string>& rejected() const { return rejected_; }

  // The process-wide plugin registry, loaded once (thread-safe) from paths().plugin_dirs; rejected
  // libraries are reported once on stderr.
  static const ReaderRegistry& plugins();

 private:
  std::deque<Reader> readers_;  // deque: pointers stay valid as readers are added
  std::vector<std::string> rejected_;
};

// Reads a profile file with the first matching reader of `registries` (searched in order): the one
// whose id is options.reader, else the one claiming the file's extension. Checks the reader's options,
// reads, and finishes the profile (finish_profile). Errors name the file (and line).
Profile load_profile_file(const std::string& path, const LoadOptions& options,
                          const std::vector<const ReaderRegistry*>& registries);

// The same with the plugin registry only.
Profile load_profile_file(const std::string& path, const LoadOptions& options);

}  // namespace wrc
