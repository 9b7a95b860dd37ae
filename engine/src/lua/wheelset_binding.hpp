// The wrc.Wheelset userdata, shared by the parts of the binding that work on a wheelset (wheelset_binding.cpp:
// construction, geometry, ws:locate; contact_binding.cpp: ws:contact, ws:equilibrium, ws:wheel, ws:rigid, ws:sweep).
#pragma once

#include "lua/lua.hpp"
#include "lua/strategy_binding.hpp"
#include "wrc/contact/wheelset_contact.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/geometry/model.hpp"
#include "wrc/geometry/track.hpp"

#include <memory>

namespace wrc::lua {

extern const char* const kWheelsetType;  // "wrc.Wheelset"

struct Wheelset {
  std::shared_ptr<const Track> track;
  std::shared_ptr<const GeometryModel> model;
  std::shared_ptr<const ContactModel> contact;  // geometry + material + normal solver
  std::unique_ptr<LuaSearch> search;  // the strategy's locate, in the state that built the wheelset
  LocationState state;                // the last pose located by ws:locate
  bool located = false;
  std::unique_ptr<ContactWorkspace> workspace;  // the calling thread's (lazily made; uses `search`)
};

// "left" / "right" at stack index idx -> kLeft / kRight (error naming `what` otherwise).
int check_side_arg(lua_State* L, int idx, const char* what);

// A located patch as a table (side, nominal_point, nominal_normal, wheel_point, cone, eps, wheel_radius, depth,
// first_line, last_line, longest, segments) on the top of the stack; contact_binding.cpp adds the normal-contact
// fields to the same table.
void push_patch(lua_State* L, const LocationState& st, const Patch& p);
void push_segment(lua_State* L, const Segment& s);

void open_contact(lua_State* L);  // registers the contact methods on wrc.Wheelset (after open_wheelset made it)

}  // namespace wrc::lua
