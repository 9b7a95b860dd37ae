// wrc.fs: the file operations study scripts need beyond Lua's io library (README "Studies: outputs"): folders,
// files written atomically, listings and content hashes. Each function converts and calls core/files.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "wrc/core/files.hpp"
#include "wrc/core/options.hpp"

#include <filesystem>
#include <system_error>

namespace wrc::lua {
namespace {

namespace fs = std::filesystem;
const char* const kAtomicType = "wrc.AtomicFile";

// wrc.fs.mkdir(path): creates a folder and its parents (no error if it exists).
int fs_mkdir(lua_State* L) {
  const std::string path = check_string(L, 1, "wrc.fs.mkdir");
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
  write_file_atomic(check_string(L, 1, "wrc.fs.write_file"), check_string(L, 2, "wrc.fs.write_file"));
  return 0;
}

// wrc.fs.list(folder) -> sorted names.
int fs_list(lua_State* L) {
  const std::vector<std::string> names = list_folder(check_string(L, 1, "wrc.fs.list"));
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
  const fs::file_status st = fs::status(check_string(L, 1, "wrc.fs.kind"), ec);
  if (ec || !fs::exists(st)) return 0;
  lua_pushstring(L, fs::is_regular_file(st) ? "file" : fs::is_directory(st) ? "folder" : "other");
  return 1;
}

// wrc.fs.remove(path): a file or an empty folder; nothing when missing.
int fs_remove(lua_State* L) {
  const std::string path = check_string(L, 1, "wrc.fs.remove");
  std::error_code ec;
  fs::remove(path, ec);
  if (ec) fail("wrc.fs.remove: cannot remove '{}': {}", path, ec.message());
  return 0;
}

// wrc.fs.remove_tree(path): a folder and everything in it.
int fs_remove_tree(lua_State* L) {
  const std::string path = check_string(L, 1, "wrc.fs.remove_tree");
  std::error_code ec;
  fs::remove_all(path, ec);
  if (ec) fail("wrc.fs.remove_tree: cannot remove '{}': {}", path, ec.message());
  return 0;
}

int fs_check_writable(lua_State* L) {
  check_writable(check_string(L, 1, "wrc.fs.check_writable"));
  return 0;
}

int fs_is_temporary(lua_State* L) {
  lua_pushboolean(L, is_temporary_name(check_string(L, 1, "wrc.fs.is_temporary")));
  return 1;
}

int fs_absolute(lua_State* L) {
  std::error_code ec;
  const fs::path p = fs::absolute(check_string(L, 1, "wrc.fs.absolute"), ec).lexically_normal();
  if (ec) fail("wrc.fs.absolute: {}", ec.message());
  lua_pushstring(L, p.string().c_str());
  return 1;
}

int fs_size(lua_State* L) {
  const std::string path = check_string(L, 1, "wrc.fs.size");
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
  lua_pushstring(L, hash_file(check_string(L, 1, "wrc.fs.hash_file")).c_str());
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
                          {nullptr, nullptr}};
  luaL_newlib(L, fns);
  lua_setfield(L, -2, "fs");
  lua_pushcfunction(L, guarded<closest>);
  lua_setfield(L, -2, "closest_name");
  lua_pushinteger(L, available_cores());
  lua_setfield(L, -2, "cores");
}

}  // namespace wrc::lua
