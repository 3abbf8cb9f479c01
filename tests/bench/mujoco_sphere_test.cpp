// MuJoCo itself (built only when MuJoCo is installed) against the closed form of its elliptic
// cone: a sphere spinning in place on a plane, with condim 4, is decelerated by the torque on the
// cone's boundary, N mu3 (friction/mujoco_elliptic_law.h), so its spin falls at m g mu3 / C.

#include "bench/mujoco/mujoco_sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace frictionlab::mujoco_side {
namespace mujoco_sphere_test {

TEST(MujocoSphere, PureSpinDeceleratesAtTheConesTorqueLimit) {
  SphereSpec s;  // R = 5 cm, m = 1 kg, k = 0.2, g = 9.81
  s.A = s.C = 0.4 * s.mass * s.R * s.R;
  s.torsional = 3.7e-4;
  s.omega0 = {0.0, 0.0, 20.0};
  s.t_end = 1.0;
  s.output_dt = 0.1;
  const auto xml = std::filesystem::temp_directory_path() / ("mujoco_sphere_" + std::to_string(::getpid()) + ".xml");
  const auto samples = run_sphere(s, xml);
  std::filesystem::remove(xml);
  ASSERT_EQ(samples.size(), 11u);
  // Past the launch transient (the soft contact settles its normal force within ~0.2 s: solref
  // time constant 0.02 s), the spin falls linearly at m g mu3 / C. MuJoCo's Newton solver with
  // tolerance 1e-12 holds it to 1e-6 relative (observed ~1e-7).
  const double slope = (samples[3].Omega - samples[10].Omega) / (samples[10].t - samples[3].t);
  EXPECT_NEAR(slope, s.mass * s.g * s.torsional / s.C, 1e-6 * slope);
  for (std::size_t i = 3; i < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].N, s.mass * s.g, 1e-3 * s.mass * s.g) << "t = " << samples[i].t;
    EXPECT_NEAR(std::abs(samples[i].tau), samples[i].N * s.torsional, 1e-4 * samples[i].N * s.torsional);
    EXPECT_LT(samples[i].U, 1e-9);  // no slip: the sphere spins in place
  }
}

TEST(MujocoSphere, BadSpecIsNamed) {
  SphereSpec s;
  s.torsional = 1e-6;  // below mjMINMU = 1e-5, which MuJoCo would silently raise
  EXPECT_THROW(s.validate(), std::invalid_argument);
  s = SphereSpec{};
  s.solref_timeconst = s.timestep;  // MuJoCo needs at least two steps per time constant
  EXPECT_THROW(s.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::mujoco_side
