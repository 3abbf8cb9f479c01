// The rattleback on the compliant plane (docs/rattleback.md): the shipped Kane & Levinson body
// (data/scenarios/rattleback-*.toml). Expected values come from closed forms of the spin's braking
// and from the rest rule's physics, not from runs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"

namespace frictionlab::dynamics {
namespace rattleback_test {

struct SpinRecorder final : public Observer {
  void sample(const Sample& s) override {
    t.push_back(s.t);
    spin.push_back(s.contact.Omega);
  }
  std::vector<double> t, spin;
};

Scenario rattleback(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/" + name + ".toml", overrides);
}

// The time at which a pure spin n0 about the vertical stops under the moment M of the static patch:
// upright (gamma = e3, J13 = J23 = 0) the angular momentum J33 omega3 is vertical, omega x L = 0, and
// the only torque about the vertical is the patch's spin moment, constant at pure spin (every law
// is homogeneous of degree zero in (U, Omega)): Omega(t) = n0 - M t / J33. The patch is the static
// one of the section hypothesis (docs/contact-models.md): compression (m g/lambda)^(2/3), semi-axes
// sqrt(2 eps R_i) with the radii a1^2/a3 and a2^2/a3 at the lowest vertex.
double stop_time(const Scenario& sc, double n0) {
  const double m = sc.body.mass, g = sc.contact.g;
  const double eps = std::pow(m * g / sc.contact.lambda, 2.0 / 3.0);
  const double a1 = 0.2, a2 = 0.03, a3 = 0.02;  // the shipped semi-axes, m
  friction::ContactInput in;
  in.U = 0.0;
  in.Omega = n0;
  in.a = std::sqrt(2.0 * eps * a1 * a1 / a3);
  in.b = std::sqrt(2.0 * eps * a2 * a2 / a3);
  in.psi = friction::PatchAngle(0.0);
  in.N = m * g;
  in.k = sc.contact.k;
  const double M = friction::make_law(sc.law)->evaluate(in).M;
  return sc.body.inertia(2, 2) * n0 / M;
}

// Upright, the spin stops where the closed form says (the run's rest is declared when |Omega| falls
// below run.rest_spin, 7e-3 1/s here: 1e-3 of the spin's scale; allow for that).
TEST(DynRattleback, AnUprightSpinStopsAtTheTimeOfTheStaticPatchsSpinMoment) {
  const Scenario sc = rattleback("rattleback-braked", {"initial.gamma=[0, 0, 1]"});
  const double n0 = sc.initial.omega.z();
  const double T = stop_time(sc, n0);
  const auto law = friction::make_law(sc.law);
  const BodyOnPlane sys(sc.body, sc.contact, *law);
  const RunSummary s = simulate(sys, initial_state(sc), sc.run);
  ASSERT_EQ(s.reason, Termination::rest) << s.message;
  EXPECT_NEAR(s.t_final, T, 2.0 * s.rest.spin.value / n0 * T + 1e-3 * T) << "closed form T = " << T << " s";
}

// Tilted by 1.4e-3 rad the instability grows (rolling without slip, at 5 1/s: e-folding in 0.47 s,
// docs/rigid-rolling.md §2.4), but on this soft contact (static compression 1e-5 m) the spin moment
// stops the spin within ~1.2 s, while a reversal needs the pitch to hold the spin's energy, an
// amplitude n0 sqrt(J33/(m g (R1 - l))) = 0.047 rad, ~30 times the start (e^(1.2/0.47) ~ 13):
// the spin must stop, without reversing, near the upright stop time.
TEST(DynRattleback, OnASoftContactTheSpinMomentStopsTheSpinBeforeItCanReverse) {
  const Scenario sc = rattleback("rattleback-braked");
  const double n0 = sc.initial.omega.z();
  const auto law = friction::make_law(sc.law);
  const BodyOnPlane sys(sc.body, sc.contact, *law);
  SpinRecorder rec;
  const RunSummary s = simulate(sys, initial_state(sc), sc.run, &rec);
  ASSERT_EQ(s.reason, Termination::rest) << s.message;
  for (std::size_t i = 0; i < rec.t.size(); ++i) EXPECT_GT(rec.spin[i], -s.rest.spin.value) << "t = " << rec.t[i];
  EXPECT_NEAR(s.t_final, stop_time(sc, n0), 0.05 * stop_time(sc, n0));
}

// At the spin reversal the rattleback pitches through a turning point: its kinetic energy, slip and
// spin pass near zero together while the pitch holds the energy the spin had (~6e-3 J here, 30 times
// run.rest_kinetic_energy). That is not rest (dynamics/body/rocking_energy.h): the run must go on
// through the reversal. Before the rocking energy was counted, this run stopped "rest" at 4.28 s.
TEST(DynRattleback, TheTurningPointOfThePitchAtTheReversalIsNotRest) {
  const Scenario sc = rattleback("rattleback-reversal", {"initial.gamma=[1e-4, 1e-4, 1]", "run.t_end=4.6",
                                                         "run.output_dt=0.01"});
  const auto law = friction::make_law(sc.law);
  const BodyOnPlane sys(sc.body, sc.contact, *law);
  SpinRecorder rec;
  const RunSummary s = simulate(sys, initial_state(sc), sc.run, &rec);
  EXPECT_EQ(s.reason, Termination::t_end) << s.message;
  EXPECT_LT(rec.spin.back(), 0.0) << "the spin has reversed by 4.6 s";
}

}  // namespace
}  // namespace frictionlab::dynamics
