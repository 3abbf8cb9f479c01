// The calibration study of the engines' laws: its pure-spin coefficients against the closed forms
// of each pressure, its best coefficient against the closed form of the decoupled law on a circle,
// the identity of the MuJoCo and ellipsoidal laws, and the optimality of what Brent's method finds.

#include "bench/calibration/calibration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "bench/calibration/engine_laws.h"
#include "friction/registry.h"
#include "tests/friction/hertz_closed_forms.h"

namespace frictionlab::calibration {
namespace calibration_test {

constexpr double pi = std::numbers::pi;

// The exact law is accurate to 1e-10 relative to kN and kNa for every pressure (docs/exact-law.md);
// the closed forms to a few ulp.
constexpr double kExactTol = 1e-10;
// Brent's method stops within about 2^-26 = 1.5e-8 relative in c (calibration.cpp): with margin.
constexpr double kBrentTol = 1e-7;

// A small grid for speed, with s up to 10 so that the Hertz circle's closed forms
// (tests/friction/hertz_closed_forms.h, good for s <= 30) reach its end.
CalibrationOptions small(std::vector<std::string> laws, std::vector<std::string> pressures) {
  CalibrationOptions o;
  o.grid.s_points = 41;
  o.grid.s_min = 1e-3;
  o.grid.s_max = 10.0;
  o.grid.mu_points = 3;
  o.grid.psi_points = 5;
  o.laws = std::move(laws);
  o.pressures = std::move(pressures);
  o.scan_points = 41;
  o.threads = 2;
  return o;
}

const CalibrationRow& row_of(const CalibrationResult& r, const std::string& law, const std::string& p, Scope scope) {
  const auto it = std::find_if(r.rows.begin(), r.rows.end(), [&](const CalibrationRow& row) {
    return row.law == law && row.pressure == p && row.scope == scope;
  });
  if (it == r.rows.end()) throw std::logic_error("no row " + law + " " + p);
  return *it;
}

TEST(Calibration, PureSpinCoefficientsAreTheClosedFormsOfEachPressure) {
  // Hertz 3 pi/16, uniform 2/3, punch pi/4 (docs/exact-law.md), computed by the exact law.
  const auto r = run_calibration(small({"decoupled"}, {}));
  // Only the pressures the exact law offers are computed; the closed forms of the others are
  // checked all the same.
  const std::pair<const char*, double> closed[] = {{"hertz", 3.0 * pi / 16.0}, {"uniform", 2.0 / 3.0},
                                                   {"punch", pi / 4.0}};
  const auto offered = exact_pressures();
  for (const auto& [p, value] : closed) {
    EXPECT_DOUBLE_EQ(circle_spin_closed_form(p), value) << p;
    if (std::find(offered.begin(), offered.end(), p) == offered.end()) continue;
    EXPECT_NEAR(row_of(r, "decoupled", p, Scope::circle).exact_circle_spin, value, kExactTol) << p;
  }
}

TEST(Calibration, DecoupledLawOnTheHertzCircleHasTheClosedFormOptimum) {
  // The decoupled law's torque is c whatever s, the exact one falls from M(s_min) to M(s_max)
  // (circle closed forms): the largest error is smallest at c = (M(s_min) + M(s_max))/2, where it
  // is (M(s_min) - M(s_max))/2; at c = 3 pi/16 it is 3 pi/16 - M(s_max).
  const auto o = small({"decoupled"}, {"hertz"});
  const auto r = run_calibration(o);
  const double m_lo = friction::test::circle(o.grid.s_min).m;
  const double m_hi = friction::test::circle(o.grid.s_max).m;
  const auto& row = row_of(r, "decoupled", "hertz", Scope::circle);
  EXPECT_NEAR(row.best.c, (m_lo + m_hi) / 2.0, kBrentTol);
  EXPECT_NEAR(row.best.max[2], (m_lo - m_hi) / 2.0, kBrentTol);
  EXPECT_NEAR(row.at_spin.c, 3.0 * pi / 16.0, kExactTol);
  EXPECT_NEAR(row.at_spin.max[2], 3.0 * pi / 16.0 - m_hi, kExactTol);
  // Its F1 = kN against the exact F1(s_min) ~ (3 pi/8) s_min: the error is the same for every c.
  EXPECT_NEAR(row.best.max[0], 1.0 - friction::test::circle(o.grid.s_min).f1, kExactTol);
  EXPECT_NEAR(row.at_spin.max[0], row.best.max[0], kExactTol);
}

TEST(Calibration, MujocoLawCalibratesLikeTheEllipsoidalLaw) {
  // torsional = c k a and Rb = c a give the same law (friction/mujoco_elliptic_law.h): the same
  // coefficients and errors, found independently.
  const auto r = run_calibration(small({"ellipsoidal", "mujoco-elliptic"}, {"hertz"}));
  for (const char* p : {"hertz"}) {
    for (const Scope scope : {Scope::circle, Scope::grid}) {
      const auto& e = row_of(r, "ellipsoidal", p, scope);
      const auto& m = row_of(r, "mujoco-elliptic", p, scope);
      EXPECT_NEAR(e.best.c, m.best.c, kBrentTol) << p;
      for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(e.best.max[k], m.best.max[k], kBrentTol) << p;
      EXPECT_NEAR(e.at_spin.max[2], m.at_spin.max[2], 1e-12) << p;
    }
  }
}

TEST(Calibration, BestCoefficientIsALocalMinimumAndBeatsThePureSpinOne) {
  // Evaluated apart from the study: E(c) = max |M_law(c) - M_exact| over the scope.
  const auto o = small({"ellipsoidal"}, {"hertz"});
  const auto r = run_calibration(o);
  const auto exact = friction::make_reference_law();
  for (const Scope scope : {Scope::circle, Scope::grid}) {
    const auto& row = row_of(r, "ellipsoidal", "hertz", scope);
    const auto E = [&](double c) {
      const auto law = make_engine_law(engine_law("ellipsoidal"), c, 1.0, 1.0);
      double e = 0.0;
      for (std::size_t i = 0; i < r.grid.size(); ++i) {
        if (scope == Scope::circle && r.grid.mu_index(i) != r.grid.mu().size() - 1) continue;
        const auto in = accuracy::to_contact(r.grid.point(i));
        e = std::max(e, std::abs(law->evaluate(in).M - exact->evaluate(in).M));
      }
      return e;
    };
    const double e_best = E(row.best.c);
    EXPECT_NEAR(e_best, row.best.max[2], 1e-12);
    EXPECT_LE(e_best, E(row.best.c * (1.0 + 1e-3)));
    EXPECT_LE(e_best, E(row.best.c * (1.0 - 1e-3)));
    EXPECT_LE(row.best.max[2], row.at_spin.max[2] + 1e-12);
  }
}

TEST(Calibration, EngineSpecsCarryTheParameterInItsUnit) {
  // Rb = c a; torsional and r_spin = c k a (a torque per unit normal force).
  const auto value_in = [](const std::string& spec, const std::string& prefix) {
    EXPECT_EQ(spec.rfind(prefix, 0), 0u) << spec;
    return std::stod(spec.substr(prefix.size()));
  };
  EXPECT_NEAR(value_in(engine_spec(engine_law("ellipsoidal"), 0.5, 0.004, 0.25), "ellipsoidal:Rb="), 0.002, 1e-18);
  EXPECT_NEAR(value_in(engine_spec(engine_law("mujoco-elliptic"), 0.5, 0.004, 0.25), "mujoco-elliptic:torsional="),
              0.0005, 1e-18);
  EXPECT_NEAR(value_in(engine_spec(engine_law("decoupled"), 0.5, 0.004, 0.25), "decoupled:r_spin="), 0.0005, 1e-18);
  // The law made from the spec has the pure-spin torque c kNa.
  const friction::ContactInput spin{0.0, 3.0, 0.004, 0.004, 0.0, 10.0, 0.25};
  for (const auto& law : engine_laws()) {
    EXPECT_NEAR(make_engine_law(law, 0.5, 0.004, 0.25)->evaluate(spin).M, 0.5 * 0.25 * 10.0 * 0.004, 1e-15)
        << law.name;
  }
}

TEST(Calibration, BadOptionsAreNamed) {
  auto o = small({"nope"}, {});
  EXPECT_THROW((void)run_calibration(o), std::invalid_argument);
  o = small({}, {"gaussian"});
  try {
    (void)run_calibration(o);
    ADD_FAILURE() << "unknown pressure accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'gaussian'"), std::string::npos) << e.what();
  }
  o = small({}, {});
  o.c_min = 0.0;
  EXPECT_THROW((void)run_calibration(o), std::invalid_argument);
  o = small({}, {});
  o.scan_points = 2;
  EXPECT_THROW((void)run_calibration(o), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::calibration
