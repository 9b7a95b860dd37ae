// Linearised sensitivities of a normal solution (for Newton solvers): against finite differences of the
// solver, against the dense reference, and against the analytic stiffnesses of a circular contact.
#include "halfspace/hertz_reference.hpp"
#include "halfspace/normal_cases.hpp"
#include "wrc/halfspace/normal.hpp"
#include "approx.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using wrc::test::within_rel;
using namespace wrc::halfspace;
using namespace wrc::test;

namespace {

using wrc::test::steel;

struct Field {
  const char* name;
  std::vector<double> dh;
};

std::vector<Field> perturbations(const Grid& g) {
  std::vector<Field> f = {{"uniform approach", {}}, {"tilt about y", {}}, {"tilt about x", {}}, {"twist", {}}};
  for (auto& field : f) field.dh.resize(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int k = g.index(i, j);
      f[0].dh[k] = 1;
      f[1].dh[k] = g.x(i);
      f[2].dh[k] = g.y(j);
      f[3].dh[k] = 1e3 * g.x(i) * g.y(j);
    }
  return f;
}

}  // namespace

TEST_CASE("response = central finite differences of the solver = dense response, both controls") {
  std::mt19937 rng(17);
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  NormalOptions tight;
  tight.tolerance = 1e-13;
  for (int t = 0; t < 12; ++t) {
    const NormalCase c = random_case(rng);
    const bool force_control = t % 2 == 1;
    NormalLoad load = force_control ? NormalLoad::normal_force(800.0) : NormalLoad::penetration();
    if (t % 4 == 3)  // weighted: sum w p dA = F, w varying across the rows
      for (int k = 0; k < c.grid.size(); ++k) load.weights.push_back(0.4 + 0.5 * (k / c.grid.nx) / c.grid.ny);
    if (t == 11)  // and the approach with gap weights of its own (5 % off w along the columns)
      for (int k = 0; k < c.grid.size(); ++k)
        load.gap_weights.push_back(load.weights[k] * (0.97 + 0.05 * (k % c.grid.nx) / c.grid.nx));
    const NormalSolution s = solver.solve(c.grid, c.h, load, ws, tight);
    double hscale = 0;
    for (double h : c.h) hscale = std::max(hscale, std::abs(h));
    for (const Field& f : perturbations(c.grid)) {
      CAPTURE(t);
      CAPTURE(f.name);
      double fscale = 0;
      for (double v : f.dh) fscale = std::max(fscale, std::abs(v));
      const double eps = 1e-5 * hscale / fscale;  // small enough to keep the contact set
      std::vector<double> hp = c.h, hm = c.h;
      for (int k = 0; k < c.grid.size(); ++k) hp[k] += eps * f.dh[k], hm[k] -= eps * f.dh[k];
      const NormalSolution sp = solver.solve(c.grid, hp, load, ws, tight);
      const NormalSolution sm = solver.solve(c.grid, hm, load, ws, tight);
      REQUIRE(sp.elements_in_contact == s.elements_in_contact);
      REQUIRE(sm.elements_in_contact == s.elements_in_contact);
      const NormalResponse r = solver.response(s, f.dh, ws, 1e-12);
      const NormalResponse d = normal_response_dense(steel, s, f.dh);
      double pscale = 0, fd_err = 0, dense_err = 0;
      for (int k = 0; k < c.grid.size(); ++k) pscale = std::max(pscale, std::abs(d.pressure[k]));
      for (int k = 0; k < c.grid.size(); ++k) {
        const double fd = (sp.pressure[k] - sm.pressure[k]) / (2 * eps);
        fd_err = std::max(fd_err, std::abs(r.pressure[k] - fd));
        dense_err = std::max(dense_err, std::abs(r.pressure[k] - d.pressure[k]));
      }
      if (pscale > 0) {
        CHECK(fd_err < 1e-5 * pscale);
        CHECK(dense_err < 1e-8 * pscale);
      }
      const double Fscale = s.force * fscale / hscale;  // the size of dF for a perturbation of this size
      CHECK(std::abs(r.force - (sp.force - sm.force) / (2 * eps)) < 1e-5 * Fscale);
      CHECK(std::abs(r.moment_x - d.moment_x) < 1e-8 * Fscale * 1e-3);
      CHECK(std::abs(r.moment_y - d.moment_y) < 1e-8 * Fscale * 1e-3);
      if (force_control) {
        double dFw = 0;  // the prescribed (weighted) force does not change
        for (int k = 0; k < c.grid.size(); ++k) dFw += load.weight(k) * r.pressure[k] * c.grid.element_area();
        CHECK(std::abs(dFw) < 1e-9 * Fscale);
        CHECK(r.approach == doctest::Approx((sp.approach - sm.approach) / (2 * eps)).epsilon(1e-5).scale(1.0));
        CHECK(r.approach == doctest::Approx(d.approach).epsilon(1e-8).scale(1.0));
      }
    }
  }
}

TEST_CASE("response of a circular Hertz contact: flat-punch stiffnesses 2 E* a and 4/3 E* a^3") {
  const NormalSolver solver(steel);
  NormalWorkspace ws;
  const double R = 0.45, A = 1 / (2 * R), element = 0.1e-3;
  const double a = 24 * element, delta = a * a / R;
  const NormalCase c = paraboloid_case(A, A, delta, element);
  const NormalSolution s = solver.solve(c.grid, c.h, NormalLoad::penetration(), ws);
  const auto fields = perturbations(c.grid);
  const double Es = steel.combined_modulus();
  const NormalResponse up = solver.response(s, fields[0].dh, ws);
  // On the fixed contact set the uniform response is a flat circular punch: dF/d(delta) = 2 E* a; and
  // Hertz's F ~ delta^(3/2) gives the same, 3/2 F / delta.
  CHECK(up.force == within_rel(2 * Es * a, 0.02));
  CHECK(up.force == within_rel(1.5 * s.force / delta, 0.02));
  CHECK(std::abs(up.moment_x) < 1e-6 * up.force * a);  // symmetric
  // A tilt about y (dh = x): a tilted circular punch, moment 4/3 E* a^3 per radian, no net force.
  const NormalResponse tilt = solver.response(s, fields[1].dh, ws);
  CHECK(tilt.moment_x == within_rel(4.0 / 3.0 * Es * a * a * a, 0.03));
  CHECK(std::abs(tilt.force) < 1e-6 * up.force);
  // Prescribed force: a uniform dh only moves the approach back.
  const NormalSolution f = solver.solve(c.grid, c.h, NormalLoad::normal_force(s.force), ws);
  const NormalResponse uf = solver.response(f, fields[0].dh, ws);
  CHECK(uf.approach == within_rel(-1.0, 1e-12));
  double most = 0;
  for (double v : uf.pressure) most = std::max(most, std::abs(v));
  CHECK(most < 1e-6 * up.force / (a * a));
}
