// wrc.fs: the file operations study scripts need beyond Lua's io library (docs/guide/studies.md "What a run
// guarantees"): folders, files written atomically, listings and content hashes. Each function converts and calls
// core/files.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "wrc/core/files.hpp"
#include "wrc/core/options.hpp"
#include "wrc/core/parallel.hpp"

#include <filesystem>
#include <system_error>

namespace wrc::lua {
namespace {

namespace fs = std::filesystem;

// A string argument that names a file or folder: refused when it holds a NUL byte (check_path_text).
std::string check_path(lua_State* L, int idx, const char* context) {
  std::string path = check_string(L, idx, context);
  check_path_text(path, context);
  return path;
}
const char* const kAtomicType = "wrc.AtomicFile";
const char* const kLockType = "wrc.FileLock";

// wrc.fs.mkdir(path): creates a folder and its parents (no error if it exists).
int fs_mkdir(lua_State* L) {
  const std::string path = check_path(L, 1, "wrc.fs.mkdir");
  std::error_code ec;
  fs::create_directories(path, ec);
  if (ec) fail("wrc.fs.mkdir: cannot create '{}': {}", path, ec.message());
  return 0;
}

AtomicFile& atomic_self(lua_State* L, const char* ctx) { return *check_shared<AtomicFile>(L, 1, kAtomicType, ctx); }

// wrc.fs.open_atomic(path) -> writer with :write(...), :commit(), :discard() (also when collected or closed).
int fs_open_atomic(lua_State* L) {
  push_shared(L, std::make_shared<AtomicFile>(check_string(L, 1, "wrc.fs.open_atomic")), kAtomicType);
  return 1;
}

// f:write(s, ...): strings and numbers, as io.write; returns f.
int atomic_write(lua_State* L) {
  AtomicFile& f = atomic_self(L, "AtomicFile:write");
  for (int i = 2, n = lua_gettop(L); i <= n; ++i) {
    if (lua_type(L, i) != LUA_TSTRING && lua_type(L, i) != LUA_TNUMBER)
      fail("AtomicFile:write: argument {} must be a string or a number, got {}", i - 1, type_name(L, i));
    std::size_t len = 0;
    const char* s = lua_tolstring(L, i, &len);
    f.write(std::string_view(s, len));
  }
  lua_settop(L, 1);
  return 1;
}

int atomic_commit(lua_State* L) {
  atomic_self(L, "AtomicFile:commit").commit();
  return 0;
}

int atomic_discard(lua_State* L) {
  auto* p = static_cast<std::shared_ptr<AtomicFile>*>(luaL_testudata(L, 1, kAtomicType));
  if (p && *p) (*p)->discard();
  return 0;
}

// wrc.fs.write_file(path, text): the whole file, atomically.
int fs_write_file(lua_State* L) {
  write_file_atomic(check_path(L, 1, "wrc.fs.write_file"), check_string(L, 2, "wrc.fs.write_file"));
  return 0;
}

// wrc.fs.list(folder) -> sorted names.
int fs_list(lua_State* L) {
  const std::vector<std::string> names = list_folder(check_path(L, 1, "wrc.fs.list"));
  lua_createtable(L, static_cast<int>(names.size()), 0);
  for (std::size_t i = 0; i < names.size(); ++i) {
    lua_pushlstring(L, names[i].data(), names[i].size());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

// wrc.fs.kind(path) -> "file", "folder", "other" or nil (missing).
int fs_kind(lua_State* L) {
  std::error_code ec;
  const fs::file_status st = fs::status(check_path(L, 1, "wrc.fs.kind"), ec);
  if (ec || !fs::exists(st)) return 0;
  lua_pushstring(L, fs::is_regular_file(st) ? "file" : fs::is_directory(st) ? "folder" : "other");
  return 1;
}

// wrc.fs.remove(path): a file or an empty folder; nothing when missing.
int fs_remove(lua_State* L) {
  const std::string path = check_path(L, 1, "wrc.fs.remove");
  std::error_code ec;
  fs::remove(path, ec);
  if (ec) fail("wrc.fs.remove: cannot remove '{}': {}", path, ec.message());
  return 0;
}

// wrc.fs.remove_tree(path): a folder and everything in it.
int fs_remove_tree(lua_State* L) {
  const std::string path = check_path(L, 1, "wrc.fs.remove_tree");
  std::error_code ec;
  fs::remove_all(path, ec);
  if (ec) fail("wrc.fs.remove_tree: cannot remove '{}': {}", path, ec.message());
  return 0;
}

// wrc.fs.is_link(path) -> true when path is a symbolic link (not followed).
int fs_is_link(lua_State* L) {
  std::error_code ec;
  lua_pushboolean(L, fs::is_symlink(fs::symlink_status(check_path(L, 1, "wrc.fs.is_link"), ec)));
  return 1;
}

// wrc.fs.name_problem(name) -> nil, or why `name` cannot name an entry inside a folder (core/files).
int fs_name_problem(lua_State* L) {
  const std::string why = inside_name_problem(check_string(L, 1, "wrc.fs.name_problem"));
  if (why.empty()) return 0;
  lua_pushstring(L, why.c_str());
  return 1;
}

// wrc.fs.mkdir_inside(root, name): mkdir -p of root/name through real folders only.
int fs_mkdir_inside(lua_State* L) {
  make_folders_inside(check_path(L, 1, "wrc.fs.mkdir_inside"), check_string(L, 2, "wrc.fs.mkdir_inside"));
  return 0;
}

// wrc.fs.remove_inside(root, name [, hash]) -> "removed" or "missing", or nil and why the file was left in place.
int fs_remove_inside(lua_State* L) {
  const char* ctx = "wrc.fs.remove_inside";
  const std::string hash = lua_isnoneornil(L, 3) ? std::string() : check_string(L, 3, ctx);
  const RemoveResult r = remove_file_inside(check_path(L, 1, ctx), check_string(L, 2, ctx), hash);
  if (r.what == Removal::refused) {
    lua_pushnil(L);
    lua_pushstring(L, r.why.c_str());
    return 2;
  }
  lua_pushstring(L, r.what == Removal::removed ? "removed" : "missing");
  return 1;
}

// wrc.fs.remove_tree_inside(root, name): the folder root/name and its content, no link followed.
int fs_remove_tree_inside(lua_State* L) {
  remove_tree_inside(check_path(L, 1, "wrc.fs.remove_tree_inside"), check_string(L, 2, "wrc.fs.remove_tree_inside"));
  return 0;
}

// wrc.fs.lock(path) -> a lock (lock:release(), lock.locked; released when collected and at the process's end), or
// nil and the note of the process that holds it.
int fs_lock(lua_State* L) {
  std::string holder;
  std::unique_ptr<FileLock> lock = FileLock::try_acquire(check_path(L, 1, "wrc.fs.lock"), holder);
  if (!lock) {
    lua_pushnil(L);
    lua_pushstring(L, holder.c_str());
    return 2;
  }
  push_shared(L, std::shared_ptr<FileLock>(std::move(lock)), kLockType);
  if (holder.empty()) return 1;
  lua_pushstring(L, holder.c_str());  // a lock the file system does not enforce: why
  return 2;
}

int lock_release(lua_State* L) {
  auto* p = static_cast<std::shared_ptr<FileLock>*>(luaL_testudata(L, 1, kLockType));
  if (p && *p) (*p)->release();
  return 0;
}

int lock_index(lua_State* L) {
  const std::shared_ptr<FileLock>& lock = check_shared<FileLock>(L, 1, kLockType, "wrc.FileLock");
  const std::string key = check_string(L, 2, "wrc.FileLock");
  if (key == "locked") lua_pushboolean(L, lock->locked());
  else if (key == "release") lua_pushcfunction(L, guarded<lock_release>);
  else lua_pushnil(L);
  return 1;
}

// wrc.fs.temporary_name(path) -> a fresh temporary path next to `path` (the pattern fs.is_temporary recognises),
// tracked: an interrupted run removes it (track_temporary) until wrc.fs.forget_temporary(name) says it is gone.
int fs_temporary_name(lua_State* L) {
  const std::string name = temporary_path(check_path(L, 1, "wrc.fs.temporary_name"));
  track_temporary(name);
  lua_pushstring(L, name.c_str());
  return 1;
}

// wrc.fs.forget_temporary(name): a name of wrc.fs.temporary_name that was removed or renamed; nothing otherwise.
int fs_forget_temporary(lua_State* L) {
  untrack_temporary(check_path(L, 1, "wrc.fs.forget_temporary"));
  return 0;
}

// wrc.fs.digest(path [, bytes]) -> the hash of the first `bytes` bytes (all by default), bytes read, line breaks.
int fs_digest(lua_State* L) {
  const char* ctx = "wrc.fs.digest";
  const std::string path = check_path(L, 1, ctx);
  std::uint64_t limit = UINT64_MAX;
  if (!lua_isnoneornil(L, 2)) {
    const double n = check_number(L, 2, ctx);
    if (n < 0) fail("{}: bytes must be >= 0, got {}", ctx, n);
    limit = static_cast<std::uint64_t>(n);
  }
  const FileDigest d = digest_file(path, limit);
  lua_pushstring(L, d.hash.c_str());
  lua_pushinteger(L, static_cast<lua_Integer>(d.bytes));
  lua_pushinteger(L, static_cast<lua_Integer>(d.lines));
  return 3;
}

int fs_check_writable(lua_State* L) {
  check_writable(check_path(L, 1, "wrc.fs.check_writable"));
  return 0;
}

int fs_is_temporary(lua_State* L) {
  lua_pushboolean(L, is_temporary_name(check_string(L, 1, "wrc.fs.is_temporary")));
  return 1;
}

int fs_absolute(lua_State* L) {
  std::error_code ec;
  const fs::path p = fs::absolute(check_path(L, 1, "wrc.fs.absolute"), ec).lexically_normal();
  if (ec) fail("wrc.fs.absolute: {}", ec.message());
  lua_pushstring(L, p.string().c_str());
  return 1;
}

int fs_size(lua_State* L) {
  const std::string path = check_path(L, 1, "wrc.fs.size");
  std::error_code ec;
  const auto n = fs::file_size(path, ec);
  if (ec) fail("wrc.fs.size: '{}': {}", path, ec.message());
  lua_pushinteger(L, static_cast<lua_Integer>(n));
  return 1;
}

int fs_hash(lua_State* L) {
  lua_pushstring(L, hash_text(check_string(L, 1, "wrc.fs.hash")).c_str());
  return 1;
}

int fs_hash_file(lua_State* L) {
  lua_pushstring(L, hash_file(check_path(L, 1, "wrc.fs.hash_file")).c_str());
  return 1;
}

// wrc.closest_name(word, {names}) -> the name a misspelt word probably meant, or nil.
int closest(lua_State* L) {
  const char* ctx = "wrc.closest_name";
  const std::string word = check_string(L, 1, ctx);
  check_table(L, 2, ctx);
  std::vector<std::string> names;
  for (lua_Integer i = 1, n = static_cast<lua_Integer>(lua_rawlen(L, 2)); i <= n; ++i) {
    lua_rawgeti(L, 2, i);
    names.push_back(check_string(L, -1, ctx));
    lua_pop(L, 1);
  }
  const std::string best = closest_name(word, names);
  if (best.empty()) return 0;
  lua_pushstring(L, best.c_str());
  return 1;
}

// wrc.number_text(x) -> the number x as a message writes it: NaN as "NaN" whatever its sign bit (Lua's tostring writes
// 0/0 "-nan"), integers as tostring, other numbers as the engine's messages (wrc::number_text).
int number_text_of(lua_State* L) {
  if (lua_type(L, 1) != LUA_TNUMBER) fail("wrc.number_text: argument 1 must be a number, got {}", type_name(L, 1));
  if (lua_isinteger(L, 1)) lua_pushstring(L, std::to_string(lua_tointeger(L, 1)).c_str());
  else lua_pushstring(L, number_text(lua_tonumber(L, 1)).c_str());
  return 1;
}

}  // namespace

void open_fs(lua_State* L) {
  if (luaL_newmetatable(L, kAtomicType)) {
    const luaL_Reg methods[] = {{"write", guarded<atomic_write>}, {"commit", guarded<atomic_commit>},
                                {"discard", guarded<atomic_discard>}, {nullptr, nullptr}};
    luaL_newlib(L, methods);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, guarded<atomic_discard>);
    lua_setfield(L, -2, "__close");
    lua_pushcfunction(L, gc_shared<AtomicFile>);
    lua_setfield(L, -2, "__gc");
  }
  lua_pop(L, 1);
  if (luaL_newmetatable(L, kLockType)) {
    lua_pushcfunction(L, guarded<lock_index>);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, guarded<lock_release>);
    lua_setfield(L, -2, "__close");
    lua_pushcfunction(L, gc_shared<FileLock>);
    lua_setfield(L, -2, "__gc");
  }
  lua_pop(L, 1);
  const luaL_Reg fns[] = {{"mkdir", guarded<fs_mkdir>},
                          {"open_atomic", guarded<fs_open_atomic>},
                          {"write_file", guarded<fs_write_file>},
                          {"list", guarded<fs_list>},
                          {"kind", guarded<fs_kind>},
                          {"remove", guarded<fs_remove>},
                          {"remove_tree", guarded<fs_remove_tree>},
                          {"check_writable", guarded<fs_check_writable>},
                          {"is_temporary", guarded<fs_is_temporary>},
                          {"absolute", guarded<fs_absolute>},
                          {"size", guarded<fs_size>},
                          {"hash", guarded<fs_hash>},
                          {"hash_file", guarded<fs_hash_file>},
                          {"digest", guarded<fs_digest>},
                          {"is_link", guarded<fs_is_link>},
                          {"name_problem", guarded<fs_name_problem>},
                          {"mkdir_inside", guarded<fs_mkdir_inside>},
                          {"remove_inside", guarded<fs_remove_inside>},
                          {"remove_tree_inside", guarded<fs_remove_tree_inside>},
                          {"lock", guarded<fs_lock>},
                          {"temporary_name", guarded<fs_temporary_name>},
                          {"forget_temporary", guarded<fs_forget_temporary>},
                          {nullptr, nullptr}};
  luaL_newlib(L, fns);
  lua_setfield(L, -2, "fs");
  lua_pushcfunction(L, guarded<closest>);
  lua_setfield(L, -2, "closest_name");
  lua_pushcfunction(L, guarded<number_text_of>);
  lua_setfield(L, -2, "number_text");
  lua_pushinteger(L, available_cores());
  lua_setfield(L, -2, "cores");
}

}  // namespace wrc::lua
