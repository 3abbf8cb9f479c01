#include "dynamics/core/step_sampler.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "dynamics/body/equations_of_motion.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace step_sampler_test {

// The egg in free flight without gravity, spinning about its symmetry axis at w: omega stays
// (0, 0, w); gamma and v turn about e3 at -w (gamma' = gamma x omega); eps grows at the constant
// vertical speed v.gamma (r(gamma).gamma depends on gamma3 only, which is fixed). The pose
// (dynamics/body/state.h): the orientation turns by w t about body e3, q = q0 (cos(w t/2), 0, 0,
// sin(w t/2)), and the centre moves at the constant world velocity q0 v0.
struct SpinningFlight {
  double w = 30.0;
  Eigen::Vector3d v0{0.3, -0.2, 0.1};
  Eigen::Vector3d g0 = Eigen::Vector3d(0.3, 0.1, 0.9).normalized();
  double eps0 = 0.5;

  [[nodiscard]] StateVector at(double t) const {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(-w * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    StateVector x = make_state(turn * v0, {0.0, 0.0, w}, turn * g0, eps0 + v0.dot(g0) * t);
    const Eigen::Vector4d o = orientation_from(g0, 0.0);
    const Eigen::Quaterniond q0(o[0], o[1], o[2], o[3]);
    const Eigen::Quaterniond q = q0 * Eigen::Quaterniond(Eigen::AngleAxisd(w * t, Eigen::Vector3d::UnitZ()));
    orientation(x) << q.w(), q.x(), q.y(), q.z();
    position(x) = (q0 * v0 * t).head<2>();
    return x;
  }
};

using AcceptedStep = AcceptedStepOf<StateVector>;
const BodyMode kFree{};  // the body's one mode

AcceptedStep exact_step(const BodyOnPlane& sys, const SpinningFlight& f, double t0, double h) {
  AcceptedStep s;
  s.t0 = t0;
  s.t1 = t0 + h;
  s.x0 = f.at(s.t0);
  s.x1 = f.at(s.t1);
  sys(s.t0, s.x0, s.f0);
  sys(s.t1, s.x1, s.f1);
  return s;
}

TEST(DynStepSampler, SamplesInsideAStepAreAsAccurateAsItsEnds) {
  // A step of w h = 0.2 (rk8pd's local error ~ (w h)^9/9! ~ 1e-12, what the tolerances of the
  // tests accept). One rk8pd step of size tau from x0 errs by less; the cubic Hermite interpolant
  // errs by ~(w h)^4/384 ~ 4e-6 of the state.
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(testing::egg_body("egg-printed"), PlaneContact{0.1, 1e7, 0.0}, law);
  const SpinningFlight f;
  const double h = 0.2 / f.w;
  const AcceptedStep step = exact_step(sys, f, 0.1, h);
  StepSamplerOf<BodyOnPlane> sampler("rk8pd", sys, kFree);
  double worst_hermite = 0.0;
  for (const double u : {0.1, 0.37, 0.5, 0.81}) {
    const double t = step.t0 + u * h;
    EXPECT_EIGEN_NEAR(sampler.at(step, t), f.at(t), 1e-13) << "u = " << u;
    worst_hermite = std::max(worst_hermite, (cubic_hermite(step, t) - f.at(t)).norm());
  }
  EXPECT_GT(worst_hermite, 1e-7);
  EXPECT_EQ(sampler.hermite_fallbacks(), 0);
  EXPECT_EQ(sampler.rhs_calls(), 4 * 12);  // rk8pd: 13 stages, the first is x'(t0)
}

TEST(DynStepSampler, InterpolatedSamplesAreTheCubicHermiteInterpolantAtNoRhsCall) {
  // The sampler of an observer that asks for interpolated samples (Observer::sample_accuracy):
  // the interpolant of order 4, within (w h)^4/384 ~ 4e-6 of the flight, the ends exact.
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(testing::egg_body("egg-printed"), PlaneContact{0.1, 1e7, 0.0}, law);
  const SpinningFlight f;
  const double h = 0.2 / f.w;
  const AcceptedStep step = exact_step(sys, f, 0.1, h);
  StepSamplerOf<BodyOnPlane> sampler("rk8pd", sys, kFree, SampleAccuracy::interpolated);
  for (const double u : {0.1, 0.37, 0.5, 0.81}) {
    const double t = step.t0 + u * h;
    EXPECT_EIGEN_NEAR(sampler.at(step, t), cubic_hermite(step, t), 0.0) << "u = " << u;
    EXPECT_EIGEN_NEAR(sampler.at(step, t), f.at(t), 1e-5) << "u = " << u;
  }
  EXPECT_EIGEN_NEAR(sampler.at(step, step.t1), step.x1, 0.0);
  EXPECT_EQ(sampler.rhs_calls(), 0);
  EXPECT_EQ(sampler.hermite_fallbacks(), 0) << "interpolation by choice is no fallback";
}

TEST(DynStepSampler, TheEndsAreReturnedExactly) {
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(testing::egg_body("egg-printed"), PlaneContact{0.1, 1e7, 0.0}, law);
  const AcceptedStep step = exact_step(sys, SpinningFlight{}, 0.0, 0.01);
  StepSamplerOf<BodyOnPlane> sampler("rkf45", sys, kFree);
  EXPECT_EIGEN_NEAR(sampler.at(step, step.t0), step.x0, 0.0);
  EXPECT_EIGEN_NEAR(sampler.at(step, step.t1), step.x1, 0.0);
  EXPECT_EQ(sampler.rhs_calls(), 0);
}

TEST(DynStepSampler, TheCubicHermiteInterpolantIsOfOrderFour) {
  // Its error at mid-step falls 16-fold when the step is halved.
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(testing::egg_body("egg-printed"), PlaneContact{0.1, 1e7, 0.0}, law);
  const SpinningFlight f;
  double previous = 0.0;
  for (const double h : {0.02, 0.01, 0.005}) {
    const AcceptedStep step = exact_step(sys, f, 0.0, h);
    const double e = (cubic_hermite(step, 0.5 * h) - f.at(0.5 * h)).norm();
    if (previous > 0.0) {
      EXPECT_NEAR(std::log2(previous / e), 4.0, 0.1) << "h = " << h;
    }
    previous = e;
  }
}

TEST(DynStepSampler, UsesTheRunsOneStepMethodAndRk8pdForAMultistepOne) {
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(testing::egg_body("egg-printed"), PlaneContact{0.1, 1e7, 0.0}, law);
  EXPECT_EQ(StepSamplerOf<BodyOnPlane>("rkck", sys, kFree).method(), "rkck");
  EXPECT_EQ(StepSamplerOf<BodyOnPlane>("msadams", sys, kFree).method(), "rk8pd");
  EXPECT_THROW(StepSamplerOf<BodyOnPlane>("euler", sys, kFree), std::invalid_argument);
}

// A law that rejects every contact: a sampling step that runs into it falls back on Hermite.
class RejectingLaw final : public friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-rejecting"; }
  [[nodiscard]] std::string_view summary() const override { return "always throws (tests)"; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput&) const override {
    throw std::invalid_argument("test: rejected");
  }
};

TEST(DynStepSampler, FallsBackOnHermiteWhereTheRightHandSideFails) {
  const RejectingLaw law;
  const BodyOnPlane sys(testing::sphere_body(0.05, 1.0), PlaneContact{0.2, 1e7, 9.81}, law);
  AcceptedStep step;
  step.t0 = 0.0;
  step.t1 = 1e-3;
  step.x0 = make_state({0.1, 0, 0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), -1e-4);  // in contact
  step.x1 = step.x0;
  step.f0.setZero();
  step.f1.setZero();
  StepSamplerOf<BodyOnPlane> sampler("rk8pd", sys, kFree);
  EXPECT_EIGEN_NEAR(sampler.at(step, 5e-4), cubic_hermite(step, 5e-4), 0.0);
  EXPECT_EQ(sampler.hermite_fallbacks(), 1);
}

}  // namespace
}  // namespace frictionlab::dynamics
