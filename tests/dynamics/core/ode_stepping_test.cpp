#include "dynamics/core/ode_stepping.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

namespace frictionlab::dynamics {
namespace ode_stepping_test {

// x' = -x (both components), refusing (retry) any trial state whose first component falls below
// `floor`, and stopping at t >= `stop_at`.
class Decay final : public OdeRhs {
 public:
  RhsStatus operator()(double t, const double* x, double* f) override {
    ++calls;
    if (t >= stop_at) return RhsStatus::stop;
    if (x[0] < floor) return RhsStatus::retry;
    f[0] = -x[0];
    f[1] = -x[1];
    return RhsStatus::ok;
  }
  double floor = -1.0;
  double stop_at = 1e300;
  long calls = 0;
};

IntegratorOptions tight() {
  IntegratorOptions io;
  io.abs_tol = 1e-12;
  io.rel_tol = 1e-12;
  return io;
}

TEST(DynOdeStepping, FreeStepsFollowTheClosedForm) {
  Decay rhs;
  const double scale[2] = {1.0, 1.0};
  FreeStepper stepper(rhs, 2, tight(), scale);
  double x[2] = {1.0, -2.0};
  double t = 0.0, h = 1e-3;
  int steps = 0;
  while (t < 2.0) {
    ASSERT_EQ(stepper.advance(t, 2.0, h, x).kind, StepOutcome::accepted);
    ++steps;
    EXPECT_NEAR(x[0], std::exp(-t), 1e-11);
    EXPECT_NEAR(stepper.derivative_at_end()[1], 2.0 * std::exp(-t), 1e-10);
  }
  EXPECT_EQ(t, 2.0);  // the last step is cut to land on t_end
  EXPECT_LT(steps, 40);
}

TEST(DynOdeStepping, ARefusedStateHalvesTheStepAndAStopFailsIt) {
  Decay rhs;
  rhs.floor = std::exp(-1.0);  // reached at t = 1: no step may go past it
  const double scale[2] = {1.0, 1.0};
  FreeStepper stepper(rhs, 2, tight(), scale);
  double x[2] = {1.0, 1.0};
  double t = 0.0, h = 1e-3;
  StepOutcome out;
  for (int i = 0; i < 100000 && (out = stepper.advance(t, 5.0, h, x)).kind == StepOutcome::accepted; ++i) {
  }
  EXPECT_EQ(out.kind, StepOutcome::failed);
  EXPECT_FALSE(out.gsl_message.empty());
  EXPECT_GT(stepper.failed_steps(), 0);

  Decay stopping;
  stopping.stop_at = 0.5;
  FreeStepper stopper(stopping, 2, tight(), scale);
  double y[2] = {1.0, 1.0};
  t = 0.0;
  h = 1e-3;
  for (int i = 0; i < 100000 && (out = stopper.advance(t, 5.0, h, y)).kind == StepOutcome::accepted; ++i) {
  }
  EXPECT_EQ(out.kind, StepOutcome::stopped_by_rhs);
}

// Advances `n` accepted steps from (t, x) with the trial size h0 (too large for the tolerance: GSL
// rejects trial steps before it accepts one).
void advance_steps(FreeStepper& stepper, double& t, double* x, double h0, int n) {
  double h = h0;
  for (int i = 0; i < n; ++i) ASSERT_EQ(stepper.advance(t, 50.0, h, x).kind, StepOutcome::accepted);
}

// GSL zeroes its count of failed steps when the driver is reset (the run loop resets at every jump
// of the state or the mode): the count must go on. Expected: the counts of fresh steppers that take
// the same two stretches (a reset stepper is a fresh one).
TEST(DynOdeStepping, RejectedStepsAreCountedAcrossResets) {
  Decay rhs;
  const double scale[2] = {1.0, 1.0};
  FreeStepper stepper(rhs, 2, tight(), scale);
  double x[2] = {1.0, -2.0};
  double t = 0.0;
  advance_steps(stepper, t, x, 5.0, 3);
  const double t_reset = t;
  const double x_reset[2] = {x[0], x[1]};
  stepper.reset();
  advance_steps(stepper, t, x, 5.0, 3);

  FreeStepper first(rhs, 2, tight(), scale);
  double x1[2] = {1.0, -2.0};
  double t1 = 0.0;
  advance_steps(first, t1, x1, 5.0, 3);
  ASSERT_EQ(t1, t_reset);
  FreeStepper second(rhs, 2, tight(), scale);
  double x2[2] = {x_reset[0], x_reset[1]};
  double t2 = t_reset;
  advance_steps(second, t2, x2, 5.0, 3);
  ASSERT_EQ(t2, t);

  EXPECT_GT(first.failed_steps(), 0);
  EXPECT_GT(second.failed_steps(), 0);
  EXPECT_EQ(stepper.failed_steps(), first.failed_steps() + second.failed_steps());
}

TEST(DynOdeStepping, ASubStepIsOneStepOfTheMethod) {
  Decay rhs;
  SubStepper sub("rk8pd", rhs, 2);
  const double x0[2] = {1.0, 3.0};
  const double f0[2] = {-1.0, -3.0};
  double out[2];
  ASSERT_TRUE(sub.step(0.0, x0, f0, 0.1, out));
  EXPECT_NEAR(out[0], std::exp(-0.1), 1e-15);
  EXPECT_NEAR(out[1], 3.0 * std::exp(-0.1), 4e-15);
  EXPECT_EQ(rhs.calls, 12);  // 13 stages, the first is f0
  EXPECT_EQ(SubStepper("msadams", rhs, 2).method(), "rk8pd");

  rhs.floor = 2.0;  // every stage is refused
  EXPECT_FALSE(sub.step(0.0, x0, f0, 0.1, out));
}

TEST(DynOdeStepping, TheCubicHermiteInterpolantIsExactForCubics) {
  using V = Eigen::Vector2d;
  // x(t) = (t^3, 1 - t^2): exact for every cubic.
  const auto x = [](double t) { return V(t * t * t, 1.0 - t * t); };
  const auto f = [](double t) { return V(3.0 * t * t, -2.0 * t); };
  AcceptedStepOf<V> s{0.5, x(0.5), f(0.5), 1.25, x(1.25), f(1.25)};
  for (const double t : {0.5, 0.6, 0.9, 1.25}) {
    EXPECT_NEAR((cubic_hermite(s, t) - x(t)).norm(), 0.0, 1e-14) << t;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
