// Cost of the damage indices (damage/damage.hpp) against the rolling solve they read: the paper's wheelset (S1002 on
// 60E1, 0.2 mm elements), the left wheel under 100 kN at 30 m/s with yaw 2 mrad and a yaw rate of 0.01 rad/s, at
// y = 0 (tread) and 6 mm (flange root). Per case: the tangential solve of the wheel's areas (add_rolling, the exact
// solver) and compute_damage of every area (Archard with the KTH map; USFD), CPU ms of one core, the median of
// `reps` runs.
//
//   bench_damage [reps=21]
#include "bench/timing.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/damage/damage.hpp"
#include "wrc/equilibrium/wheel.hpp"
#include "wrc/lua/definitions.hpp"
#include "wrc/profile/load.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <vector>

using wrc::bench::cpu_ms;
using wrc::bench::median_ms;

namespace {

}  // namespace

int main(int argc, char** argv) {
  int reps = 21;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "reps=", 5) == 0) reps = std::max(1, std::atoi(argv[i] + 5));
  const wrc::DefinitionLoader loader = wrc::lua::definition_loader();
  wrc::WheelsetProfiles profiles;
  const wrc::Profile wheel = wrc::load_profile(wrc::paths().profiles + "/s1002.lua", {}, &loader),
                    rail = wrc::load_profile(wrc::paths().profiles + "/60e1.lua", {}, &loader);
  profiles.wheel = {wheel, wheel};
  profiles.rail = {rail, rail};
  const auto ws = wrc::build_wheelset(profiles, wrc::WheelsetParams{});
  auto work = ws->make_workspace();
  wrc::RollingRequest rq;
  rq.kinematics = wrc::Kinematics{30.0, std::nullopt, 0.0, 0.01};
  rq.friction = wrc::halfspace::Friction::coulomb(0.3);
  wrc::damage::DamageOptions archard, usfd;
  usfd.wear.model = wrc::damage::WearModel::usfd;
  fmt::print("bench_damage: S1002 / 60E1, 0.2 mm, left wheel, 100 kN, 30 m/s, CPU ms (median of {})\n", reps);
  fmt::print("{:>5} {:>6} {:>9} | {:>9} {:>10} {:>8} {:>9} | {:>9} {:>9}\n", "y_mm", "areas", "contact", "rolling_ms",
             "archard_ms", "usfd_ms", "ratio", "Tgamma_N", "FI_surf");  // of the first area
  for (double y : {0.0, 6e-3}) {
    const wrc::WheelResult w =
        wrc::solve_wheel(ws->contact_model(), {wrc::kLeft, y, 2e-3, 0.0, 100e3}, *work, {}, std::nullopt, rq);
    wrc::ContactResult c;
    c.pose = {y, w.z, 0.0, 2e-3};
    c.wheel[wrc::kLeft] = w.wheel;
    long long elements = 0;
    for (const wrc::PatchContact& pc : w.wheel.patches) elements += pc.solution.elements_in_contact;
    const double t_roll = median_ms(reps, [&] { wrc::add_rolling(ws->contact_model(), c, rq, *work); });
    std::vector<wrc::damage::PatchDamage> out;
    const auto indices = [&](const wrc::damage::DamageOptions& o) {
      out.clear();
      for (const wrc::PatchContact& pc : w.wheel.patches)
        out.push_back(wrc::damage::compute_damage(wrc::area_fields(pc), o));
    };
    const double t_usfd = median_ms(reps, [&] { indices(usfd); });
    const double t_archard = median_ms(reps, [&] { indices(archard); });
    const double tgamma = out.front().Tgamma, fi = out.front().fi_surf.value_or(NAN);
    fmt::print("{:>5.1f} {:>6} {:>9} | {:>9.2f} {:>10.3f} {:>8.3f} {:>8.1f}% | {:>9.1f} {:>9.3f}\n", y * 1e3,
               w.wheel.patches.size(), elements, t_roll, t_archard, t_usfd, 100 * t_archard / t_roll,
               tgamma, fi);
  }
  return 0;
}
