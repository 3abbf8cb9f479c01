// The body's stick mode in whole runs (docs/dynamics.md §5 "stick"): a sphere that starts to roll
// enters stick and rolls on without friction work, its energy constant; stick is left exactly
// where the wrench rolling needs first reaches the boundary of the law's limit set (|F| = kN at
// M = 0, for the decoupled and the exact law), located inside the step; the small tippe top does
// not end at its first zero of Omega; energy never rises through entries and exits.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace stick_run_test {

using testing::sphere_body;

struct Row {
  double t;
  StateVector x;
  ContactState c;
  double energy;
  bool stick;
};
class Recorder final : public Observer {
 public:
  void sample(const Sample& s) override { rows.push_back({s.t, s.x, s.contact, s.energy, s.mode.stick}); }
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

// A sphere launched sliding without spin starts to roll at t = 2 v0/(7 k g) with v = 5 v0/7.
TEST(DynStickRun, ARollingSphereStaysInStickWithoutFrictionWork) {
  const double R = 0.05, m = 1.0, k = 0.2, g = 9.81, v0 = 2.0;
  const PlaneContact plane{k, 1e7, g};
  for (const char* name : {"exact", "decoupled", "ellipsoidal"}) {
    const auto law = friction::make_law(name);
    const BodyOnPlane sys(sphere_body(R, m), plane, *law);
    const StateVector x0 = make_state({v0, 0.0, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                      plane.static_height(m * g));
    RunOptions o = tight(3.0, 1e-3);
    o.rest.slip_speed = 1e-6;
    Recorder rec;
    const RunSummary s = simulate(sys, x0, o, &rec);
    ASSERT_EQ(s.reason, Termination::rolling) << name << ": " << s.message;
    EXPECT_EQ(s.stick_entries, 1) << name;
    EXPECT_EQ(s.stick_exits, 0) << name;
    // Entered where the sphere starts to roll (the Hertz spring's vibration shifts it by ~1e-4 s).
    EXPECT_NEAR(s.first_stick_entry, 2.0 * v0 / (7.0 * k * g), 2e-3) << name;
    // Ends by the hold rule, not at the crossing.
    EXPECT_NEAR(s.t_final - s.first_stick_entry, s.stick_hold.value, 1e-2) << name;
    EXPECT_NEAR(s.stick_time, s.t_final - s.first_stick_entry, 1e-12) << name;
    EXPECT_NEAR(velocity(s.x_final).norm(), 5.0 * v0 / 7.0, 1e-3) << name;
    // In stick: energy constant and no friction work (the entry's projection counted once).
    const Row* entry = nullptr;
    for (const Row& r : rec.rows)
      if (r.stick && !entry) entry = &r;
    ASSERT_NE(entry, nullptr) << name;
    const double e_scale = m * g * R;
    const double work_at_entry = slide_work(entry->x) + spin_work(entry->x);
    for (const Row& r : rec.rows) {
      if (r.t < entry->t) continue;
      ASSERT_TRUE(r.stick) << name << " at t = " << r.t;
      EXPECT_NEAR(r.energy, entry->energy, 1e-9 * e_scale) << name << " at t = " << r.t;
      EXPECT_NEAR(slide_work(r.x) + spin_work(r.x), work_at_entry, 1e-12 * e_scale) << name << " at t = " << r.t;
      EXPECT_LT(r.c.U, 1e-6 * o.rest.slip_speed.value()) << name;  // the drift cap
    }
  }
}

// A weeble: a sphere (R = 5 cm, 1 kg) whose centre of mass lies 2 cm below its centre, rocking
// from upright at 3 1/s about x while rolling (u = 0), on a plane of friction coefficient k, run
// from t = 0 in settled contact (run.settle_time = 0) to t_end, sampled every output_dt.
constexpr double kWeebleRadius = 0.05;  // m
constexpr double kG = 9.81;             // m/s^2
RunSummary weeble_run(const friction::FrictionLaw& law, double k, double t_end, double output_dt, Recorder* rec) {
  BodySpec spec;
  spec.preset = "sphere";
  spec.radius = kWeebleRadius;
  spec.mass = 1.0;
  spec.com = -0.02;
  const Body body = make_body(spec);
  const PlaneContact plane{k, 1e7, kG};
  const BodyOnPlane sys(body, plane, law);
  StateVector x0 = make_state(Eigen::Vector3d::Zero(), {3.0, 0.0, 0.0}, Eigen::Vector3d::UnitZ(),
                              plane.static_height(body.mass * kG));
  const ContactState c0 = sys.contact_state(x0);
  velocity(x0) = -angular_velocity(x0).cross(c0.point.r);  // rolling: u = 0
  RunOptions o = tight(t_end, output_dt);
  o.settle.time = 0.0;
  o.stop_when_rolling = false;
  return simulate(sys, x0, o, rec);
}

// The weeble rolls in stick from t = 0. The force rolling needs grows from 0 as it tilts; the
// moment about the normal stays 0 (planar rocking), where the limit set's boundary is |F| = kN for
// both laws. Run A (k large) never leaves stick; run B, with k between 0 and the largest |F|/N of
// run A, must leave it where |F|/N of run A first reaches k: the runs share every step until then
// (k enters stick only through the set).
TEST(DynStickRun, StickIsLeftWhereTheRequiredForceFirstReachesKN) {
  for (const char* name : {"decoupled", "exact"}) {
    const auto law = friction::make_law(name);
    const auto run = [&](double k, Recorder* rec) { return weeble_run(*law, k, 0.15, 1e-5, rec); };
    Recorder a;
    const RunSummary sa = run(5.0, &a);
    ASSERT_EQ(sa.stick_entries, 1) << name << ": " << sa.message;
    ASSERT_EQ(sa.stick_exits, 0) << name;
    EXPECT_EQ(sa.first_stick_entry, 0.0) << name;
    // q = |F|/N along run A, and M = 0.
    double q_max = 0.0;
    for (const Row& r : a.rows) {
      q_max = std::max(q_max, std::hypot(r.c.friction.F1, r.c.friction.F2) / r.c.N);
      EXPECT_LT(std::abs(r.c.friction.M), 1e-12 * 1.0 * kG * kWeebleRadius) << name;
    }
    const double k = 0.6 * q_max;
    double t_star = -1.0;
    for (std::size_t i = 1; i < a.rows.size(); ++i) {
      const auto q = [&](std::size_t j) { return std::hypot(a.rows[j].c.friction.F1, a.rows[j].c.friction.F2) / a.rows[j].c.N; };
      if (q(i) >= k) {
        t_star = a.rows[i - 1].t + (k - q(i - 1)) / (q(i) - q(i - 1)) * (a.rows[i].t - a.rows[i - 1].t);
        break;
      }
    }
    ASSERT_GT(t_star, 0.0) << name;
    Recorder b;
    const RunSummary sb = run(k, &b);
    ASSERT_GE(sb.stick_exits, 1) << name;
    // Linear interpolation of q between samples 1e-5 s apart: ~1e-10 s; the located exit: 2^-60
    // of its step.
    EXPECT_NEAR(sb.first_stick_exit, t_star, 1e-8) << name;
    // The same steps until then: the samples before the exit are equal bit for bit.
    for (std::size_t i = 0; i < b.rows.size() && b.rows[i].t < sb.first_stick_exit; ++i)
      ASSERT_EQ(b.rows[i].x, a.rows[i].x) << name << " at t = " << b.rows[i].t;
  }
}

// After the exit of run B above the weeble creeps at the limit (docs/dynamics.md §5 "creep"): the
// wrench it needs is a force in the rocking plane (M = 0 by the plane's symmetry), so the direction
// of creep is pure slip along that force, whatever the metric: the spin stays zero, the slip grows
// exactly opposite the friction force (its power is |F| U), |F| = kN there, and the energy never
// rises through the exits, creeps and entries.
TEST(DynStickRun, AfterAnExitThePlanarWeebleCreepsAlongTheForceWithoutSpin) {
  for (const char* name : {"decoupled", "exact"}) {
    const auto law = friction::make_law(name);
    const auto run = [&](double k, Recorder* rec) { return weeble_run(*law, k, 0.3, 1e-4, rec); };
    // k below the largest |F|/N that rolling in stick needs (run A of the test above).
    Recorder a;
    run(5.0, &a);
    double q_max = 0.0;
    for (const Row& r : a.rows) q_max = std::max(q_max, std::hypot(r.c.friction.F1, r.c.friction.F2) / r.c.N);
    const double k = 0.6 * q_max;
    Recorder rec;
    const RunSummary s = run(k, &rec);
    ASSERT_GE(s.stick_exits, 1) << name << ": " << s.message;
    const double mgR = 1.0 * kG * kWeebleRadius;  // m g R
    int slipping = 0;
    for (std::size_t i = 1; i < rec.rows.size(); ++i) {
      const Row& r = rec.rows[i];
      EXPECT_LE(r.energy, rec.rows[i - 1].energy + 1e-12 * mgR) << name << " at t = " << r.t;
      if (r.t <= s.first_stick_exit || r.stick) continue;
      // The search places beta = 0 to ~1e-9 rad (LimitSet::kDirectionTolerance): a spin moment of
      // that order of kNa drives a spin ~1e-11 1/s here.
      EXPECT_LT(std::abs(r.c.Omega), 1e-6 * s.rest.spin.value) << name << " at t = " << r.t;
      if (!(r.c.U > 1e-6 * s.rest.slip_speed.value)) continue;
      ++slipping;
      const double F = std::hypot(r.c.friction.F1, r.c.friction.F2);
      EXPECT_NEAR(F, k * r.c.N, 1e-9 * k * r.c.N) << name << " at t = " << r.t;
      EXPECT_NEAR(r.c.slide_power, F * r.c.U, 1e-6 * F * r.c.U) << name << " at t = " << r.t;
    }
    EXPECT_GT(slipping, 10) << name;
  }
}

// The shipped small tippe top: before stick its run ended "rolling" where Omega first passed below
// run.rest_spin. Now it enters stick there, leaves it (the spin moment rolling without spin needs
// exceeds what the patch holds) and goes on; energy never rises through entries and exits.
TEST(DynStickRun, TheSmallTippeTopDoesNotEndAtItsFirstZeroOfOmega) {
  const Scenario sc = load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/tippe-top.toml",
                                    {"run.t_end=17.69", "run.output_dt=1e-3"});
  const auto law = friction::make_law(sc.law);
  const BodyOnPlane sys(sc.body, sc.contact, *law);
  Recorder rec;
  const RunSummary s = simulate(sys, initial_state(sc), sc.run, &rec);
  // The first time the contact was in the stagnation region.
  double t_first = -1.0;
  for (const Row& r : rec.rows)
    if (t_first < 0.0 && r.c.in_contact && r.c.U < s.rest.slip_speed.value && std::abs(r.c.Omega) < s.rest.spin.value)
      t_first = r.t;
  ASSERT_GT(t_first, 0.0);
  EXPECT_EQ(s.reason, Termination::t_end) << s.message;
  EXPECT_GE(s.stick_entries, 1);
  EXPECT_GE(s.stick_exits, 1);
  EXPECT_GT(s.first_stick_entry, t_first - 1e-3);
  // Energy never rises (to the integrator's error, 1e-12 of m g R per sample).
  const double mgR = sc.body.mass * sc.contact.g * 0.024;
  for (std::size_t i = 1; i < rec.rows.size(); ++i)
    EXPECT_LE(rec.rows[i].energy, rec.rows[i - 1].energy + 1e-12 * mgR) << "at t = " << rec.rows[i].t;
  EXPECT_NEAR(s.final_energy + slide_work(s.x_final) + spin_work(s.x_final), s.initial_energy, 1e-9 * mgR);
}

// pade-reconstructed on the shipped tippe top: after its spin stops (~17.1 s) the spin moment rolling
// needs exceeds what the patch holds, and no slip/spin direction lets the slip grow along itself
// with this law (LimitSet::creep_direction): the run stops "chatter" after run.max_chatter_steps
// such steps instead of crawling to run.max_steps (3 million steps and 70 s of wall time before),
// its energy balanced.
TEST(DynStickRun, ACreepWithoutADirectionStopsAsChatter) {
  const Scenario sc = load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/tippe-top.toml",
                                    {"run.max_steps=300000"});
  const auto law = friction::make_law("pade-reconstructed");
  const BodyOnPlane sys(sc.body, sc.contact, *law);
  const RunSummary s = simulate(sys, initial_state(sc), sc.run);
  ASSERT_EQ(s.reason, Termination::chatter) << s.message;
  EXPECT_NE(s.message.find("without a direction of creep"), std::string::npos) << s.message;
  EXPECT_GE(s.creep_unresolved, s.chatter.max_steps.value);
  EXPECT_GE(s.stick_exits + s.creep_entries, 1);
  const double mgR = sc.body.mass * sc.contact.g * 0.024;
  EXPECT_NEAR(s.final_energy + slide_work(s.x_final) + spin_work(s.x_final), s.initial_energy, 1e-9 * mgR);
}

// run.stick = false keeps the rule from before stick: the run ends at the crossing.
TEST(DynStickRun, WithoutStickTheRunEndsRollingAtTheCrossing) {
  const double R = 0.05, m = 1.0, k = 0.2, g = 9.81, v0 = 2.0;
  const PlaneContact plane{k, 1e7, g};
  const auto law = friction::make_law("exact");
  const BodyOnPlane sys(sphere_body(R, m), plane, *law);
  const StateVector x0 = make_state({v0, 0.0, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                    plane.static_height(m * g));
  RunOptions o = tight(3.0, 1e-2);
  o.rest.slip_speed = 1e-6;
  o.stick = false;
  const RunSummary s = simulate(sys, x0, o);
  EXPECT_EQ(s.reason, Termination::rolling);
  EXPECT_EQ(s.stick_entries, 0);
  EXPECT_NEAR(s.t_final, 2.0 * v0 / (7.0 * k * g), 2e-3);
}

// A law without spin moment (decoupled:r_spin=0) has a limit set without interior: stick is never
// entered and the run keeps the rule from before stick.
TEST(DynStickRun, ALawWithoutSpinMomentNeverSticksAndEndsAsBefore) {
  const double R = 0.05, m = 1.0, k = 0.2, g = 9.81, v0 = 2.0;
  const PlaneContact plane{k, 1e7, g};
  const auto law = friction::make_law("decoupled:r_spin=0");
  const BodyOnPlane sys(sphere_body(R, m), plane, *law);
  const StateVector x0 = make_state({v0, 0.0, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                    plane.static_height(m * g));
  RunOptions o = tight(3.0, 1e-2);
  o.rest.slip_speed = 1e-6;
  const RunSummary s = simulate(sys, x0, o);
  EXPECT_EQ(s.reason, Termination::rolling);
  EXPECT_TRUE(s.stick_degenerate);
  EXPECT_EQ(s.stick_entries, 0);
  EXPECT_NEAR(s.t_final, 2.0 * v0 / (7.0 * k * g), 2e-3);
}

}  // namespace
}  // namespace frictionlab::dynamics
