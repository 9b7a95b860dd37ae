// wrc.profile: profiles from Lua tables, Lua definitions and files (reader plugins and readers registered
// from Lua), through wrc::load_profile; the wrc.Profile type and its methods are in profile_type.cpp.
#include "lua/profile_binding.hpp"

#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "wrc/lua/definitions.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/reader.hpp"
#include "wrc/profile/write.hpp"

#include <cstdio>
#include <memory>

namespace wrc::lua {

namespace {

// ---- Readers registered from Lua (one set per Lua state; plugins are process-wide) ----

const char* const kLuaReadersType = "wrc.LuaReaders";
const char* const kLuaReadersKey = "wrc.profile.lua_readers";

struct LuaReaders {
  ReaderRegistry registry;
  lua_State* current = nullptr;  // the thread of the wrc.profile.load call in progress
};

LuaReaders& lua_readers(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kLuaReadersKey);
  auto* r = static_cast<std::shared_ptr<LuaReaders>*>(luaL_testudata(L, -1, kLuaReadersType));
  lua_pop(L, 1);
  if (r && *r) return **r;
  push_shared(L, std::make_shared<LuaReaders>(), kLuaReadersType);
  auto* fresh = static_cast<std::shared_ptr<LuaReaders>*>(lua_touserdata(L, -1));
  lua_setfield(L, LUA_REGISTRYINDEX, kLuaReadersKey);
  return **fresh;
}

// Sets LuaReaders::current for the duration of a load.
struct CurrentState {
  LuaReaders& r;
  lua_State* saved;
  CurrentState(LuaReaders& r_, lua_State* L) : r(r_), saved(r_.current) { r.current = L; }
  ~CurrentState() { r.current = saved; }
};

// Shows a loaded or made profile's warnings, as every front end does (the engine prints nothing), each prefixed by
// `who`: "wrc.profile.load" before a file's path, "wrc" before a text that names wrc.profile.points.
void print_warnings(const Profile& p, const char* who = "wrc.profile.load") {
  for (const std::string& w : p.warnings) std::fprintf(stderr, "%s: warning: %s\n", who, w.c_str());
}

// wrc.profile.points{...} (profile_api::points) with its warnings shown; a profile definition's sandbox calls
// profile_api::points itself, and the loaded definition's profile is checked and shown by wrc.profile.load.
int profile_points(lua_State* L) {
  const int n = profile_api::points(L);
  print_warnings(*check_profile(L, -1, "wrc.profile.points"), "wrc");
  return n;
}

// ---- wrc.profile functions ----

// wrc.profile.load(path [, options]) -> wrc.Profile: wrc::load_profile with the sandbox for Lua definitions
// (sandbox.hpp) and the readers registered from this state looked up before the plugins.
int profile_load(lua_State* L) {
  const char* ctx = "wrc.profile.load";
  const std::string given = check_string(L, 1, ctx);
  if (!lua_isnoneornil(L, 2) && !lua_istable(L, 2)) fail("{}: options must be a table, got {}", ctx, type_name(L, 2));
  const OptionTable options = to_options(L, 2, ctx);
  LuaReaders& lr = lua_readers(L);
  CurrentState cs(lr, L);
  const DefinitionLoader definitions = definition_loader();
  auto p = std::make_shared<const Profile>(wrc::load_profile(given, options, &definitions, &lr.registry));
  print_warnings(*p);
  push_profile(L, std::move(p));
  return 1;
}

// The call of one Lua reader: read(path, options) -> table.
RawProfile call_lua_reader(LuaReaders& lr, int ref, const std::string& id, const std::string& path,
                           std::optional<ProfileKind> kind_hint, const ReaderOptions& options) {
  lua_State* L = lr.current;
  if (!L) fail("{}: the Lua reader '{}' can only run inside wrc.profile.load", path, id);
  const std::string ctx = fmt::format("{}: Lua reader '{}'", path, id);
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  lua_pushstring(L, path.c_str());
  lua_createtable(L, 0, static_cast<int>(options.size()) + 1);
  for (const auto& [k, v] : options) set_string(L, k.c_str(), v);
  if (kind_hint) set_string(L, "kind", to_string(*kind_hint));
  if (pcall_traceback(L, 2, 1) != LUA_OK) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error object is not a string";
    lua_pop(L, 1);
    fail("{} failed: {}", ctx, msg);
  }
  if (!lua_istable(L, -1)) {
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    fail("{}: the read function must return a table {{y=, z=, ...}}, got {}", ctx, tn);
  }
  const int top = lua_gettop(L);
  OptionTable t;
  try {
    t = to_options(L, top, ctx);
  } catch (...) {
    lua_settop(L, top - 1);
    throw;
  }
  lua_settop(L, top - 1);
  OptionReader r(t, ctx);
  return read_raw_profile(r);
}

// wrc.profile.register_reader{id=, extensions={...}, read=function(path, options) ... end, options={...}, description=}
int profile_register_reader(lua_State* L) {
  const char* ctx = "wrc.profile.register_reader";
  const OptionTable t = table_options(L, 1, ctx, {"read"});
  OptionReader o(t, ctx);
  o.allow({"read"});
  Reader r;
  r.id = o.string("id").value_or("");
  if (r.id.empty()) fail("{}: 'id' is required (a string of a-z, 0-9, _)", ctx);
  r.extensions = o.strings("extensions").value_or(std::vector<std::string>{});
  r.options = o.strings("options").value_or(std::vector<std::string>{});
  r.description = o.string("description").value_or("");
  o.finish();
  lua_Debug ar;
  r.origin = "Lua";
  if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "Sl", &ar)) r.origin = fmt::format("Lua ({}:{})", ar.short_src, ar.currentline);
  if (const Reader* p = ReaderRegistry::plugins().find(r.id))
    fail("{}: duplicate reader id '{}': the plugin {} provides it", ctx, r.id, p->origin);
  lua_getfield(L, 1, "read");
  if (!lua_isfunction(L, -1)) {
    const char* tn = type_name(L, -1);
    lua_pop(L, 1);
    fail("{}: 'read' must be a function(path, options) returning {{y=, z=, ...}}, got {}", ctx, tn);
  }
  LuaReaders& lr = lua_readers(L);
  if (const Reader* p = lr.registry.find(r.id)) {
    lua_pop(L, 1);
    fail("{}: duplicate reader id '{}': already registered from {}", ctx, r.id, p->origin);
  }
  const int ref = luaL_ref(L, LUA_REGISTRYINDEX);  // the read function, kept for the life of the state
  LuaReaders* lrp = &lr;
  const std::string rid = r.id;
  r.read = [lrp, ref, rid](const std::string& path, std::optional<ProfileKind> kind_hint, const ReaderOptions& options) {
    return call_lua_reader(*lrp, ref, rid, path, kind_hint, options);
  };
  try {
    lr.registry.add(std::move(r));
  } catch (...) {
    luaL_unref(L, LUA_REGISTRYINDEX, ref);
    throw;
  }
  return 0;
}

// wrc.profile.readers() -> {{id=, extensions=, options=, description=, origin=}, ...}, {rejected messages}
int profile_readers(lua_State* L) {
  const ReaderRegistry& plugins = ReaderRegistry::plugins();
  const LuaReaders& lr = lua_readers(L);
  lua_newtable(L);
  lua_Integer i = 0;
  for (const ReaderRegistry* reg : {&lr.registry, &plugins}) {
    for (const Reader& r : reg->readers()) {
      lua_createtable(L, 0, 5);
      set_string(L, "id", r.id);
      set_string(L, "description", r.description);
      set_string(L, "origin", r.origin);
      push_strings(L, r.extensions);
      lua_setfield(L, -2, "extensions");
      push_strings(L, r.options);
      lua_setfield(L, -2, "options");
      lua_rawseti(L, -2, ++i);
    }
  }
  push_strings(L, plugins.rejected());
  return 2;
}

// p:write(path, {format =, ...}) -> the format written. Not in the sandbox of definitions (which write no files).
int profile_write(lua_State* L) {
  const char* ctx = "profile:write";
  const auto& p = check_profile(L, 1, ctx);
  const std::string path = check_string(L, 2, ctx);
  const OptionTable t = to_options(L, 3, ctx);
  lua_pushstring(L, write_profile(*p, path, t, ctx).c_str());
  return 1;
}

}  // namespace

void open_profile(lua_State* L) {
  if (luaL_newmetatable(L, kProfileType)) {
    const luaL_Reg meta[] = {{"__gc", gc_shared<const Profile>},
                             {"__len", guarded<profile_api::len>},
                             {"__tostring", guarded<profile_api::tostring>},
                             {"__index", guarded<profile_api::index>},
                             {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    lua_setfield(L, -2, "methods");
  }
  lua_pop(L, 1);
  if (luaL_newmetatable(L, kLuaReadersType)) {
    lua_pushcfunction(L, gc_shared<LuaReaders>);
    lua_setfield(L, -2, "__gc");
  }
  lua_pop(L, 1);
  const luaL_Reg methods[] = {{"points", guarded<profile_api::method_points>},
                              {"resample", guarded<profile_api::method_resample>},
                              {"interpolate", guarded<profile_api::method_interpolate>},
                              {"arc_length", guarded<profile_api::method_arc_length>},
                              {"bounds", guarded<profile_api::method_bounds>},
                              {"transform", guarded<profile_api::method_transform>},
                              {"write", guarded<profile_write>},
                              {nullptr, nullptr}};
  register_profile_methods(L, methods);

  lua_newtable(L);  // wrc.profile
  const luaL_Reg funcs[] = {{"points", guarded<profile_points>},
                            {"load", guarded<profile_load>},
                            {"register_reader", guarded<profile_register_reader>},
                            {"readers", guarded<profile_readers>},
                            {nullptr, nullptr}};
  luaL_setfuncs(L, funcs, 0);
  lua_pushinteger(L, static_cast<lua_Integer>(kMaxProfilePoints));
  lua_setfield(L, -2, "max_points");
  lua_setfield(L, -2, "profile");
}

std::shared_ptr<const Profile> load_profile(const std::string& name, const OptionTable& options) {
  const DefinitionLoader definitions = definition_loader();
  auto p = std::make_shared<const Profile>(wrc::load_profile(name, options, &definitions));
  print_warnings(*p);
  return p;
}

}  // namespace wrc::lua
