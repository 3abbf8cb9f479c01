#include "dynamics/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "friction/registry.h"
#include "test_support.h"

namespace frictionlab::dynamics {
namespace {

using testing::egg_body;
using testing::sphere_body;

constexpr double pi = std::numbers::pi;

// Collects every sample.
class Recorder final : public Observer {
 public:
  struct Row {
    double t;
    StateVector x;
    ContactState c;
    double energy;
  };
  void sample(const Sample& s) override { rows.push_back({s.t, s.x, s.contact, s.energy}); }
  std::vector<Row> rows;
};

RunOptions tight(double t_end, double output_dt) {
  RunOptions o;
  o.t_end = t_end;
  o.output_dt = output_dt;
  o.integrator.abs_tol = 1e-12;
  o.integrator.rel_tol = 1e-12;
  return o;
}

// ---------------------------------------------------------------------------------------------
// Free flight: nothing touches the plane, so energy, momentum and angular momentum are conserved.
// In the body frame the invariants are |v|, |L|, v.L, v.gamma, L.gamma (g = 0; L = J omega) and
// E. With tolerances 1e-12 over ~1000 steps the drift stays far below this:
constexpr double kConservationRelTol = 1e-9;

TEST(DynSimulation, FreeFlightConservesEnergyMomentumAndAngularMomentum) {
  const testing::ForbiddenLaw law;
  const Body body = egg_body("egg-printed");
  const Eigen::Vector3d J(body.A, body.A, body.C);
  for (const double g : {0.0, 9.81}) {
    const BodyOnPlane sys(body, PlaneContact{0.1, 1e7, g}, law);
    const StateVector x0 =
        make_state({0.3, -0.2, 0.5}, {12.0, -7.0, 30.0}, Eigen::Vector3d(0.2, 0.4, 0.9).normalized(), 1.0);
    Recorder rec;
    const RunSummary s = simulate(sys, x0, tight(0.3, 0.01), &rec);
    ASSERT_EQ(s.reason, Termination::t_end) << s.message;
    EXPECT_EQ(s.landings, 0);
    const auto L = [&](const StateVector& x) { return Eigen::Vector3d(J.cwiseProduct(angular_velocity(x))); };
    const Eigen::Vector3d v0 = velocity(x0), g0 = vertical(x0);
    for (const auto& r : rec.rows) {
      const Eigen::Vector3d v = velocity(r.x), gam = vertical(r.x);
      EXPECT_NEAR(r.energy, rec.rows.front().energy, kConservationRelTol * std::abs(rec.rows.front().energy));
      EXPECT_NEAR(L(r.x).norm(), L(x0).norm(), kConservationRelTol * L(x0).norm());
      EXPECT_NEAR(L(r.x).dot(gam), L(x0).dot(g0), kConservationRelTol * L(x0).norm());
      EXPECT_NEAR(gam.norm(), 1.0, kConservationRelTol);
      // Vertical velocity falls at g; with g = 0 the whole momentum vector is fixed in space.
      EXPECT_NEAR(v.dot(gam), v0.dot(g0) - g * r.t, kConservationRelTol * 10.0);
      if (g == 0.0) {
        EXPECT_NEAR(v.norm(), v0.norm(), kConservationRelTol * v0.norm());
        EXPECT_NEAR(v.dot(L(r.x)), v0.dot(L(x0)), kConservationRelTol * v0.norm() * L(x0).norm());
      }
    }
    EXPECT_LT(s.max_gamma_drift, kConservationRelTol);
  }
}

// ---------------------------------------------------------------------------------------------
// A sphere launched sliding without spin: F = kN opposes the slip until the contact point stops,
// at t = 2 v0 / (7 k g) with v = 5 v0 / 7 (solid sphere, C = 2/5 m R^2).
//
// Hertz compliance. The model applies the friction at the undeformed contact point r = -R gamma,
// so the lever arm stays R; and for a sphere u.gamma = 0, so started at the static compression
// N = m g holds exactly for all t. Then only the detection of rolling (U < U_roll, which comes
// Delta t = U_roll / (3.5 k g) late) and the integrator separate the run from the formula:
constexpr double kRollSlipSpeed = 1e-6;                            // m/s
constexpr double kRollTimeTolStatic = 1e-6;                        // s  (>> U_roll / (3.5 k g) = 1.5e-7 s)
constexpr double kRollSpeedTolStatic = 1e-6;                       // m/s (>> k g Delta t = 3e-7 m/s)

struct SlidingSphere {
  double R = 0.05, m = 1.0, k = 0.2, lambda = 1e7, g = 9.81, v0 = 2.0;
};

RunSummary slide(const friction::FrictionLaw& law, const SlidingSphere& p, double eps0) {
  const BodyOnPlane sys(sphere_body(p.R, p.m), PlaneContact{p.k, p.lambda, p.g}, law);
  const StateVector x0 = make_state({p.v0, 0.0, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), eps0);
  RunOptions o = tight(1.0, 1e-2);
  o.rest.slip_speed = kRollSlipSpeed;
  return simulate(sys, x0, o);
}

TEST(DynSimulation, SlidingSphereStartsRollingAtFiveSeventhsOfItsSpeed) {
  const SlidingSphere p;
  const double t_roll = 2.0 * p.v0 / (7.0 * p.k * p.g);
  // Any law whose pure-slip force is kN (model-notes §1; the printed Pade law too: Omega = 0).
  for (const char* name : {"exact", "pade-printed"}) {
    const auto law = friction::make_law(name);
    const double eps_static = PlaneContact{p.k, p.lambda, p.g}.static_height(p.m * p.g);
    const RunSummary s = slide(*law, p, eps_static);
    ASSERT_EQ(s.reason, Termination::rolling) << name << ": " << s.message;
    EXPECT_NEAR(s.t_final, t_roll, kRollTimeTolStatic) << name;
    EXPECT_NEAR(velocity(s.x_final).norm(), 5.0 * p.v0 / 7.0, kRollSpeedTolStatic) << name;
    // Rolling: omega R = v.
    EXPECT_NEAR(angular_velocity(s.x_final).norm() * p.R, 5.0 * p.v0 / 7.0, kRollSpeedTolStatic) << name;
  }
}

TEST(DynSimulation, SlidingSphereDroppedOntoThePlaneRollsWithinTheHertzBound) {
  // Started touching (eps = 0) the sphere bounces on the Hertz spring: N oscillates about m g
  // and the friction impulse differs from k m g t by k m Delta(v.gamma) (eq. (2) along gamma).
  // |Delta(v.gamma)| <= v_max = sqrt(1.2 g |eps_static|) (energy of the drop to the static
  // compression, 3/5 m g |eps_s|), so t_roll moves by at most v_max/g and v by k v_max.
  const SlidingSphere p;
  const auto law = friction::make_law("exact");
  const double eps_s = PlaneContact{p.k, p.lambda, p.g}.static_height(p.m * p.g);
  const double v_max = std::sqrt(1.2 * p.g * std::abs(eps_s));
  const RunSummary s = slide(*law, p, 0.0);
  ASSERT_EQ(s.reason, Termination::rolling) << s.message;
  EXPECT_NEAR(s.t_final, 2.0 * p.v0 / (7.0 * p.k * p.g), v_max / p.g);
  EXPECT_NEAR(velocity(s.x_final).norm(), 5.0 * p.v0 / 7.0, p.k * v_max + kRollSpeedTolStatic);
  EXPECT_EQ(s.liftoffs, 0);  // the spring never unloads completely from rest at eps = 0
}

// ---------------------------------------------------------------------------------------------
// A sphere spinning about the vertical (U = 0): the exact law gives M0 = (3 pi/16) k N a on the
// static patch a = sqrt(2 |eps_s| R), so Omega falls linearly at M0/C and stops at C omega0/M0.
// Along the way only rounding separates Omega(t) from the line; the rest event fires when
// |Omega| < rest.spin, i.e. rest.spin C/M0 before the analytic stop.
constexpr double kSpinLineTol = 1e-9;  // 1/s: integrator tolerance 1e-12 over O(100) steps
// eps is held at the static compression to the absolute tolerance 1e-12 m of |eps_s| ~ 1e-4 m,
// so N (and M) stay at their static values to ~1.5e-8 relative.
constexpr double kStaticLoadRelTol = 1e-7;

TEST(DynSimulation, SpinningSphereDecaysLinearlyAndStopsAtRest) {
  const double R = 0.05, m = 1.0, k = 0.2, lambda = 1e7, g = 9.81, w0 = 20.0;
  const auto law = friction::make_law("exact");
  const PlaneContact plane{k, lambda, g};
  const BodyOnPlane sys(sphere_body(R, m), plane, *law);
  const double eps_s = plane.static_height(m * g);
  const double a = std::sqrt(2.0 * std::abs(eps_s) * R);
  const double M0 = 3.0 * pi / 16.0 * k * m * g * a;
  const double C = 0.4 * m * R * R;
  const StateVector x0 = make_state(Eigen::Vector3d::Zero(), {0.0, 0.0, w0}, Eigen::Vector3d::UnitZ(), eps_s);
  Recorder rec;
  RunOptions o = tight(10.0, 0.1);
  const RunSummary s = simulate(sys, x0, o, &rec);
  ASSERT_EQ(s.reason, Termination::rest) << s.message;
  for (const auto& r : rec.rows) {
    EXPECT_NEAR(r.c.Omega, std::max(0.0, w0 - M0 / C * r.t), kSpinLineTol) << "t = " << r.t;
    if (r.c.Omega > 0.0) {
      EXPECT_NEAR(r.c.friction.M, M0, kStaticLoadRelTol * M0);
    }
  }
  const double t_stop = C * w0 / M0;
  EXPECT_LE(s.t_final, t_stop);
  EXPECT_GE(s.t_final, t_stop - o.rest.spin * C / M0 - 1e-9);
  // No chatter. The step is bounded by the stability of the explicit stepper on the Hertz
  // vertical mode, omega_n = sqrt(1.5 lambda sqrt|eps_s| / m), |h omega_n| <~ 4: about
  // t_stop omega_n / 4 steps. Chatter at Omega = 0 would add orders of magnitude more.
  const double omega_n = std::sqrt(1.5 * lambda * std::sqrt(std::abs(eps_s)) / m);
  const double expected_steps = t_stop * omega_n / 4.0;
  EXPECT_LT(s.steps, 2.0 * expected_steps) << "steps = " << s.steps;
  EXPECT_LT(s.rhs_calls, 2.0 * 20 * expected_steps) << "rhs calls = " << s.rhs_calls;  // <= ~20 per step
}

// ---------------------------------------------------------------------------------------------
// Energy never rises under the exact law (model-notes §3): E(t) is non-increasing along random
// short starts of the egg, and E + W_slide + W_spin = E(0) (the work states integrate F1 U and
// M Omega). Both hold to the integrator's accuracy: with tolerances 1e-12 the energy error of a
// run stays below 1e-9 of the energy scale (measured ~1e-11).
constexpr double kEnergyRelTol = 1e-9;

TEST(DynSimulation, EnergyNeverRisesUnderTheExactLawOnRandomEggStarts) {
  const auto law = friction::make_law("exact");
  std::mt19937 rng(2013);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> depth(2e-5, 3e-4);
  for (const char* preset : {"egg-printed", "egg-homogeneous"}) {
    const BodyOnPlane sys(egg_body(preset), PlaneContact{0.1, 1e7, 9.81}, *law);
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d g = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
      const StateVector x0 = make_state(0.3 * Eigen::Vector3d(n(rng), n(rng), n(rng)),
                                        20.0 * Eigen::Vector3d(n(rng), n(rng), n(rng)), g, -depth(rng));
      Recorder rec;
      const RunSummary s = simulate(sys, x0, tight(0.03, 1e-4), &rec);
      ASSERT_TRUE(s.reason == Termination::t_end || s.reason == Termination::rest ||
                  s.reason == Termination::rolling)
          << s.message;
      const double E0 = rec.rows.front().energy;
      const double scale = std::abs(E0) + sys.kinetic_energy(x0);
      for (std::size_t j = 1; j < rec.rows.size(); ++j) {
        EXPECT_LE(rec.rows[j].energy, rec.rows[j - 1].energy + kEnergyRelTol * scale)
            << preset << " start " << i << " t = " << rec.rows[j].t;
        const double W = slide_work(rec.rows[j].x) + spin_work(rec.rows[j].x);
        EXPECT_NEAR(rec.rows[j].energy + W, E0, kEnergyRelTol * scale) << preset << " start " << i;
        EXPECT_GE(slide_work(rec.rows[j].x), slide_work(rec.rows[j - 1].x) - kEnergyRelTol * scale);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Lift-off and landing: a sphere dropped from 1 mm bounces on the lossless Hertz spring.
TEST(DynSimulation, DroppedSphereBouncesAndCountsLiftoffsAndLandings) {
  const testing::CoulombCircleTestLaw law;
  const double R = 0.05, m = 1.0, g = 9.81, h = 1e-3;
  const BodyOnPlane sys(sphere_body(R, m), PlaneContact{0.2, 1e7, g}, law);
  const StateVector x0 = make_state(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), h);
  RunOptions o = tight(0.1, 1e-3);
  // At the deepest point of each bounce the sphere is momentarily still: without this the rest
  // event would (correctly, by its definition) stop the run there.
  o.rest = RestThresholds{0.0, 0.0, 0.0};
  const RunSummary s = simulate(sys, x0, o);
  ASSERT_EQ(s.reason, Termination::t_end) << s.message;
  // Flight time between impacts 2 sqrt(2h/g) = 28.6 ms (+ ~0.5 ms in contact): 3 or 4 landings.
  EXPECT_GE(s.landings, 3);
  EXPECT_LE(s.landings, 4);
  EXPECT_TRUE(s.liftoffs == s.landings || s.liftoffs == s.landings - 1);
  EXPECT_EQ(s.min_normal_force, 0.0);
  EXPECT_NEAR(s.final_energy, s.initial_energy, kConservationRelTol * std::abs(s.initial_energy));
}

// ---------------------------------------------------------------------------------------------
// Failures stop the run with a reason and keep the last good state.
TEST(DynSimulation, NonFiniteFrictionStopsTheRunAndKeepsTheLastGoodState) {
  const testing::PoleTestLaw law(1.0);  // F2 = inf once U < 1 m/s
  const SlidingSphere p;
  const double eps_s = PlaneContact{p.k, p.lambda, p.g}.static_height(p.m * p.g);
  const RunSummary s = slide(law, p, eps_s);
  ASSERT_EQ(s.reason, Termination::non_finite);
  EXPECT_NE(s.message.find("F2 = inf"), std::string::npos) << s.message;
  EXPECT_TRUE(s.x_final.allFinite());
  // U(t) = v0 - 3.5 k g t reaches 1 m/s at t = 1/(3.5 k g) = 0.1456 s.
  EXPECT_NEAR(s.t_final, (p.v0 - 1.0) / (3.5 * p.k * p.g), 1e-6);
}

TEST(DynSimulation, ALawRejectingItsInputStopsTheRunWithItsMessage) {
  const testing::ThrowingTestLaw law;  // throws once |Omega| < 5
  const BodyOnPlane sys(sphere_body(0.05, 1.0), PlaneContact{0.2, 1e7, 9.81}, law);
  const double eps_s = sys.plane().static_height(9.81);
  const StateVector x0 = make_state(Eigen::Vector3d::Zero(), {0.0, 0.0, 5.05}, Eigen::Vector3d::UnitZ(), eps_s);
  const RunSummary s = simulate(sys, x0, tight(10.0, 0.1));
  ASSERT_EQ(s.reason, Termination::law_error);
  EXPECT_NE(s.message.find("Omega below 5"), std::string::npos) << s.message;
  EXPECT_GE(angular_velocity(s.x_final).z(), 5.0);
}

TEST(DynSimulation, MaxStepsAndCancelStopTheRun) {
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(sphere_body(0.05, 1.0), PlaneContact{0.2, 1e7, 0.0}, law);
  const StateVector x0 = make_state({1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, Eigen::Vector3d::UnitZ(), 0.1);
  RunOptions o = tight(1.0, 1e-3);
  o.integrator.max_steps = 10;
  EXPECT_EQ(simulate(sys, x0, o).reason, Termination::max_steps);
  std::atomic<bool> cancel{true};
  o = tight(1.0, 1e-3);
  o.cancel = &cancel;
  const RunSummary s = simulate(sys, x0, o);
  EXPECT_EQ(s.reason, Termination::interrupted);
  EXPECT_EQ(s.steps, 1);
}

TEST(DynSimulation, EveryStepperRunsAndUnknownOnesAreRejected) {
  const testing::ForbiddenLaw law;
  const BodyOnPlane sys(sphere_body(0.05, 1.0), PlaneContact{0.2, 1e7, 0.0}, law);
  const StateVector x0 = make_state({1.0, 0.0, 0.0}, {0.0, 3.0, 1.0}, Eigen::Vector3d::UnitZ(), 0.1);
  for (const auto& method : integrator_methods()) {
    RunOptions o = tight(0.1, 0.01);
    o.integrator.method = method;
    o.integrator.abs_tol = o.integrator.rel_tol = 1e-8;
    if (method == "rk2" || method == "rk4") o.integrator.initial_step = 1e-4;
    const RunSummary s = simulate(sys, x0, o);
    EXPECT_EQ(s.reason, Termination::t_end) << method << ": " << s.message;
    EXPECT_NEAR(s.t_final, 0.1, 1e-15) << method;
  }
  RunOptions o = tight(0.1, 0.01);
  o.integrator.method = "euler";
  try {
    (void)simulate(sys, x0, o);
    FAIL() << "an unknown stepper must be rejected";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("run.integrator = 'euler'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
