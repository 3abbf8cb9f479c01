#include "dynamics/rigid_rolling/rolling_integrator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "dynamics/rigid_rolling/ellipsoid_body.h"
#include "dynamics/rigid_rolling/rattleback_presets.h"
#include "dynamics/rigid_rolling/rounded_disk_surface.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace rolling_integrator_test {

// Energy over a run at rk8pd tolerances 1e-12: the local errors (<= 1e-12 per component and step)
// add up over ~1e4 steps to ~1e-11 of the energy; 1e-9 leaves room and still fails for any
// non-conservative term (those drift by O(1) here).
constexpr double kEnergyDrift = 1e-9;

// Steady spin n tilted by (0.02, 0.01) rad: both rocking modes excited, the pitch grows for n > 0.
RollingState tilted_spin(double n) { return {Eigen::Vector3d(0.0, 0.0, n), Eigen::Vector3d(0.02, 0.01, 1.0).normalized()}; }

TEST(DynRigidRollingIntegrator, RattlebackConservesEnergyThroughAReversal) {
  const EllipsoidBody rb = kane_levinson_rattleback();
  const RigidRollingModel model(rigid_body(rb));
  RollingIntegrator integrator(model);
  double t = 0.0;
  RollingState x = tilted_spin(5.0);
  const double e0 = model.energy(x);
  double worst = 0.0, lowest_spin = x.spin();
  integrator.integrate(t, x, 6.0, [&](double, const RollingState& s) {
    worst = std::max(worst, std::abs(model.energy(s) - e0));
    lowest_spin = std::min(lowest_spin, s.spin());
    return true;
  });
  EXPECT_EQ(t, 6.0);
  EXPECT_LT(lowest_spin, -1.0) << "the run must go through a reversal for the check to mean something";
  EXPECT_LE(worst, kEnergyDrift * e0);
  EXPECT_NEAR(x.gamma.norm(), 1.0, 1e-10);
}

TEST(DynRigidRollingIntegrator, DampedRattlebackLosesWhatTheDampingDissipates) {
  constexpr double c = 1e-4;  // N m s
  const EllipsoidBody rb = kane_levinson_rattleback();
  const RigidRollingModel model(rigid_body(rb, c));
  RollingIntegrator integrator(model), midpoints(model);
  double t = 0.0, work = 0.0, t_prev = 0.0;
  RollingState x = tilted_spin(5.0), x_prev = x;
  const double e0 = model.energy(x);
  // The dissipated work by Simpson's rule on each accepted step (the midpoint state integrated
  // from the step's start): error O(h^5) per step, ~1e-10 of the energy here.
  integrator.integrate(t, x, 2.0, [&](double t_now, const RollingState& s) {
    const RollingState mid = midpoints.state_at(t_prev, x_prev, 0.5 * (t_prev + t_now));
    work += (model.dissipation(x_prev) + 4.0 * model.dissipation(mid) + model.dissipation(s)) * (t_now - t_prev) / 6.0;
    t_prev = t_now;
    x_prev = s;
    return true;
  });
  EXPECT_GT(work, 1e-4 * e0) << "the damping must do measurable work";
  EXPECT_NEAR(model.energy(x) + work, e0, 1e-8 * e0);
}

TEST(DynRigidRollingIntegrator, ObserverCanStopAndStateAtAgreesWithIntegrate) {
  const EllipsoidBody rb = kane_levinson_rattleback();
  const RigidRollingModel model(rigid_body(rb));
  const RollingState x0 = tilted_spin(2.0);
  RollingIntegrator integrator(model);
  double t = 0.0;
  RollingState x = x0;
  int calls = 0;
  integrator.integrate(t, x, 1.0, [&](double, const RollingState&) { return ++calls < 3; });
  EXPECT_EQ(calls, 3);
  EXPECT_LT(t, 1.0);
  const RollingState again = integrator.state_at(0.0, x0, t);
  EXPECT_NEAR((again.packed() - x.packed()).norm(), 0.0, 1e-10);
}

TEST(DynRigidRollingIntegrator, ModelErrorsReachTheCaller) {
  RigidRollingBody disk;
  disk.mass = 0.3;
  disk.inertia = Eigen::Vector3d(1.875e-4, 1.875e-4, 3.75e-4).asDiagonal();
  disk.surface = std::make_shared<RoundedDiskSurface>(0.05, 0.0);
  const RigidRollingModel model(disk);
  RollingIntegrator integrator(model);
  double t = 0.0;
  RollingState flat{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  EXPECT_THROW(integrator.integrate(t, flat, 1.0), std::domain_error);
  RollingIntegratorOptions bad;
  bad.abs_tol = 0.0;
  EXPECT_THROW(RollingIntegrator(model, bad), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
