#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/profile_binding.hpp"
#include "wrc/core/build.hpp"
#include "wrc/core/config.hpp"
#include "wrc/core/paths.hpp"
#include "lua/guard.hpp"

namespace wrc::lua {

void open_core(lua_State* L) {
  set_string(L, "version", WRC_VERSION);
  set_string(L, "build_id", build_id());          // wrc/core/build.hpp: what a study records of the build
  set_string(L, "build_origin", build_origin());
  const Paths& p = paths();
  lua_createtable(L, 0, 4);
  set_string(L, "root", p.root);
  set_string(L, "scripts", p.scripts);
  set_string(L, "profiles", p.profiles);
  lua_createtable(L, static_cast<int>(p.plugin_dirs.size()), 0);
  for (std::size_t i = 0; i < p.plugin_dirs.size(); ++i) {
    lua_pushstring(L, p.plugin_dirs[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "plugins");
  lua_setfield(L, -2, "paths");
}

int luaopen_wrc(lua_State* L) {
  lua_newtable(L);
  open_core(L);
  open_fs(L);
  open_profile(L);
  open_wheelset(L);
  open_kinematics(L);
  open_wear(L);
  return 1;
}

}  // namespace wrc::lua
