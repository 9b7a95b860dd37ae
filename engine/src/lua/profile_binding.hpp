// The wrc.Profile userdata (a shared_ptr<const Profile>), shared by the bindings that take profiles, and the
// wrc.profile module. The type and its methods are defined in profile_type.cpp (the sandbox of profile definitions
// uses them without the rest of the binding), open_profile and the module's functions in profile_binding.cpp.
#pragma once

#include "lua/lua.hpp"
#include "wrc/profile/profile.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace wrc::lua {

extern const char* const kProfileType;  // "wrc.Profile"

void push_profile(lua_State* L, std::shared_ptr<const Profile> p);
const std::shared_ptr<const Profile>& check_profile(lua_State* L, int idx, std::string_view context);

// Adds methods (p:name(...)) to wrc.Profile; used by the parts of the binding that extend profiles.
void register_profile_methods(lua_State* L, const luaL_Reg* methods);

// Pushes an array of strings.
void push_strings(lua_State* L, const std::vector<std::string>& v);

void open_profile(lua_State* L);  // wrc.profile and the wrc.Profile metatable

// The functions behind wrc.profile.points and the wrc.Profile methods and metamethods, as they are: they throw
// wrc::Error, so Lua calls them through a wrapper that turns the exception into a Lua error (guarded<>, or the
// sandbox's own for profile definitions, sandbox.cpp).
namespace profile_api {
int points(lua_State* L);              // wrc.profile.points{kind =, y =, z =, name =}
int method_points(lua_State* L);       // p:points()
int method_resample(lua_State* L);     // p:resample{step =, along =}
int method_interpolate(lua_State* L);  // p:interpolate(y)
int method_arc_length(lua_State* L);   // p:arc_length()
int method_bounds(lua_State* L);       // p:bounds()
int method_transform(lua_State* L);    // p:transform{...}
int len(lua_State* L);                 // #p
int tostring(lua_State* L);            // tostring(p)
int index(lua_State* L);               // p.kind, p.name, ... and the methods
}  // namespace profile_api
}  // namespace wrc::lua
