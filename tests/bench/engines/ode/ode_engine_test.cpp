// The ODE adapter against closed forms: rolling after sliding (5/7), its own spin law, the rocking
// of a body whose centre of mass is off its centre, determinism, and bad input.
#include "bench/engines/ode/ode_engine.h"
#include "tests/bench/engines/engine_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace frictionlab::engines {
namespace ode_engine_test {

using testing::slope;

constexpr double g = 9.81;

// A solid sphere of radius R and mass m resting on the plane.
RunSpec solid_sphere(double R, double m, double k) {
  RunSpec spec;
  spec.body = testing::solid_sphere(R, m);
  spec.friction.k = k;
  spec.numerics.g = g;
  return spec;
}

// The message of the std::invalid_argument thrown by `f`, or "" if none.
template <class F>
std::string invalid_argument_message(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Problem 4: a solid sphere launched sliding at v0 without spin rolls at 5/7 v0 from
// t = 2 v0 / (7 k g) (Coulomb friction k m g decelerates it while its spin grows).
TEST(OdeEngine, SlidingSphereRollsAtFiveSevenths) {
  const auto engine = make_ode_engine();
  const double R = 0.05, m = 1.0, k = 0.2, v0 = 2.0;
  RunSpec spec = solid_sphere(R, m, k);
  spec.start.v = {v0, 0.0, 0.0};
  spec.t_end = 0.6;
  spec.output_dt = 1e-3;
  const engines::Run run = engine->run(spec);  // the engine's default step
  ASSERT_FALSE(run.samples.empty());
  EXPECT_DOUBLE_EQ(run.timestep, 1e-3);
  EXPECT_EQ(run.iterations, 50);

  const double ratio = run.samples.back().v[0] / v0;
  EXPECT_NEAR(ratio, 5.0 / 7.0, 0.02 * 5.0 / 7.0);

  // Slip ends when the contact point's velocity v_x - R omega_y vanishes (to 0.1 % of v0).
  double t_roll = -1.0;
  for (const Sample& s : run.samples) {
    if (std::abs(s.v[0] - R * s.omega[1]) < 1e-3 * v0) {
      t_roll = s.t;
      break;
    }
  }
  const double t_exact = 2.0 * v0 / (7.0 * k * g);
  std::printf("[ ODE ] v/v0 at the end %.6f (5/7 = %.6f); slip ends at t = %.4f s, closed form 2 v0/(7 k g) = %.4f s\n", ratio,
              5.0 / 7.0, t_roll, t_exact);
  ASSERT_GT(t_roll, 0.0) << "the sphere never stopped slipping";
  EXPECT_NEAR(t_roll, t_exact, 0.03 * t_exact);
}

// The same spec gives the same samples, bit for bit, also twice in one process: a disk (four contact
// points, QuickStep shuffles their rows with ODE's random generator) sliding and spinning, with
// spin friction on, and with settling.
TEST(OdeEngine, Deterministic) {
  const auto engine = make_ode_engine();
  RunSpec spec;
  spec.body.shape = Body::Shape::disk;
  spec.body.radius = 0.05;
  spec.body.thickness = 0.01;
  spec.body.mass = 0.1;
  const double C = 0.5 * 0.1 * 0.05 * 0.05, A = 0.25 * 0.1 * 0.05 * 0.05 + 0.1 * 0.01 * 0.01 / 12.0;
  spec.body.inertia = {A, A, C};
  spec.friction = engine->calibrated(0.3, 3.0 * std::numbers::pi / 16.0, 0.02);
  spec.start.v = {1.0, 0.0, 0.0};
  spec.start.omega = {0.0, 0.0, 20.0};
  spec.numerics.settle_time = 0.05;
  spec.t_end = 0.5;
  const engines::Run a = engine->run(spec);
  const engines::Run b = engine->run(spec);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  ASSERT_EQ(a.samples.size(), 501u);
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const Sample& x = a.samples[i];
    const Sample& y = b.samples[i];
    ASSERT_EQ(x.t, y.t) << i;
    for (int j = 0; j < 3; ++j) {
      ASSERT_EQ(x.com[j], y.com[j]) << i;
      ASSERT_EQ(x.v[j], y.v[j]) << i;
      ASSERT_EQ(x.omega[j], y.omega[j]) << i;
    }
    for (int j = 0; j < 4; ++j) ASSERT_EQ(x.orientation[j], y.orientation[j]) << i;
    ASSERT_EQ(x.normal_force, y.normal_force) << i;
  }
  EXPECT_EQ(a.notes, b.notes);
  // It moved, touched and slowed (a comparison of two frozen runs would prove nothing).
  EXPECT_LT(a.samples.back().v[0], 0.9);
  EXPECT_LT(a.samples.back().omega[2], 19.0);
  EXPECT_NEAR(a.samples[250].normal_force, 0.1 * g, 0.05 * 0.1 * g);
}

// ODE's own spin law: with calibrated(k, c, a) a sphere spinning in place feels the torque c k N a
// (rhoN = c k a times the normal force N = m g), so omega falls linearly at c k m g a / C. With the
// defaults there is no spin friction at all: a sphere's one contact point lies on the spin axis,
// where the sliding friction has nothing to act on, and no rolling rows are added.
TEST(OdeEngine, SpinLawOfCalibratedTorsionalFriction) {
  const auto engine = make_ode_engine();
  const double R = 0.05, m = 1.0, k = 0.3, a = 0.005, c = 3.0 * std::numbers::pi / 16.0, w0 = 20.0;
  RunSpec spec = solid_sphere(R, m, k);
  spec.friction = engine->calibrated(k, c, a);
  EXPECT_DOUBLE_EQ(spec.friction.torsional, c * k * a);
  spec.start.omega = {0.0, 0.0, w0};
  const double C = spec.body.inertia[2];
  const double decel = c * k * m * g * a / C;
  const double t_stop = w0 / decel;
  spec.t_end = 1.2 * t_stop;
  spec.output_dt = 1e-3;
  const engines::Run run = engine->run(spec);
  const double measured = -slope(run.samples, 0.0, 0.5 * t_stop, [](const Sample& s) { return s.omega[2]; });
  std::printf("[ ODE ] spin deceleration %.5f 1/s^2, closed form c k m g a / C = %.5f 1/s^2 (ratio %.5f)\n", measured, decel,
              measured / decel);
  // The normal force is m g up to the contact's settling into its 1 mm surface layer (ERP 0.2 per
  // step: a transient of a few ms, under 1 % of the half decay); QuickStep's 50 sweeps converge the
  // one-point problem almost exactly. 2 % covers both.
  EXPECT_NEAR(measured, decel, 0.02 * decel);
  EXPECT_NEAR(run.samples.back().omega[2], 0.0, 1e-3 * w0) << "it should have stopped by 1.2 t_stop";
  // Spinning in place: the centre hardly moves.
  EXPECT_LT(std::hypot(run.samples.back().com[0], run.samples.back().com[1]), 1e-4);

  // The defaults: no spin friction at all.
  const Friction d = engine->defaults(k);
  EXPECT_EQ(d.k, k);
  EXPECT_EQ(d.torsional, 0.0);
  EXPECT_EQ(d.rolling, 0.0);
  spec.friction = d;
  spec.t_end = 1.0;
  const engines::Run free_spin = engine->run(spec);
  EXPECT_NEAR(free_spin.samples.back().omega[2], w0, 1e-9 * w0);
}

// The centre of mass d below the centre is honoured (the geom offset, the body at the centre of
// mass): tilted by a small angle at rest with friction enough to roll without slipping, the body
// rocks at w^2 = m g d / (A + m (R - d)^2) (A about the centre of mass, R - d from the centre of
// mass to the contact point).
TEST(OdeEngine, CentreOfMassOffsetRocksAtTheClosedFormFrequency) {
  const auto engine = make_ode_engine();
  const double R = 0.05, m = 1.0, d = 0.01, A = 8e-4, C = 1e-3, tilt = 0.02;
  RunSpec spec;
  spec.body.shape = Body::Shape::sphere;
  spec.body.radius = R;
  spec.body.mass = m;
  spec.body.inertia = {A, A, C};
  spec.body.com = {0.0, 0.0, -d};
  spec.friction = engine->defaults(1.0);
  spec.start.orientation = {std::cos(0.5 * tilt), std::sin(0.5 * tilt), 0.0, 0.0};  // about x
  spec.t_end = 4.0;
  spec.output_dt = 1e-3;
  const engines::Run run = engine->run(spec);
  // The tilt about x, and the times it crosses zero (linear interpolation between samples).
  std::vector<double> crossings;
  double previous = tilt, previous_t = 0.0;
  for (const Sample& s : run.samples) {
    const double angle = 2.0 * std::atan2(s.orientation[1], s.orientation[0]);
    if ((previous > 0.0) != (angle > 0.0)) crossings.push_back(previous_t + (s.t - previous_t) * previous / (previous - angle));
    previous = angle;
    previous_t = s.t;
  }
  ASSERT_GE(crossings.size(), 4u) << "it did not rock";
  const double half_period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double w = std::numbers::pi / half_period;
  const double w_exact = std::sqrt(m * g * d / (A + m * (R - d) * (R - d)));
  std::printf("[ ODE ] rocking frequency %.5f rad/s over %zu half periods, closed form %.5f rad/s (ratio %.5f)\n", w,
              crossings.size() - 1, w_exact, w / w_exact);
  EXPECT_NEAR(w, w_exact, 0.03 * w_exact);
}

// A flat disk touches the plane at four points on its rim (ode/src/collision_cylinder_plane.cpp),
// so spinning in place it already feels the sliding friction of a ring, k N a, with the defaults;
// the spin rows of calibrated() add rhoN N on top (their per-point limits rhoN N_i add up to rhoN N).
// Closed form: omega falls at (k a + rhoN) m g / C. The rim points slide along the friction
// pyramid's edges (world x and y), where the pyramid is exact.
TEST(OdeEngine, FlatDiskSpinsDownOnItsFourRimPoints) {
  const auto engine = make_ode_engine();
  const double a = 0.05, h = 0.01, m = 0.1, k = 0.3, w0 = 20.0;
  RunSpec spec;
  spec.body.shape = Body::Shape::disk;
  spec.body.radius = a;
  spec.body.thickness = h;
  spec.body.mass = m;
  const double C = 0.5 * m * a * a, A = 0.25 * m * a * a + m * h * h / 12.0;
  spec.body.inertia = {A, A, C};
  spec.start.omega = {0.0, 0.0, w0};
  spec.numerics.settle_time = 0.02;  // into contact: the flat collider needs a positive depth
  for (const bool calibrated : {false, true}) {
    spec.friction = calibrated ? engine->calibrated(k, 2.0 / 3.0, a) : engine->defaults(k);
    const double decel = (k * a + spec.friction.torsional) * m * g / C;
    spec.t_end = 0.5 * w0 / decel;
    const engines::Run run = engine->run(spec);
    const double measured = -slope(run.samples, 0.0, spec.t_end, [](const Sample& s) { return s.omega[2]; });
    std::printf("[ ODE ] disk spin deceleration (%s) %.5f 1/s^2, closed form (k a + rhoN) m g / C = %.5f 1/s^2\n",
                calibrated ? "calibrated" : "defaults", measured, decel);
    EXPECT_NEAR(measured, decel, 0.02 * decel);
    EXPECT_NEAR(run.samples.back().normal_force, m * g, 0.01 * m * g);
  }
}

// The exact LCP (dWorldStep) instead of QuickStep gives the same rolling, and says so.
TEST(OdeEngine, ExactLcpOptionRollsAtFiveSevenths) {
  OdeOptions options;
  options.solver = OdeOptions::Solver::world;
  const auto engine = make_ode_engine(options);
  RunSpec spec = solid_sphere(0.05, 1.0, 0.2);
  spec.start.v = {2.0, 0.0, 0.0};
  spec.t_end = 0.5;
  const engines::Run run = engine->run(spec);
  EXPECT_NEAR(run.samples.back().v[0] / 2.0, 5.0 / 7.0, 0.02 * 5.0 / 7.0);
  EXPECT_EQ(run.iterations, 0);
  EXPECT_NE(run.notes.find("dWorldStep"), std::string::npos);
}

TEST(OdeEngine, BadInputThrowsNamingTheField) {
  const auto engine = make_ode_engine();
  RunSpec spec = solid_sphere(0.05, 1.0, 0.2);
  spec.t_end = 0.01;

  RunSpec bad = spec;
  bad.body.radius = -0.05;
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("body.radius"), std::string::npos);

  bad = spec;
  bad.start.v = {std::nan(""), 0.0, 0.0};
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("start.v"), std::string::npos);

  bad = spec;
  bad.start.omega = {0.0, 0.0, std::numeric_limits<double>::infinity()};
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("start.omega"), std::string::npos);

  // Numerics::timestep = 0 is the default step; a negative one is refused; the engine's own
  // default step cannot be 0.
  bad = spec;
  bad.numerics.timestep = -1e-3;
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("numerics.timestep"), std::string::npos);
  OdeOptions options;
  options.timestep = 0.0;
  EXPECT_NE(invalid_argument_message([&] { (void)make_ode_engine(options); }).find("ode.timestep"), std::string::npos);

  bad = spec;
  bad.body.mass = 0.0;
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("body.mass"), std::string::npos);

  bad = spec;
  bad.friction.torsional = -0.1;
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("friction.torsional"), std::string::npos);

  bad = spec;
  bad.output_dt = 1e-5;  // under half the 1 ms step
  EXPECT_NE(invalid_argument_message([&] { (void)engine->run(bad); }).find("output_dt"), std::string::npos);

  // And a good spec still runs after all that.
  EXPECT_NO_THROW((void)engine->run(spec));
}

}  // namespace
}  // namespace frictionlab::engines
