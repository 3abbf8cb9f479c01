#include "dynamics/body/equations_of_motion.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>

#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

// Counts heap allocations in this test program (the right-hand side must make none).
#include "bench/allocation_counter.h"
using frictionlab::bench::g_allocations;

namespace frictionlab::dynamics {
namespace equations_of_motion_test {

using testing::egg_body;
using testing::SmoothTestLaw;

// Central differences along the flow with step h: truncation ~h^2 |E'''|, rounding ~eps |E| / h.
// With h = 1e-7 s both stay below 1e-6 of the rate for these states.
constexpr double kFlowStep = 1e-7;
constexpr double kRateRelTol = 1e-6;

PlaneContact paper_plane() { return {0.1, 1e7, 9.81}; }

StateVector random_contact_state(std::mt19937& rng) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> depth(1e-5, 3e-4);
  const Eigen::Vector3d g = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
  return make_state(Eigen::Vector3d(n(rng), n(rng), n(rng)) * 0.3, Eigen::Vector3d(n(rng), n(rng), n(rng)) * 20.0,
                    g, -depth(rng));
}

// d/dt f(x) along the flow, by central differences.
template <class F>
double rate_along_flow(const BodyOnPlane& sys, const StateVector& x, F f) {
  StateVector d;
  sys(0.0, x, d);
  const StateVector xp = x + kFlowStep * d;
  const StateVector xm = x - kFlowStep * d;
  return (f(xp) - f(xm)) / (2.0 * kFlowStep);
}

TEST(DynEquationsOfMotion, EnergyRateIsMinusTheFrictionPower) {
  // E' = -(F1 U + M Omega) is the whole energy balance of eqs. (2)-(6): a sign error in any
  // force, torque, lever arm or in eq. (5) breaks it.
  const SmoothTestLaw law;
  for (const char* preset : {"egg-printed", "egg-homogeneous"}) {
    const BodyOnPlane sys(egg_body(preset), paper_plane(), law);
    std::mt19937 rng(7);
    for (int i = 0; i < 20; ++i) {
      const StateVector x = random_contact_state(rng);
      const ContactState c = sys.contact_state(x);
      ASSERT_TRUE(c.in_contact);
      const double power = c.friction.F1 * c.U + c.friction.M * c.Omega;
      const double dE = rate_along_flow(sys, x, [&](const StateVector& y) { return sys.energy(y); });
      const double scale = std::abs(power) + c.N * std::abs(c.u.dot(c.gamma)) + 1e-3;
      EXPECT_NEAR(dE, -power, kRateRelTol * scale) << preset << " sample " << i;
      // The work states integrate exactly this power.
      StateVector d;
      sys(0.0, x, d);
      EXPECT_DOUBLE_EQ(slide_work(d) + spin_work(d), power);
    }
  }
}

TEST(DynEquationsOfMotion, ContactHeightMovesWithTheCentreOfMass) {
  // eps = h + r(gamma).gamma, so h = eps - r.gamma must move at the vertical speed v.gamma of the
  // centre of mass: this checks eq. (5) and the contact-point kinematics together.
  const SmoothTestLaw law;
  const BodyOnPlane sys(egg_body("egg-printed"), paper_plane(), law);
  std::mt19937 rng(11);
  for (int i = 0; i < 20; ++i) {
    const StateVector x = random_contact_state(rng);
    const auto h = [&](const StateVector& y) {
      const ContactState c = sys.contact_state(y);
      return height(y) - c.point.r.dot(c.gamma);
    };
    const double vz = velocity(x).dot(vertical(x).normalized());
    EXPECT_NEAR(rate_along_flow(sys, x, h), vz, kRateRelTol * (std::abs(vz) + 1.0)) << "sample " << i;
  }
}

TEST(DynEquationsOfMotion, FrictionOpposesTheSlipAndActsAtTheContactPoint) {
  const SmoothTestLaw law;
  const BodyOnPlane sys(egg_body("egg-homogeneous"), paper_plane(), law);
  std::mt19937 rng(3);
  for (int i = 0; i < 10; ++i) {
    const StateVector x = random_contact_state(rng);
    const ContactState c = sys.contact_state(x);
    const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
    const Eigen::Vector3d F = c.force - c.N * c.gamma;
    EXPECT_NEAR(F.dot(slip), -c.friction.F1 * c.U, 1e-12 * (1.0 + c.friction.F1 * c.U));
    // Eq. (7) in the slip frame: F = -F1 e1 - F2 e2 with e1 along the slip and e2 = gamma x e1.
    ASSERT_GT(c.U, 0.0);
    EXPECT_EIGEN_NEAR(c.e1, Eigen::Vector3d(slip / c.U), 1e-14);
    EXPECT_NEAR(F.dot(c.e1), -c.friction.F1, 1e-12 * c.N);
    EXPECT_NEAR(F.dot(c.gamma.cross(c.e1)), -c.friction.F2, 1e-12 * c.N);
    EXPECT_GT(std::abs(c.friction.F2), 1e-6 * c.N);  // the test law's F2 is exercised
    EXPECT_NEAR(F.dot(c.gamma), 0.0, 1e-12 * c.N);
    EXPECT_EIGEN_NEAR(c.torque, Eigen::Vector3d(c.point.r.cross(c.force) - c.friction.M * c.gamma), 1e-12);
    EXPECT_GE(c.psi.radians(), 0.0);
    EXPECT_LT(c.psi.radians(), std::numbers::pi);
    // The law gets the major axis as a direction (no angle formed), unit to rounding, on the side
    // sin psi >= 0 that psi in [0, pi) names.
    EXPECT_TRUE(c.psi.is_direction());
    EXPECT_NEAR(std::hypot(c.psi.cos_sin().c, c.psi.cos_sin().s), 1.0, 1e-15);
    EXPECT_GE(c.psi.cos_sin().s, 0.0);
    EXPECT_GE(c.a, c.b);
  }
}

TEST(DynEquationsOfMotion, NoFrictionOutOfContact) {
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(egg_body("egg-printed"), paper_plane(), law);
  StateVector x = make_state({0.1, 0.2, 0.3}, {1.0, 2.0, 3.0}, Eigen::Vector3d(0.3, 0.1, 0.9).normalized(), 1e-3);
  StateVector d;
  sys(0.0, x, d);  // ForbiddenLaw fails the test if called
  const ContactState c = sys.contact_state(x);
  EXPECT_FALSE(c.in_contact);
  EXPECT_EQ(c.N, 0.0);
  EXPECT_EQ(c.a, 0.0);
  height(x) = 0.0;  // touching, N = 0: still no friction
  sys(0.0, x, d);
  // Free flight: v' = -omega x v - g gamma.
  const Eigen::Vector3d g = vertical(x).normalized();
  EXPECT_EIGEN_NEAR(Eigen::Vector3d(velocity(d)),
                  Eigen::Vector3d(-Eigen::Vector3d(angular_velocity(x)).cross(Eigen::Vector3d(velocity(x))) - 9.81 * g),
                  1e-14);
}

TEST(DynEquationsOfMotion, ZeroSlipTakesTheMajorAxisAsE1) {
  const SmoothTestLaw law;
  const BodyOnPlane sys(egg_body("egg-printed"), paper_plane(), law);
  const Eigen::Vector3d g = Eigen::Vector3d(0.3, 0.2, 0.9).normalized();
  // omega along gamma and v = -omega x r: the contact point does not move.
  const Eigen::Vector3d w = 10.0 * g;
  const ContactPoint cp = sys.geometry().contact_point(g);
  const StateVector x = make_state(-w.cross(cp.r), w, g, -1e-4);
  const ContactState c = sys.contact_state(x);
  EXPECT_EQ(c.U, 0.0);
  EXPECT_EQ(c.psi.radians(), 0.0);
  EXPECT_NEAR(c.psi.cos_sin().c, 1.0, 1e-15);
  EXPECT_NEAR(c.Omega, 10.0, 1e-13);
  EXPECT_NEAR(c.e1.dot(g), 0.0, 1e-15);
}

TEST(DynEquationsOfMotion, PsiIsTheAngleFromTheSlipToTheMajorAxisCounterClockwise) {
  // Oblate spheroid on its equator, gamma = body e1: the major axis is the parallel, along body
  // e2; counter-clockwise about gamma turns e2 into e3. A slip at angle theta from e2 towards e3
  // sees the major axis at -theta, i.e. psi = pi - theta in [0, pi).
  const SmoothTestLaw law;
  BodySpec spec;
  spec.preset = "spheroid";
  spec.semi_axes = std::array<double, 2>{0.2, 0.05};
  spec.mass = 1.0;
  const BodyOnPlane sys(make_body(spec), paper_plane(), law);
  for (const double theta : {0.3, 1.2, 2.0}) {
    const Eigen::Vector3d slip(0.0, std::cos(theta), std::sin(theta));
    const StateVector x = make_state(0.5 * slip, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), -1e-4);
    const ContactState c = sys.contact_state(x);
    EXPECT_NEAR(c.psi.radians(), std::numbers::pi - theta, 1e-12) << "theta = " << theta;
    EXPECT_NEAR(c.psi.cos_sin().c, -std::cos(theta), 1e-15) << "theta = " << theta;
    EXPECT_NEAR(c.psi.cos_sin().s, std::sin(theta), 1e-15) << "theta = " << theta;
    EXPECT_NEAR(c.a / c.b, 0.2 / 0.05, 1e-12);  // sqrt(R_parallel / R_meridian) = sqrt(a / (c^2/a))
  }
}

TEST(DynEquationsOfMotion, GammaIsRenormalisedWhereItIsRead) {
  const SmoothTestLaw law;
  const BodyOnPlane sys(egg_body("egg-printed"), paper_plane(), law);
  std::mt19937 rng(5);
  const StateVector x = random_contact_state(rng);
  StateVector y = x;
  vertical(y) *= 1.0 + 1e-9;
  const ContactState a = sys.contact_state(x), b = sys.contact_state(y);
  EXPECT_EIGEN_NEAR(a.gamma, b.gamma, 1e-15);
  EXPECT_EIGEN_NEAR(a.force, b.force, 1e-12 * a.force.norm());
  // Eq. (4) conserves |gamma|.
  StateVector d;
  sys(0.0, x, d);
  EXPECT_NEAR(Eigen::Vector3d(vertical(d)).dot(Eigen::Vector3d(vertical(x))), 0.0, 1e-12);
}

TEST(DynEquationsOfMotion, TheRightHandSideMakesNoHeapAllocation) {
  // A later study times laws along trajectories: the RHS around the law must stay lean.
  for (const char* name : {"exact", "pade-printed"}) {
    const auto law = friction::make_law(name);
    const BodyOnPlane sys(egg_body("egg-printed"), paper_plane(), *law);
    std::mt19937 rng(13);
    std::vector<StateVector> xs;
    for (int i = 0; i < 50; ++i) xs.push_back(random_contact_state(rng));
    StateVector d;
    sys(0.0, xs.front(), d);  // warm-up
    const long long before = g_allocations.load();
    for (const auto& x : xs) sys(0.0, x, d);
    EXPECT_EQ(g_allocations.load() - before, 0) << name;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
