// The contact model patch = "hertz" on bodies of revolution (dynamics/contact/hertz_patch.h): the sphere
// and the spheroid in closed form, the potential of the normal force, and energy conservation of
// a frictionless run.
#include "dynamics/contact/hertz_patch.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/contact/hertz_ellipse.h"
#include "dynamics/body/simulation.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace hertz_patch_test {

using testing::egg_body;
using testing::sphere_body;

constexpr double kEStar = 2e9;  // Pa
constexpr double kRelTol = 1e-12;

Body spheroid_body(double equatorial, double polar) {
  BodySpec spec;
  spec.preset = "spheroid";
  spec.semi_axes = std::array<double, 2>{equatorial, polar};
  spec.mass = 1.0;
  return make_body(spec);
}

HertzContact at(const Body& body, const Eigen::Vector3d& gamma, double eps) {
  const ContactGeometry geometry(body.axisymmetric->profile, body.axisymmetric->com);
  return HertzNormalContact(kEStar).evaluate(geometry, geometry.contact_point(gamma), gamma, eps);
}

TEST(DynHertzPatch, SphereGivesHertzsCircleAtEveryOrientation) {
  const double R = 0.05, delta = 3e-5;
  const Body body = sphere_body(R, 1.0);
  std::mt19937 rng(1882);
  std::normal_distribution<double> n;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector3d g =
        i == 0 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    const HertzContact h = at(body, g, -delta);
    // a^2 = R delta (the section hypothesis gives 2 R delta), N = (4/3) E* sqrt(R) delta^(3/2).
    EXPECT_NEAR(h.patch.a, std::sqrt(R * delta), 1e-12 * std::sqrt(R * delta)) << g.transpose();
    EXPECT_EQ(h.patch.b, h.patch.a);
    EXPECT_TRUE(h.patch.circle);
    const double N = 4.0 / 3.0 * kEStar * std::sqrt(R) * delta * std::sqrt(delta);
    EXPECT_NEAR(h.N, N, 1e-12 * N);
    EXPECT_NEAR(h.energy, 0.4 * N * delta, 1e-12 * N * delta);
    // The stiffness does not depend on the orientation: no torque (to the difference's rounding).
    EXPECT_LE(h.torque.norm(), 1e-9 * N * delta);
  }
  // Out of contact: nothing.
  const HertzContact off = at(body, Eigen::Vector3d::UnitZ(), 1e-6);
  EXPECT_EQ(off.N, 0.0);
  EXPECT_EQ(off.patch.a, 0.0);
}

// A spheroid with semi-axes (A, A, C): at a pole the radii are both A^2/C (a circle); at the
// equator the parallel radius is A and the meridian radius C^2/A.
TEST(DynHertzPatch, SpheroidAtItsPoleIsTheCircleOfItsPolarRadius) {
  const double A = 0.04, C = 0.025, delta = 1e-5;
  for (const double c : {C, 0.07}) {
    const Body body = spheroid_body(A, c);
    const double R = A * A / c;
    for (const double s : {1.0, -1.0}) {
      const HertzContact h = at(body, {0.0, 0.0, s}, -delta);
      EXPECT_TRUE(h.patch.circle);
      EXPECT_NEAR(h.patch.a, std::sqrt(R * delta), kRelTol * std::sqrt(R * delta)) << c << " " << s;
      const double N = 4.0 / 3.0 * kEStar * std::sqrt(R) * delta * std::sqrt(delta);
      EXPECT_NEAR(h.N, N, kRelTol * N) << c << " " << s;
      EXPECT_EQ(h.torque.norm(), 0.0);
    }
  }
}

TEST(DynHertzPatch, SpheroidAtItsEquatorFollowsHertzsEllipseOfItsTwoRadii) {
  const double A = 0.04, delta = 1e-5;
  for (const double C : {0.025, 0.07}) {  // oblate: major axis along the parallel; prolate: the meridian
    const Body body = spheroid_body(A, C);
    const double R_parallel = A, R_meridian = C * C / A;
    const double R_major = std::max(R_parallel, R_meridian), R_minor = std::min(R_parallel, R_meridian);
    const HertzEllipse e = hertz_ellipse(R_major, R_minor);
    for (const double phi : {0.0, 1.0, 2.5}) {
      const Eigen::Vector3d g(std::cos(phi), std::sin(phi), 0.0);
      const HertzContact h = at(body, g, -delta);
      EXPECT_NEAR(h.patch.a, std::sqrt(2.0 * R_major * delta * e.D / e.K), kRelTol * h.patch.a) << C;
      EXPECT_NEAR(h.patch.b, e.mu * h.patch.a, kRelTol * h.patch.a) << C;
      EXPECT_NEAR(h.N, kEStar * e.stiffness_per_modulus * delta * std::sqrt(delta), kRelTol * h.N) << C;
      // The meridian in the contact plane is the body axis e3 here (gamma3 = 0).
      const Eigen::Vector3d major_expected = R_meridian > R_parallel ? Eigen::Vector3d::UnitZ() : g.cross(Eigen::Vector3d::UnitZ());
      EXPECT_NEAR(std::abs(h.patch.major.dot(major_expected)), 1.0, 1e-14) << C;
    }
  }
}

// N = dV/d(delta), and the torque is the work of V under a rotation at fixed eps: T . omega =
// -dV/dt with gamma' = gamma x omega. Central differences on the egg at random orientations.
TEST(DynHertzPatch, NormalForceAndTorqueDeriveFromThePotential) {
  const Body body = egg_body("egg-homogeneous");
  const ContactGeometry geometry(body.axisymmetric->profile, body.axisymmetric->com);
  const HertzNormalContact model(kEStar);
  std::mt19937 rng(4);
  std::normal_distribution<double> n;
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector3d g = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    const Eigen::Vector3d w = Eigen::Vector3d(n(rng), n(rng), n(rng));
    const double eps = -1e-4;
    const HertzContact h = model.evaluate(geometry, geometry.contact_point(g), g, eps);
    const auto V = [&](const Eigen::Vector3d& gg, double e) { return model.energy(geometry.contact_point(gg), e); };
    const double de = 1e-8;  // truncation (de/delta)^2/8 ~ 1e-9 relative
    EXPECT_NEAR((V(g, eps - de) - V(g, eps + de)) / (2.0 * de), h.N, 1e-8 * h.N) << g.transpose();
    // gamma(t) = exp(-t [omega]x) gamma: a rotation by -|omega| t about omega.
    const double dt = 1e-5;
    const auto turned = [&](double t) { return Eigen::AngleAxisd(-w.norm() * t, w.normalized()) * g; };
    const double dVdt = (V(turned(dt), eps) - V(turned(-dt), eps)) / (2.0 * dt);
    EXPECT_NEAR(h.torque.dot(w), -dVdt, 1e-6 * std::abs(dVdt) + 1e-12 * h.energy) << g.transpose();
    EXPECT_GT(std::abs(dVdt), 1e-3 * h.energy * w.norm()) << "the test needs a stiffness that varies";
  }
}

// lambda'(gamma3) against a central difference of lambda itself on the egg (step 1e-5: truncation
// ~1e-10 relative); one-sided at the poles.
TEST(DynHertzPatch, StiffnessSlopeMatchesDifferencesOfTheStiffness) {
  const Body body = egg_body("egg-printed");
  const ContactGeometry geometry(body.axisymmetric->profile, body.axisymmetric->com);
  const HertzNormalContact model(kEStar);
  const double h = 1e-5;
  for (const double g3 : {-0.9999, -0.8, -0.3, 0.0, 0.4, 0.9, 0.99, 0.9999}) {
    const double expected = (model.stiffness(geometry, g3 + h) - model.stiffness(geometry, g3 - h)) / (2.0 * h);
    EXPECT_NEAR(model.stiffness_slope(geometry, g3), expected, 1e-8 * model.stiffness(geometry, g3)) << "g3 = " << g3;
  }
  for (const double g3 : {1.0, -1.0}) {
    const double in = g3 > 0.0 ? -h : h;  // into [-1, 1]
    const auto lambda = [&](double x) { return model.stiffness(geometry, x); };
    // One-sided, second order: truncation ~h^2 lambda'''/3.
    const double expected = (-3.0 * lambda(g3) + 4.0 * lambda(g3 + in) - lambda(g3 + 2.0 * in)) / (2.0 * in);
    EXPECT_NEAR(model.stiffness_slope(geometry, g3), expected, 1e-7 * lambda(g3)) << "g3 = " << g3;
    EXPECT_GT(std::abs(expected), 1e-2 * lambda(g3)) << "the test needs a slope at the pole";
  }
}

TEST(DynHertzPatch, MatchedModulusGivesTheStiffnessAtTheReferenceOrientation) {
  const Body body = egg_body("egg-printed");
  const ContactGeometry geometry(body.axisymmetric->profile, body.axisymmetric->com);
  for (const double g3 : {1.0, 0.3, -1.0}) {
    const double E = modulus_matching_stiffness(geometry, 1e7, g3);
    EXPECT_NEAR(HertzNormalContact(E).stiffness(geometry, g3), 1e7, 1e-15 * 1e7 * 4);
  }
  // At the lower pole the patch is a circle of radius R_pole = P'(z_lo)/2: lambda = (4/3) E* sqrt(R).
  const double R_pole = geometry.contact_point(Eigen::Vector3d::UnitZ()).R_parallel;
  EXPECT_NEAR(modulus_matching_stiffness(geometry, 1e7, 1.0), 0.75e7 / std::sqrt(R_pole), 1e-15 * 1e7 / std::sqrt(R_pole) * 4);
}

// A frictionless egg dropped tilted onto the plane rocks (its stiffness changing with gamma3) and
// bounces for 0.4 s, integrated at the tolerance `tol`.
struct RockingRun {
  RunSummary summary;
  double gamma3_range = 0.0;  // how far it rocks
  double energy_range = 0.0;  // max - min of the energy over the samples, J
  double scale = 0.0;         // m g R, J
};

RockingRun rock_frictionless_egg(double tol) {
  const testing::CoulombCircleTestLaw law;  // k = 0: no friction at all
  const Body body = egg_body("egg-homogeneous");
  const ContactGeometry geometry(body.axisymmetric->profile, body.axisymmetric->com);
  PlaneContact plane{0.0, 1e7, 9.81};
  plane.patch = PatchModel::hertz;
  plane.E_star = modulus_matching_stiffness(geometry, 1e7, 1.0);
  const BodyOnPlane sys(body, plane, law);
  const double g3 = 0.8;
  const StateVector x0 =
      make_state(Eigen::Vector3d::Zero(), {0.0, 4.0, 0.0}, {std::sqrt(1.0 - g3 * g3), 0.0, g3}, -1e-4);
  RunOptions o;
  o.t_end = 0.4;
  o.output_dt = 1e-3;
  o.integrator.abs_tol = tol;
  o.integrator.rel_tol = tol;
  struct Track final : Observer {
    double lo = 1.0, hi = -1.0, E_min = 1e300, E_max = -1e300;
    void sample(const Sample& s) override {
      lo = std::min(lo, s.contact.gamma.z());
      hi = std::max(hi, s.contact.gamma.z());
      E_min = std::min(E_min, s.energy);
      E_max = std::max(E_max, s.energy);
    }
  } track;
  RockingRun r;
  r.summary = simulate(sys, x0, o, &track);
  r.gamma3_range = track.hi - track.lo;
  r.energy_range = track.E_max - track.E_min;
  r.scale = body.mass * 9.81 * 0.265;
  return r;
}

// Without friction the Hertz contact is conservative: the energy stays constant although the
// stiffness changes as the egg rocks (without the torque T it drifts by 4.7e-4 J).
TEST(DynHertzPatch, FrictionlessRockingEggConservesEnergy) {
  const RockingRun r = rock_frictionless_egg(1e-12);
  ASSERT_EQ(r.summary.reason, Termination::t_end) << r.summary.message;
  EXPECT_GT(r.gamma3_range, 0.05) << "the egg must rock, so that the stiffness changes";
  EXPECT_LE(r.energy_range, 1e-9 * r.scale);
  EXPECT_NEAR(r.summary.final_energy, r.summary.initial_energy, 1e-9 * r.scale);
}

// With lambda' exact, what is left of the energy's drift is the integrator's: it keeps falling as
// the tolerance tightens, below 1e-12 m g R at 1e-13. (A central difference for lambda', ~1e-10
// relative, left a floor of 1.3e-11 m g R at every tolerance from 1e-12 down.)
TEST(DynHertzPatch, TheEnergyDriftFallsWithTheIntegratorsTolerance) {
  const RockingRun coarse = rock_frictionless_egg(1e-11);
  const RockingRun fine = rock_frictionless_egg(1e-13);
  ASSERT_EQ(fine.summary.reason, Termination::t_end) << fine.summary.message;
  EXPECT_GT(fine.gamma3_range, 0.05);
  EXPECT_LT(fine.energy_range, 1e-12 * fine.scale);
  EXPECT_LT(fine.energy_range, 0.5 * coarse.energy_range) << "the drift must follow the tolerance";
}

}  // namespace
}  // namespace frictionlab::dynamics
