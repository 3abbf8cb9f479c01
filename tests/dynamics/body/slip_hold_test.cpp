// The slip held on its slow manifold (dynamics/body/slip_hold.h, docs/dynamics.md §5 "slip hold").
// At a small slip every coupled law's force is linear in the slip: on a circular patch spinning at
// Omega, F = -c k N u_t/(a |Omega|) with c = 1 for a uniform pressure and 3 pi/8 for Hertz's
// (d/dU of the Coulomb traction integrated over the disk: (k/|Omega|) pi ∫ p(rho) drho), so the
// held slip is w* = -(a |Omega|/(c k N)) F_hold to O(s^2), and the slip relaxes at the rate
// g c k N/(a |Omega|), g the largest eigenvalue of the slip response. Whole runs: a weeble that
// rolls and spins on a stiff contact follows the run that integrates the stiff slip, in far fewer
// steps, its energy balanced.
// A law discontinuous at zero slip (`decoupled`) is held at zero slip: a sliding, spinning sphere
// rolls on from t = 2 v0/(7 k g) at 5 v0/7 with the spin the law's moment leaves it (closed forms),
// a sliding sphere whose spin stops keeps it at zero (the spin's hold), and a rocking weeble leaves
// the hold where the force it needs reaches kN, located.
#include "dynamics/body/slip_hold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "dynamics/body/body.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace slip_hold_test {

using testing::sphere_body;

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

// ---------------------------------------------------------------------------------------------
// At zero slip: a law discontinuous there (decoupled: F = kN along any slip, M = M0 sign(Omega)).

// A sphere (R = 5 cm, 1 kg, homogeneous: C = 0.4 m R^2) launched sliding at v0 while spinning at
// Omega0 about the vertical. Its spin moves no contact point (omega x r = 0 for r = -R gamma) and the
// friction's moment r x F is horizontal, so the slip falls at (7/2) k g to 0 at t_s = 2 v0/(7 k g),
// where the centre moves at 5 v0/7; rolling straight on needs no force. The spin moment M0
// (decoupled's default: (3 pi/16) k N a on the circular patch) brakes the spin at M0/C throughout.
struct SlideSpin {
  double R = 0.05, m = 1.0, k = 0.2, g = kG, v0 = 0.2, Omega0 = 20.0;
  [[nodiscard]] double t_slip() const { return 2.0 * v0 / (7.0 * k * g); }
  [[nodiscard]] double C() const { return 0.4 * m * R * R; }
};

struct SlideSpinRun {
  RunSummary s;
  ContactState c;  // at the end
  double a = 0.0;  // the patch radius at the start, m
};

SlideSpinRun slide_spin(const char* law_name, bool slip_hold, double t_end) {
  const SlideSpin p;
  const auto law = friction::make_law(law_name);
  const BodyOnPlane sys(sphere_body(p.R, p.m), PlaneContact{p.k, 1e7, p.g}, *law);
  const StateVector x0 = make_state({p.v0, 0.0, 0.0}, {0.0, 0.0, p.Omega0}, Eigen::Vector3d::UnitZ(),
                                    sys.plane().static_height(p.m * p.g));
  RunOptions o;
  o.t_end = t_end;
  o.output_dt = 1e-2;
  o.slip_hold = slip_hold;
  o.integrator.max_steps = 50'000;  // without the hold the chatter event ends it first
  SlideSpinRun r{simulate(sys, x0, o), {}, sys.contact_state(x0).a};
  r.c = sys.contact_state(r.s.x_final);
  return r;
}

TEST(DynSlipHoldAtZero, ADiscontinuousLawsSlipIsHeldAtZeroFromWhereItStops) {
  const SlideSpin p;
  const SlideSpinRun r = slide_spin("decoupled:r_spin=0", true, 0.2);
  ASSERT_EQ(r.s.reason, Termination::t_end) << r.s.message;
  EXPECT_EQ(r.s.hold_entries, 1);
  EXPECT_EQ(r.s.hold_zero_entries, 1);
  EXPECT_EQ(r.s.hold_force_exits, 0);
  // Entered once the slip fell below run.rest_slip_speed, i.e. within U_rest/((7/2) k g) of t_s.
  EXPECT_LE(r.s.first_hold_entry, p.t_slip() + 1e-9);
  EXPECT_GE(r.s.first_hold_entry, p.t_slip() - r.s.rest.slip_speed.value / (3.5 * p.k * p.g));
  EXPECT_LT(r.c.U, 1e-9);
  EXPECT_NEAR(velocity(r.s.x_final).norm(), 5.0 * p.v0 / 7.0, 1e-9);
  EXPECT_NEAR(r.c.Omega, p.Omega0, 1e-9);  // no spin moment
  // From t_s on the sphere rolls: the energy lost is the slide's alone, (1/2) m v0^2 (1 - 5/7).
  const double lost = 0.5 * p.m * p.v0 * p.v0 * (1.0 - 5.0 / 7.0);
  EXPECT_NEAR(r.s.initial_energy - r.s.final_energy, lost, 1e-9 * lost);
  EXPECT_NEAR(slide_work(r.s.x_final), lost, 1e-9 * lost);
}

TEST(DynSlipHoldAtZero, TheSpinIsFreeUnderTheLawsOwnMomentWhileTheSlipIsHeld) {
  const SlideSpin p;
  const double t_end = 0.5;
  const SlideSpinRun r = slide_spin("decoupled", true, t_end);
  ASSERT_EQ(r.s.reason, Termination::t_end) << r.s.message;
  EXPECT_EQ(r.s.hold_zero_entries, 1);
  EXPECT_LT(r.c.U, 1e-9);
  // N = m g throughout (nothing moves the sphere vertically), so M0 and the braking are constant.
  const double M0 = 3.0 * std::numbers::pi / 16.0 * p.k * p.m * p.g * r.a;
  EXPECT_NEAR(r.c.Omega, p.Omega0 - M0 * t_end / p.C(), 1e-9 * p.Omega0);
  EXPECT_NEAR(velocity(r.s.x_final).norm(), 5.0 * p.v0 / 7.0, 1e-9);
  const double mgR = p.m * p.g * p.R;
  EXPECT_NEAR(r.s.final_energy + slide_work(r.s.x_final) + spin_work(r.s.x_final), r.s.initial_energy, 1e-9 * mgR);
}

// The spin held at zero: the same sphere launched fast (v0 = 5 m/s) and spinning slowly (0.2 1/s):
// decoupled's spin moment stops the spin at t_Omega = Omega0 C/M0 while the sphere still slides
// (until t_s = 2 v0/(7 k g)); the spin is then held at zero (a sphere needs no spin moment for that:
// the friction force acts through the contact point, whose moment about the vertical is zero) and
// the slip falls on at (7/2) k g.
TEST(DynSlipHoldAtZero, ADiscontinuousLawsSpinIsHeldAtZeroWhileTheBodySlides) {
  SlideSpin p;
  p.v0 = 5.0;
  p.Omega0 = 0.2;
  const auto law = friction::make_law("decoupled");
  const BodyOnPlane sys(sphere_body(p.R, p.m), PlaneContact{p.k, 1e7, p.g}, *law);
  const StateVector x0 = make_state({p.v0, 0.0, 0.0}, {0.0, 0.0, p.Omega0}, Eigen::Vector3d::UnitZ(),
                                    sys.plane().static_height(p.m * p.g));
  const double a = sys.contact_state(x0).a;
  const double spin_rate = 3.0 * std::numbers::pi / 16.0 * p.k * p.m * p.g * a / p.C();  // M0/C, 1/s^2
  const double t_Omega = p.Omega0 / spin_rate;
  ASSERT_LT(t_Omega, 0.8 * p.t_slip());
  RunOptions o;
  o.t_end = 0.5 * (t_Omega + p.t_slip());
  o.output_dt = 1e-2;
  o.integrator.max_steps = 50'000;
  const RunSummary s = simulate(sys, x0, o);
  ASSERT_EQ(s.reason, Termination::t_end) << s.message;
  EXPECT_EQ(s.spin_hold_entries, 1);
  EXPECT_EQ(s.spin_moment_exits, 0);
  // Entered once the spin fell below run.rest_spin, i.e. within rest_spin/(M0/C) before t_Omega.
  EXPECT_LE(s.first_spin_hold_entry, t_Omega + 1e-9);
  EXPECT_GE(s.first_spin_hold_entry, t_Omega - s.rest.spin.value / spin_rate);
  const ContactState c = sys.contact_state(s.x_final);
  EXPECT_LT(std::abs(c.Omega), 1e-9);
  EXPECT_NEAR(c.U, p.v0 - 3.5 * p.k * p.g * o.t_end, 1e-9 * p.v0);
  const double mgR = p.m * p.g * p.R;
  EXPECT_NEAR(s.final_energy + slide_work(s.x_final) + spin_work(s.x_final), s.initial_energy, 1e-9 * mgR);
  // The spin's energy, (1/2) C Omega0^2, went to the spin moment's work, all of it.
  EXPECT_NEAR(spin_work(s.x_final), 0.5 * p.C() * p.Omega0 * p.Omega0, 1e-9 * mgR);
}

// The weeble rolling, rocking and spinning under `decoupled` with k = 0.05 for 3 s: it slides at
// first (rolling needs more than kN), then the force that rolling needs follows the rocking and
// reaches kN again and again (7 exits and 8 entries on 2026-11-29), where the slip starts again in
// the direction of that force's deficit. The exit is located: just before it the force is inside and within the
// integrator's error of the limit.
struct WeebleZero {
  std::unique_ptr<friction::FrictionLaw> law = friction::make_law("decoupled");
  BodyOnPlane sys{weeble(), PlaneContact{0.05, 1e9, kG}, *law};
  [[nodiscard]] RunSummary run(double t_end) const {
    RunOptions o;
    o.t_end = t_end;
    o.output_dt = 0.01;
    o.stop_when_rolling = false;
    o.integrator.max_steps = 200'000;
    return simulate(sys, rolling_state(sys, 0.3, 4.0, 3.0), o);
  }
  // kN - |F| at x: F the force that holds the zero slip with the law's spin moment (computed here
  // from the public pieces: the stick problem, slip_hold_force, the law).
  [[nodiscard]] double margin(const StateVector& x) const {
    ContactState c;
    sys.contact_state(x, c, false);
    const StickProblem p = sys.stick_problem(x, c);
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const double M = sys.law_at_slip(c, Eigen::Vector3d::Zero(), c.Omega, e1, psi).M;
    const SlipHoldForce hold = slip_hold_force(p, Eigen::Vector3d::Zero());
    return sys.plane().k * c.N - (hold.force0 + M * hold.force_per_M).norm();
  }
};

TEST(DynSlipHoldAtZero, TheHoldIsLeftWhereTheForceItNeedsReachesKNLocated) {
  const WeebleZero w;
  const RunSummary s = w.run(3.0);
  ASSERT_EQ(s.reason, Termination::t_end) << s.message;
  ASSERT_GE(s.hold_zero_entries, 1);
  ASSERT_GE(s.hold_force_exits, 1);
  const double t_exit = s.first_force_exit;
  ASSERT_GT(t_exit, s.first_hold_entry);
  const double mgR = 1.0 * kG * 0.05;
  EXPECT_NEAR(s.final_energy + slide_work(s.x_final) + spin_work(s.x_final), s.initial_energy, 1e-9 * mgR);
  // Just before the exit the run is still held, inside the limit and close to it; kN changes at a
  // rate ~ kN |N'|/N, so 1e-5 s before the exit the margin is a small fraction of kN.
  const RunSummary before = w.run(t_exit - 1e-5);
  const double kN = 0.05 * 1.0 * kG;
  const double m = w.margin(before.x_final);
  EXPECT_GT(m, 0.0);
  EXPECT_LT(m, 1e-2 * kN);
  EXPECT_EQ(before.hold_force_exits, 0);
}

}  // namespace
}  // namespace frictionlab::dynamics
