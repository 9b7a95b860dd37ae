// The wrc.Profile userdata and its methods (profile_binding.hpp): what the wrc.profile module (profile_binding.cpp)
// and the sandbox of profile definitions (sandbox.cpp) share. A file of its own so that the sandbox, the part of the
// binding that libwrc.so links, needs nothing of the Lua host (host.cpp, module.cpp).
#include "lua/profile_binding.hpp"

#include "lua/convert.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/profile/spline.hpp"

#include <algorithm>
#include <memory>

namespace wrc::lua {

const char* const kProfileType = "wrc.Profile";

void push_profile(lua_State* L, std::shared_ptr<const Profile> p) { push_shared(L, std::move(p), kProfileType); }

const std::shared_ptr<const Profile>& check_profile(lua_State* L, int idx, std::string_view context) {
  return check_shared<const Profile>(L, idx, kProfileType, context);
}

void push_strings(lua_State* L, const std::vector<std::string>& v) {
  lua_createtable(L, static_cast<int>(v.size()), 0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    lua_pushstring(L, v[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

namespace {

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
  push_profile(L, std::make_shared<const Profile>(read_points_profile(r)));  // its warnings: the caller's to show
  return 1;
}

// ---- wrc.Profile methods ----

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
  const OptionTable t = to_options(L, 2, ctx);
  OptionReader r(t, ctx);
  const LoadOptions o = read_load_options(r, true);
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

}  // namespace wrc::lua
