// Discretisation strategies written in Lua (scripts/strategies/*.lua, DESIGN.md section 1): resolving a
// `strategy = ...` value into a strategy table, running its `discretise` at model build and its `locate` per pose.
//
// Threads: a strategy chosen by name (or by a list of names, with options) is rebuilt in any Lua state from its
// StrategyInfo, so a worker thread with its own state (new_state()) can run it: make_lua_search(L, model), or
// model.strategy.make_search() which creates a fresh state. An inline strategy table lives in the state that
// built the wheelset and runs only there (StrategyInfo::portable = false).
#pragma once

#include "lua/lua.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/geometry/model.hpp"

#include <memory>
#include <string>

namespace wrc::lua {

// A PoseSearch that calls the strategy's `locate(ctx, side)` in a Lua state.
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

// Resolves the strategy value at stack index idx (nil: the default strategy) by calling
// require("wrc.strategies.compose").resolve(value); pushes the strategy table and returns its description.
// The returned info has no make_search yet (see attach_search_factory).
StrategyInfo resolve_strategy(lua_State* L, int idx);

// Pushes the strategy table for `info` rebuilt in L (by name and options). Throws for a non-portable strategy.
void push_strategy(lua_State* L, const StrategyInfo& info);

// Sets info.make_search to a factory creating, per call, a new Lua state running the strategy (portable ones).
void attach_search_factory(StrategyInfo& info);

// A search running the model's strategy in the worker's own state L (created with new_state()); L must outlive
// the search and be used by one thread.
std::unique_ptr<LuaSearch> make_lua_search(lua_State* L, const GeometryModel& model);

// The geometry model of the wrc.Wheelset at stack index idx (throws if it is not one).
std::shared_ptr<const GeometryModel> wheelset_model(lua_State* L, int idx);

// wrc.geometry: strategy helpers (constant_slope, offset_outward, cell_dilation) and the SearchContext type.
void open_geometry(lua_State* L);

}  // namespace wrc::lua
