// The built-in location strategies, natively (strategy.hpp). Each mirrors a module of scripts/strategies/: what
// its discretise does, whether it makes coarse windows, and how it scans; compositions expand as compose.lua does.
#include "wrc/geometry/strategy.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {
namespace {

enum class Scan { none, test, walk };

struct Component {
  std::string name;
  std::vector<std::pair<std::string, double>> defaults;
  std::vector<std::string> uses;  // what the name means alone (or always, for a pure alias)
  bool discretises = false, windows = false;
  Scan scan = Scan::none;
  bool is_component() const { return discretises || windows || scan != Scan::none; }
};

const std::vector<Component>& components() {
  static const std::vector<Component> all = {
      {"brute", {}, {}, false, false, Scan::test},
      {"uniform", {{"step", 0.1e-3}}, {}, true, false, Scan::test},
      {"constant_slope", {{"step", 0.1e-3}, {"slope_step", ConstantSlope{}.slope_step}, {"max_step", ConstantSlope{}.max_step}},
       {}, true, false, Scan::test},
      {"coarse", {{"coarse_every", 16}, {"coarse_wheel_step", 2e-3}}, {"uniform", "coarse"}, true, true, Scan::none},
      {"topology", {}, {"uniform", "topology"}, false, false, Scan::walk},
      {"accurate", {}, {"uniform", "coarse", "topology"}},
      {"fast", {}, {"constant_slope", "coarse", "topology"}},
  };
  return all;
}

const Component& component(const std::string& name) {
  for (const Component& c : components())
    if (c.name == name) return c;
  std::vector<std::string> names;
  for (const Component& c : components()) names.push_back(c.name);
  const std::string near = closest_name(name, names);
  fail("unknown strategy '{}'{} (the built-in strategies: brute, uniform, constant_slope, coarse, topology, "
       "accurate, fast, or a composition such as uniform+coarse+topology)",
       name, near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near));
}

// compose.lua's expand: a pure alias always expands; a component with `uses` expands only when named alone.
void expand(const std::vector<std::string>& names, std::vector<const Component*>& out, int depth, bool alone) {
  for (const auto& n : names) {
    const Component& c = component(n);
    if (!c.uses.empty() && (!c.is_component() || alone) && depth < 8) expand(c.uses, out, depth + 1, false);
    else out.push_back(&c);
  }
}

std::vector<std::string> split_plus(const std::string& name) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t p = name.find('+', start);
    parts.push_back(name.substr(start, p == std::string::npos ? std::string::npos : p - start));
    if (p == std::string::npos) return parts;
    start = p + 1;
  }
}

class NativeStrategy final : public LocationStrategy {
 public:
  NativeStrategy(const std::string& name, const OptionTable& user, double element) {
    const std::vector<std::string> names = split_plus(name);
    expand(names, comps_, 0, names.size() == 1);
    info_.name = name;
    info_.components = names;
    info_.portable = true;
    OptionReader r(user, fmt::format("strategy '{}'", name));
    for (const Component* c : comps_) {
      for (const auto& [key, fallback] : c->defaults) {
        if (info_.options.count(key)) continue;
        info_.options[key] = r.number(key, key == "step" ? std::min(fallback, element) : fallback);
      }
      if (c->windows) plan_.coarse = true;
      if (c->scan != Scan::none) plan_.scan = c->scan == Scan::walk ? NativePlan::Scan::walk : NativePlan::Scan::test;
    }
    r.finish();
  }

  const StrategyInfo& info() const override { return info_; }

  SideDiscretisation discretise(int, const Profile& wheel, const Profile& rail) const override {
    SideDiscretisation d;
    d.wheel = wheel;
    d.rail = rail;
    for (const Component* c : comps_) {
      if (c->name == "uniform") {
        d.wheel = resample_arc(d.wheel, option("step"));
        d.rail = resample_arc(d.rail, option("step"));
      } else if (c->name == "constant_slope") {
        d.wheel = resample_constant_slope(d.wheel, option("slope_step"), option("max_step"));
        d.rail = resample_arc(d.rail, option("step"));
      } else if (c->name == "coarse") {
        const double every = option("coarse_every");
        if (every != std::floor(every) || every < 2) fail("strategy '{}': coarse_every must be an integer >= 2, got {}", info_.name, every);
        d.coarse_every = static_cast<int>(every);
        d.coarse_wheel = offset_outward(d.wheel, cell_dilation(d.rail, d.coarse_every), d.coarse_wheel_step);
      }
    }
    return d;
  }

  std::unique_ptr<PoseSearch> make_search() const override { return std::make_unique<NativeSearch>(plan_); }

 private:
  double option(const std::string& key) const { return std::get<double>(info_.options.at(key)); }
  std::vector<const Component*> comps_;
  StrategyInfo info_;
  NativePlan plan_{false, NativePlan::Scan::test};
};

}  // namespace

std::shared_ptr<const LocationStrategy> native_strategy(const std::string& name, const OptionTable& options,
                                                        double element) {
  return std::make_shared<const NativeStrategy>(name, options, element);
}

}  // namespace wrc
