#include "dynamics/core/shadow_laws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace shadow_laws_test {

using testing::CoulombCircleTestLaw;
using testing::PoleTestLaw;
using testing::SmoothTestLaw;
using testing::ThrowingTestLaw;

MotionPhaseRule rule() {
  MotionPhaseRule r;
  r.rest_slip_speed = 1e-3;
  r.rest_spin = 1e-2;
  r.settle_normal_speed = 0.05;
  return r;
}

ShadowPoint point(double U, double Omega, double a = 2e-3, double b = 1e-3, double N = 10.0, double k = 0.3) {
  ShadowPoint p;
  p.in_contact = true;
  p.input = {U, Omega, a, b, friction::PatchAngle(0.4), N, k};
  return p;
}

TEST(DynShadowLaws, ALawShadowingItselfIsExactlyRightEverywhere) {
  const SmoothTestLaw law;
  ShadowLaws shadow(law, {&law}, rule());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 3.0), w(-50.0, 50.0);
  std::vector<ShadowError> e(1);
  for (int i = 0; i < 200; ++i) {
    ShadowPoint p = point(u(rng), w(rng));
    p.own = law.evaluate(p.input);
    p.own_known = i % 2 == 0;  // given, or evaluated by the shadow
    shadow.evaluate(p, e);
    EXPECT_EQ(e[0].dF1, 0.0);
    EXPECT_EQ(e[0].dF2, 0.0);
    EXPECT_EQ(e[0].dM, 0.0);
    EXPECT_EQ(e[0].dP, 0.0);
  }
}

TEST(DynShadowLaws, ErrorsArePerKNAndKNaAndThePowerIsInWatts) {
  // The two test laws' closed forms (tests/dynamics/test_support.h), written out here.
  const CoulombCircleTestLaw own;
  const SmoothTestLaw other;
  ShadowLaws shadow(own, {&other}, rule());
  const double U = 0.7, Omega = -12.0, a = 2e-3, b = 1e-3, N = 10.0, k = 0.3;
  const ShadowPoint p = point(U, Omega, a, b, N, k);
  std::vector<ShadowError> e(1);
  shadow.evaluate(p, e);
  const double kN = k * N;
  const double Rb = 3.0 * std::numbers::pi / 16.0 * std::sqrt(a * b);
  const double den = std::sqrt(U * U + Rb * Rb * Omega * Omega);
  const double F1 = kN * U / den, F2 = kN * U * a * Omega / (U * U + a * a * Omega * Omega + a * a);
  const double M = kN * Rb * Rb * Omega / den;
  const double M0 = -3.0 * std::numbers::pi / 16.0 * kN * a;  // Omega < 0
  EXPECT_NEAR(e[0].dF1, (F1 - kN) / kN, 1e-14);
  EXPECT_NEAR(e[0].dF2, F2 / kN, 1e-14);
  EXPECT_NEAR(e[0].dF, std::hypot((F1 - kN) / kN, F2 / kN), 1e-14);
  EXPECT_NEAR(e[0].dM, (M - M0) / (kN * a), 1e-14);
  EXPECT_NEAR(e[0].dP, (F1 - kN) * U + (M - M0) * Omega, 1e-14);
}

TEST(DynShadowLaws, OutOfContactEveryErrorIsZeroAndNoLawIsCalled) {
  const testing::ForbiddenLaw forbidden;
  ShadowLaws shadow(forbidden, {&forbidden}, rule());
  ShadowPoint p = point(1.0, 1.0);
  p.in_contact = false;
  std::vector<ShadowError> e(1);
  shadow.evaluate(p, e);
  EXPECT_EQ(e[0].dF1, 0.0);
  EXPECT_EQ(e[0].dP, 0.0);
  shadow.record_step(0.0, p);
  shadow.record_step(0.5, p);
  EXPECT_EQ(shadow.phase_time()[static_cast<int>(MotionPhase::airborne)], 0.5);
  EXPECT_EQ(shadow.statistics(0).errors[kMotionPhases][0].count(), 0);  // no contact state counted
}

TEST(DynShadowLaws, AFailingShadowLawGivesNaNAndIsCountedWithItsFirstTime) {
  const SmoothTestLaw own;
  const ThrowingTestLaw throwing;     // throws below |Omega| = 5
  const PoleTestLaw pole(0.5);        // infinite F2 below U = 0.5
  ShadowLaws shadow(own, {&throwing, &pole}, rule());
  std::vector<ShadowError> e(2);
  shadow.evaluate(point(1.0, 1.0), e);
  EXPECT_TRUE(std::isnan(e[0].dF1));
  EXPECT_TRUE(std::isfinite(e[1].dF1));
  shadow.evaluate(point(0.1, 10.0), e);
  EXPECT_TRUE(std::isfinite(e[0].dM));
  EXPECT_TRUE(std::isnan(e[1].dF2));

  shadow.record_step(0.0, point(1.0, 10.0));  // both fine
  shadow.record_step(0.1, point(1.0, 1.0));   // the throwing law fails
  shadow.record_step(0.2, point(0.1, 10.0));  // the pole law fails
  shadow.record_step(0.3, point(0.1, 1.0));   // both fail
  EXPECT_EQ(shadow.statistics(0).failures, 2);
  EXPECT_EQ(shadow.statistics(0).first_failure_time, 0.1);
  EXPECT_NE(shadow.statistics(0).first_failure.find("Omega below 5"), std::string::npos);
  EXPECT_EQ(shadow.statistics(1).failures, 2);
  EXPECT_EQ(shadow.statistics(1).first_failure_time, 0.2);
  // The energy integral leaves out every step with a failure at one of its ends.
  EXPECT_NEAR(shadow.statistics(0).skipped_time, 0.3, 1e-15);
  EXPECT_NEAR(shadow.statistics(1).skipped_time, 0.2, 1e-15);
  EXPECT_EQ(shadow.steps(), 3);
}

TEST(DynShadowLaws, TheEnergyDifferenceIsTheTrapezoidalIntegralOfDP) {
  // A shadow law with F1 = kN/2 against a constant-kN law, at a slip U(t) = 2 - t with no spin:
  // dP = -(kN/2) U, linear in t, which the trapezoidal rule integrates exactly:
  // int_0^1 dP dt = -(kN/2) (2 - 1/2).
  const CoulombCircleTestLaw own;  // F1 = kN, M = 0 at Omega = 0
  class HalfSlide final : public friction::FrictionLaw {
   public:
    [[nodiscard]] std::string_view name() const override { return "test-half"; }
    [[nodiscard]] std::string_view summary() const override { return "F1 = kN/2 (tests)"; }

   private:
    [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
      return {0.5 * in.k * in.N, 0.0, 0.0};
    }
  } half;
  ShadowLaws shadow(own, {&half}, rule());
  const double kN = 0.3 * 10.0;
  for (int i = 0; i <= 7; ++i) {
    const double t = i / 7.0;
    shadow.record_step(t, point(2.0 - t, 0.0));
  }
  EXPECT_NEAR(shadow.statistics(0).difference, -0.5 * kN * 1.5, 1e-13);
  EXPECT_NEAR(shadow.own_dissipated(), kN * 1.5, 1e-13);
  EXPECT_NEAR(shadow.phase_time()[static_cast<int>(MotionPhase::sliding)], 1.0, 1e-15);
  // Every state has |dF1| = 1/2: its median and maximum.
  const LogHistogram& f1 = shadow.statistics(0).errors[static_cast<int>(MotionPhase::sliding)][0];
  EXPECT_EQ(f1.quantile(0.5), 0.5);
  EXPECT_EQ(f1.max(), 0.5);
}

TEST(DynShadowLaws, StatisticsWeighEachStateByTheTimeItStandsFor) {
  // Ten short steps (1 ms each) with |dF1| = 1/2, then one long step (1 s) with |dF1| = 0: by time the
  // median is 0, by count it would be 1/2.
  const CoulombCircleTestLaw own;  // F1 = kN at U > 0, 0 at U = 0
  class HalfAtSpeed final : public friction::FrictionLaw {
   public:
    [[nodiscard]] std::string_view name() const override { return "test-half-fast"; }
    [[nodiscard]] std::string_view summary() const override { return "tests"; }

   private:
    [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
      return {in.U > 1.0 ? 0.5 * in.k * in.N : in.k * in.N, 0.0, 0.0};
    }
  } law;
  ShadowLaws shadow(own, {&law}, rule());
  shadow.record_step(0.0, point(2.0, 0.0));
  for (int i = 1; i <= 10; ++i) shadow.record_step(i * 1e-3, point(2.0, 0.0));
  shadow.record_step(1.01, point(0.5, 0.0));
  const LogHistogram& f1 = shadow.statistics(0).errors[kMotionPhases][0];
  EXPECT_EQ(f1.quantile(0.5), 0.0);
  EXPECT_EQ(f1.quantile(0.995), 0.5);
  EXPECT_EQ(f1.count(), 12);  // the opening state is counted with no weight
}

TEST(DynShadowLaws, AHeldContactHasTheRunsLawEvaluatedAtItsInput) {
  // own_known false: the friction the run applied is not the law's (stick, a hold), so the shadow
  // evaluates the run's law itself: a law against itself is then still exactly right.
  const SmoothTestLaw law;
  ShadowLaws shadow(law, {&law}, rule());
  ShadowPoint p = point(1e-4, 1e-3);
  p.own = {123.0, 4.0, 5.0};  // a stick wrench, not the law's
  p.own_known = false;
  std::vector<ShadowError> e(1);
  shadow.evaluate(p, e);
  EXPECT_EQ(e[0].dF1, 0.0);
  EXPECT_EQ(e[0].dM, 0.0);
  EXPECT_EQ(shadow.phase(p), MotionPhase::near_rest);
}

}  // namespace
}  // namespace frictionlab::dynamics
