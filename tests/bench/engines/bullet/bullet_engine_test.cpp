// Bullet 3.24 through the engines' interface (bench/engines/bullet/bullet_engine.h), against closed
// forms: the sliding sphere's 5/7, its own spin law with calibrated() and defaults(), the centre
// of mass off the centre (a rocking frequency), determinism, bad input; and the engine's quirks as
// it has them (spinning friction needs rolling friction; the angular speed cap), which document
// Bullet and fail if a later Bullet changes them.
#include "bench/engines/bullet/bullet_engine.h"
#include "tests/bench/engines/engine_test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace frictionlab::engines {
namespace bullet_engine_test {

using testing::body_z;
using testing::lowest_point_slip;
using testing::slope;
using testing::solid_sphere;

constexpr double kG = 9.81;

void require_finite_sample(const Sample& s) {
  bool ok = std::isfinite(s.normal_force);
  for (const double x : s.com) ok = ok && std::isfinite(x);
  for (const double x : s.v) ok = ok && std::isfinite(x);
  for (const double x : s.omega) ok = ok && std::isfinite(x);
  EXPECT_TRUE(ok) << "a non-finite sample at t = " << s.t;
}

TEST(BulletEngine, NameVersionUnit) {
  const auto engine = make_bullet_engine();
  EXPECT_EQ(engine->name(), "Bullet");
  EXPECT_EQ(engine->version(), "3.24");
  EXPECT_EQ(engine->torsional_unit(), "m");
}

// Problem 4 at Bullet's default step (1/60 s): a solid sphere launched sliding at v0 without spin
// slows at k g and spins up until it rolls, at 5/7 v0, from t = 2 v0 / (7 k g).
TEST(BulletEngine, SlidingSphereRollsAtFiveSevenths) {
  const auto engine = make_bullet_engine();
  const double v0 = 2.0, k = 0.2, R = 0.05;
  RunSpec spec;
  spec.body = solid_sphere(R);
  spec.start.v = {v0, 0.0, 0.0};
  spec.friction = engine->defaults(k);
  spec.t_end = 1.0;
  spec.output_dt = 1.0 / 60.0;
  const engines::Run run = engine->run(spec);
  EXPECT_NEAR(run.timestep, 1.0 / 60.0, 1e-8);  // the default (as a float in the single build)
  EXPECT_EQ(run.iterations, 10);
  const Sample& last = run.samples.back();
  EXPECT_NEAR(last.t, 1.0, 1e-6);
  EXPECT_NEAR(last.v[0] / v0, 5.0 / 7.0, 0.02 * 5.0 / 7.0);
  double t_roll = -1.0;
  for (const Sample& s : run.samples) {
    if (lowest_point_slip(s, R) < 1e-3 * v0) {
      t_roll = s.t;
      break;
    }
  }
  const double t_expected = 2.0 * v0 / (7.0 * k * kG);
  std::printf("sliding sphere at the default step: v/v0 = %.6f (5/7 = %.6f); slip < 1e-3 v0 from t = %.4f s, "
              "2 v0/(7 k g) = %.4f s (the first step after it: %.4f s)\n",
              last.v[0] / v0, 5.0 / 7.0, t_roll, t_expected, std::ceil(t_expected / run.timestep) * run.timestep);
  EXPECT_GT(t_roll, 0.0) << "the sphere never stopped slipping";
  // The slip ends within a step or two of the closed form (the impulse solver stops it at a step).
  EXPECT_NEAR(t_roll, t_expected, 2.0 * run.timestep);
  // The normal force while rolling: m g (the solver's normal impulse over the step).
  EXPECT_NEAR(last.normal_force, spec.body.mass * kG, 0.01 * spec.body.mass * kG);
  std::printf("notes: %s\n", run.notes.c_str());
}

// The same run twice, in one process and from two engines, gives the same samples bit for bit
// (a sphere sliding and spinning with calibrated spin friction: every row of the solver active).
TEST(BulletEngine, Deterministic) {
  const auto engine = make_bullet_engine();
  RunSpec spec;
  spec.body = solid_sphere();
  spec.start.v = {1.0, 0.5, 0.0};
  spec.start.omega = {3.0, -2.0, 20.0};
  spec.friction = engine->calibrated(0.3, 3.0 * std::numbers::pi / 16.0, 0.003);
  spec.numerics.settle_time = 0.1;
  spec.t_end = 1.0;
  spec.output_dt = 1.0 / 60.0;
  const engines::Run a = engine->run(spec);
  const engines::Run b = engine->run(spec);
  const engines::Run c = make_bullet_engine()->run(spec);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  ASSERT_EQ(a.samples.size(), c.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    for (const engines::Run* other : {&b, &c}) {
      const Sample& x = a.samples[i];
      const Sample& y = other->samples[i];
      EXPECT_EQ(x.t, y.t);
      EXPECT_EQ(x.normal_force, y.normal_force) << "sample " << i;
      for (int j = 0; j < 3; ++j) {
        EXPECT_EQ(x.com[j], y.com[j]) << "sample " << i;
        EXPECT_EQ(x.v[j], y.v[j]) << "sample " << i;
        EXPECT_EQ(x.omega[j], y.omega[j]) << "sample " << i;
      }
      for (int j = 0; j < 4; ++j) EXPECT_EQ(x.orientation[j], y.orientation[j]) << "sample " << i;
    }
  }
  EXPECT_EQ(a.notes, b.notes);
}

// A sphere spinning in place about the vertical.
RunSpec spinning_sphere(const Friction& friction, double t_end) {
  RunSpec spec;
  spec.body = solid_sphere();
  spec.start.omega = {0.0, 0.0, 20.0};
  spec.friction = friction;
  spec.t_end = t_end;
  spec.output_dt = 1.0 / 60.0;
  return spec;
}

// Bullet's own spin law with calibrated(k, c, a): the torque c k N a, so dOmega/dt = -c k m g a / C
// while it spins. Tolerance 1 %: the torque is an impulse bounded by torsional x the point's normal
// impulse in the same solver pass, which at rest is m g dt up to the Baumgarte correction of the
// float state (the normal force is checked to 0.5 %); the slope is fitted over many steps.
TEST(BulletEngine, CalibratedSpinDecaysAtTheClosedFormRate) {
  const auto engine = make_bullet_engine();
  const double k = 0.2, c = 3.0 * std::numbers::pi / 16.0, a = 0.005, m = 1.0, R = 0.05;
  const double C = 0.4 * m * R * R;
  const double rate = c * k * m * kG * a / C;  // 1/s^2
  const double t_stop = 20.0 / rate;
  const engines::Run run = engine->run(spinning_sphere(engine->calibrated(k, c, a), t_stop * 1.2));
  const double measured = -slope(run.samples, 0.0, t_stop / 2, [](const Sample& s) { return s.omega[2]; });
  std::printf("spin-down with calibrated(k = %g, c = 3 pi/16, a = %g m): dOmega/dt = -%.5f 1/s^2, closed form -%.5f "
              "(ratio %.5f); Omega at %.3f s (the closed-form stop): %.4f 1/s\n",
              k, a, measured, rate, measured / rate, t_stop,
              run.samples[static_cast<std::size_t>(std::lround(t_stop / (1.0 / 60.0)))].omega[2]);
  EXPECT_NEAR(measured, rate, 0.01 * rate);
  EXPECT_NEAR(run.samples[10].normal_force, m * kG, 0.005 * m * kG);
  EXPECT_NEAR(run.samples.back().omega[2], 0.0, 1e-3) << "the spin stops, and stays stopped";
}

// defaults(k): what Bullet gives a user who sets only the friction, no spinning friction
// (btCollisionObject's m_spinningFriction = 0): the spin does not decay at all.
TEST(BulletEngine, DefaultsGiveNoSpinFriction) {
  const auto engine = make_bullet_engine();
  const Friction d = engine->defaults(0.2);
  EXPECT_EQ(d.k, 0.2);
  EXPECT_EQ(d.torsional, 0.0);
  EXPECT_EQ(d.rolling, 0.0);
  const engines::Run run = engine->run(spinning_sphere(d, 2.0));
  EXPECT_NEAR(run.samples.back().omega[2], 20.0, 20.0 * 1e-5);
}

// The quirk (bulletphysics/bullet3#4188): spinning friction set, rolling friction 0, and the spin
// does not decay, because the solver adds the spinning row only when the combined rolling friction
// is > 0 (btSequentialImpulseConstraintSolver.cpp line 1058). This documents Bullet 3.24: it fails
// if a later Bullet applies spinning friction on its own.
TEST(BulletEngine, SpinningFrictionActsOnlyWithRollingFriction) {
  const auto engine = make_bullet_engine();
  Friction f = engine->calibrated(0.2, 3.0 * std::numbers::pi / 16.0, 0.005);
  ASSERT_GT(f.torsional, 0.0);
  ASSERT_GT(f.rolling, 0.0);
  f.rolling = 0.0;
  const engines::Run run = engine->run(spinning_sphere(f, 2.0));
  EXPECT_NEAR(run.samples.back().omega[2], 20.0, 20.0 * 1e-5) << "spinning friction acted without rolling friction";
  EXPECT_NE(run.notes.find("OFF here"), std::string::npos) << run.notes;
}

// The rolling friction calibrated() adds to switch spinning friction on does not slow rolling:
// problem 4 with calibrated settings ends at 5/7 v0 as with defaults, to float resolution.
TEST(BulletEngine, CalibratedRollingFrictionDoesNotSlowRolling) {
  const auto engine = make_bullet_engine();
  RunSpec spec;
  spec.body = solid_sphere();
  spec.start.v = {2.0, 0.0, 0.0};
  spec.t_end = 2.0;
  spec.output_dt = 1.0 / 60.0;
  spec.friction = engine->defaults(0.2);
  const engines::Run plain = engine->run(spec);
  spec.friction = engine->calibrated(0.2, 3.0 * std::numbers::pi / 16.0, 0.003);
  const engines::Run calibrated = engine->run(spec);
  EXPECT_NEAR(calibrated.samples.back().v[0], plain.samples.back().v[0], 1e-6);
}

// The centre of mass d below the sphere's centre, tilted 0.02 rad at rest, k = 1: it rocks,
// rolling without slip, at w^2 = m g d / (A + m (R - d)^2) (small angles), within 3 %. Both tilt
// axes: Bullet's single friction row per point lies along the slip, or along btPlaneSpace1 of the
// normal (the world's -y for +z) when there is no slip, so the two axes are not alike to Bullet.
double rocking_ratio(const std::array<double, 3>& tilt_axis, const BulletOptions& options = {}) {
  const auto engine = make_bullet_engine(options);
  const double R = 0.05, m = 1.0, d = 0.01, A = 4e-4, C = 5e-4, tilt = 0.02;
  RunSpec spec;
  spec.body = solid_sphere(R, m);
  spec.body.inertia = {A, A, C};
  spec.body.com = {0.0, 0.0, -d};
  const double s = std::sin(tilt / 2);
  spec.start.orientation = {std::cos(tilt / 2), s * tilt_axis[0], s * tilt_axis[1], s * tilt_axis[2]};
  spec.friction = engine->defaults(1.0);
  spec.t_end = 4.0;
  spec.output_dt = 1.0 / 60.0;
  const engines::Run run = engine->run(spec);
  // The tilt angle about the tilt axis: the body's z axis is (sin th) (axis x e_z) ... signed via
  // the component along axis x e_z.
  const std::array<double, 3> side{tilt_axis[1], -tilt_axis[0], 0.0};  // axis x e_z
  std::vector<double> crossings;
  double previous = 0.0;
  for (std::size_t i = 0; i < run.samples.size(); ++i) {
    const auto z = body_z(run.samples[i].orientation);
    const double angle = std::atan2(z[0] * side[0] + z[1] * side[1], z[2]);
    if (i > 0 && (previous > 0) != (angle > 0)) {
      const double t0 = run.samples[i - 1].t, t1 = run.samples[i].t;
      crossings.push_back(t0 + (t1 - t0) * previous / (previous - angle));
    }
    previous = angle;
  }
  const double expected = std::sqrt(m * kG * d / (A + m * (R - d) * (R - d)));
  if (crossings.size() < 3) {
    ADD_FAILURE() << "it does not rock";
    return 0.0;
  }
  const double half_period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double measured = std::numbers::pi / half_period;
  std::printf("rocking about (%g, %g, %g)%s: w = %.4f 1/s over %zu half periods, closed form %.4f (ratio %.4f)\n",
              tilt_axis[0], tilt_axis[1], tilt_axis[2], options.two_friction_directions ? ", two friction directions" : "",
              measured, crossings.size() - 1, expected, measured / expected);
  return measured / expected;
}

TEST(BulletEngine, CentreOfMassOffsetRocksAtItsFrequency) {
  EXPECT_NEAR(rocking_ratio({1.0, 0.0, 0.0}), 1.0, 0.03);
  EXPECT_NEAR(rocking_ratio({std::sqrt(0.5), std::sqrt(0.5), 0.0}), 1.0, 0.03);
}

// The quirk of Bullet's default solver mode: one friction row per contact point, along the point's
// slip if its square exceeds SIMD_EPSILON, else along btPlaneSpace1 of the normal, world -y for +z
// (btSequentialImpulseConstraintSolver.cpp, convertContact, lines 1100-1125). In the single build
// (SIMD_EPSILON = FLT_EPSILON: slips below 3.5e-4 m/s) rocking about y rolls the contact along x,
// across that row: the sphere slips each time and rocks too fast (measured +22 % in Bullet 3.24 at
// the default step); SOLVER_USE_2_FRICTION_DIRECTIONS (BulletOptions::two_friction_directions)
// restores the closed form. In the double build (DBL_EPSILON: 1.5e-8 m/s) the row follows the
// slip and both are right. This documents Bullet 3.24: it fails if a later Bullet changes it.
TEST(BulletEngine, RockingAlongXNeedsTwoFrictionDirections) {
  RunSpec probe;
  probe.body = solid_sphere();
  probe.t_end = 0.0;
  probe.output_dt = 1.0 / 60.0;
  const bool single = make_bullet_engine()->run(probe).notes.find("btScalar = float") != std::string::npos;
  if (single) {
    EXPECT_GT(rocking_ratio({0.0, 1.0, 0.0}), 1.1);
  } else {
    EXPECT_NEAR(rocking_ratio({0.0, 1.0, 0.0}), 1.0, 0.03);
  }
  EXPECT_NEAR(rocking_ratio({0.0, 1.0, 0.0}, {.two_friction_directions = true}), 1.0, 0.03);
}

// The centre of mass is where the start puts it: the shape's lowest point on the plane at x = y = 0.
TEST(BulletEngine, StartPoseTouchesThePlaneAtTheOrigin) {
  const auto engine = make_bullet_engine();
  RunSpec spec;
  spec.body = solid_sphere();
  spec.body.com = {0.0, 0.0, -0.01};
  spec.t_end = 0.0;
  spec.output_dt = 1.0 / 60.0;
  const engines::Run run = engine->run(spec);
  ASSERT_EQ(run.samples.size(), 1U);
  EXPECT_NEAR(run.samples[0].com[0], 0.0, 1e-7);
  EXPECT_NEAR(run.samples[0].com[2], 0.04, 1e-7);
  EXPECT_EQ(run.samples[0].normal_force, 0.0);  // no step yet
  // A disk lying flat: its centre of mass at half its thickness.
  spec.body.shape = Body::Shape::disk;
  spec.body.thickness = 0.01;
  spec.body.com = {};
  const engines::Run disk = engine->run(spec);
  EXPECT_NEAR(disk.samples[0].com[2], 0.005, 1e-7);
}

// Above |omega| = (pi/4)/step, btTransformUtil::integrateTransform limits the exponential map's
// angle to pi/4 but keeps the whole omega in the quaternion's vector part: the orientation turns by
// 2 atan(|omega| step / (pi/4) tan(pi/8)) in a step instead of |omega| step, while omega is kept
// (btRigidBody::integrateVelocities's clamp at (pi/2)/step is not called by the discrete world).
// A sphere spinning about the vertical without spin friction, one step: at 180 1/s and 1/60 s it
// turns 2.014 rad, not 3; at 40 1/s (below 47.1) it turns 40/60 rad. This documents Bullet 3.24.
TEST(BulletEngine, OrientationStepIsLimitedAboveQuarterPiPerStep) {
  const auto engine = make_bullet_engine();
  const auto turn_in_one_step = [&](double omega) {
    RunSpec spec = spinning_sphere(engine->defaults(0.2), 1.0 / 60.0);
    spec.start.omega = {0.0, 0.0, omega};
    const engines::Run run = engine->run(spec);
    EXPECT_EQ(run.samples.size(), 2U);
    EXPECT_NEAR(run.samples[1].omega[2], omega, omega * 1e-6) << "omega is kept";
    const auto& q = run.samples[1].orientation;
    return std::pair{2.0 * std::atan2(q[3], q[0]), run.timestep};
  };
  const auto [fast, step] = turn_in_one_step(180.0);
  const double limit = std::numbers::pi / 4;
  EXPECT_NEAR(fast, 2.0 * std::atan(180.0 * step / limit * std::tan(limit / 2)), 1e-5);
  EXPECT_LT(fast, 0.7 * 180.0 * step);
  const auto [slow, step2] = turn_in_one_step(40.0);
  EXPECT_NEAR(slow, 40.0 * step2, 1e-5);
}

// A flat disk (btCylinderShapeZ) spinning in place with defaults(k), no spinning friction at all:
// its contact points are Bullet's support points of the cylinder, on the rim even when it lies
// flat (CylinderLocalSupportZ, btCylinderShape.cpp), so the sliding friction at the rim brakes the
// spin as a ring's would: dOmega/dt = -k m g a / C (C = m a^2 / 2). At a step of 1e-3 s (at the
// default step the spinning disk does not stay flat), within 10 % (the disk wobbles on its rim
// points, which changes N at each). This documents Bullet 3.24.
TEST(BulletEngine, FlatDiskSpinsDownOnItsRim) {
  const auto engine = make_bullet_engine();
  const double r = 0.05, h = 0.01, m = 0.1, k = 0.3;
  RunSpec spec;
  spec.body.shape = Body::Shape::disk;
  spec.body.radius = r;
  spec.body.thickness = h;
  spec.body.mass = m;
  spec.body.inertia = {m * (3 * r * r + h * h) / 12, m * (3 * r * r + h * h) / 12, m * r * r / 2};
  spec.start.omega = {0.0, 0.0, 20.0};
  spec.friction = engine->defaults(k);
  spec.numerics.timestep = 1e-3;
  spec.output_dt = 1e-3;
  const double rate = k * m * kG * r / (m * r * r / 2);
  spec.t_end = 20.0 / rate;
  const engines::Run run = engine->run(spec);
  const double measured = -slope(run.samples, 0.0, 0.5 * 20.0 / rate, [](const Sample& s) { return s.omega[2]; });
  std::printf("flat disk, no spinning friction: dOmega/dt = -%.3f 1/s^2, ring k m g a / C = %.3f (ratio %.3f)\n",
              measured, rate, measured / rate);
  EXPECT_NEAR(measured, rate, 0.1 * rate);
}

// Bad input: std::invalid_argument whose message names the field.
TEST(BulletEngine, BadInputThrowsNamingTheField) {
  const auto engine = make_bullet_engine();
  const auto expect_throw = [&](const RunSpec& spec, const std::string& field) {
    try {
      (void)engine->run(spec);
      ADD_FAILURE() << "no exception for " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  RunSpec good;
  good.body = solid_sphere();
  good.t_end = 0.1;
  RunSpec bad = good;
  bad.body.radius = -0.05;
  expect_throw(bad, "body.radius");
  bad = good;
  bad.numerics.timestep = -1e-3;
  expect_throw(bad, "numerics.timestep");
  bad = good;
  bad.output_dt = 0.0;
  expect_throw(bad, "output_dt");
  bad = good;
  bad.start.v = {0.0, std::nan(""), 0.0};
  expect_throw(bad, "start.v");
  bad = good;
  bad.start.omega = {0.0, 0.0, INFINITY};
  expect_throw(bad, "start.omega");
  bad = good;
  bad.body.shape = Body::Shape::disk;
  bad.body.thickness = 0.0;
  expect_throw(bad, "body.thickness");
  bad = good;
  bad.friction.k = 11.0;
  expect_throw(bad, "friction.k");
  bad = good;
  bad.start.orientation = {1.0, 0.1, 0.0, 0.0};
  expect_throw(bad, "start.orientation");
  EXPECT_THROW((void)engine->calibrated(0.2, -1.0, 0.003), std::invalid_argument);
  EXPECT_THROW((void)make_bullet_engine(BulletOptions{.disk_margin = -1e-4}), std::invalid_argument);
}

// The four problems of the side by side at Bullet's default step run to their end.
TEST(BulletEngine, FourProblemsRunToTheirEndAtTheDefaultStep) {
  const auto engine = make_bullet_engine();
  const double c = 3.0 * std::numbers::pi / 16.0;
  // 1: the sphere's spin-down (R = 5 cm, k = 0.2, a = 3 mm, omega0 = 20 1/s).
  RunSpec spin = spinning_sphere(engine->calibrated(0.2, c, 0.003), 6.0);
  // 2: the puck (r = 5 cm, 1 cm thick, 100 g, k = 0.3), 1 m/s and 20 1/s, spin friction calibrated
  // to a uniform patch of the disk's radius (c = 2/3).
  RunSpec puck;
  puck.body.shape = Body::Shape::disk;
  puck.body.radius = 0.05;
  puck.body.thickness = 0.01;
  puck.body.mass = 0.1;
  const double r = 0.05, h = 0.01, mp = 0.1;
  puck.body.inertia = {mp * (3 * r * r + h * h) / 12, mp * (3 * r * r + h * h) / 12, mp * r * r / 2};
  puck.start.v = {1.0, 0.0, 0.0};
  puck.start.omega = {0.0, 0.0, 20.0};
  puck.friction = engine->calibrated(0.3, 2.0 / 3.0, r);
  puck.t_end = 1.0;
  puck.output_dt = 1.0 / 60.0;
  // 3: the tippe top of Leine & Glocker (2003).
  RunSpec top;
  top.body = solid_sphere(0.015, 0.006);
  top.body.inertia = {8e-7, 8e-7, 7e-7};
  top.body.com = {0.0, 0.0, -0.003};
  top.start.orientation = {std::cos(0.05), std::sin(0.05), 0.0, 0.0};
  top.start.omega = {0.0, -180.0 * std::sin(0.1), 180.0 * std::cos(0.1)};  // about its tilted axis
  top.friction = engine->calibrated(0.3, c, 2e-4);
  top.t_end = 8.0;
  top.output_dt = 1.0 / 60.0;
  // 4: the sliding sphere.
  RunSpec slide;
  slide.body = solid_sphere();
  slide.start.v = {2.0, 0.0, 0.0};
  slide.friction = engine->defaults(0.2);
  slide.t_end = 1.0;
  slide.output_dt = 1.0 / 60.0;

  // Each runs to its end with a finite state and one sample per step of 1/60 s (the program
  // engines_side_by_side measures what they give, and their cost, in docs/engines.md §6).
  const RunSpec* specs[] = {&spin, &puck, &top, &slide};
  for (const RunSpec* spec : specs) {
    const engines::Run run = engine->run(*spec);
    EXPECT_EQ(run.samples.size(), static_cast<std::size_t>(std::lround(spec->t_end * 60.0)) + 1);
    for (const Sample& x : run.samples) require_finite_sample(x);
  }
}

}  // namespace
}  // namespace frictionlab::engines
