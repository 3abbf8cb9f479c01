#include "dynamics/puck/puck_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dynamics/puck/terminal_ratio.h"
#include "friction/registry.h"
#include "tests/dynamics/test_support.h"
#include "uniform_circle_law.h"

namespace frictionlab::dynamics::puck {
namespace puck_run_test {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

// Keeps every sample.
class Recorder final : public PuckObserver {
 public:
  void sample(const PuckSample& s) override {
    t.push_back(s.t);
    x.push_back(s.x);
    energy.push_back(s.energy);
  }
  std::vector<double> t;
  std::vector<PuckState> x;
  std::vector<double> energy;
};

class FailingObserver final : public PuckObserver {
 public:
  void sample(const PuckSample& s) override {
    if (s.t > 0.05) throw OutputFailure("disk full");
  }
};

RunOptions options(double t_end = 10.0, double output_dt = 1e-2) {
  RunOptions o;
  o.t_end = t_end;
  o.output_dt = output_dt;
  o.integrator.abs_tol = 1e-11;
  o.integrator.rel_tol = 1e-11;
  return o;
}

Puck disk(double a = 0.03, double mass = 0.16) { return {mass, uniform_plate_inertia(mass, a, a), a, a}; }
Puck ellipse() { return {0.16, uniform_plate_inertia(0.16, 0.04, 0.015), 0.04, 0.015}; }

TEST(DynPuckRun, PureSlidingStopsWhereAndWhenTheClosedFormSays) {
  // omega0 = 0: every law gives F1 = kN, F2 = 0, M = 0 (docs/model.md §2), so U = v0 - k g t and the
  // puck slides straight. Its slip stops when U reaches the threshold U_th: at t = (v0 - U_th)/(k g),
  // after (v0^2 - U_th^2)/(2 k g) (v0/(k g) and v0^2/(2 k g) at U_th -> 0); the spin is held from
  // t = 0 (Omega = 0 is below its threshold).
  const auto exact = friction::make_law("exact");
  const double k = 0.2, v0 = 2.0, dir = 0.3;
  for (const Puck& p : {disk(), ellipse()}) {
    const PuckOnPlane sys(p, k, kG, *exact);
    const PuckRunSummary s =
        simulate_puck(sys, make_puck_state({0.5, -0.2}, 1.1, v0 * Eigen::Vector2d(std::cos(dir), std::sin(dir)), 0.0), options());
    const double U_th = 1e-3 * std::sqrt(kG * p.a);
    EXPECT_EQ(s.reason, Termination::rest) << s.message;
    EXPECT_DOUBLE_EQ(s.slip_speed.value, U_th);
    EXPECT_EQ(s.spin_stop_time, 0.0);
    EXPECT_NEAR(s.slip_stop_time, (v0 - U_th) / (k * kG), 1e-9);
    const Eigen::Vector2d moved = position(s.x_final) - Eigen::Vector2d(0.5, -0.2);
    EXPECT_NEAR(moved.norm(), (v0 * v0 - U_th * U_th) / (2.0 * k * kG), 1e-9);
    EXPECT_NEAR(std::atan2(moved.y(), moved.x()), dir, 1e-12);
    EXPECT_EQ(heading(s.x_final), 1.1);
  }
}

TEST(DynPuckRun, PureSpinStopsWhenTheClosedFormSays) {
  // v0 = 0: Omega = omega0 - M0 t/I with the law's pure-spin moment M0: exact (Hertz)
  // (3/8) k N a E(e) (docs/model.md §2), uniform pressure (2/3) k N a on a circle. The spin stops at
  // t = I (omega0 - Omega_th)/M0, the body turned by I (omega0^2 - Omega_th^2)/(2 M0).
  const auto exact = friction::make_law("exact");
  const testing::UniformCircleTestLaw uniform;
  const double k = 0.25, w0 = 40.0;
  struct Case {
    Puck p;
    const friction::FrictionLaw* law;
    double M0_per_kNa;
  };
  const double e = std::sqrt(1.0 - std::pow(0.015 / 0.04, 2));
  for (const Case& c : {Case{disk(), exact.get(), 3.0 * kPi / 16.0}, Case{ellipse(), exact.get(), 3.0 / 8.0 * std::comp_ellint_2(e)},
                        Case{disk(), &uniform, 2.0 / 3.0}}) {
    const PuckOnPlane sys(c.p, k, kG, *c.law);
    const PuckRunSummary s = simulate_puck(sys, make_puck_state({0, 0}, 0.0, {0, 0}, w0), options());
    const double M0 = c.M0_per_kNa * k * c.p.mass * kG * c.p.a;
    const double W_th = 1e-3 * std::sqrt(kG / c.p.a);
    EXPECT_EQ(s.reason, Termination::rest) << s.message;
    EXPECT_EQ(s.slip_stop_time, 0.0);
    EXPECT_NEAR(s.spin_stop_time, c.p.inertia * (w0 - W_th) / M0, 1e-9) << c.law->name();
    EXPECT_NEAR(heading(s.x_final), c.p.inertia * (w0 * w0 - W_th * W_th) / (2.0 * M0), 1e-9);
    EXPECT_EQ(position(s.x_final).norm(), 0.0);
  }
}

TEST(DynPuckRun, ACircularPuckSlidesStraightAnEllipticOneDoesNot) {
  // F2 = 0 for a circle (docs/model.md §2): the force stays along the slip, so the path is the
  // straight line of the initial velocity. An elliptic patch has F2 != 0 and bends the path.
  const auto exact = friction::make_law("exact");
  const Eigen::Vector2d v0(1.2, 0.4);
  Recorder circle;
  const PuckRunSummary s = simulate_puck(PuckOnPlane(disk(), 0.2, kG, *exact), make_puck_state({0, 0}, 0.0, v0, 60.0),
                                         options(), &circle);
  EXPECT_EQ(s.reason, Termination::rest) << s.message;
  for (const PuckState& x : circle.x) {
    const Eigen::Vector2d r = position(x);
    EXPECT_NEAR(v0.x() * r.y() - v0.y() * r.x(), 0.0, 1e-13);
  }
  EXPECT_GT(std::abs(heading(s.x_final)), 1.0);  // it did spin
  const PuckRunSummary e =
      simulate_puck(PuckOnPlane(ellipse(), 0.2, kG, *exact), make_puck_state({0, 0}, 0.0, v0, 60.0), options());
  const Eigen::Vector2d r = position(e.x_final);
  EXPECT_GT(std::abs(v0.normalized().x() * r.y() - v0.normalized().y() * r.x()), 1e-4);
}

TEST(DynPuckRun, EnergyFallsByExactlyTheFrictionWork) {
  const auto exact = friction::make_law("exact");
  const PuckOnPlane sys(ellipse(), 0.2, kG, *exact);
  Recorder rec;
  const PuckRunSummary s = simulate_puck(sys, make_puck_state({0, 0}, 0.4, {1.5, -0.3}, -45.0), options(), &rec);
  EXPECT_EQ(s.reason, Termination::rest) << s.message;
  ASSERT_GT(rec.x.size(), 10u);
  for (std::size_t i = 0; i < rec.x.size(); ++i) {
    EXPECT_NEAR(rec.energy[i] + slide_work(rec.x[i]) + spin_work(rec.x[i]), s.initial_energy, 1e-9 * s.initial_energy)
        << "t = " << rec.t[i];
    if (i > 0) {
      EXPECT_LE(rec.energy[i], rec.energy[i - 1] + 1e-12);
    }
  }
  EXPECT_NEAR(s.final_energy + slide_work(s.x_final) + spin_work(s.x_final), s.initial_energy, 1e-9 * s.initial_energy);
  EXPECT_EQ(s.final_energy, 0.0);  // both held at 0: what was left is counted as friction work
  EXPECT_GT(s.held_slide_energy + s.held_spin_energy, 0.0);
}

TEST(DynPuckRun, ReversingTheSpinMirrorsThePath) {
  // The mirror y -> -y maps a solution with (heading, omega) onto one with (-heading, -omega):
  // psi -> -psi flips F2, and M is odd in Omega (docs/model.md §2).
  const auto exact = friction::make_law("exact");
  const PuckOnPlane sys(ellipse(), 0.2, kG, *exact);
  Recorder plus, minus;
  const PuckRunSummary a = simulate_puck(sys, make_puck_state({0, 0}, 0.0, {1.0, 0.0}, 50.0), options(), &plus);
  const PuckRunSummary b = simulate_puck(sys, make_puck_state({0, 0}, 0.0, {1.0, 0.0}, -50.0), options(), &minus);
  ASSERT_EQ(plus.x.size(), minus.x.size());
  for (std::size_t i = 0; i < plus.x.size(); ++i) {
    const PuckState& p = plus.x[i];
    const PuckState& m = minus.x[i];
    EXPECT_NEAR(position(p).x(), position(m).x(), 1e-9);
    EXPECT_NEAR(position(p).y(), -position(m).y(), 1e-9);
    // The two runs round differently (and so take slightly different steps): ~1e-9 of the spin.
    EXPECT_NEAR(heading(p), -heading(m), 1e-7);
    EXPECT_NEAR(spin(p), -spin(m), 1e-7);
  }
  EXPECT_GT(std::abs(position(a.x_final).y()), 1e-4);  // the path bends, one way or the other
  EXPECT_NEAR(a.slip_stop_time, b.slip_stop_time, 1e-9);
  EXPECT_NEAR(a.spin_stop_time, b.spin_stop_time, 1e-9);
}

TEST(DynPuckRun, AUniformDiskStopsSlidingAndSpinningTogetherAtTheClassicalRatio) {
  // Contensou-Erismann: under uniform pressure with kappa = 1/2 both motions stop together and
  // v/(a omega) tends to 0.653 (Farkas et al. 2003; Weidman & Malhotra 2005), the attracting zero of
  // the drift G (dynamics/puck/terminal_ratio.h). From two starting ratios, 0.2 and 3.
  const testing::UniformCircleTestLaw uniform;
  const Puck p = disk();
  const PuckOnPlane sys(p, 0.2, kG, uniform);
  const double r_star = analyse_terminal_ratio(uniform, 0.5, 1e-3, 1e3, 20).attracting.at(0);
  // Thresholds 1e-6 of the scales (instead of 1e-3): six more decades of the energy to converge in.
  RunOptions o = options();
  o.rest.slip_speed = 1e-6 * std::sqrt(kG * p.a);
  o.rest.spin = 1e-6 * std::sqrt(kG / p.a);
  for (const double r0 : {0.2, 3.0}) {
    const double w0 = 40.0;
    const PuckRunSummary s = simulate_puck(sys, make_puck_state({0, 0}, 0.0, {r0 * p.a * w0, 0.0}, w0), o);
    EXPECT_EQ(s.reason, Termination::rest) << s.message;
    // The ratio closes in on r* like v^lambda (lambda = 0.35 here, terminal_ratio.h): at the stop it
    // is on its way, between the start and r*; its limit, extrapolated from the last decades of the
    // energy, is r*.
    EXPECT_LT(std::abs(s.terminal_ratio - r_star), 0.15 * std::abs(r0 - r_star)) << r0;
    EXPECT_GT((s.terminal_ratio - r_star) * (r0 - r_star), 0.0) << r0;
    EXPECT_NEAR(s.terminal_ratio_limit, 0.653, 2e-3) << r0;
    EXPECT_NEAR(s.terminal_ratio_limit, r_star, 1e-3) << r0;
    // Together: the gap between the two stops is the time the remaining spin (the thresholds meet at
    // ratio 1, the motion ends at r* < 1) takes at the pure-spin deceleration, ~1e-4 of the run.
    EXPECT_LT(std::abs(s.spin_stop_time - s.slip_stop_time), 1e-3 * s.slip_stop_time) << r0;
    ASSERT_GE(s.ratio_by_energy.size(), 4u);
    // The last decades contract by 10^(-lambda/2) each (r - r* ~ v^lambda, E ~ v^2).
    const std::size_t n = s.ratio_by_energy.size();
    const double q = (s.ratio_by_energy[n - 1].ratio - s.ratio_by_energy[n - 2].ratio) /
                     (s.ratio_by_energy[n - 2].ratio - s.ratio_by_energy[n - 3].ratio);
    const double lambda = analyse_terminal_ratio(uniform, 0.5, 1e-3, 1e3, 20).exponents.at(0);
    EXPECT_NEAR(q, std::pow(10.0, -lambda / 2.0), 0.03) << r0;
    for (std::size_t i = 1; i < s.ratio_by_energy.size(); ++i)  // monotone approach
      EXPECT_LT(std::abs(s.ratio_by_energy[i].ratio - r_star), std::abs(s.ratio_by_energy[i - 1].ratio - r_star)) << i;
  }
}

TEST(DynPuckRun, TheLimitOfTheRatioIsExtrapolatedOnlyFromAGeometricApproach) {
  std::vector<RatioAtEnergy> r;
  for (int i = 0; i < 6; ++i) r.push_back({0.0, 0.0, 0.0, 0.7 + 0.3 * std::pow(0.45, i)});
  EXPECT_NEAR(aitken_limit(r), 0.7, 1e-14);
  std::vector<RatioAtEnergy> drifting;  // 1/sqrt(n): no geometric contraction
  for (int i = 1; i < 7; ++i) drifting.push_back({0.0, 0.0, 0.0, 1.0 / std::sqrt(i)});
  EXPECT_TRUE(std::isnan(aitken_limit(drifting)));
  r.resize(4);
  EXPECT_TRUE(std::isnan(aitken_limit(r)));  // too few decades
}

TEST(DynPuckRun, AHertzDiskStopsSlidingFirst) {
  // With the Hertz pressure and kappa = 1/2 the drift is G = (9 pi/64) r^3 (r^2 - 2) < 0
  // (dynamics/puck/terminal_ratio.h): the ratio falls for ever, slowly (1/r^2 grows like
  // (3/2) ln(1/v)), and the slip stops before the spin.
  const auto exact = friction::make_law("exact");
  const Puck p = disk();
  const PuckRunSummary s =
      simulate_puck(PuckOnPlane(p, 0.2, kG, *exact), make_puck_state({0, 0}, 0.0, {0.6 * p.a * 40.0, 0.0}, 40.0), options());
  EXPECT_EQ(s.reason, Termination::rest) << s.message;
  EXPECT_LT(s.slip_stop_time, s.spin_stop_time);
  ASSERT_GE(s.ratio_by_energy.size(), 3u);
  for (std::size_t i = 1; i < s.ratio_by_energy.size(); ++i)
    EXPECT_LT(s.ratio_by_energy[i].ratio, s.ratio_by_energy[i - 1].ratio);
  EXPECT_LT(s.terminal_ratio, s.ratio_by_energy.front().ratio);
}

TEST(DynPuckRun, ADecoupledLawEndsEachMotionOnItsOwnWithoutChatter) {
  // F1 = kN and M = M0 sign(Omega): two constant decelerations, each motion held at 0 once below its
  // threshold (no chatter of the sign functions), at t = (v0 - U_th)/(k g) and I (w0 - W_th)/M0.
  const auto decoupled = friction::make_law("coulomb-decoupled");
  const Puck p = disk();
  const double k = 0.2, v0 = 1.0, w0 = 30.0;
  const PuckRunSummary s = simulate_puck(PuckOnPlane(p, k, kG, *decoupled), make_puck_state({0, 0}, 0.0, {v0, 0}, w0), options());
  EXPECT_EQ(s.reason, Termination::rest) << s.message;
  const double U_th = 1e-3 * std::sqrt(kG * p.a), W_th = 1e-3 * std::sqrt(kG / p.a);
  const double M0 = 3.0 * kPi / 16.0 * k * p.mass * kG * p.a;
  EXPECT_NEAR(s.slip_stop_time, (v0 - U_th) / (k * kG), 1e-9);
  EXPECT_NEAR(s.spin_stop_time, p.inertia * (w0 - W_th) / M0, 1e-9);
  EXPECT_LT(s.steps, 200);
}

TEST(DynPuckRun, StopsAtADeclaredPoleOfTheLaw) {
  // The test law's forces are those of a decoupled Coulomb law, so U = v0 - k g t and
  // Omega = w0 - M0 t/I; it declares a pole where U/(a Omega) = 2: the run stops there (law-pole).
  const testing::DeclaredPoleTestLaw law(2.0, true);
  const Puck p = disk();
  const double k = 0.2, v0 = 1.0, w0 = 20.0;  // s(0) = 1.67, rising (the spin stops first)
  const PuckRunSummary s = simulate_puck(PuckOnPlane(p, k, kG, law), make_puck_state({0, 0}, 0.0, {v0, 0}, w0), options());
  ASSERT_EQ(s.reason, Termination::law_pole) << s.message;
  const double kg = k * kG, alpha = 3.0 * kPi / 16.0 * k * p.mass * kG * p.a / p.inertia;
  const double t_pole = (v0 - 2.0 * p.a * w0) / (kg - 2.0 * p.a * alpha);  // v0 - kg t = 2 a (w0 - alpha t)
  EXPECT_NEAR(s.t_final, t_pole, 1e-9);
}

TEST(DynPuckRun, TheOutputNeverShapesTheSteps) {
  const auto exact = friction::make_law("exact");
  const PuckOnPlane sys(ellipse(), 0.2, kG, *exact);
  const PuckState x0 = make_puck_state({0, 0}, 0.2, {1.0, 0.3}, 25.0);
  const PuckRunSummary a = simulate_puck(sys, x0, options(10.0, 1e-3));
  const PuckRunSummary b = simulate_puck(sys, x0, options(10.0, 0.1));
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.rhs_calls, b.rhs_calls);
  EXPECT_EQ(a.t_final, b.t_final);
  EXPECT_EIGEN_NEAR(a.x_final, b.x_final, 0.0);
}

TEST(DynPuckRun, AFailingOutputStopsTheRunAtOnce) {
  const auto exact = friction::make_law("exact");
  FailingObserver failing;
  const PuckRunSummary s = simulate_puck(PuckOnPlane(disk(), 0.2, kG, *exact),
                                         make_puck_state({0, 0}, 0.0, {1.0, 0.0}, 20.0), options(), &failing);
  EXPECT_EQ(s.reason, Termination::output_error);
  EXPECT_NE(s.message.find("disk full"), std::string::npos);
  EXPECT_LT(s.t_final, 0.1);
}

TEST(DynPuckRun, AtRestFromTheStartEndsAtOnce) {
  const auto exact = friction::make_law("exact");
  const PuckRunSummary s = simulate_puck(PuckOnPlane(disk(), 0.2, kG, *exact), make_puck_state({0, 0}, 0.0, {0, 0}, 0.0), options());
  EXPECT_EQ(s.reason, Termination::rest);
  EXPECT_EQ(s.t_final, 0.0);
  EXPECT_EQ(s.steps, 0);
}

}  // namespace
}  // namespace frictionlab::dynamics::puck
