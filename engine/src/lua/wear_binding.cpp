// wrc.wear: the numeric kernels of a wear loop (damage/profile_wear.hpp) for the loop's policy in Lua
// (examples/wear_evolution.lua). Each takes one table of arrays, reads it with the engine's OptionReader (unknown keys,
// types and finiteness are errors naming the key) and pushes arrays.
#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "lua/guard.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/options.hpp"
#include "wrc/damage/profile_wear.hpp"

#include <string>
#include <vector>

namespace wrc::lua {
namespace {

using damage::Polyline;

// The call's table and its reader (finish() after the last key: unknown keys named).
struct KernelArgs {
  OptionTable table;
  OptionReader r;
  KernelArgs(lua_State* L, const char* ctx) : table(table_options(L, 1, ctx)), r(table, ctx) {}
  std::vector<double> need(const char* key, const char* unit, const char* help) {
    auto v = r.numbers(key, OptionDoc{unit, help});
    if (!v) fail("{}: '{}' is required (an array of numbers, {})", r.context(), key, unit);
    return std::move(*v);
  }
  ProfileKind kind() {
    return parse_profile_kind(r.choice("kind", {"wheel", "rail"}, OptionDoc{"-", "the body"}, "wheel"), r.context());
  }
};

// Pushes a kernel's results (arrays and numbers); returns their count.
void push_value(lua_State* L, const std::vector<double>& v) { push_array(L, v); }
void push_value(lua_State* L, double v) { lua_pushnumber(L, v); }
template <class... T>
int push(lua_State* L, const T&... v) {
  (push_value(L, v), ...);
  return sizeof...(T);
}

// wrc.wear.arc_length{y =, z =} -> arc (m)
int arc_length(lua_State* L) {
  KernelArgs a(L, "wrc.wear.arc_length");
  const auto y = a.need("y", "m", "points"), z = a.need("z", "m", "points");
  a.r.finish();
  return push(L, damage::arc_length(y, z));
}

// wrc.wear.cells{arc =} -> the points' cell lengths (m)
int cells(lua_State* L) {
  KernelArgs a(L, "wrc.wear.cells");
  const auto arc = a.need("arc", "m", "arc length of the points");
  a.r.finish();
  return push(L, damage::cell_lengths(arc));
}

// wrc.wear.project{y =, z =, points_y =, points_z =} -> arc, distance (m) of the nearest polyline points
int project(lua_State* L) {
  KernelArgs a(L, "wrc.wear.project");
  const auto y = a.need("y", "m", "polyline"), z = a.need("z", "m", "polyline");
  const auto py = a.need("points_y", "m", "points"), pz = a.need("points_z", "m", "points");
  a.r.finish();
  const damage::Projection p = damage::project_onto(y, z, py, pz);
  return push(L, p.arc, p.distance);
}

// wrc.wear.deposit{arc =, centre =, width =, area =} -> depth per point (m), the area beyond the ends
int deposit(lua_State* L) {
  KernelArgs a(L, "wrc.wear.deposit");
  const auto arc = a.need("arc", "m", "arc length of the points");
  const auto c = a.need("centre", "m", "strip centres (arc)"), w = a.need("width", "m", "strip widths");
  const auto area = a.need("area", "m^2", "strip areas");
  a.r.finish();
  const damage::Deposit d = damage::deposit_strips(arc, c, w, area);
  return push(L, d.depth, d.outside);
}

// wrc.wear.smooth{arc =, depth =, length =} -> depth per point (m), the area sum kept
int smooth(lua_State* L) {
  KernelArgs a(L, "wrc.wear.smooth");
  const auto arc = a.need("arc", "m", "arc length of the points"), d = a.need("depth", "m", "depth per point");
  const double length = a.r.need_number("length", OptionDoc{"m", "standard deviation of the Gaussian"});
  a.r.finish();
  return push(L, damage::smooth_depths(arc, d, length));
}

// wrc.wear.normals{y =, z =, kind =} -> ny, nz: unit normals into the body
int normals(lua_State* L) {
  KernelArgs a(L, "wrc.wear.normals");
  const auto y = a.need("y", "m", "points"), z = a.need("z", "m", "points");
  const ProfileKind kind = a.kind();
  a.r.finish();
  const damage::Normals n = damage::inward_normals(y, z, kind);
  return push(L, n.ny, n.nz);
}

// wrc.wear.move{y =, z =, depth =, kind =} -> y, z moved by depth into the body
int move(lua_State* L) {
  KernelArgs a(L, "wrc.wear.move");
  const auto y = a.need("y", "m", "points"), z = a.need("z", "m", "points");
  const auto d = a.need("depth", "m", "depth per point");
  const ProfileKind kind = a.kind();
  a.r.finish();
  const Polyline p = damage::move_along_normals(y, z, d, kind);
  return push(L, p.y, p.z);
}

// wrc.wear.area_between{y =, z =, y2 =, z2 =} -> the area between two polylines of as many points (m^2)
int area_between(lua_State* L) {
  KernelArgs a(L, "wrc.wear.area_between");
  const auto y = a.need("y", "m", "first polyline"), z = a.need("z", "m", "first polyline");
  const auto y2 = a.need("y2", "m", "second polyline"), z2 = a.need("z2", "m", "second polyline");
  a.r.finish();
  return push(L, damage::area_between(y, z, y2, z2));
}

}  // namespace

void open_wear(lua_State* L) {
  lua_newtable(L);
  const luaL_Reg funcs[] = {{"arc_length", guarded<arc_length>},     {"cells", guarded<cells>},
                            {"project", guarded<project>},           {"deposit", guarded<deposit>},
                            {"smooth", guarded<smooth>},             {"normals", guarded<normals>},
                            {"move", guarded<move>},                 {"area_between", guarded<area_between>},
                            {nullptr, nullptr}};
  luaL_setfuncs(L, funcs, 0);
  lua_setfield(L, -2, "wear");
}

}  // namespace wrc::lua
