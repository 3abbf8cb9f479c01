// The MuJoCo adapter (bench/engines/mujoco) against closed forms: a sliding sphere that ends rolling,
// MuJoCo's own spin law, the rocking of a sphere whose centre of mass is below its centre, and the
// adapter's contract (determinism, bad input, the start pose, the disk's contact points).

#include "bench/engines/mujoco/mujoco_engine.h"
#include "tests/bench/engines/engine_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/engines/mujoco/mujoco_world.h"

namespace frictionlab::engines {
namespace mujoco_engine_test {

using testing::lowest_point_slip;
using testing::slope;
using testing::solid_sphere;

constexpr double g = 9.81;

double norm_xy(const std::array<double, 3>& x) { return std::hypot(x[0], x[1]); }

// Problem 4 at MuJoCo's default step (0.002 s) and friction (condim 4, the pyramidal cone): a solid
// sphere launched sliding at v0 without spin rolls at 5/7 v0 from t = 2 v0 / (7 k g).
TEST(MujocoEngine, SlidingSphereRollsAtFiveSevenths) {
  const auto engine = make_mujoco_engine();
  const double R = 0.05, k = 0.2, v0 = 2.0;
  RunSpec s;
  s.body = solid_sphere(R, 1.0);
  s.friction = engine->defaults(k);
  s.start.v = {v0, 0.0, 0.0};
  s.numerics.settle_time = 0.2;  // the soft contact finds its depth before the launch
  s.t_end = 1.0;
  s.output_dt = 0.002;
  const engines::Run run = engine->run(s);
  EXPECT_EQ(run.timestep, mujoco_default_timestep);
  ASSERT_EQ(run.samples.size(), 501u);
  const double v_end = norm_xy(run.samples.back().v);
  EXPECT_NEAR(v_end / v0, 5.0 / 7.0, 0.02 * 5.0 / 7.0);
  // Slip ends: the first sample whose contact-point slip is below 1 % of v0.
  double t_roll = NAN;
  for (const auto& x : run.samples) {
    if (lowest_point_slip(x, R) < 0.01 * v0) {
      t_roll = x.t;
      break;
    }
  }
  const double t_exact = 2.0 * v0 / (7.0 * k * g);
  std::cout << "[ mujoco ] v_end / v0 = " << v_end / v0 << " (5/7 = " << 5.0 / 7.0 << "); slip < 1% v0 from t = "
            << t_roll << " s, 2 v0/(7 k g) = " << t_exact << " s; slip at t_end = " << lowest_point_slip(run.samples.back(), R)
            << " m/s\n[ mujoco ] notes: " << run.notes << std::endl;
  // Coulomb sliding at k g until then: the slip ends within a few steps of the closed form.
  EXPECT_NEAR(t_roll, t_exact, 0.05 * t_exact);
}

// Two runs of one spec (a tilted disk, sliding and spinning, after a settling) give the same samples,
// every double equal, from one engine and from another.
TEST(MujocoEngine, Deterministic) {
  RunSpec s;
  s.body.shape = Body::Shape::disk;
  s.body.radius = 0.05;
  s.body.thickness = 0.01;
  s.body.mass = 0.1;
  const double C = 0.5 * 0.1 * 0.05 * 0.05, A = 0.25 * 0.1 * 0.05 * 0.05 + 0.1 * 0.01 * 0.01 / 12.0;
  s.body.inertia = {A, A, C};
  s.body.com = {0.0, 0.0, -0.001};
  s.start.orientation = {std::cos(0.05), std::sin(0.05), 0.0, 0.0};
  s.start.v = {1.0, 0.2, 0.0};
  s.start.omega = {0.0, 0.0, 20.0};
  s.numerics.settle_time = 0.05;
  s.t_end = 0.5;
  s.output_dt = 0.01;
  const auto one = make_mujoco_engine();
  s.friction = one->calibrated(0.3, 3.0 * std::numbers::pi / 16.0, 0.01);
  const engines::Run a = one->run(s), b = one->run(s), c = make_mujoco_engine()->run(s);
  ASSERT_EQ(a.samples.size(), 51u);
  for (const engines::Run* other : {&b, &c}) {
    ASSERT_EQ(other->samples.size(), a.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
      const Sample &x = a.samples[i], &y = other->samples[i];
      EXPECT_EQ(x.t, y.t);
      EXPECT_EQ(x.normal_force, y.normal_force) << i;
      for (int j = 0; j < 3; ++j) {
        EXPECT_EQ(x.com[j], y.com[j]) << i;
        EXPECT_EQ(x.v[j], y.v[j]) << i;
        EXPECT_EQ(x.omega[j], y.omega[j]) << i;
      }
      for (int j = 0; j < 4; ++j) EXPECT_EQ(x.orientation[j], y.orientation[j]) << i;
    }
  }
  EXPECT_EQ(a.notes, b.notes);
}

// A sphere spinning in place on its one contact point: the spin torque is the cone's bound mu3 N,
// so with calibrated(k, c, a) (mu3 = c k a) the spin falls at c k m g a / C. MuJoCo's default
// friction (torsional 0.005 m at condim 4) falls at m g 0.005 / C, and condim 3 (MuJoCo's own
// default) has no spin friction at all.
TEST(MujocoEngine, SpinDecaysAtTheTorsionalBound) {
  const double R = 0.05, m = 1.0, k = 0.3, c = 3.0 * std::numbers::pi / 16.0, a = 2e-3;
  const double C = 0.4 * m * R * R;
  RunSpec s;
  s.body = solid_sphere(R, m);
  s.start.omega = {0.0, 0.0, 20.0};
  s.numerics.settle_time = 0.2;
  s.output_dt = 0.01;
  const auto measure = [&](const Engine& engine, const Friction& f, double expected) {
    s.friction = f;
    s.t_end = std::min(3.0, 10.0 / expected);  // the first half of the decay from 20 1/s
    const engines::Run run = engine.run(s);
    return -slope(run.samples, 0.0, s.t_end, [](const Sample& x) { return x.omega[2]; });
  };
  const auto engine = make_mujoco_engine();
  const double expected = c * k * m * g * a / C;
  const double calibrated = measure(*engine, engine->calibrated(k, c, a), expected);
  const double defaults = measure(*engine, engine->defaults(k), m * g * 0.005 / C);
  MujocoOptions condim3;
  condim3.condim = 3;
  const double none = measure(*make_mujoco_engine(condim3), engine->defaults(k), m * g * 0.005 / C);
  std::cout << "[ mujoco ] spin deceleration: calibrated " << calibrated << " 1/s^2 (c k m g a / C = " << expected
            << "), defaults " << defaults << " (m g 0.005 / C = " << m * g * 0.005 / C << "), condim 3 " << none
            << std::endl;
  // The torque sits on the cone's boundary, mu3 N. With the calibrated mu3 = 3.5e-4 m the sphere
  // stays on the plane (the pyramid edges' damping pushes up by B mu3 omega = 0.74 m/s^2 < g, with
  // B = 2 / (dmax timeconst) = 105 1/s), N = m g on average over the window to the window's
  // vertical momentum: 1 % is ample (observed 1e-5). With 0.005 m, B mu3 omega = 10 m/s^2 > g: the
  // sphere hops (N = 0 in most samples), and the spin falls in steps whose mean is still mu3 m g / C
  // over a window of many hops, up to the vertical momentum at its ends: 3 % (observed 0.9 %).
  EXPECT_NEAR(calibrated, expected, 0.01 * expected);
  EXPECT_NEAR(defaults, m * g * 0.005 / C, 0.03 * m * g * 0.005 / C);
  EXPECT_NEAR(none, 0.0, 1e-6);
  EXPECT_EQ(engine->torsional_unit(), "m");
  EXPECT_EQ(engine->defaults(k).torsional, 0.005);
}

// The centre of mass d below the centre, tilted by 0.02 rad at rest, k = 1: the sphere rolls to and
// fro without slip at w^2 = m g d / (A + m (R - d)^2) (small angles; A about the centre of mass).
TEST(MujocoEngine, OffsetCentreOfMassRocksAtTheRollingFrequency) {
  const double R = 0.05, m = 1.0, d = 0.01, A = 4e-4, tilt = 0.02;
  RunSpec s;
  s.body.shape = Body::Shape::sphere;
  s.body.radius = R;
  s.body.mass = m;
  s.body.inertia = {A, A, A};
  s.body.com = {0.0, 0.0, -d};
  s.start.orientation = {std::cos(tilt / 2), std::sin(tilt / 2), 0.0, 0.0};
  s.friction = {1.0, 0.005, 0.0001};
  s.t_end = 4.0;
  s.output_dt = 0.002;
  const engines::Run run = make_mujoco_engine()->run(s);
  // Tilt about x: 2 atan(q_x / q_w). Times of its downward zero crossings (interpolated).
  std::vector<double> crossings;
  for (std::size_t i = 1; i < run.samples.size(); ++i) {
    const auto& p = run.samples[i - 1];
    const auto& q = run.samples[i];
    const double a0 = 2.0 * std::atan2(p.orientation[1], p.orientation[0]);
    const double a1 = 2.0 * std::atan2(q.orientation[1], q.orientation[0]);
    if (a0 > 0.0 && a1 <= 0.0) crossings.push_back(p.t + (q.t - p.t) * a0 / (a0 - a1));
  }
  ASSERT_GE(crossings.size(), 3u);
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double w = 2.0 * std::numbers::pi / period;
  const double w_exact = std::sqrt(m * g * d / (A + m * (R - d) * (R - d)));
  const double last = 2.0 * std::atan2(run.samples.back().orientation[1], run.samples.back().orientation[0]);
  std::cout << "[ mujoco ] rocking: w = " << w << " rad/s over " << crossings.size() - 1 << " periods, exact "
            << w_exact
            << "; tilt at t_end " << last << " rad (start " << tilt << ")" << std::endl;
  EXPECT_NEAR(w, w_exact, 0.03 * w_exact);
}

// Bad input names the field.
TEST(MujocoEngine, BadInputNamesTheField) {
  const auto engine = make_mujoco_engine();
  const auto message = [&](const RunSpec& s) -> std::string {
    try {
      (void)engine->run(s);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no exception)";
  };
  RunSpec s;
  s.t_end = 0.01;
  s.body.radius = -0.05;
  EXPECT_NE(message(s).find("body.radius"), std::string::npos) << message(s);
  s = RunSpec{};
  s.t_end = 0.01;
  s.numerics.timestep = -1e-3;  // 0 is allowed: MuJoCo's default step
  EXPECT_NE(message(s).find("numerics.timestep"), std::string::npos) << message(s);
  s.numerics.timestep = 0.0;
  EXPECT_NO_THROW((void)engine->run(s));
  s.start.v[1] = std::nan("");
  EXPECT_NE(message(s).find("start.v"), std::string::npos) << message(s);
  s = RunSpec{};
  s.body.shape = Body::Shape::disk;  // thickness 0: a MuJoCo cylinder needs a height
  EXPECT_NE(message(s).find("body.thickness"), std::string::npos) << message(s);
  MujocoOptions o;
  o.condim = 2;
  try {
    (void)make_mujoco_engine(o);
    ADD_FAILURE() << "condim 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mujoco.condim"), std::string::npos) << e.what();
  }
}

// The start pose: the lowest point on the plane at x = y = 0, no penetration (a tilted disk: its rim).
TEST(MujocoEngine, StartsTouchingThePlaneAtTheOrigin) {
  RunSpec s;
  s.body.shape = Body::Shape::disk;
  s.body.radius = 0.05;
  s.body.thickness = 0.01;
  s.body.inertia = {1e-3, 1e-3, 1e-3};
  s.start.orientation = {std::cos(0.15), 0.0, std::sin(0.15), 0.0};  // 0.3 rad about y
  MujocoWorld world(s, {});
  world.evaluate();
  // MuJoCo's own pose of the cylinder geom, searched over both rims (independent of the adapter's
  // placement formula): the lowest rim point is at the origin.
  const mjData& d = world.data();
  const mjtNum* c = d.geom_xpos + 3;  // geom 0 is the floor, 1 the disk
  const mjtNum* R = d.geom_xmat + 9;  // row-major: column j is the geom's axis j in the world
  double lowest[3] = {0.0, 0.0, 1.0};
  for (const double side : {-1.0, 1.0}) {
    for (int i = 0; i < 360000; ++i) {
      const double th = 2.0 * std::numbers::pi * i / 360000.0, u = 0.05 * std::cos(th), v = 0.05 * std::sin(th);
      double p[3];
      for (int r = 0; r < 3; ++r) p[r] = c[r] + R[3 * r] * u + R[3 * r + 1] * v + R[3 * r + 2] * side * 0.005;
      if (p[2] < lowest[2]) std::copy(p, p + 3, lowest);
    }
  }
  EXPECT_NEAR(lowest[2], 0.0, 1e-12);
  EXPECT_NEAR(lowest[0], 0.0, 1e-6);  // the grid's spacing, 0.05 m 2 pi / 360000
  EXPECT_NEAR(lowest[1], 0.0, 1e-6);
}

// A flat disk touches at three rim points 120 degrees apart (mjc_PlaneCylinder), whose normal
// forces sum to m g once settled.
TEST(MujocoEngine, FlatDiskTouchesAtThreeRimPoints) {
  RunSpec s;
  s.body.shape = Body::Shape::disk;
  s.body.radius = 0.05;
  s.body.thickness = 0.01;
  s.body.mass = 0.1;
  s.body.inertia = {6.3e-5, 6.3e-5, 1.25e-4};
  s.numerics.settle_time = 0.5;
  MujocoWorld world(s, {});
  world.evaluate();
  const mjData& d = world.data();
  ASSERT_EQ(d.ncon, 3);
  const mjtNum* centre = d.xpos + 3 * world.body();
  for (int i = 0; i < d.ncon; ++i) {
    EXPECT_NEAR(std::hypot(d.contact[i].pos[0] - centre[0], d.contact[i].pos[1] - centre[1]), 0.05, 1e-9);
  }
  EXPECT_NEAR(world.sample().normal_force, 0.1 * g, 1e-4 * 0.1 * g);
}

}  // namespace
}  // namespace frictionlab::engines
