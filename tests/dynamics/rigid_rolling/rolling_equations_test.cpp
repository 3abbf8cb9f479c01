#include "dynamics/rigid_rolling/rolling_equations.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <random>

#include "dynamics/rigid_rolling/ellipsoid_body.h"
#include "dynamics/rigid_rolling/rattleback_presets.h"
#include "dynamics/rigid_rolling/rounded_disk_surface.h"
#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace rolling_equations_test {

// A uniform thin disk (A = m R^2/4, C = m R^2/2) of radius 5 cm with a 5 mm rim.
RigidRollingBody rounded_disk() {
  RigidRollingBody d;
  d.mass = 0.3;
  d.inertia = Eigen::Vector3d(0.3 * 0.05 * 0.05 / 4.0, 0.3 * 0.05 * 0.05 / 4.0, 0.3 * 0.05 * 0.05 / 2.0).asDiagonal();
  d.surface = std::make_shared<RoundedDiskSurface>(0.05, 0.005);
  return d;
}

RollingState random_state(std::mt19937& rng, double spin_scale) {
  std::normal_distribution<double> n;
  RollingState x;
  x.omega = spin_scale * Eigen::Vector3d(n(rng), n(rng), n(rng));
  x.gamma = Eigen::Vector3d(0.3 * n(rng), 0.3 * n(rng), 1.0).normalized();
  return x;
}

// dE/dt = grad E . f by the five-point stencil along the line x + s f(x), with s scaled so that
// the state moves by 1e-4 (its largest component): truncation ~(1e-4/0.1)^4 of E's variation on
// the ~0.1 scale of the tilt, rounding ~1e-12 E. (Second-order differences leave ~1e-7 E here.)
double energy_rate(const RigidRollingModel& model, const RollingState& x) {
  const Eigen::Matrix<double, 6, 1> f = model.derivative(x).packed();
  const Eigen::Matrix<double, 6, 1> x0 = x.packed();
  const double h = 1e-4 / f.cwiseAbs().maxCoeff();
  const auto e = [&](double s) { return model.energy(RollingState::unpacked(Eigen::Matrix<double, 6, 1>(x0 + s * f))); };
  return (e(-2.0 * h) - 8.0 * e(-h) + 8.0 * e(h) - e(2.0 * h)) / (12.0 * h);
}

TEST(DynRigidRolling, SteadySpinAboutTheRestPointIsAnEquilibrium) {
  const RigidRollingModel model(rigid_body(kane_levinson_rattleback()));
  for (double n : {-30.0, -5.0, 0.0, 0.5, 5.0, 30.0}) {
    const RollingState steady{Eigen::Vector3d(0.0, 0.0, n), Eigen::Vector3d::UnitZ()};
    const RollingState d = model.derivative(steady);
    EXPECT_EIGEN_NEAR(d.omega, Eigen::Vector3d::Zero(), 1e-12 * (1.0 + n * n)) << "n = " << n;
    EXPECT_EIGEN_NEAR(d.gamma, Eigen::Vector3d::Zero(), 1e-15 * (1.0 + std::abs(n))) << "n = " << n;
  }
  // ... and a tilted rattleback at rest is not (the test can fail).
  const RollingState tilted{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.01, 0.0, 1.0).normalized()};
  EXPECT_GT(model.derivative(tilted).omega.norm(), 1.0);
}

TEST(DynRigidRolling, ContactForceAtRestIsTheWeight) {
  const EllipsoidBody rb = kane_levinson_rattleback();
  const RigidRollingModel model(rigid_body(rb));
  const RollingState rest{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  EXPECT_EIGEN_NEAR(model.contact_force(rest), Eigen::Vector3d(0.0, 0.0, rb.mass * rb.gravity), 1e-14);
}

TEST(DynRigidRolling, EnergyIsConstantAlongTheFlowEllipsoid) {
  const RigidRollingModel model(rigid_body(kane_levinson_rattleback()));
  std::mt19937 rng(1);
  for (int i = 0; i < 50; ++i) {
    const RollingState x = random_state(rng, 5.0);
    EXPECT_NEAR(energy_rate(model, x), 0.0, 1e-8 * model.energy(x)) << i;
  }
}

TEST(DynRigidRolling, EnergyIsConstantAlongTheFlowRoundedDisk) {
  const RigidRollingModel model(rounded_disk());
  std::mt19937 rng(2);
  for (int i = 0; i < 50; ++i) {
    RollingState x = random_state(rng, 10.0);
    x.gamma = Eigen::Vector3d(x.gamma.x() + 1.0, x.gamma.y(), x.gamma.z()).normalized();  // well away from flat
    EXPECT_NEAR(energy_rate(model, x), 0.0, 1e-8 * model.energy(x)) << i;
  }
}

TEST(DynRigidRolling, SpinDampingRemovesEnergyAtItsRate) {
  constexpr double c = 2e-4;  // N m s
  const RigidRollingModel model(rigid_body(kane_levinson_rattleback(), c));
  std::mt19937 rng(4);
  for (int i = 0; i < 20; ++i) {
    const RollingState x = random_state(rng, 5.0);
    const double rate = energy_rate(model, x);
    EXPECT_NEAR(rate, -model.dissipation(x), 1e-8 * model.energy(x)) << i;
    EXPECT_NEAR(model.dissipation(x), c * x.spin() * x.spin(), 1e-15);
  }
}

TEST(DynRigidRolling, MirrorImageBodyMirrorsTheMotion) {
  // Reflecting the body in its x-z plane (y -> -y) maps J12 -> -J12 and a solution (omega, gamma)
  // to (-w1, w2, -w3; g1, -g2, g3): an exact symmetry of the equations (omega is a pseudo-vector).
  EllipsoidBody a = kane_levinson_rattleback();
  EllipsoidBody b = a;
  b.inertia(0, 1) = b.inertia(1, 0) = -a.inertia(0, 1);
  const RigidRollingModel ma(rigid_body(a)), mb(rigid_body(b));
  const Eigen::Vector3d flip_w(-1.0, 1.0, -1.0), flip_g(1.0, -1.0, 1.0);
  std::mt19937 rng(9);
  for (int i = 0; i < 20; ++i) {
    const RollingState x = random_state(rng, 5.0);
    const RollingState y{x.omega.cwiseProduct(flip_w), x.gamma.cwiseProduct(flip_g)};
    const RollingState dx = ma.derivative(x), dy = mb.derivative(y);
    EXPECT_EIGEN_NEAR(dy.omega, dx.omega.cwiseProduct(flip_w), 1e-11 * (1.0 + dx.omega.norm()));
    EXPECT_EIGEN_NEAR(dy.gamma, dx.gamma.cwiseProduct(flip_g), 1e-14 * (1.0 + dx.gamma.norm()));
  }
}

TEST(DynRigidRolling, CentreVelocityMakesTheContactPointRest) {
  const RigidRollingModel model(rigid_body(kane_levinson_rattleback()));
  std::mt19937 rng(6);
  const RollingState x = random_state(rng, 5.0);
  EXPECT_EIGEN_NEAR(model.centre_velocity(x) + x.omega.cross(model.contact_point(x)), Eigen::Vector3d::Zero(), 1e-16);
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
