// The damage area's piecewise functions at points in every range, each expected value evaluated by hand from the
// published tables (the numbers written out here, in the sources' own units), and the options' reading and checks.
#include "wrc/damage/damage.hpp"
#include "approx.hpp"

#include <doctest/doctest.h>

#include <map>
#include <numbers>
#include <string>

using wrc::test::within_rel;
using namespace wrc;
using namespace wrc::damage;

namespace {

std::string error_of(const auto& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("KTH wear map: k in each of Jendel's four regions, with their limits") {
  const double H = 2.5e9;  // 0.8 H = 2.0 GPa
  CHECK(kth_wear_coefficient(2.1e9, 0.05, H) == 350e-4);  // K1, p > 0.8 H, whatever the speed
  CHECK(kth_wear_coefficient(2.1e9, 1.5, H) == 350e-4);
  CHECK(kth_wear_coefficient(1.0e9, 0.1, H) == 5.5e-4);   // K2, below 0.2 m/s
  CHECK(kth_wear_coefficient(1.0e9, 0.5, H) == 35e-4);    // K3
  CHECK(kth_wear_coefficient(1.0e9, -0.5, H) == 35e-4);   // the speed's magnitude
  CHECK(kth_wear_coefficient(1.0e9, 0.2, H) == 35e-4);    // K3 includes both ends
  CHECK(kth_wear_coefficient(1.0e9, 0.7, H) == 35e-4);
  CHECK(kth_wear_coefficient(1.0e9, 0.7001, H) == 5.5e-4);  // K4
  CHECK(kth_wear_coefficient(2.0e9, 0.5, H) == 35e-4);      // p = 0.8 H exactly: not yet K1
}

TEST_CASE("USFD wear function: the rate in each regime against the published lines in ug/(m mm^2)") {
  const double to_si = 1e-3;  // 1 ug/(m mm^2) = 1e-9 kg / (1 m x 1e-6 m^2)
  CHECK(usfd_wear_rate(5e6) == within_rel(5.3 * 5 * to_si, 1e-14));   // mild: 26.5
  CHECK(usfd_regime(5e6) == UsfdRegime::mild);
  CHECK(usfd_wear_rate(10.3e6) == within_rel(54.59 * to_si, 1e-13));
  CHECK(usfd_wear_rate(10.4e6) == within_rel(55.0 * to_si, 1e-12));  // severe from 10.4 on
  CHECK(usfd_regime(10.4e6) == UsfdRegime::severe);
  CHECK(usfd_wear_rate(40e6) == within_rel(55.0 * to_si, 1e-12));
  CHECK(usfd_wear_rate(77.2e6) == within_rel(55.0 * to_si, 1e-12));
  CHECK(usfd_regime(77.3e6) == UsfdRegime::catastrophic);
  CHECK(usfd_wear_rate(77.3e6) == within_rel((61.9 * 77.3 - 4778.7) * to_si, 1e-9));  // 6.17
  CHECK(usfd_wear_rate(77.2001e6) == 0);  // the line's -0.02 at the transition: no negative wear
  CHECK(usfd_wear_rate(100e6) == within_rel(1411.3 * to_si, 1e-12));
  CHECK(usfd_wear_rate(0) == 0);
}

TEST_CASE("Burstow's damage function: zero, rising, falling, zero at 15, 65 and 175 N") {
  CHECK(burstow_damage(0) == 0);
  CHECK(burstow_damage(14.9) == 0);
  CHECK(burstow_regime(14.9) == BurstowRegime::none);
  CHECK(burstow_damage(15) == 0);
  CHECK(burstow_damage(40) == within_rel(25e-6, 1e-13));  // (40 - 15) x 1e-6
  CHECK(burstow_regime(40) == BurstowRegime::rcf);
  CHECK(burstow_damage(65) == within_rel(50e-6, 1e-13));
  CHECK(burstow_damage(120) == within_rel(25e-6, 1e-13));  // 5e-5 x 55 / 110
  CHECK(burstow_regime(120) == BurstowRegime::rcf_and_wear);
  CHECK(burstow_damage(174) == within_rel(5e-5 / 110, 1e-12));
  CHECK(burstow_damage(175) == 0);
  CHECK(burstow_regime(175) == BurstowRegime::wear);
  CHECK(burstow_damage(400) == 0);
  // Another rail grade's function: threshold 20, peak 80 at 2e-5, limit 200.
  const BurstowFunction f{20, 80, 200, 2e-5};
  CHECK(burstow_damage(50, f) == within_rel(1e-5, 1e-13));
  CHECK(burstow_damage(140, f) == within_rel(1e-5, 1e-13));
}

TEST_CASE("T gamma and Ekberg's FI_surf against hand computations") {
  const halfspace::Creepages c{-2e-3, 1e-3, 0.5};
  CHECK(tgamma(12e3, -4e3, c) == within_rel(24 + 4, 1e-14));
  CHECK(tgamma_spin(12e3, -4e3, -30, c) == within_rel(24 + 4 + 15, 1e-14));
  // Hertz: 2 pi a b / (3 Fz) = 1 / p0, so FI_surf = mu - k / p0: 0.3 - 300 / 1200.
  const double a = 6e-3, b = 4e-3, p0 = 1.2e9, fz = 2.0 / 3.0 * std::numbers::pi * a * b * p0;
  CHECK(surface_fatigue_index(0.3, a, b, 300e6, fz) == within_rel(0.05, 1e-13));
  CHECK(surface_fatigue_index(0.2, a, b, 300e6, fz) == within_rel(-0.05, 1e-13));
}

TEST_CASE("damage options: defaults, reading, and errors that name the key") {
  OptionTable none;
  OptionReader r0(none, "ws:contact");
  const DamageOptions d = read_damage_options(r0);
  CHECK(d.wear.model == WearModel::archard);
  CHECK(!d.wear.k);
  CHECK(d.wear.hardness == kDefaultHardness);
  CHECK(d.fatigue.shear_yield == halfspace::kDefaultShearYield);
  CHECK(d.fatigue.burstow.peak == 65);

  OptionTable wear, fatigue, call;
  wear.set("model", OptionValue::of(std::string("usfd"))).set("density", OptionValue::of(7800.0));
  fatigue.set("shear_yield", OptionValue::of(350e6)).set("threshold", OptionValue::of(20.0));
  call.set("wear", OptionValue::of(wear)).set("fatigue", OptionValue::of(fatigue));
  OptionReader r1(call, "ws:contact");
  const DamageOptions o = read_damage_options(r1);
  r1.finish();
  o.validate();
  CHECK(o.wear.model == WearModel::usfd);
  CHECK(o.wear.density == 7800);
  CHECK(o.fatigue.shear_yield == 350e6);
  CHECK(o.fatigue.burstow.threshold == 20);

  const auto read = [](OptionTable w) {
    OptionTable t;
    t.set("wear", OptionValue::of(std::move(w)));
    OptionReader r(t, "ws:contact");
    read_damage_options(r).validate();
  };
  CHECK(error_of([&] { read(OptionTable{}.set("model", OptionValue::of(std::string("lewis")))); })
            .find("archard") != std::string::npos);
  const std::string k_usfd = error_of([&] {
    read(OptionTable{}.set("model", OptionValue::of(std::string("usfd"))).set("k", OptionValue::of(1e-3)));
  });
  CHECK(k_usfd.find("'k' belongs to the archard model") != std::string::npos);
  CHECK(error_of([&] { read(OptionTable{}.set("density", OptionValue::of(7800.0))); })
            .find("'density' belongs to the usfd model") != std::string::npos);
  CHECK(error_of([&] { read(OptionTable{}.set("k", OptionValue::of(2.0))); }).find("ws:contact: 'wear': k = 2 must be in ]0, 1]") != std::string::npos);
  CHECK(error_of([&] { read(OptionTable{}.set("hardness", OptionValue::of(-1.0))); })
            .find("hardness = -1 Pa") != std::string::npos);
  CHECK(error_of([&] { read(OptionTable{}.set("hardnes", OptionValue::of(2e9))); }).find("'hardness'") !=
        std::string::npos);
  FatigueOptions bad;
  bad.burstow.peak = 10;
  CHECK(error_of([&] { bad.validate(); }).find("threshold < peak < limit") != std::string::npos);
}

TEST_CASE("damage options: a documenting reader records every key with its unit") {
  std::vector<OptionInfo> keys;
  OptionReader r = OptionReader::documenting("ws:contact", keys);
  read_damage_options(r);
  std::map<std::string, std::string> unit;
  for (const OptionInfo& k : keys) unit[k.key] = k.unit;
  CHECK(unit.at("wear.model") == "-");
  CHECK(unit.at("wear.k") == "-");
  CHECK(unit.at("wear.hardness") == "Pa");
  CHECK(unit.at("wear.density") == "kg/m^3");
  CHECK(unit.at("fatigue.shear_yield") == "Pa");
  CHECK(unit.at("fatigue.peak_damage") == "-");
}
