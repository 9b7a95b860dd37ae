// Location strategies written in Lua (scripts/strategies/*.lua, a user's file or an inline table; docs/design.md,
// section 3): LuaStrategy is the engine's LocationStrategy for them. `strategy = ...` is resolved by
// wrc.strategies.compose into a table with discretise(d) and locate(ctx, side); discretise runs when the wheelset
// is built, locate per pose with a SearchContext userdata whose primitives (ctx:test, ctx:walk, ...) are native.
//
// Threads: a strategy chosen by name (or a list of names, with options) is rebuilt in another Lua state from its
// StrategyInfo, so make_search() on a worker thread makes a fresh state running it. An inline table lives in the
// state that built the wheelset and runs only there (StrategyInfo::portable = false).
#pragma once

#include "lua/lua.hpp"
#include "wrc/geometry/strategy.hpp"

#include <memory>
#include <string>

namespace wrc::lua {

// A PoseSearch that calls a strategy's `locate(ctx, side)` in a Lua state.
class LuaSearch final : public PoseSearch {
 public:
  // Takes the strategy table on the top of L's stack (popped). If `owns_state`, lua_close(L) on destruction.
  LuaSearch(lua_State* L, bool owns_state);
  ~LuaSearch() override;
  LuaSearch(const LuaSearch&) = delete;
  LuaSearch& operator=(const LuaSearch&) = delete;
  // The thread (coroutine) of the same Lua state to run in for the next calls.
  void set_thread(lua_State* L) { L_ = L; }
  // Drops the registry references (for a search that does not own its state, before the state closes).
  void release(lua_State* L);
  void search(SearchContext& ctx, int side) override;

 private:
  lua_State* L_;
  int locate_ref_ = LUA_NOREF, ctx_ref_ = LUA_NOREF;
  bool owns_;
};

class LuaStrategy final : public LocationStrategy {
 public:
  // Resolves the `strategy` value at stack index idx of L (the building state) with wrc.strategies.compose, for a
  // wheelset whose grid element is `element` (m): a default `step` is no coarser (native_strategy's rule).
  LuaStrategy(lua_State* L, int idx, double element);
  const StrategyInfo& info() const override { return info_; }
  // Runs the table's discretise in the building state (called while the wheelset is built, on its thread).
  SideDiscretisation discretise(int side, const Profile& wheel, const Profile& rail) const override;
  // Portable: a fresh Lua state running the strategy. Otherwise the building state's search (that thread only).
  std::unique_ptr<PoseSearch> make_search() const override;
  // The building state's search, bound to the calling coroutine L of that state.
  PoseSearch& main_search(lua_State* L);
  // Drops the references into the building state (before it closes).
  void release(lua_State* L);

 private:
  lua_State* L_;       // the building state (discretise)
  int table_ref_ = LUA_NOREF;
  StrategyInfo info_;
  std::unique_ptr<LuaSearch> main_;
};

// A search running the strategy described by `info` in the state L of the calling thread (made with new_state());
// L must outlive the search. Throws for a non-portable strategy.
std::unique_ptr<LuaSearch> make_lua_search(lua_State* L, const StrategyInfo& info);

// wrc.geometry: strategy helpers (constant_slope, offset_outward, cell_dilation) and the SearchContext type.
void open_geometry(lua_State* L);

}  // namespace wrc::lua
