#include "wrc/damage/damage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

namespace wrc::damage {

void DamageOptions::validate() const {
  wear.validate();
  fatigue.validate();
}

DamageOptions read_damage_options(OptionReader& r) {
  DamageOptions o;
  o.with_wear = false;
  if (auto w = r.table("wear", {"-", "the wear model: {model = \"archard\" | \"usfd\", k, hardness, density}"})) {
    o.wear = read_wear_options(*w);
    o.with_wear = true;
    w->finish();
  }
  if (auto f = r.table("fatigue", {"-", "the fatigue indices: {shear_yield, threshold, peak, limit, peak_damage}"})) {
    o.fatigue = read_fatigue_options(*f);
    f->finish();
  }
  return o;
}

namespace {

// Whether every value is finite (and >= 0 with `nonnegative`); the message's search runs only when one is not.
bool all_valid(std::span<const double> v, bool nonnegative) {
  bool ok = true;
  for (double x : v) ok &= std::isfinite(x) && !(nonnegative && x < 0);
  return ok;
}

void check(const AreaFields& f, FieldCheck how) {
  halfspace::validate(f.grid, "damage");
  const auto n = static_cast<std::size_t>(f.grid.size());
  for (auto [name, v] : {std::pair<std::string_view, std::span<const double>>{"pressure", f.pressure}, {"px", f.px},
                         {"py", f.py}, {"sx", f.sx}, {"sy", f.sy}}) {
    if (v.size() != n) fail("damage: {} has {} values; the {} x {} grid needs {}", name, v.size(), f.grid.nx, f.grid.ny, n);
    const bool pressure = name == "pressure";
    if (how == FieldCheck::sizes) continue;
    if (all_valid(v, pressure)) continue;
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(v[k]) || (pressure && v[k] < 0))
        fail("damage: {} (= {}) must be finite{}", value_at(k, name), v[k], pressure ? " and >= 0" : "");
  }
  if (!(std::isfinite(f.V) && f.V != 0)) fail("damage: V = {} m/s must be finite and != 0", f.V);
  for (auto [name, v] : {std::pair{"xi", f.creepage.xi}, {"eta", f.creepage.eta}, {"phi", f.creepage.phi},
                         {"Fx", f.fx}, {"Fy", f.fy}, {"Mz", f.mz}})
    if (!std::isfinite(v)) fail("damage: {} = {} must be finite", name, v);
}

// Wear per element and per row (wear.hpp): rate d (m/m), Archard's k, the local T gamma / A.
void add_wear(const AreaFields& f, const WearOptions& w, PatchDamage& d) {
  const halfspace::Grid& g = f.grid;
  const auto n = static_cast<std::size_t>(g.size());
  const double speed = std::abs(f.V);
  d.wear = true;
  d.wear_depth.assign(n, 0.0);
  d.tgamma_density.assign(n, 0.0);
  if (w.model == WearModel::archard) d.wear_coefficient.assign(n, 0.0);
  d.wear_passage.assign(static_cast<std::size_t>(g.ny), 0.0);
  for (int j = 0; j < g.ny; ++j) {
    double row = 0;
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(g.index(i, j));
      const double p = f.pressure[k];
      if (p <= 0) continue;
      const double slip = std::hypot(f.sx[k], f.sy[k]);
      d.tgamma_density[k] = std::abs(f.px[k] * f.sx[k]) + std::abs(f.py[k] * f.sy[k]);
      double rate;
      if (w.model == WearModel::archard) {
        const double c = w.k ? *w.k : kth_wear_coefficient(p, speed * slip, w.hardness);
        d.wear_coefficient[k] = c;
        rate = c * p * slip / w.hardness;
      } else {
        rate = usfd_wear_rate(d.tgamma_density[k]) / w.density;
      }
      d.wear_depth[k] = rate;
      row += rate;
    }
    d.wear_passage[static_cast<std::size_t>(j)] = row * g.dx;
    d.wear_volume += row * g.element_area();
  }
  d.wear_passage_max = d.wear_passage.empty() ? 0.0 : *std::max_element(d.wear_passage.begin(), d.wear_passage.end());
}

// One pass over the pressure: the normal force, the contact area and the extents of the contact elements along x
// and y (m).
struct Contact {
  double force = 0, area = 0, lx = 0, ly = 0;
};
Contact contact_of(const AreaFields& f) {
  const halfspace::Grid& g = f.grid;
  int i0 = g.nx, i1 = -1, j0 = g.ny, j1 = -1, count = 0;
  double sum = 0;
  for (int j = 0; j < g.ny; ++j) {
    const double* row = f.pressure.data() + static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(j);
    int first = -1, last = -1;
    for (int i = 0; i < g.nx; ++i)
      if (row[i] > 0) {
        sum += row[i];
        ++count;
        if (first < 0) first = i;
        last = i;
      }
    if (first < 0) continue;
    i0 = std::min(i0, first), i1 = std::max(i1, last), j0 = std::min(j0, j), j1 = j;
  }
  if (count == 0) return {};
  return {sum * g.element_area(), count * g.element_area(), (i1 - i0 + 1) * g.dx, (j1 - j0 + 1) * g.dy};
}

void add_fatigue(const AreaFields& f, const FatigueOptions& o, const Contact& c, PatchDamage& d) {
  d.rcf_damage = burstow_damage(d.Tgamma, o.burstow);
  d.rcf_regime = burstow_regime(d.Tgamma, o.burstow);
  d.shear_yield = o.shear_yield;
  if (!(d.normal_force > 0)) return;
  d.traction_coefficient = std::hypot(f.fx, f.fy) / d.normal_force;
  const double ab = d.contact_area / std::numbers::pi;
  d.a = std::sqrt(ab * c.lx / c.ly);
  d.b = std::sqrt(ab * c.ly / c.lx);
  d.fi_surf = surface_fatigue_index(d.traction_coefficient, d.a, d.b, o.shear_yield, d.normal_force);
}

}  // namespace

PatchDamage compute_damage(const AreaFields& f, const DamageOptions& options, FieldCheck how) {
  check(f, how);
  options.validate();
  PatchDamage d;
  d.grid = f.grid;
  d.model = options.wear.model;
  d.map = d.model == WearModel::archard && !options.wear.k;
  d.Tgamma = tgamma(f.fx, f.fy, f.creepage);
  d.Tgamma_spin = tgamma_spin(f.fx, f.fy, f.mz, f.creepage);
  const Contact c = contact_of(f);
  d.normal_force = c.force;
  d.contact_area = c.area;
  if (d.contact_area > 0) d.Tgamma_per_area = d.Tgamma / d.contact_area;
  d.usfd_regime = usfd_regime(d.Tgamma_per_area);
  if (options.with_wear) add_wear(f, options.wear, d);
  add_fatigue(f, options.fatigue, c, d);
  return d;
}

namespace {

void describe_wear(const PatchDamage& d, FieldSink& out) {
  const int nx = d.grid.nx, ny = d.grid.ny;
  out.string("wear_model", model_name(d.model), {"", "\"archard\" or \"usfd\" (the call's wear.model; with wear)"});
  if (d.model == WearModel::archard)
    out.boolean("wear_map", d.map, {"", "true: Archard's k by the KTH map; false: a constant k"});
  else
    out.string("usfd_regime", regime_name(d.usfd_regime), {"", "mild, severe or catastrophic at Tgamma_per_area"});
  out.number("wear_volume", d.wear_volume, {"m^3/m", "volume worn off per metre rolled: sum of wear_depth dA (with wear)"});
  out.number("wear_passage_max", d.wear_passage_max, {"m", "the largest of wear_passage"});
  if (!d.wear_passage.empty())  // a sweep's rows = true keeps it without the grids
    out.numbers("wear_passage", d.wear_passage.data(), d.wear_passage.size(),
                {"m", "per grid row: depth worn off in one passage through the area, sum of wear_depth dx"});
  if (d.wear_depth.empty()) return;  // grids dropped
  out.grid("wear_depth", d.wear_depth.data(), nx, ny,
           {"m/m", "per element: depth worn off per metre rolled while the material is in the element"});
  if (d.model == WearModel::archard)
    out.grid("wear_coefficient", d.wear_coefficient.data(), nx, ny, {"-", "per element: Archard's k (0 outside)"});
  out.grid("tgamma_density", d.tgamma_density.data(), nx, ny,
           {"Pa", "per element: |px sx| + |py sy|, the local T gamma / A (power density / |V|)"});
}

}  // namespace

void drop_grids(PatchDamage& d, bool keep_rows) {
  d.wear_depth = {};
  if (!keep_rows) d.wear_passage = {};
  d.wear_coefficient = {};
  d.tgamma_density = {};
}

void describe(const PatchDamage& d, FieldSink& out) {
  out.number("Tgamma", d.Tgamma, {"N", "|Fx xi| + |Fy eta|: frictional work per metre rolled (J/m)"});
  out.number("Tgamma_spin", d.Tgamma_spin, {"N", "Tgamma + |Mz phi|"});
  out.number("Tgamma_per_area", d.Tgamma_per_area, {"Pa", "Tgamma / contact area (USFD's T gamma / A; N/m^2)"});
  if (d.wear) describe_wear(d, out);
  out.number("rcf_damage", d.rcf_damage, {"-", "Burstow's RCF damage of the rail per passage, from Tgamma"});
  out.string("rcf_regime", regime_name(d.rcf_regime), {"", "none, rcf, rcf and wear, or wear (Burstow's ranges)"});
  out.number("traction_coefficient", d.traction_coefficient, {"-", "|(Fx, Fy)| / (sum of p dA)"});
  out.number("fi_a", d.a, {"m", "FI_surf's semi-axis along x: pi a b = contact area, a / b the extents' ratio"});
  out.number("fi_b", d.b, {"m", "FI_surf's semi-axis along y"});
  out.number("shear_yield", d.shear_yield, {"Pa", "k of Ekberg's FI_surf"});
  if (d.fi_surf)
    out.number("fi_surf", *d.fi_surf, {"-", "Ekberg's FI_surf = mu - 2 pi a b k / (3 Fz); > 0: surface fatigue"});
}

}  // namespace wrc::damage
