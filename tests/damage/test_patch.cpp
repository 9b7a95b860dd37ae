// The indices of whole areas against independent references: Archard's volume in full sliding on a Hertzian patch
// against k Fn |w| / H (the patch built here, and solved by the rolling solver at large creepage), the USFD volume in
// its mild regime against its closed form, the local T gamma / A against the solver's frictional power, Ekberg's
// index against the hand formula on the grid, and T gamma on the S1002 / 60E1 wheelset in rolling against the
// creep forces summed here from the traction grids.
#include "halfspace/rolling_cases.hpp"
#include "wheelset/paper_profiles.hpp"
#include "wrc/damage/damage.hpp"
#include "wrc/equilibrium/wheel.hpp"
#include "wrc/wheelset/wheelset.hpp"
#include "approx.hpp"
#include "field_recorder.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>

using wrc::test::within_rel;
using namespace wrc;
using namespace wrc::damage;

namespace {

constexpr double kA = 6e-3, kB = 4e-3, kP0 = 1.0e9;
const double kHertzForce = 2.0 / 3.0 * std::numbers::pi * kA * kB * kP0;  // N

// A Hertzian patch in full sliding built directly: the slip is the rigid slip (w_x, w_y) everywhere in the contact,
// the traction mu p against it.
struct Sliding {
  test::HertzPatch h;
  std::vector<double> px, py, sx, sy;
  AreaFields fields(double V) const {
    return {h.grid, h.pressure, px, py, sx, sy, V, {wx, wy, 0}, fx, fy, 0};
  }
  double wx = 0, wy = 0, fx = 0, fy = 0;
};

Sliding sliding(double wx, double wy, double mu, int n = 40) {
  Sliding s;
  s.h = test::hertz_patch(kA, kB, kP0, n, 0.5, 0.5);
  s.wx = wx, s.wy = wy;
  const std::size_t m = s.h.pressure.size();
  s.px.assign(m, 0), s.py.assign(m, 0), s.sx.assign(m, 0), s.sy.assign(m, 0);
  const double w = std::hypot(wx, wy), dA = s.h.grid.element_area();
  for (std::size_t k = 0; k < m; ++k)
    if (s.h.pressure[k] > 0) {
      s.sx[k] = wx, s.sy[k] = wy;
      s.px[k] = -mu * s.h.pressure[k] * wx / w, s.py[k] = -mu * s.h.pressure[k] * wy / w;
      s.fx += s.px[k] * dA, s.fy += s.py[k] * dA;
    }
  return s;
}

DamageOptions archard(std::optional<double> k = std::nullopt, double H = 2.5e9) {
  DamageOptions o;
  o.wear.k = k;
  o.wear.hardness = H;
  return o;
}

}  // namespace

TEST_CASE("Archard in full sliding on a Hertzian patch: volume per metre rolled = k Fn |w| / H within 1 %") {
  for (auto [wx, wy] : {std::pair{0.02, 0.0}, {0.0, -0.03}, {-0.012, 0.016}}) {
    CAPTURE(wx);
    CAPTURE(wy);
    const Sliding s = sliding(wx, wy, 0.3);
    const double w = std::hypot(wx, wy);
    // A constant k.
    const PatchDamage c = compute_damage(s.fields(10), archard(1e-3));
    CHECK(c.wear_volume == within_rel(1e-3 * kHertzForce * w / 2.5e9, 0.01));
    CHECK(c.wear_volume == within_rel(1e-3 * s.h.force * w / 2.5e9, 1e-12));  // with the load of the sampled pressure
    // The KTH map at V = 20 m/s: sliding at 20 |w| = 0.4 .. 0.6 m/s, p0 = 1 GPa < 0.8 H: region K3 everywhere.
    const PatchDamage m = compute_damage(s.fields(20), archard());
    CHECK(m.map);
    CHECK(m.wear_volume == within_rel(kKthSevere * kHertzForce * w / 2.5e9, 0.01));
    // At 5 m/s (0.1 .. 0.15 m/s): K2.
    CHECK(compute_damage(s.fields(5), archard()).wear_volume ==
          within_rel(kKthMildSlow * kHertzForce * w / 2.5e9, 0.01));
  }
  // The depth per passage along the central row: k p0 |w| / H times the integral of sqrt(1 - x^2/a^2) over x, i.e.
  // k p0 |w| pi a / (2 H); the deepest row is the central one.
  const Sliding s = sliding(0.02, 0, 0.3, 80);
  const PatchDamage d = compute_damage(s.fields(10), archard(1e-3));
  CHECK(d.wear_passage_max == within_rel(1e-3 * kP0 * 0.02 * std::numbers::pi * kA / (2 * 2.5e9), 0.01));
  // The seizure region: with H = 1.1 GPa the elements above 0.8 H = 0.88 GPa take K1, the rest K3 (V = 20 m/s):
  // the volume by the map's two values over the pressure integrals of the two parts, computed here.
  const PatchDamage z = compute_damage(sliding(0.02, 0, 0.3).fields(20), archard(std::nullopt, 1.1e9));
  const Sliding s40 = sliding(0.02, 0, 0.3);
  double high = 0, low = 0;
  for (double p : s40.h.pressure) (p > 0.88e9 ? high : low) += p * s40.h.grid.element_area();
  CHECK(high > 0.1 * kHertzForce);
  CHECK(z.wear_volume == within_rel((kKthSeizure * high + kKthSevere * low) * 0.02 / 1.1e9, 1e-12));
}

TEST_CASE("Archard on the rolling solver's Hertzian patch at large creepage: k Fn |xi| / H within 1 %") {
  const test::HertzPatch h = test::hertz_patch(kA, kB, kP0, 20, 0.5, 0.5);
  const halfspace::Material steel{};
  const halfspace::RollingSolver solver(steel);
  for (auto c : {halfspace::Creepages{0.05, 0, 0}, {0, -0.05, 0}, {0.03, 0.04, 0}}) {
    CAPTURE(c.xi);
    CAPTURE(c.eta);
    const halfspace::TangentialSolution t = solver.solve(test::rolling_problem(h, c, 0.3));
    REQUIRE(t.adhesion_area == 0);  // full sliding
    const AreaFields f{h.grid, h.pressure, t.px, t.py, t.sx, t.sy, 10.0, c, t.fx, t.fy, t.mz};
    const PatchDamage d = compute_damage(f, archard(1e-3));
    CHECK(d.wear_volume == within_rel(1e-3 * h.force * std::hypot(c.xi, c.eta) / 2.5e9, 0.01));
    // The local T gamma / A summed is the solver's frictional work per metre rolled (slip opposes traction).
    double sum = 0;
    for (double v : d.tgamma_density) sum += v * h.grid.element_area();
    CHECK(sum == within_rel(t.power_per_speed, 1e-9));
  }
}

TEST_CASE("T gamma of a partially slipping Hertzian patch converges to its frictional work per metre rolled") {
  // Steady rolling: the creep forces' work against the creepages is dissipated by the slip, so with one creepage
  // T gamma = |Fx xi| = sum -(p . s) dA, the solver's power per speed -- up to the upwind difference's own
  // dissipation, first order in the element: the gap halves with the element (15, 7, 3.5, 1.8 % at 10, 20, 40, 80
  // elements on b for xi = 1e-3).
  const halfspace::RollingSolver solver(halfspace::Material{});
  for (double xi : {1e-3, 3e-3}) {
    CAPTURE(xi);
    std::vector<double> gap;
    for (int n : {20, 40}) {
      const test::HertzPatch h = test::hertz_patch(kA, kB, kP0, n, 0.5, 0.5);
      const halfspace::Creepages c{xi, 0, 0};
      const halfspace::TangentialSolution t = solver.solve(test::rolling_problem(h, c, 0.3));
      REQUIRE(t.adhesion_area > 0);
      const AreaFields f{h.grid, h.pressure, t.px, t.py, t.sx, t.sy, 10.0, c, t.fx, t.fy, t.mz};
      gap.push_back(compute_damage(f, {}).Tgamma / t.power_per_speed - 1);
    }
    CHECK(gap[1] > 0);
    CHECK(gap[1] < 0.04);
    CHECK(gap[1] / gap[0] == within_rel(0.5, 0.1));
  }
}

TEST_CASE("USFD in the mild regime: volume per metre rolled = 5.3e-9 mu |w| Fn / rho") {
  // Full sliding at w = 0.02, mu = 0.3: the local T gamma / A = mu p |w| <= 6 N/mm^2, all mild.
  const Sliding s = sliding(0.02, 0, 0.3);
  DamageOptions o;
  o.wear.model = WearModel::usfd;
  const PatchDamage d = compute_damage(s.fields(10), o);
  CHECK(d.wear_coefficient.empty());
  CHECK(d.wear_volume == within_rel(5.3e-9 * 0.3 * 0.02 * kHertzForce / kSteelDensity, 0.01));
  CHECK(d.wear_volume == within_rel(5.3e-9 * 0.3 * 0.02 * s.h.force / kSteelDensity, 1e-12));  // the sampled load
  // The area's T gamma / A = |Fx| |xi| / A: mu Fn |xi| / (pi a b) = 2 mu p0 |xi| / 3 = 4 N/mm^2 (grid within 1 %).
  CHECK(d.Tgamma_per_area == within_rel(2.0 / 3.0 * 0.3 * kP0 * 0.02, 0.01));
  CHECK(d.usfd_regime == UsfdRegime::mild);
}

TEST_CASE("Ekberg's FI_surf of a patch: mu - 2 A k / (3 Fz) with the grid's contact area, about mu - k / p0") {
  const Sliding s = sliding(0.02, 0, 0.25);
  DamageOptions o;
  o.fatigue.shear_yield = 200e6;
  const PatchDamage d = compute_damage(s.fields(10), o);
  const double dA = s.h.grid.element_area();
  double area = 0, fz = 0;
  for (double p : s.h.pressure)
    if (p > 0) area += dA, fz += p * dA;
  REQUIRE(d.fi_surf);
  CHECK(d.traction_coefficient == within_rel(0.25, 1e-12));
  CHECK(*d.fi_surf == within_rel(0.25 - 2 * area * 200e6 / (3 * fz), 1e-12));
  CHECK(*d.fi_surf == within_rel(0.25 - 200e6 / kP0, 0.01));
  CHECK(d.a * d.b * std::numbers::pi == within_rel(area, 1e-12));
  CHECK(d.a / d.b == within_rel(kA / kB, 0.03));  // the extents' ratio
}

TEST_CASE("compute_damage refuses bad fields, naming them") {
  Sliding s = sliding(0.02, 0, 0.3, 6);
  const auto message = [](const AreaFields& f) {
    try {
      compute_damage(f, {});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  AreaFields f = s.fields(10);
  f.px = std::span<const double>(s.px).first(3);
  CHECK(message(f).find("px has 3 values") != std::string::npos);
  s.sy[5] = NAN;
  CHECK(message(s.fields(10)).find("the 6th value of sy (= NaN) must be finite") != std::string::npos);
  s.sy[5] = 0;
  s.h.pressure[7] = -1;
  CHECK(message(s.fields(10)).find("the 8th value of pressure (= -1) must be finite and >= 0") != std::string::npos);
  s.h.pressure[7] = 0;
  CHECK(message(s.fields(0)).find("V = 0 m/s") != std::string::npos);
  // No contact: zeros, no FI_surf, nothing not finite.
  std::fill(s.h.pressure.begin(), s.h.pressure.end(), 0.0);
  const PatchDamage none = compute_damage(s.fields(10), {});
  CHECK(!none.fi_surf);
  CHECK(none.wear_volume == 0);
  CHECK(none.Tgamma_per_area == 0);
}

TEST_CASE("describe(PatchDamage): every field documented, values as computed") {
  const Sliding s = sliding(0.02, 0, 0.3, 10);
  for (WearModel model : {WearModel::archard, WearModel::usfd}) {
    DamageOptions o;
    o.wear.model = model;
    const PatchDamage d = compute_damage(s.fields(10), o);
    const auto rec = test::field_paths(d);
    CHECK(rec.finite);
    std::size_t fields = rec.nums.size() + rec.strs.size() + rec.arrays.size();
    CHECK(rec.docs.size() == fields);
    for (const auto& [key, doc] : rec.docs) {
      CAPTURE(key);
      CHECK(std::string(doc.meaning).size() > 3);
    }
    CHECK(rec.nums.at("Tgamma") == d.Tgamma);
    CHECK(rec.nums.at("wear_volume") == d.wear_volume);
    CHECK(rec.nums.at("fi_surf") == *d.fi_surf);
    CHECK(rec.arrays.at("wear_passage") == static_cast<std::size_t>(s.h.grid.ny));
    CHECK(rec.arrays.at("wear_depth") == static_cast<std::size_t>(s.h.grid.size()));
    CHECK(rec.arrays.count("wear_coefficient") == (model == WearModel::archard ? 1u : 0u));
    CHECK(std::string(rec.docs.at("wear_volume").unit) == "m^3/m");
    CHECK(std::string(rec.docs.at("Tgamma").unit) == "N");
  }
}

TEST_CASE("T gamma on S1002 / 60E1 in rolling: |Fx xi| + |Fy eta| (+ |Mz phi|) of the traction grids summed here") {
  WheelsetParams params;
  params.contact.element = 0.5e-3;
  for (ContactSurface surface : {ContactSurface::conformal, ContactSurface::planar}) {
    params.contact.surface = surface;
    const auto ws = build_wheelset(test::paper_profiles(), params);
    auto work = ws->make_workspace();
    RollingRequest rq;
    rq.kinematics = Kinematics{30.0, std::nullopt, 0.0, 0.01};  // yaw rate: lateral creepage and more spin
    rq.friction = halfspace::Friction::coulomb(0.3);
    for (double y : {0.0, 6e-3}) {
      CAPTURE(y);
      const WheelResult w = solve_wheel(ws->contact_model(), {kLeft, y, 2e-3, 0.0, 100e3}, *work, {}, std::nullopt, rq);
      REQUIRE(!w.wheel.patches.empty());
      for (const PatchContact& pc : w.wheel.patches) {
        const PatchRolling& r = *pc.rolling;
        const halfspace::TangentialSolution& t = r.solution;
        const halfspace::Grid& g = t.grid;
        double fx = 0, fy = 0;
        for (std::size_t k = 0; k < t.px.size(); ++k) fx += t.px[k] * g.element_area(), fy += t.py[k] * g.element_area();
        const PatchDamage d = compute_damage(area_fields(pc), {});
        const halfspace::Creepages& c = r.creepage;
        CHECK(std::abs(fx * c.xi) + std::abs(fy * c.eta) > 1);  // a case with creep work
        CHECK(d.Tgamma == within_rel(std::abs(fx * c.xi) + std::abs(fy * c.eta), 1e-9));
        CHECK(d.Tgamma_spin - d.Tgamma == within_rel(std::abs(r.mz * c.phi), 1e-9));
        CHECK(d.Tgamma_spin > d.Tgamma);
        CHECK(d.normal_force == within_rel(pc.solution.force, 1e-12));
        // The work dissipated by the slip is the creep forces' work against the rigid slip, which varies
        // across the area beyond the linear field: within a few % of sum -(p . w) over the elements.
        double work_rigid = 0, dissipated = 0;
        for (std::size_t k = 0; k < t.px.size(); ++k) {
          work_rigid -= (t.px[k] * r.rigid_x[k] + t.py[k] * r.rigid_y[k]) * g.element_area();
          dissipated += d.tgamma_density[k] * g.element_area();
        }
        CHECK(dissipated == within_rel(t.power_per_speed, 1e-9));
        // The fields sit beside the area's own (p.Tgamma, p.wear_volume), which the area's description holds (the
        // solve filled them): each once, no name in common with the area's own.
        DamageOptions no_wear;
        no_wear.with_wear = false;
        auto area_rec = test::field_paths(pc);
        auto damage_rec = test::field_paths(compute_damage(area_fields(pc), no_wear));
        const auto wear_rec = test::field_paths(d);
        for (const auto& [key, doc] : damage_rec.docs) {
          CAPTURE(key);
          CHECK(area_rec.emitted[key] == 1);
        }
        for (const auto& [key, doc] : wear_rec.docs) {
          CAPTURE(key);
          CHECK(area_rec.emitted[key] == damage_rec.emitted[key]);
        }
        CHECK(area_rec.nums.at("Tgamma") == d.Tgamma);
        CHECK(area_rec.nums.count("wear_volume") == 0);  // no wear model asked of the solve
        MESSAGE(fmt::format("y = {} mm: Tgamma {:.2f} N, spin {:.2f} N, rigid work {:.2f} N, dissipated {:.2f} N, "
                            "wear {:.3e} m^3/m, FI {:.3f}",
                            y * 1e3, d.Tgamma, d.Tgamma_spin, work_rigid, dissipated, d.wear_volume, d.fi_surf.value_or(0)));
      }
    }
  }
}
