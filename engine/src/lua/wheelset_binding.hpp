// The wrc.Wheelset userdata: the engine's wheelset model, its Lua strategy and the building state's workspace.
#pragma once

#include "lua/lua.hpp"
#include "lua/strategy_binding.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <array>
#include <memory>

namespace wrc::lua {

extern const char* const kWheelsetType;  // "wrc.Wheelset"

struct LuaWheelset {
  std::shared_ptr<const Wheelset> model;
  std::shared_ptr<LuaStrategy> strategy;        // the model's, as the binding sees it
  std::unique_ptr<ContactWorkspace> workspace;  // for calls from the building state (made on first use)
  std::array<long long, 2> last_tests{-1, -1};  // closed-form tests of the last ws:locate, per side
  // Whether a result's under-resolved contact area was shown (once per wheelset, its trajectories and sweeps included)
  std::shared_ptr<bool> resolution_shown = std::make_shared<bool>(false);
};

// The wheelset model of the wrc.Wheelset at stack index idx (an error naming `context` otherwise).
std::shared_ptr<const Wheelset> check_wheelset(lua_State* L, int idx, const char* context);

}  // namespace wrc::lua
