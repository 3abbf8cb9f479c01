#include "dynamics/rigid_rolling/rattleback_presets.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/rigid_rolling/inertia_misalignment.h"
#include "dynamics/rigid_rolling/steady_spin.h"
#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace rattleback_presets_test {

TEST(DynRigidRattlebackPresets, KaneLevinsonIsTheCitedBody) {
  const EllipsoidBody b = kane_levinson_rattleback();
  EXPECT_EIGEN_NEAR(b.semi_axes, Eigen::Vector3d(0.20, 0.03, 0.02), 0.0);
  EXPECT_EQ(b.centre_height, 0.01);
  EXPECT_EQ(b.mass, 1.0);
  Eigen::Matrix3d per_unit_mass_cm2;
  per_unit_mass_cm2 << 2.0, 0.2, 0.0, 0.2, 16.0, 0.0, 0.0, 0.0, 17.0;
  EXPECT_EIGEN_NEAR(b.inertia / b.mass * 1e4, per_unit_mass_cm2, 1e-13);
}

TEST(DynRigidRattlebackPresets, KaneLevinsonRestPointAndMisalignment) {
  const SteadySpinBody lin = steady_spin_body(kane_levinson_rattleback());
  EXPECT_NEAR(lin.height, 0.01, 1e-17);
  EXPECT_NEAR(lin.radius_1, 2.0, 1e-15);    // a1^2/a3
  EXPECT_NEAR(lin.radius_2, 0.045, 1e-17);  // a2^2/a3
  // The axis of least inertia is turned clockwise (seen from above) from the long axis.
  EXPECT_NEAR(misalignment_angle(lin.inertia), 0.5 * std::atan2(-0.4, 14.0), 1e-15);
  EXPECT_LT(misalignment_angle(lin.inertia), 0.0);
}

TEST(DynRigidRattlebackPresets, KaneLevinsonCounterClockwiseSpinIsFastUnstable) {
  // Both senses are unstable without dissipation; with J12 = +0.2 cm^2 (z up) spin n > 0
  // (counter-clockwise seen from above) grows through the pitch mode, n < 0 through the roll mode,
  // slower at slow spin by the ratio of the uncoupled squared frequencies (docs §2.2:
  // alpha_pitch/|alpha_roll| = wp^2/wr^2 to first order in J12, i.e. to ~1e-3 here).
  const SteadySpinBody lin = steady_spin_body(kane_levinson_rattleback());
  const SlowSpinCoefficients first = small_misalignment_coefficients(lin);
  const double frequency_ratio = first.pitch_frequency * first.pitch_frequency / (first.roll_frequency * first.roll_frequency);
  constexpr double n = 0.01;
  const double up = steady_spin_growth_rate(lin, n), down = steady_spin_growth_rate(lin, -n);
  EXPECT_GT(down, 0.0);
  EXPECT_NEAR(up / down, frequency_ratio, 0.01 * frequency_ratio);
  for (double spin : {0.5, 5.0, 20.0}) {
    EXPECT_GT(steady_spin_growth_rate(lin, spin), 5.0 * steady_spin_growth_rate(lin, -spin)) << spin;
    EXPECT_GT(steady_spin_growth_rate(lin, -spin), 0.0) << spin;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
