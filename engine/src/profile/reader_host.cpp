// The reader host: plugin loading (dlopen, ABI checks) and the C sink that collects a plugin's output.
#include "wrc/profile/reader.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/reader.h"

#include "plugin_file.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <system_error>

namespace fs = std::filesystem;

namespace wrc {
namespace {

bool valid_id(const std::string& id) {
  if (id.empty() || id.size() > 64) return false;
  return std::all_of(id.begin(), id.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

bool valid_extension(const std::string& ext) {
  if (ext.size() < 2 || ext[0] != '.' || ext.size() > 32) return false;
  return std::all_of(ext.begin() + 1, ext.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

// Host side of one `read` call: the sink's context.
struct SinkState {
  RawProfile raw;
  std::string first_error;
  int first_error_line = 0;
  int errors = 0;
  bool failed_internally = false;

  void error(int line, std::string message) {
    if (errors++ == 0) {
      first_error = std::move(message);
      first_error_line = line;
    }
  }
};

SinkState& state(void* host) { return *static_cast<SinkState*>(host); }
std::string text(const char* s) { return s ? std::string(s) : std::string(); }

// The callbacks never let an exception cross into the plugin's C frames.
int sink_point(void* host, double y, double z, int32_t line) {
  try {
    SinkState& s = state(host);
    if (!std::isfinite(y) || !std::isfinite(z)) {
      s.error(line, format_message("coordinate is not a finite number (y = {}, z = {})", y, z));
      return 1;
    }
    if (s.raw.y.size() >= kMaxProfilePoints) {
      s.error(line, fmt::format("more than {} points; this is not a profile", kMaxProfilePoints));
      return 1;
    }
    s.raw.y.push_back(y);
    s.raw.z.push_back(z);
    s.raw.lines.push_back(line);
    return 0;
  } catch (...) {
    state(host).failed_internally = true;
    return 1;
  }
}

void sink_kind(void* host, int32_t kind) {
  SinkState& s = state(host);
  if (kind == WRC_KIND_WHEEL) s.raw.kind = ProfileKind::wheel;
  else if (kind == WRC_KIND_RAIL) s.raw.kind = ProfileKind::rail;
  else s.failed_internally = true;
}

void sink_units(void* host, double metres_per_unit, const char* declared_by) {
  try {
    SinkState& s = state(host);
    s.raw.metres_per_unit = metres_per_unit;
    s.raw.units_declared_by = text(declared_by);
    if (!(metres_per_unit > 0) || !std::isfinite(metres_per_unit)) s.error(0, format_message("invalid length unit {} ({})", metres_per_unit, s.raw.units_declared_by));
  } catch (...) {
    state(host).failed_internally = true;
  }
}

void sink_transform(void* host, const char* description) {
  try {
    state(host).raw.transforms.push_back(text(description));
  } catch (...) {
    state(host).failed_internally = true;
  }
}

void sink_metadata(void* host, const char* key, const char* value) {
  try {
    state(host).raw.metadata.emplace_back(text(key), text(value));
  } catch (...) {
    state(host).failed_internally = true;
  }
}

void sink_reversed(void* host, int32_t axis, const char* undo) {
  try {
    SinkState& s = state(host);
    if (axis == WRC_AXIS_Y) s.raw.reversed.y.push_back(text(undo));
    else if (axis == WRC_AXIS_Z) s.raw.reversed.z.push_back(text(undo));
    else s.failed_internally = true;
  } catch (...) {
    state(host).failed_internally = true;
  }
}

void sink_error(void* host, int32_t line, const char* message) {
  try {
    state(host).error(line, text(message));
  } catch (...) {
    state(host).failed_internally = true;
  }
}

std::string located(const std::string& path, int line, const std::string& message) {
  return line > 0 ? fmt::format("{}:{}: {}", path, line, message) : fmt::format("{}: {}", path, message);
}

// Calls a plugin's read through the C ABI and returns what it produced, or throws its first error.
RawProfile read_with_plugin(const wrc_reader_descriptor* d, const std::string& id, const std::string& path,
                            std::optional<ProfileKind> kind_hint, const ReaderOptions& options) {
  SinkState st;
  wrc_reader_sink sink{};
  sink.struct_size = sizeof(sink);
  sink.host = &st;
  sink.point = sink_point;
  sink.kind = sink_kind;
  sink.units = sink_units;
  sink.transform = sink_transform;
  sink.metadata = sink_metadata;
  sink.error = sink_error;
  sink.reversed = sink_reversed;
  std::vector<wrc_reader_option> opts;
  opts.reserve(options.size());
  for (const auto& [k, v] : options) opts.push_back({k.c_str(), v.c_str()});
  wrc_reader_request req{};
  req.struct_size = sizeof(req);
  req.path = path.c_str();
  req.kind_hint = !kind_hint ? WRC_KIND_UNKNOWN : *kind_hint == ProfileKind::wheel ? WRC_KIND_WHEEL : WRC_KIND_RAIL;
  req.options = opts.data();
  req.option_count = opts.size();
  int rc = 0;
  try {
    rc = d->read(&req, &sink);
  } catch (...) {  // a plugin breaking the ABI's no-exception rule; not reachable for a conforming plugin
    fail("{}: reader '{}' let an exception escape its read function", path, id);
  }
  if (st.failed_internally) fail("{}: reader '{}' called the host with invalid arguments or the host ran out of memory", path, id);
  if (st.errors > 0) {
    std::string msg = located(path, st.first_error_line, st.first_error);
    if (st.errors > 1) msg += fmt::format(" (and {} more error{})", st.errors - 1, st.errors > 2 ? "s" : "");
    throw Error(msg);
  }
  if (rc != 0) fail("{}: reader '{}' failed without saying why (returned {})", path, id, rc);
  return std::move(st.raw);
}

std::string list_readers(const std::vector<const ReaderRegistry*>& registries) {
  std::string out;
  for (const ReaderRegistry* r : registries)
    for (const Reader& rd : r->readers()) {
      std::string exts;
      for (const auto& e : rd.extensions) exts += (exts.empty() ? "" : " ") + e;
      out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", rd.id, exts);
    }
  return out.empty() ? "none" : out;
}

std::string list_rejected(const std::vector<const ReaderRegistry*>& registries) {
  std::string out;
  for (const ReaderRegistry* r : registries)
    for (const std::string& m : r->rejected()) out += "\n  rejected: " + m;
  return out;
}

}  // namespace

void ReaderRegistry::add(Reader reader) {
  if (!valid_id(reader.id)) fail("reader id '{}' ({}) must be 1-64 characters of a-z, 0-9 and _", reader.id, reader.origin);
  if (reader.extensions.empty()) fail("reader '{}' ({}) claims no file extension", reader.id, reader.origin);
  for (auto& e : reader.extensions) {
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!valid_extension(e)) fail("reader '{}' ({}): extension '{}' must be a dot and 1-31 characters of a-z, 0-9 and _", reader.id, reader.origin, e);
  }
  if (!reader.read) fail("reader '{}' ({}) has no read function", reader.id, reader.origin);
  if (const Reader* other = find(reader.id))
    fail("duplicate reader id '{}': {} provides it and so does {} (kept the first)", reader.id, other->origin, reader.origin);
  readers_.push_back(std::move(reader));
}

std::optional<std::string> ReaderRegistry::load_plugin(const std::string& library_path) {
  // A broken file (truncated, not ELF) is refused before dlopen maps it: a mapped segment past the end of the
  // file kills the process with SIGBUS.
  if (auto why = check_library_file(library_path)) return fmt::format("{}: cannot load the library: {}", library_path, *why);
  void* handle = dlopen(library_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* e = dlerror();
    return fmt::format("{}: cannot load the library: {}", library_path, e ? e : "unknown error");
  }
  auto reject = [&](std::string why) {
    dlclose(handle);
    return std::optional<std::string>(fmt::format("{}: {}", library_path, why));
  };
  dlerror();
  void* sym = dlsym(handle, WRC_READER_ENTRY_NAME);
  if (!sym) return reject("not a wrc reader plugin: it does not export the entry point '" WRC_READER_ENTRY_NAME "'");
  auto entry = reinterpret_cast<wrc_reader_entry_fn>(sym);
  const wrc_reader_descriptor* d = entry();
  if (!d) return reject("the entry point returned no descriptor (the plugin declined to load)");
  if (d->abi_major != WRC_READER_ABI_MAJOR)
    return reject(fmt::format("reader ABI version {}.{}, but this host implements {}.{} (major versions must match); "
                              "rebuild the plugin against this wrc's wrc/reader.h",
                              d->abi_major, d->abi_minor, WRC_READER_ABI_MAJOR, WRC_READER_ABI_MINOR));
  if (d->struct_size < sizeof(wrc_reader_descriptor))
    return reject(fmt::format("descriptor struct_size {} is smaller than the {} bytes of ABI {}.{}", d->struct_size,
                              sizeof(wrc_reader_descriptor), WRC_READER_ABI_MAJOR, WRC_READER_ABI_MINOR));
  if (!d->id || !d->read || !d->extensions) return reject("the descriptor lacks its id, extensions or read function");
  Reader r;
  r.id = d->id;
  r.description = text(d->description);
  r.origin = library_path;
  for (const char* const* e = d->extensions; *e; ++e) r.extensions.emplace_back(*e);
  if (d->options)
    for (const char* const* o = d->options; *o; ++o) r.options.emplace_back(*o);
  const std::string id = r.id;
  r.read = [d, id](const std::string& path, std::optional<ProfileKind> kind_hint, const ReaderOptions& options) {
    return read_with_plugin(d, id, path, kind_hint, options);
  };
  try {
    add(std::move(r));
  } catch (const Error& e) {
    return reject(e.what());
  }
  return std::nullopt;  // the handle stays open for the life of the process
}

void ReaderRegistry::load_plugin_dir(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    rejected_.push_back(fmt::format("{}: plugin folder does not exist", dir));
    return;
  }
  std::vector<std::string> libs;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().extension() == ".so") libs.push_back(entry.path().string());
  std::sort(libs.begin(), libs.end());
  for (const auto& lib : libs)
    if (auto why = load_plugin(lib)) rejected_.push_back(*why);
}

const Reader* ReaderRegistry::find(const std::string& id) const {
  for (const Reader& r : readers_)
    if (r.id == id) return &r;
  return nullptr;
}

const Reader* ReaderRegistry::find_by_extension(const std::string& extension) const {
  for (const Reader& r : readers_)
    if (std::find(r.extensions.begin(), r.extensions.end(), extension) != r.extensions.end()) return &r;
  return nullptr;
}

const ReaderRegistry& ReaderRegistry::plugins() {
  static ReaderRegistry registry;
  static std::once_flag once;
  std::call_once(once, [] {
    for (const auto& dir : paths().plugin_dirs) registry.load_plugin_dir(dir);
    for (const auto& why : registry.rejected()) std::fprintf(stderr, "wrc: warning: plugin %s\n", why.c_str());
  });
  return registry;
}

Profile load_profile_file(const std::string& path, const LoadOptions& options,
                          const std::vector<const ReaderRegistry*>& registries) {
  const Reader* reader = nullptr;
  if (options.reader) {
    for (const ReaderRegistry* r : registries)
      if (!reader) reader = r->find(*options.reader);
    if (!reader)
      fail("{}: no reader with id '{}' (readers: {}){}", path, *options.reader, list_readers(registries), list_rejected(registries));
  } else {
    const std::string ext = file_extension(path);
    for (const ReaderRegistry* r : registries)
      if (!reader) reader = r->find_by_extension(ext);
    if (!reader)
      fail("{}: no reader for the extension '{}' (readers: {}); pass reader = \"<id>\" to choose one{}", path, ext,
           list_readers(registries), list_rejected(registries));
  }
  for (const auto& [key, value] : options.reader_options) {
    if (std::find(reader->options.begin(), reader->options.end(), key) == reader->options.end()) {
      std::string known = "mirror_y, mirror_z, units, shift, crop, kind, name, reader";
      for (const auto& k : reader->options) known += ", " + k;
      fail("{}: unknown option '{}' for reader '{}' (expected one of: {})", path, key, reader->id, known);
    }
  }
  std::error_code ec;
  if (!fs::exists(path, ec)) fail("{}: no such file", path);
  if (fs::is_directory(path, ec)) fail("{}: is a folder, not a profile file", path);
  RawProfile raw = reader->read(path, options.kind, options.reader_options);
  return finish_profile(std::move(raw), options, path, reader->id);
}

Profile load_profile_file(const std::string& path, const LoadOptions& options) {
  return load_profile_file(path, options, {&ReaderRegistry::plugins()});
}

}  // namespace wrc
