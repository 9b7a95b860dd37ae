// A contact-location strategy as the engine sees it (docs/design.md, section 3): how the profiles are discretised
// into cones and lines when a wheelset is built, and which line-cone pairs are tested at each pose. The engine
// takes any implementation: the built-in strategies run natively (native_strategy, for C++ and the C API); the Lua
// binding supplies the strategies written in Lua (scripts/strategies/*.lua, or a user's file or table).
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/geometry/location.hpp"
#include "wrc/geometry/model.hpp"

#include <cmath>
#include <memory>
#include <string>

namespace wrc {

class LocationStrategy {
 public:
  virtual ~LocationStrategy() = default;
  // Name, components and options (what a worker thread needs to rebuild it; `portable` says whether it can).
  virtual const StrategyInfo& info() const = 0;
  // The profiles of one side to discretise, and the coarse level (called once per side when a wheelset is built,
  // on the building thread). Profiles are in their own left-side frames.
  virtual SideDiscretisation discretise(int side, const Profile& wheel, const Profile& rail) const = 0;
  // A per-pose search for the calling thread. Thread-safe; throws for a strategy that cannot run on another
  // thread (info().portable == false) when called from one.
  virtual std::unique_ptr<PoseSearch> make_search() const = 0;
};

// The built-in strategies, natively: "brute", "uniform", "constant_slope", "coarse", "topology", "accurate",
// "fast", or a composition "uniform+coarse+topology", with the options of their components (step, slope_step,
// max_step, coarse_every, coarse_wheel_step). They discretise and search exactly as scripts/strategies/*.lua do
// (the same engine primitives in the same order, so the same cones, lines and crossings bit for bit; a test
// compares them). `element` (m): the grid element of the wheelset it is for; a `step` not given in `options` defaults
// to its 0.1e-3 or to element when finer, as wrc.strategies.compose does: a grid finer than the discretisation
// resolves the kinks between cones and lines, and pmax then grows with the refinement instead of converging
// (docs/guide/normal.md). Throws wrc::Error naming an unknown strategy or option.
std::shared_ptr<const LocationStrategy> native_strategy(const std::string& name, const OptionTable& options = {},
                                                        double element = INFINITY);

}  // namespace wrc
