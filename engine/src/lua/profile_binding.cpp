// wrc.profile: profiles from Lua tables (and, through the reader host, from files).
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/profile_binding.hpp"

#include <memory>

namespace wrc::lua {

const char* const kProfileType = "wrc.Profile";

void push_profile(lua_State* L, std::shared_ptr<const Profile> p) { push_shared(L, std::move(p), kProfileType); }

const std::shared_ptr<const Profile>& check_profile(lua_State* L, int idx, std::string_view context) {
  return check_shared<const Profile>(L, idx, kProfileType, context);
}

namespace {

// wrc.profile.points{kind=, y={...}, z={...}, name=}: metres, left-side frame.
int profile_points(lua_State* L) {
  const char* ctx = "wrc.profile.points";
  check_table(L, 1, ctx);
  check_keys(L, 1, ctx, {"kind", "y", "z", "name"});
  const auto kind_text = opt_string(L, 1, "kind", ctx);
  if (!kind_text) fail("{}: 'kind' is required (\"wheel\" or \"rail\")", ctx);
  const ProfileKind kind = parse_profile_kind(*kind_text, ctx);
  auto y = number_array(L, 1, "y", ctx);
  auto z = number_array(L, 1, "z", ctx);
  const std::string name = opt_string(L, 1, "name", ctx).value_or(std::string(to_string(kind)));
  push_profile(L, std::make_shared<const Profile>(make_profile(kind, std::move(y), std::move(z), name, ctx)));
  return 1;
}

// p:points() -> y, z (two Lua arrays, metres)
int profile_method_points(lua_State* L) {
  const auto& p = check_profile(L, 1, "profile:points");
  push_array(L, p->y);
  push_array(L, p->z);
  return 2;
}

int profile_len(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(check_profile(L, 1, "#profile")->size()));
  return 1;
}

int profile_tostring(lua_State* L) {
  const auto& p = check_profile(L, 1, "tostring(profile)");
  lua_pushstring(L, fmt::format("wrc.Profile({} '{}', {} points, y {:.4f}..{:.4f} m, from {})", to_string(p->kind),
                                p->name, p->size(), p->y.front(), p->y.back(), p->source)
                        .c_str());
  return 1;
}

int profile_index(lua_State* L) {
  const auto& p = check_profile(L, 1, "profile");
  if (lua_type(L, 2) == LUA_TSTRING) {
    const std::string_view key = lua_tostring(L, 2);
    if (key == "kind") return lua_pushstring(L, to_string(p->kind)), 1;
    if (key == "name") return lua_pushstring(L, p->name.c_str()), 1;
    if (key == "source") return lua_pushstring(L, p->source.c_str()), 1;
    if (key == "duplicates_dropped") return lua_pushinteger(L, p->duplicates_dropped), 1;
    if (key == "transforms") {
      lua_createtable(L, static_cast<int>(p->transforms.size()), 0);
      for (std::size_t i = 0; i < p->transforms.size(); ++i) {
        lua_pushstring(L, p->transforms[i].c_str());
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
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

}  // namespace

void register_profile_methods(lua_State* L, const luaL_Reg* methods) {
  luaL_getmetatable(L, kProfileType);
  lua_getfield(L, -1, "methods");
  luaL_setfuncs(L, methods, 0);
  lua_pop(L, 2);
}

void open_profile(lua_State* L) {
  if (luaL_newmetatable(L, kProfileType)) {
    const luaL_Reg meta[] = {{"__gc", gc_shared<const Profile>},
                             {"__len", guarded<profile_len>},
                             {"__tostring", guarded<profile_tostring>},
                             {"__index", guarded<profile_index>},
                             {nullptr, nullptr}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    lua_setfield(L, -2, "methods");
  }
  lua_pop(L, 1);
  const luaL_Reg methods[] = {{"points", guarded<profile_method_points>}, {nullptr, nullptr}};
  register_profile_methods(L, methods);

  lua_newtable(L);  // wrc.profile
  const luaL_Reg funcs[] = {{"points", guarded<profile_points>}, {nullptr, nullptr}};
  luaL_setfuncs(L, funcs, 0);
  lua_setfield(L, -2, "profile");
}

}  // namespace wrc::lua
