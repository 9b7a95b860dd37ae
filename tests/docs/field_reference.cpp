// Writes docs/reference/fields.md, the result-field reference: representative results of every kind (S1002 on 60E1,
// profiles/) described into a DocSink (wrc/core/field_reference.hpp), so that the page lists what the describe()
// calls write, with the units and meanings they give. Optional fields (an error message, a flange-climb reason, a
// resolution note, a threads note) are shown by setting them on a copy of a computed result: the paths come from the
// describe() code either way.
//
//   field_reference ROOT OUT.md          write the page
//   field_reference ROOT OUT.md --check  compare with OUT.md instead; exit 1 when it differs
// Exit 1 too when a described field has no unit or meaning (DocSink::problems).
#include "wrc/core/field_reference.hpp"
#include "wrc/equilibrium/equilibrium.hpp"
#include "wrc/equilibrium/trajectory.hpp"
#include "wrc/geometry/strategy_check.hpp"
#include "wrc/halfspace/subsurface.hpp"
#include "wrc/kinematics/table.hpp"
#include "wrc/lua/host.hpp"
#include "wrc/profile/measures.hpp"
#include "wrc/wheelset/wheelset.hpp"

#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace wrc;

struct Section {
  std::string title;
  std::string calls;  // the Lua and C calls that return it
  std::string note;
  std::vector<std::function<void(FieldSink&)>> results;
};

std::shared_ptr<const Wheelset> paper_wheelset(const std::string& root, ContactSurface surface) {
  WheelsetProfiles p;
  const auto w = lua::load_profile(root + "/profiles/s1002.lua", {});
  const auto r = lua::load_profile(root + "/profiles/60e1.lua", {});
  p.wheel = {*w, *w};
  p.rail = {*r, *r};
  WheelsetParams params;
  params.contact.element = 0.5e-3;  // coarse: the fields do not depend on the element size
  params.contact.surface = surface;
  return build_wheelset(p, params);
}

// With a wear model: its fields too (Archard with the KTH map, or USFD).
RollingRequest rolling(RollingMethod method, bool creepages, std::optional<damage::WearModel> wear = std::nullopt) {
  RollingRequest q;
  if (wear) {
    q.damage.with_wear = true;
    q.damage.wear.model = *wear;
  }
  if (creepages) q.creepage = halfspace::Creepages{1e-3, -0.5e-3, 0.1};
  else q.kinematics = Kinematics{20.0, std::nullopt, 0.01, 0.0};
  q.V = 20;
  q.friction = halfspace::Friction::coulomb(0.3);
  q.method = method;
  return q;
}

std::vector<Section> sections(const std::string& root) {
  const auto conformal = paper_wheelset(root, ContactSurface::conformal);
  const auto planar = paper_wheelset(root, ContactSurface::planar);
  auto ws = conformal->make_workspace();
  auto pws = planar->make_workspace();
  const ContactModel& cm = conformal->contact_model();
  std::vector<Section> out;

  // A wheel: frictionless, rolling (exact, FASTSIM), planar, a trajectory's step with sensitivity; failed and past
  // flange climb.
  {
    const WheelCase c{kLeft, 2e-3, 0.0, 0.0, 100e3};
    WheelResult exact =
        solve_wheel(cm, c, *ws, {}, std::nullopt, rolling(RollingMethod::exact, false, damage::WearModel::archard));
    const WheelResult fastsim = solve_wheel(cm, c, *ws, {}, std::nullopt, rolling(RollingMethod::fastsim, false));
    const WheelResult plain = solve_wheel(planar->contact_model(), c, *pws);
    Trajectory tr(conformal);
    const WheelResult step = tr.wheel(c, rolling(RollingMethod::fastsim, false), true);  // with its jacobians
    WheelResult failed = exact;
    failed.converged = false;
    failed.message = "example";
    failed.wheel.flange_climb = "example";
    failed.wheel.patches.front().span_y = 2;  // too few elements across: the resolution_note
    out.push_back({"Wheel", "`ws:wheel{...}`, `tr:wheel{...}`; `wrc_wheel`, `wrc_trajectory_wheel`",
                   "One wheel with its vertical force prescribed.",
                   {[=](FieldSink& s) { describe(exact, s); }, [=](FieldSink& s) { describe(fastsim, s); },
                    [=](FieldSink& s) { describe(plain, s); }, [=](FieldSink& s) { describe(step, s); },
                    [=](FieldSink& s) { describe(failed, s); }}});
  }
  // A rolling contact at a prescribed pose: kinematics and creepages, sensitivities; planar.
  {
    const Pose pose{2e-3, -0.1e-3, 0.0, 0.0};
    ContactRequest req;
    req.sensitivity = req.jacobian = true;
    req.rolling = rolling(RollingMethod::exact, false);
    const ContactResult kin = evaluate_contact(cm, pose, *ws, req);
    req.rolling = rolling(RollingMethod::fastsim, true, damage::WearModel::usfd);
    const ContactResult creep = evaluate_contact(cm, pose, *ws, req);
    const ContactResult plain = evaluate_contact(planar->contact_model(), pose, *pws);
    Trajectory tr(conformal);
    const ContactResult step = tr.contact(pose, rolling(RollingMethod::fastsim, false));
    ContactResult narrow = plain;
    narrow.wheel[kLeft].patches.front().span_y = 2;  // too few elements across: the resolution_note
    out.push_back(
        {"Contact",
         "`ws:contact{...}`, `tr:contact{...}`; `wrc_contact`, `wrc_trajectory_contact`",
         "The contact at a prescribed pose; `sensitivity` only when asked for, the tangential fields only with "
         "rolling keys (kinematics or creepages).",
         {[=](FieldSink& s) { describe(kin, s, true); }, [=](FieldSink& s) { describe(creep, s, true); },
          [=](FieldSink& s) { describe(plain, s, false); }, [=](FieldSink& s) { describe(step, s); },
          [=](FieldSink& s) { describe(narrow, s); }}});
  }
  // An equilibrium; failed and past flange climb.
  {
    const EquilibriumResult e = solve_equilibrium(cm, {2e-3, 0.0, 100e3}, *ws);
    EquilibriumResult failed = e;
    failed.converged = false;
    failed.message = "example";
    failed.flange_climb = "example";
    failed.contact.wheel[kLeft].flange_climb = "example";
    failed.contact.wheel[kLeft].patches.front().span_y = 2;
    out.push_back({"Equilibrium", "`ws:equilibrium{...}`; `wrc_equilibrium`",
                   "The elastic equilibrium of the wheelset under the vertical load Q (frictionless).",
                   {[=](FieldSink& s) { describe(e, s); }, [=](FieldSink& s) { describe(failed, s); }}});
  }
  // A sweep's case with the rigid reference and rolling.
  {
    SweepOptions so;
    so.threads = 1;
    so.Q = 100e3;
    so.rigid = true;
    so.rolling = rolling(RollingMethod::fastsim, false);
    SweepResult r = run_sweep(cm, {0.0, 2e-3}, {0.0}, so, [&] { return conformal->make_workspace(); });
    r.elastic[1].message = "example";
    r.elastic[1].flange_climb = "example";
    r.elastic[1].contact.wheel[kLeft].patches.front().span_y = 2;
    out.push_back({"Sweep case", "the entries of `ws:sweep{...}`",
                   "Each entry of a sweep is an equilibrium (above) with its case number and, with `rigid = true`, the "
                   "rigid reference; with rolling keys the creep forces at the equilibrium pose. Beside the entries "
                   "the Lua binding sets `seconds`, `threads`, `threads_note` and `failed` (cases not converged) "
                   "on the sweep's table.",
                   {[=](FieldSink& s) { describe_case(r, 0, s); }, [=](FieldSink& s) { describe_case(r, 1, s); }}});
  }
  // Rigid contact: roll free (forces), roll fixed; failed.
  {
    const GeometryModel& g = conformal->geometry();
    RigidOptions with_material;  // as the call layer gives it: the contact points' Hertz ellipses too
    with_material.material = conformal->contact_model().material();
    const RigidResult free = solve_rigid(g, 2e-3, 0.0, with_material);
    RigidOptions fixed = with_material;
    fixed.roll_mode = RollMode::fixed;
    const RigidResult held = solve_rigid(g, 7e-3, 0.0, fixed);
    RigidResult failed = free;
    failed.message = "example";
    out.push_back({"Rigid contact", "`ws:rigid{...}`; `wrc_rigid`, `wrc_rigid_contact`",
                   "The rigid (kinematic) contact at a lateral position and yaw.",
                   {[=](FieldSink& s) { describe(free, s); }, [=](FieldSink& s) { describe(held, s); },
                    [=](FieldSink& s) { describe(failed, s); }}});
  }
  // A geometry table across the flange-root jump.
  {
    GeometryTableOptions o;
    for (int k = 0; k <= 10; ++k) o.y.push_back(k * 1e-3);
    o.threads = 1;
    o.rigid.material = conformal->contact_model().material();
    GeometryTable t = run_geometry_table(conformal->geometry(), o);
    if (t.jumps.empty()) throw Error("field_reference: the representative geometry table has no contact jump");
    t.threads_note = "example";
    out.push_back({"Geometry table", "`ws:geometry_table{...}`; `wrc_geometry_table`",
                   "Rigid contact rows for a series of lateral positions, and the jumps of the touching points.",
                   {[=](FieldSink& s) { describe(t, s); }}});
  }
  // Conicity.
  {
    WheelsetConicityOptions o;
    o.conicity.yhat = {2e-3, 3e-3};
    o.table.threads = 1;
    const WheelsetConicity c = wheelset_conicity(conformal->geometry(), o);
    out.push_back({"Wheelset conicity", "`ws:conicity{...}` (its second value); `wrc_wheelset_conicity`",
                   "The equivalent conicity of the wheelset from its rigid rolling-radius difference table.",
                   {[=](FieldSink& s) { describe(c, s); }}});
    DeltaRFunction dr;
    dr.y = c.dr.y;
    dr.dr = c.dr.dr;
    ConicityOptions co;  // r0 and contact_distance of their own (the wheelset's options leave them to the wheelset)
    co.yhat = o.conicity.yhat;
    const ConicityResult r = equivalent_conicity(dr, co);
    out.push_back({"Conicity of a Δr table", "`wrc.conicity(dr, options)` (its second value); `wrc_conicity`",
                   "The equivalent conicity of a given rolling-radius difference function.",
                   {[=](FieldSink& s) { describe(r, s); }}});
  }
  // Flange measures.
  {
    const auto w = lua::load_profile(root + "/profiles/s1002.lua", {});
    const FlangeMeasures m = flange_measures(*w);
    out.push_back({"Flange measures", "`p:flange_measures{...}`; `wrc_profile_flange_measures`",
                   "EN 15313 flange measures of a wheel profile.", {[=](FieldSink& s) { describe(m, s); }}});
  }
  // Location, parameters, strategy check (Lua only).
  {
    const LocateResult l = locate(*conformal, {2e-3, -0.1e-3, 0.0, 0.0}, *ws);
    out.push_back({"Location", "`ws:locate{...}` (Lua only)", "The inter-penetration areas of the undeformed profiles.",
                   {[=](FieldSink& s) { describe(l, s); }}});
    const WheelsetParams p = conformal->params();
    out.push_back({"Wheelset parameters", "`ws.params`, `wrc.defaults.wheelset` (Lua only)",
                   "The parameters a wheelset was built with (the defaults: those of `wrc.wheelset{}`).",
                   {[=](FieldSink& s) { describe(p, s); }}});
    StrategyCheckOptions so;
    so.poses = 2;
    so.threads = 1;
    const StrategyCheckResult sc =
        check_strategy(conformal->geometry(), so, [&] { return conformal->strategy().make_search(); });
    out.push_back({"Strategy check", "`ws:check_strategy{...}` (Lua only)",
                   "The wheelset's location strategy checked against brute force on random poses.",
                   {[=](FieldSink& s) { describe(sc, s); }}});
  }
  // Subsurface stresses of a rolling patch (p:subsurface, wrc_subsurface: api::SubsurfaceCall).
  {
    ContactRequest req;
    req.rolling = rolling(RollingMethod::exact, false);
    const ContactResult c = evaluate_contact(planar->contact_model(), {2e-3, -0.1e-3, 0.0, 0.0}, *pws, req);
    const PatchContact& pc = c.wheel[kLeft].patches.at(0);
    const auto& t = pc.rolling->solution;
    halfspace::SubsurfaceRequest q;
    q.z = {0.5e-3, 1e-3};
    const halfspace::SubsurfaceResult r = halfspace::compute_subsurface(
        planar->contact_model().material(), {pc.solution.grid, pc.solution.pressure, t.px, t.py}, q);
    out.push_back({"Subsurface stresses", "`p:subsurface{...}` (p an area of a result); `wrc_subsurface`",
                   "The stresses below a contact area and its shakedown point ([What contact does to the "
                   "steel](../guide/damage.md)).",
                   {[=](FieldSink& s) { halfspace::describe(r, s); }}});
  }
  return out;
}

const char* kHead = R"(# Result fields

<!-- Generated by tests/docs/field_reference.cpp from the engine's describe() code: do not edit. Regenerate with
     cmake --build build --target field_reference_page -->

Every field a result can hold, written by the same description code (`describe()`, `wrc/core/fields.hpp`) that fills
the Lua tables and the C API's paths, with its unit and meaning. The test "docs: the result-field reference is up to
date" regenerates this page and fails when it differs.

- **Paths.** Lua indexes a list with `[N]` (`e.left.patches[1].pmax`); the C API names the same field
  `left.patches.1.pmax` (`wrc_result_number`, and `wrc_result_fields` lists every path of a result). `N` counts from
  1. `<side>` is `left` or `right`: the two wheels' tables hold the same fields. A list itself is a field too: its
  length in Lua (`#`), its count in C (`wrc_result_count`).
- **Types.** number; integer (a whole number: an index, a count); boolean (C: 1 or 0); string (C:
  `wrc_result_string`); numbers, integers (arrays; C: `wrc_result_numbers`); grid (one value per element of an
  area's grid, nx by ny: in Lua ny rows of nx values, `g[j][i]`; in C nx ny values, element (i, j) at i + nx j,
  0-based); table (in C only its fields have paths); list.
- **Units** are SI; `-` marks a pure number, an index or a count.
- **Signs and frames** follow docs/design.md, [section 2](../design.md#2-frames-units-and-signs): track frame x along the
  track, z up, +y toward the left rail; forces are those the rail exerts on the wheel, in the track frame; moments
  about the wheelset centre in track axes; contact angles positive when the normal tilts toward the track centre.
  A field shown only in some results says when it is there.
)";

std::string page(const std::vector<Section>& secs, std::vector<std::string>& problems) {
  std::ostringstream o;
  o << kHead;
  for (const Section& sec : secs) {
    DocSink sink;
    for (const auto& r : sec.results) {
      sink.restart();
      r(sink);
    }
    for (const std::string& p : sink.problems()) problems.push_back(sec.title + ": " + p);
    o << "\n## " << sec.title << "\n\n" << sec.calls << ". " << sec.note << "\n\n" << field_table(sink.entries());
  }
  return o.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || (argc == 4 && std::string(argv[3]) != "--check") || argc > 4) {
    std::fprintf(stderr, "usage: field_reference ROOT OUT.md [--check]\n");
    return 2;
  }
  const std::string root = argv[1], path = argv[2];
  const bool check = argc == 4;
  try {
    std::vector<std::string> problems;
    const std::string text = page(sections(root), problems);
    for (const std::string& p : problems) std::fprintf(stderr, "field_reference: %s\n", p.c_str());
    if (!problems.empty()) {
      std::fprintf(stderr, "field_reference: %zu problems: give every field a FieldDoc {unit, meaning} in its "
                   "describe() call (wrc/core/fields.hpp, wrc/core/field_reference.hpp)\n", problems.size());
      return 1;
    }
    if (check) {
      std::ifstream in(path, std::ios::binary);
      std::stringstream old;
      old << in.rdbuf();
      if (old.str() == text) return 0;
      std::fprintf(stderr, "field_reference: %s is not what the engine's describe() calls write: regenerate it with\n"
                   "  cmake --build build --target field_reference_page\nand commit it\n", path.c_str());
      return 1;
    }
    const std::string tmp = path + ".tmp";
    {
      std::ofstream f(tmp, std::ios::binary);
      f << text;
      if (!f.flush()) throw Error("field_reference: cannot write " + tmp);
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw Error("field_reference: cannot write " + path);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "field_reference: %s\n", e.what());
    return 1;
  }
}
