// The slip held on its slow manifold (dynamics/body/slip_hold.h, docs/dynamics.md §5 "slip hold").
// At a small slip every coupled law's force is linear in the slip: on a circular patch spinning at
// Omega, F = -c k N u_t/(a |Omega|) with c = 1 for a uniform pressure and 3 pi/8 for Hertz's
// (d/dU of the Coulomb traction integrated over the disk: (k/|Omega|) pi ∫ p(rho) drho), so the
// held slip is w* = -(a |Omega|/(c k N)) F_hold to O(s^2), and the slip relaxes at the rate
// g c k N/(a |Omega|), g the largest eigenvalue of the slip response. Whole runs: a weeble that
// rolls and spins on a stiff contact follows the run that integrates the stiff slip, in far fewer
// steps, its energy balanced.
#include "dynamics/body/slip_hold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynamics/body/body.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"

namespace frictionlab::dynamics {
namespace {

constexpr double kG = 9.81;  // m/s^2

// A weeble: a sphere (R = 5 cm, 1 kg) whose centre of mass lies 2 cm below its centre.
Body weeble() {
  BodySpec spec;
  spec.preset = "sphere";
  spec.radius = 0.05;
  spec.mass = 1.0;
  spec.com = -0.02;
  return make_body(spec);
}

// Tilted by `tilt` about x, rocking at `rock` about x and spinning at Omega about the vertical,
// rolling (u = 0), at the static compression.
StateVector rolling_state(const BodyOnPlane& sys, double tilt, double rock, double Omega) {
  const Eigen::Vector3d gamma(0.0, std::sin(tilt), std::cos(tilt));
  StateVector x = make_state(Eigen::Vector3d::Zero(), Eigen::Vector3d(rock, 0.0, 0.0) + Omega * gamma, gamma,
                             sys.plane().static_height(sys.body().mass * kG));
  const ContactState c = sys.contact_state(x);
  velocity(x) = -angular_velocity(x).cross(c.point.r);
  return x;
}

TEST(DynSlipHold, TheHeldSlipIsTheCoupledLawsLinearResponseToTheHoldingForce) {
  const struct {
    const char* law;
    double c;  // dF/ds at s = 0, in k N
  } cases[] = {{"exact", 3.0 * std::numbers::pi / 8.0}, {"exact:pressure=uniform", 1.0}};
  for (const auto& [name, slope] : cases) {
    const auto law = friction::make_law(name);
    const BodyOnPlane sys(weeble(), PlaneContact{0.3, 1e9, kG}, *law);
    const double Omega = 0.5;
    const StateVector x = rolling_state(sys, 0.01, 0.2, Omega);
    ContactState c;
    sys.contact_state(x, c, false);
    ASSERT_TRUE(c.in_contact);
    ASSERT_DOUBLE_EQ(c.a, c.b);  // a circle
    const StickProblem p = sys.stick_problem(x, c);
    const HeldSlip h = held_slip(sys, c, p, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    ASSERT_TRUE(h.found) << name;
    const double s = h.ratio;
    ASSERT_GT(s, 1e-4) << name;  // the holding force is not zero here
    ASSERT_LT(s, 0.03) << name;  // and small against k N: the linear regime
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const double M = sys.law_at_slip(c, h.slip, c.Omega, e1, psi).M;
    const SlipHoldForce hold = slip_hold_force(p, Eigen::Vector3d::Zero());
    const Eigen::Vector3d F = hold.force0 + M * hold.force_per_M;
    const double kN = sys.plane().k * c.N;
    const Eigen::Vector3d expected = -(c.a * std::abs(c.Omega) / (slope * kN)) * F;
    // The law's force is odd in the slip: the next term is O(s^3), relative O(s^2).
    EXPECT_LT((h.slip - expected).norm(), 2.0 * s * s * expected.norm())
        << name << ": " << h.slip.transpose() << " vs " << expected.transpose();
    EXPECT_NEAR(h.stiffness, largest_slip_response(p, c.major) * slope * kN / (c.a * std::abs(c.Omega)),
                2.0 * s * s * h.stiffness)
        << name;
  }
}

struct WeebleRun {
  RunSummary summary;
  double omega_end;  // |omega| at the end, 1/s
};

// The weeble tilted by 0.05 rad, rocking at 2 1/s and spinning at 0.15 1/s, on a stiff contact
// (static compression 4.6e-6 m, patch radius ~0.7 mm) with the exact law, for 0.3 s: the spin
// moment brakes the spin to a stop (stick) within ~0.12 s, and below ~0.1 1/s the slip relaxes
// 1e3 times faster than the body moves (~1e5 1/s).
WeebleRun weeble_run(bool slip_hold) {
  const auto law = friction::make_law("exact");
  const BodyOnPlane sys(weeble(), PlaneContact{0.3, 1e9, kG}, *law);
  RunOptions o;
  o.t_end = 0.3;
  o.output_dt = 0.01;
  o.settle.time = 0.0;
  o.stop_when_rolling = false;
  o.slip_hold = slip_hold;
  o.integrator.max_steps = 3000000;
  const RunSummary s = simulate(sys, rolling_state(sys, 0.05, 2.0, 0.15), o);
  return {s, angular_velocity(s.x_final).norm()};
}

TEST(DynSlipHoldRun, AHeldRunFollowsTheStiffRunInAFractionOfItsSteps) {
  const WeebleRun held = weeble_run(true);
  const WeebleRun stiff = weeble_run(false);
  ASSERT_EQ(stiff.summary.reason, Termination::t_end) << stiff.summary.message;
  ASSERT_EQ(held.summary.reason, Termination::t_end) << held.summary.message;
  EXPECT_GE(held.summary.hold_entries, 1);
  EXPECT_EQ(stiff.summary.hold_entries, 0);
  EXPECT_LT(held.summary.steps, stiff.summary.steps / 4);
  // The reduction's error is of the order of 1/(lambda T) <= 1e-3 of the slip (kHoldStiffness):
  // the motion differs by less (2e-8 relative in |omega|, 527 steps against 4052, on 2026-11-29),
  // and stick begins at the same time to within the slip's relaxation (1.5e-4 s then).
  EXPECT_NEAR(held.omega_end, stiff.omega_end, 1e-3 * stiff.omega_end);
  EXPECT_EQ(held.summary.stick_entries, 1);
  EXPECT_EQ(stiff.summary.stick_entries, 1);
  EXPECT_NEAR(held.summary.first_stick_entry, stiff.summary.first_stick_entry, 1e-3);
  const double mgR = 1.0 * kG * 0.05;
  for (const WeebleRun* r : {&held, &stiff}) {
    const RunSummary& s = r->summary;
    EXPECT_NEAR(s.final_energy + slide_work(s.x_final) + spin_work(s.x_final), s.initial_energy, 1e-9 * mgR);
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
