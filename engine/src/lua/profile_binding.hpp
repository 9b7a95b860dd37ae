// The wrc.Profile userdata (a shared_ptr<const Profile>), shared by the bindings that take profiles.
#pragma once

#include "lua/lua.hpp"
#include "wrc/profile/profile.hpp"

#include <memory>
#include <string_view>

namespace wrc::lua {

extern const char* const kProfileType;  // "wrc.Profile"

void push_profile(lua_State* L, std::shared_ptr<const Profile> p);
const std::shared_ptr<const Profile>& check_profile(lua_State* L, int idx, std::string_view context);

// Adds methods (p:name(...)) to wrc.Profile; used by the parts of the binding that extend profiles.
void register_profile_methods(lua_State* L, const luaL_Reg* methods);

void open_profile(lua_State* L);  // wrc.profile and the wrc.Profile metatable
}  // namespace wrc::lua
