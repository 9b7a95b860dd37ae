// Friction falling with the slip velocity and friction varying per element (friction.hpp), in the exact solver and
// FASTSIM, against references computed here: the law evaluated at the slip velocity of full sliding, the slip of the
// exact solution recomputed by direct sums of the influence coefficients, constant friction, and zones solved apart.
#include "direct_slip.hpp"
#include "rolling_cases.hpp"

#include "wrc/halfspace/rolling.hpp"
#include "wrc/core/error.hpp"
#include "approx.hpp"
#include "materials.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using wrc::test::direct_slip;
using wrc::test::within_rel;
using namespace wrc::halfspace;
using wrc::test::hertz_patch;
using wrc::test::rolling_problem;

namespace {

using wrc::test::rolling_steel;

// Polach's law written out here (not through Friction::at).
double polach(double mu0, double A, double B, double w) { return mu0 * ((1 - A) * std::exp(-B * w) + A); }

TangentialSolution solve(bool exact, const TangentialProblem& pb) {
  static const RollingSolver solver(rolling_steel);
  return exact ? solver.solve(pb) : solve_fastsim(rolling_steel, pb);
}

}  // namespace

TEST_CASE("falling friction at small creepage: the linear slope of constant friction mu0 (both solvers)") {
  const wrc::test::HertzPatch h = hertz_patch(5e-3, 3e-3, 1e9, 10);
  for (bool exact : {true, false}) {
    CAPTURE(exact);
    for (const Creepages c : {Creepages{2e-5, 0, 0}, Creepages{0, -2e-5, 0}}) {
      TangentialProblem pb = rolling_problem(h, c, 0.4);
      const TangentialSolution coulomb = solve(exact, pb);
      pb.friction = Friction::polach(0.4, 0.4, 0.6);
      pb.speed = 30;
      const TangentialSolution falling = solve(exact, pb);
      pb.friction = Friction::coulomb(1e9);  // no slip: Kalker's linear theory on this grid
      const TangentialSolution linear = solve(exact, pb);
      const double F = std::hypot(falling.fx, falling.fy), L = std::hypot(linear.fx, linear.fy);
      // FASTSIM's elements at the trailing edge slip even at small creepage (its bound mu p vanishes there): 0.3 %
      CHECK(F == within_rel(L, exact ? 2e-3 : 5e-3));
      CHECK(F == within_rel(std::hypot(coulomb.fx, coulomb.fy), 1e-4));
    }
  }
}

TEST_CASE("falling friction in full sliding: |F| = mu(V |creepage|) N within 1 % (both solvers, three laws)") {
  const wrc::test::HertzPatch h = hertz_patch(5e-3, 3e-3, 1e9, 8);
  struct Case {
    Friction law;
    double mu_at_half;  // mu(0.5 m/s) written out
  };
  const Case laws[] = {
      {Friction::polach(0.4, 0.4, 0.6), polach(0.4, 0.4, 0.6, 0.5)},
      {Friction::falling(FrictionLaw::linear, 0.2, {0.2, 0.0}, {0.8, 1.0}), 0.2 + 0.2 * (1 - 0.5 / 1.6)},
      {Friction::falling(FrictionLaw::rational, 0.15, {0.1, 0.1}, {0.3, 0.4}),
       0.15 + 0.1 / (1 + 0.5 / 0.3) + 0.1 / (1 + 0.5 * 0.5 / 0.16)},
  };
  for (bool exact : {true, false})
    for (const Case& law : laws)
      for (double V : {5.0, 10.0, 25.0}) {
        CAPTURE(exact);
        CAPTURE(law_name(law.law.law));
        CAPTURE(V);
        const double creep = 0.5 / V;  // w = 0.5 m/s: 10 to 50 times the saturation creepage
        for (double angle : {0.0, 2.0}) {
          TangentialProblem pb = rolling_problem(h, {creep * std::cos(angle), creep * std::sin(angle), 0}, 0);
          pb.friction = law.law;
          pb.speed = V;
          const TangentialSolution s = solve(exact, pb);
          const double F = std::hypot(s.fx, s.fy);
          CHECK(s.adhesion_fraction() < 0.05);
          CHECK(F == within_rel(law.mu_at_half * h.force, 0.01));
          CHECK((s.fx * std::cos(angle) + s.fy * std::sin(angle)) / F == within_rel(-1, 1e-4));
        }
      }
}

TEST_CASE("falling friction, exact solver: the traction of every slip element is mu(V |s|) p, s by direct sums") {
  const wrc::test::HertzPatch h = hertz_patch(4e-3, 6e-3, 900e6, 7, 0.3, -0.2);
  const double mu0 = 0.4, A = 0.3, B = 3.0;
  for (int dir : {1, -1})
    for (const Creepages c : {Creepages{2e-3, 0, 0}, Creepages{-0.8e-3, 1.2e-3, 0.3}, Creepages{0, 0, -2.0}})
      for (double V : {10.0, 40.0}) {
        CAPTURE(dir);
        CAPTURE(c.xi);
        CAPTURE(c.phi);
        CAPTURE(V);
        TangentialProblem pb = rolling_problem(h, c, 0, dir);
        pb.friction = Friction::polach(mu0, A, B);
        pb.speed = V;
        const TangentialSolution s = solve(true, pb);
        std::vector<double> sx, sy;
        direct_slip(rolling_steel, pb, s, sx, sy);
        const double wscale = std::max({std::abs(c.xi), std::abs(c.eta), std::abs(c.phi) * 6e-3});
        int slip = 0, adhesion = 0;
        double lowest = 1;  // the lowest mu met in slip / mu0: the law is exercised
        for (std::size_t k = 0; k < h.pressure.size(); ++k) {
          const double pn = h.pressure[k], p = std::hypot(s.px[k], s.py[k]), sl = std::hypot(sx[k], sy[k]);
          if (!(pn > 0)) continue;
          if (s.state[k] == kAdhesion) {
            ++adhesion;
            CHECK(sl < 1e-5 * wscale);
            CHECK(p <= mu0 * pn * (1 + 1e-9));
          } else {
            ++slip;
            const double mu = polach(mu0, A, B, V * sl);
            lowest = std::min(lowest, mu / mu0);
            CHECK(p == within_rel(mu * pn, 1e-5));
            CHECK((s.px[k] * sx[k] + s.py[k] * sy[k]) / (p * sl) == within_rel(-1, 1e-4));
          }
        }
        CHECK(adhesion > 0);
        CHECK(slip > 0);
        CHECK(lowest < 0.97);
      }
}

TEST_CASE("falling friction, FASTSIM: each slip element's traction is mu(V |s|) p opposite to its layer's slip") {
  const wrc::test::HertzPatch h = hertz_patch(5e-3, 4e-3, 1e9, 12);
  const double mu0 = 0.4, A = 0.3, B = 3.0, V = 30;
  for (const Creepages c : {Creepages{3e-3, 0, 0}, Creepages{1e-3, -2e-3, 0.4}}) {
    TangentialProblem pb = rolling_problem(h, c, 0);
    pb.friction = Friction::polach(mu0, A, B);
    pb.speed = V;
    const TangentialSolution s = solve(false, pb);
    int slip = 0;
    for (std::size_t k = 0; k < h.pressure.size(); ++k) {
      const double pn = h.pressure[k], p = std::hypot(s.px[k], s.py[k]);
      if (s.state[k] == kAdhesion) CHECK(p <= mu0 * pn * (1 + 1e-12));
      if (s.state[k] != kSlip) continue;
      ++slip;
      const double sl = std::hypot(s.sx[k], s.sy[k]);
      CHECK(p == within_rel(polach(mu0, A, B, V * sl) * pn, 1e-9));
      CHECK(s.px[k] * s.sx[k] + s.py[k] * s.sy[k] < 0);
    }
    CHECK(slip > 10);
  }
}

TEST_CASE("falling friction: a creep curve rises to a maximum, then falls along mu(V xi) N (both solvers)") {
  const wrc::test::HertzPatch h = hertz_patch(5e-3, 4e-3, 1e9, 10);
  const double mu0 = 0.4, A = 0.4, B = 0.6, V = 30;
  for (bool exact : {true, false}) {
    CAPTURE(exact);
    std::vector<double> xi, F;
    for (double x = 0.5e-3; x <= 0.1; x *= 1.25) {
      TangentialProblem pb = rolling_problem(h, {x, 0, 0}, 0);
      pb.friction = Friction::polach(mu0, A, B);
      pb.speed = V;
      xi.push_back(x);
      F.push_back(-solve(exact, pb).fx / h.force);
    }
    const auto top = static_cast<std::size_t>(std::max_element(F.begin(), F.end()) - F.begin());
    CAPTURE(xi[top]);
    CHECK(top > 0);
    CHECK(top + 5 < F.size());
    CHECK(F[top] < mu0);
    for (std::size_t i = top + 1; i < F.size(); ++i) CHECK(F[i] < F[i - 1]);
    CHECK(F.back() == within_rel(polach(mu0, A, B, V * xi.back()), 0.01));
  }
}

TEST_CASE("friction varying per element: two zones together equal the zones solved apart in full sliding") {
  const wrc::test::HertzPatch h = hertz_patch(5e-3, 4e-3, 1e9, 10);
  for (bool exact : {true, false})
    for (bool falling : {false, true}) {
      CAPTURE(exact);
      CAPTURE(falling);
      std::vector<double> scale(h.pressure.size()), p1(h.pressure.size(), 0.0), p2(p1.size(), 0.0);
      for (int j = 0; j < h.grid.ny; ++j)
        for (int i = 0; i < h.grid.nx; ++i) {
          const auto k = static_cast<std::size_t>(h.grid.index(i, j));
          const bool gauge = h.grid.y(j) > 1e-3;  // a lubricated band: a third of the friction
          scale[k] = gauge ? 1.0 / 3 : 1.0;
          (gauge ? p2 : p1)[k] = h.pressure[k];
        }
      const Creepages c{0.03, 0.01, 0};
      TangentialProblem pb = rolling_problem(h, c, 0.4);
      if (falling) pb.friction = Friction::polach(0.4, 0.4, 0.6), pb.speed = 20;
      pb.friction_scale = scale;
      const TangentialSolution both = solve(exact, pb);
      pb.friction_scale = {};
      pb.pressure = p1;
      const TangentialSolution s1 = solve(exact, pb);
      pb.pressure = p2;
      pb.friction = falling ? Friction::polach(0.4 / 3, 0.4, 0.6) : Friction::coulomb(0.4 / 3);
      const TangentialSolution s2 = solve(exact, pb);
      CHECK(both.fx == within_rel(s1.fx + s2.fx, 0.01));
      CHECK(both.fy == within_rel(s1.fy + s2.fy, 0.01));
      // and not the uniform friction's
      pb.pressure = h.pressure;
      pb.friction = falling ? Friction::polach(0.4, 0.4, 0.6) : Friction::coulomb(0.4);
      CHECK(std::abs(solve(exact, pb).fx / both.fx - 1) > 0.1);
    }
}

TEST_CASE("falling friction: bad laws and a missing speed are refused, naming the problem") {
  const wrc::test::HertzPatch h = hertz_patch(5e-3, 4e-3, 1e9, 6);
  TangentialProblem pb = rolling_problem(h, {1e-3, 0, 0}, 0);
  pb.friction = Friction::polach(0.4, 0.4, 0.6);
  const auto refused = [&](const char* what) {
    for (bool exact : {true, false}) {
      try {
        solve(exact, pb);
        FAIL("accepted");
      } catch (const wrc::Error& e) {
        CHECK(std::string(e.what()).find(what) != std::string::npos);
      }
    }
  };
  refused("rolling speed");  // no speed
  pb.speed = 10;
  pb.friction = Friction::falling(FrictionLaw::linear, 0.2, {-0.1, 0.0}, {1.0, 1.0});
  refused("term 1");
  pb.friction = Friction::falling(FrictionLaw::exponential, 0.2, {0.1, 0.0}, {0.0, 1.0});
  refused("velocity 1");
  pb.friction = Friction::polach(0.4, 0.4, 0.6);
  std::vector<double> scale(h.pressure.size(), 1.0);
  scale[3] = 0;
  pb.friction_scale = scale;
  refused("friction scale at element 3");
}
