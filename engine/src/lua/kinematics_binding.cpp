// wrc.conicity (kinematics/conicity.hpp) and the profile measures p:flange_measures (profile/measures.hpp) and
// p:curvature (profile/spline.hpp): each converts its arguments, calls the engine and pushes what it describes.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "lua/profile_binding.hpp"
#include "lua/results_binding.hpp"
#include "wrc/api/calls.hpp"
#include "wrc/kinematics/conicity.hpp"
#include "wrc/profile/measures.hpp"
#include "wrc/profile/spline.hpp"

namespace wrc::lua {
namespace {

// wrc.conicity({y = {...}, dr = {...}, flange = {...}}, {yhat =, method =, r0 =, contact_distance =})
// -> {tan gamma_e per amplitude}, details
int conicity(lua_State* L) {
  const char* ctx = "wrc.conicity";
  const OptionTable dt = table_options(L, 1, ctx);
  const OptionTable ot = table_options(L, 2, ctx);
  OptionReader dr(dt, std::string(ctx) + ": Δr table"), o(ot, ctx);
  const auto call = api::ConicityCall::read(dr, o);
  dr.finish();
  o.finish();
  const ConicityResult r = call.run();
  push_array(L, r.tan_gamma);
  push_result(L, r);
  return 2;
}

// p:flange_measures{tape_offset = m} -> {Sh =, Sd =, qR =, tip =, sd_point =, qr_point =, ...} (m)
int profile_flange_measures(lua_State* L) {
  const char* ctx = "profile:flange_measures";
  const auto& p = check_profile(L, 1, ctx);
  push_result(L, api::read<api::FlangeMeasuresCall>(to_options(L, 2, ctx), ctx).run(*p));
  return 1;
}

// p:curvature(y) -> curvature (1/m, > 0 convex), lateral radius (m; nil where the profile is straight)
int profile_curvature_at(lua_State* L) {
  const char* ctx = "profile:curvature";
  const auto& p = check_profile(L, 1, ctx);
  const double k = profile_curvature(*p, check_number(L, 2, ctx));
  lua_pushnumber(L, k);
  if (k != 0) lua_pushnumber(L, 1 / k);
  else lua_pushnil(L);
  return 2;
}

}  // namespace

void open_kinematics(lua_State* L) {
  lua_pushcfunction(L, guarded<conicity>);
  lua_setfield(L, -2, "conicity");
  const luaL_Reg methods[] = {{"flange_measures", guarded<profile_flange_measures>},
                              {"curvature", guarded<profile_curvature_at>},
                              {nullptr, nullptr}};
  register_profile_methods(L, methods);
}

}  // namespace wrc::lua
