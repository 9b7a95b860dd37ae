// wrc.profile: profiles from Lua tables, Lua definitions and files (reader plugins and readers registered
// from Lua), and the wrc.Profile methods scripts use for checks and plots.
#include "lua/profile_binding.hpp"

#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/sandbox.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/orientation.hpp"
#include "wrc/profile/reader.hpp"
#include "wrc/profile/spline.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

namespace fs = std::filesystem;

namespace wrc::lua {

const char* const kProfileType = "wrc.Profile";

void push_profile(lua_State* L, std::shared_ptr<const Profile> p) { push_shared(L, std::move(p), kProfileType); }

const std::shared_ptr<const Profile>& check_profile(lua_State* L, int idx, std::string_view context) {
  return check_shared<const Profile>(L, idx, kProfileType, context);
}

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

// The options table at idx (may be none). For a file, keys the host does not know go to the reader;
// `geometric_only` (p:transform) rejects them.
LoadOptions read_options(lua_State* L, int idx, std::string_view ctx, bool geometric_only) {
  if (!lua_isnoneornil(L, idx) && !lua_istable(L, idx)) fail("{}: options must be a table, got {}", ctx, type_name(L, idx));
  const OptionTable t = to_options(L, idx, ctx);
  OptionReader r(t, std::string(ctx));
  return read_load_options(r, geometric_only);
}

// ---- wrc.profile functions ----

// The length of t[key] when it is a table (raw access, no metamethod), else 0.
std::size_t raw_length(lua_State* L, int t, const char* key) {
  if (!lua_istable(L, t)) return 0;
  lua_pushstring(L, key);
  lua_rawget(L, t);
  const std::size_t n = lua_istable(L, -1) ? lua_rawlen(L, -1) : 0;
  lua_pop(L, 1);
  return n;
}

}  // namespace

namespace profile_api {

// wrc.profile.points{kind=, y={...}, z={...}, name=}: metres, left-side frame.
int points(lua_State* L) {
  const char* ctx = "wrc.profile.points";
  // Counted before the arrays are converted (each number would become an option value first).
  check_point_count(static_cast<double>(std::max(raw_length(L, 1, "y"), raw_length(L, 1, "z"))), ctx);
  const OptionTable t = table_options(L, 1, ctx);
  OptionReader r(t, ctx);
  const auto kind_text = r.string("kind");
  if (!kind_text) fail("{}: 'kind' is required (\"wheel\" or \"rail\")", ctx);
  const ProfileKind kind = parse_profile_kind(*kind_text, ctx);
  auto y = r.numbers("y").value_or(std::vector<double>{});
  auto z = r.numbers("z").value_or(std::vector<double>{});
  const std::string name = r.string("name").value_or(std::string(to_string(kind)));
  r.finish();
  push_profile(L, std::make_shared<const Profile>(make_profile(kind, std::move(y), std::move(z), name, ctx)));
  return 1;
}

}  // namespace profile_api

namespace {

// wrc.profile.load(path [, options]) -> wrc.Profile: a Lua definition runs in a sandbox (sandbox.hpp), a file goes
// to the readers (those registered from this state first).
int profile_load(lua_State* L) {
  const char* ctx = "wrc.profile.load";
  const std::string given = check_string(L, 1, ctx);
  const LoadOptions o = read_options(L, 2, ctx, false);
  const std::string path = resolve_profile_path(given);
  std::shared_ptr<Profile> p;
  if (is_definition(path, o)) {
    p = std::make_shared<Profile>(load_definition(path, to_options(L, 2, ctx)));
  } else {
    LuaReaders& lr = lua_readers(L);
    CurrentState cs(lr, L);
    p = std::make_shared<Profile>(load_profile_file(path, o, {&lr.registry, &ReaderRegistry::plugins()}));
  }
  for (const std::string& w : p->warnings) std::fprintf(stderr, "wrc.profile.load: warning: %s\n", w.c_str());
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

void push_strings(lua_State* L, const std::vector<std::string>& v) {
  lua_createtable(L, static_cast<int>(v.size()), 0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    lua_pushstring(L, v[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
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

}  // namespace

// ---- wrc.Profile methods ----

namespace profile_api {

// p:points() -> y, z (two Lua arrays, metres)
int method_points(lua_State* L) {
  const auto& p = check_profile(L, 1, "profile:points");
  push_array(L, p->y);
  push_array(L, p->z);
  return 2;
}

// p:resample{step=, along="arc"|"y"} -> a new profile
int method_resample(lua_State* L) {
  const char* ctx = "profile:resample";
  const auto& p = check_profile(L, 1, ctx);
  const OptionTable t = table_options(L, 2, ctx);
  OptionReader r(t, ctx);
  const double step = r.need_number("step");
  const std::string along = r.choice("along", {"arc", "y"}).value_or("arc");
  r.finish();
  if (!(step > 0)) fail("{}: 'step' must be a positive number of metres, got {}", ctx, step);
  if (along == "arc") push_profile(L, std::make_shared<const Profile>(resample_arc(*p, step)));
  else push_profile(L, std::make_shared<const Profile>(resample_y(*p, step)));
  return 1;
}

// p:interpolate(y) -> z at y (linear between the points); y must lie within the profile.
int method_interpolate(lua_State* L) {
  const char* ctx = "profile:interpolate";
  const auto& p = check_profile(L, 1, ctx);
  const double y = check_number(L, 2, ctx);
  if (y < p->y.front() || y > p->y.back())
    fail("{}: y = {} m lies outside the profile ({} .. {} m)", ctx, y, p->y.front(), p->y.back());
  lua_pushnumber(L, interpolate_z(*p, y));
  return 1;
}

// p:arc_length() -> metres
int method_arc_length(lua_State* L) {
  lua_pushnumber(L, arc_length(*check_profile(L, 1, "profile:arc_length")));
  return 1;
}

// p:bounds() -> {y_min=, y_max=, z_min=, z_max=} (metres)
int method_bounds(lua_State* L) {
  const auto& p = check_profile(L, 1, "profile:bounds");
  const auto [zmin, zmax] = std::minmax_element(p->z.begin(), p->z.end());
  lua_createtable(L, 0, 4);
  set_number(L, "y_min", p->y.front());
  set_number(L, "y_max", p->y.back());
  set_number(L, "z_min", *zmin);
  set_number(L, "z_max", *zmax);
  return 1;
}

// p:transform{mirror_y=, mirror_z=, crop=, shift=, name=} -> a new profile
int method_transform(lua_State* L) {
  const char* ctx = "profile:transform";
  const auto& p = check_profile(L, 1, ctx);
  check_table(L, 2, ctx);
  const LoadOptions o = read_options(L, 2, ctx, true);
  push_profile(L, std::make_shared<const Profile>(transform_profile(*p, o)));
  return 1;
}

int len(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(check_profile(L, 1, "#profile")->size()));
  return 1;
}

int tostring(lua_State* L) {
  const auto& p = check_profile(L, 1, "tostring(profile)");
  lua_pushstring(L, fmt::format("wrc.Profile({} '{}', {} points, y {:.4f}..{:.4f} m, from {})", to_string(p->kind),
                                p->name, p->size(), p->y.front(), p->y.back(), p->source)
                        .c_str());
  return 1;
}

int index(lua_State* L) {
  const auto& p = check_profile(L, 1, "profile");
  if (lua_type(L, 2) == LUA_TSTRING) {
    const std::string_view key = lua_tostring(L, 2);
    if (key == "kind") return lua_pushstring(L, to_string(p->kind)), 1;
    if (key == "name") return lua_pushstring(L, p->name.c_str()), 1;
    if (key == "source") return lua_pushstring(L, p->source.c_str()), 1;
    if (key == "duplicates_dropped") return lua_pushinteger(L, p->duplicates_dropped), 1;
    if (key == "transforms") return push_strings(L, p->transforms), 1;
    if (key == "warnings") return push_strings(L, p->warnings), 1;
    if (key == "smooth") return p->spline ? lua_pushnumber(L, p->spline->smoothing) : lua_pushnil(L), 1;
    if (key == "metadata") {
      lua_createtable(L, 0, static_cast<int>(p->metadata.size()));
      for (const auto& [k, v] : p->metadata) set_string(L, k.c_str(), v);
      return 1;
    }
  }
  // Methods.
  luaL_getmetatable(L, kProfileType);
  lua_getfield(L, -1, "methods");
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}

}  // namespace profile_api

void register_profile_methods(lua_State* L, const luaL_Reg* methods) {
  luaL_getmetatable(L, kProfileType);
  lua_getfield(L, -1, "methods");
  luaL_setfuncs(L, methods, 0);
  lua_pop(L, 2);
}

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
                              {nullptr, nullptr}};
  register_profile_methods(L, methods);

  lua_newtable(L);  // wrc.profile
  const luaL_Reg funcs[] = {{"points", guarded<profile_api::points>},
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
  const char* ctx = "wrc.profile.load";
  OptionReader r(options, ctx);
  const LoadOptions o = read_load_options(r, false);
  const std::string path = resolve_profile_path(name);
  auto p = std::make_shared<Profile>(is_definition(path, o) ? load_definition(path, options)
                                                            : load_profile_file(path, o, {&ReaderRegistry::plugins()}));
  for (const std::string& w : p->warnings) std::fprintf(stderr, "wrc.profile.load: warning: %s\n", w.c_str());
  return p;
}

}  // namespace wrc::lua
