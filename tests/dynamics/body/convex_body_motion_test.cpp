// The body model with shapes other than today's bodies of revolution (docs/convex-bodies.md §9-§12):
// two independent geometry codes agree (the ellipsoid's closed forms against the profile's Newton
// solve), energy is conserved without friction and balanced with it, the full inertia tensor
// against the same body described in its principal axes, and the pose carried beside the state.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/body/simulation.h"
#include "dynamics/shapes/ellipsoid.h"
#include "dynamics/shapes/solid_mass_properties.h"
#include "dynamics/shapes/toroidal_disk.h"
#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace convex_body_motion_test {

// Collects every sample.
class Recorder final : public Observer {
 public:
  struct Row {
    double t;
    StateVector x;
    double energy;
  };
  void sample(const Sample& s) override { rows.push_back({s.t, s.x, s.energy}); }
  std::vector<Row> rows;
};

RunOptions tight(double t_end, double output_dt, double tol = 1e-12) {
  RunOptions o;
  o.t_end = t_end;
  o.output_dt = output_dt;
  o.integrator.abs_tol = tol;
  o.integrator.rel_tol = tol;
  o.stop_when_rolling = false;
  return o;
}

// Fixed steps of h: tolerances so loose that GSL's error control never shortens a step (its error
// ratio stays < 0.5, so it only lengthens them, and run.max_step caps them at h). Two runs whose
// right-hand sides agree to rounding then take the same steps, and whatever differs between them
// is their right-hand sides' doing, not the step sequence's (adaptive steps of two such runs part at
// the first differently rejected step, by the integrator's tolerance). h resolves the Hertz
// vibration (period ~16 ms here) by more than 100 steps.
RunOptions fixed_steps(double t_end, double output_dt, double h = 1e-4) {
  RunOptions o;
  o.t_end = t_end;
  o.output_dt = output_dt;
  o.integrator.abs_tol = 1e6;
  o.integrator.rel_tol = 1e6;
  o.integrator.initial_step = h;
  o.integrator.max_step = h;
  o.stop_when_rolling = false;
  return o;
}

// A body of revolution with given mass properties (the fast path: centre of mass on the axis, J diagonal).
Body revolution_body(BodySpec spec, double com, double A, double C) {
  spec.com = com;
  spec.A = A;
  spec.C = C;
  Body b = make_body(spec);
  EXPECT_TRUE(b.axisymmetric.has_value());
  return b;
}

Body ellipsoid_body(const Eigen::Vector3d& semi_axes, double mass, const Eigen::Vector3d& com,
                    const Eigen::Matrix3d& J) {
  BodySpec spec;
  spec.shape = "ellipsoid";
  spec.shape_parameters["semi_axes"] = {semi_axes[0], semi_axes[1], semi_axes[2]};
  spec.mass = mass;
  spec.com_vector = com;
  spec.inertia = J;
  Body b = make_body(spec);
  EXPECT_FALSE(b.axisymmetric.has_value());
  return b;
}

// With patch = "hertz", E* = 5e7 Pa gives these few-centimetre bodies a stiffness near lambda = 1e7
// N/m^1.5 (N = (4/3) E* sqrt(R) delta^1.5 for a sphere).
PlaneContact plane(double k, PatchModel patch, double lambda = 1e7, double E_star = 5e7) {
  PlaneContact c{k, lambda, 9.81};
  c.patch = patch;
  c.E_star = patch == PatchModel::hertz ? E_star : 0.0;
  return c;
}

// The largest difference of two recorded runs over the reduced state (v, omega, gamma, eps), each
// part relative to its scale (sqrt(g R), sqrt(g/R), 1, and R for the height eps: a length of the
// motion, on the body's scale); the runs must have the same sample times.
double max_difference(const Recorder& a, const Recorder& b, double speed, double rate, double length) {
  EXPECT_EQ(a.rows.size(), b.rows.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.rows.size(), b.rows.size()); ++i) {
    EXPECT_EQ(a.rows[i].t, b.rows[i].t);
    const StateVector& x = a.rows[i].x;
    const StateVector& y = b.rows[i].x;
    worst = std::max({worst, (velocity(x) - velocity(y)).norm() / speed,
                      (angular_velocity(x) - angular_velocity(y)).norm() / rate,
                      (vertical(x) - vertical(y)).norm(), std::abs(height(x) - height(y)) / length});
  }
  return worst;
}

// ---------------------------------------------------------------------------------------------
// Two geometry codes: a sphere and a spheroid as ellipsoids (closed forms, dynamics/shapes/ellipsoid.h)
// against the same bodies of revolution (Newton on the profile, dynamics/shapes/contact_geometry.h),
// with the same mass properties given to both, on the same fixed steps (fixed_steps): the right-hand
// sides agree to rounding, so the runs differ only by rounding carried through the steps. The
// bounds asked for: 1e-12 for the sphere (the contact point -R gamma, no orientation) and 1e-9 for
// the spheroid, over 1 s; each part of the state relative to its scale (the height eps to the body's size).
constexpr double kSphereAgreement = 1e-12;
constexpr double kSpheroidAgreement = 1e-9;

// Runs both systems from x0 on the same fixed steps for 1 s and asks that they take the same steps
// and stay within `tol`, each part of the state relative to its scale for a body of size `size`.
void expect_same_motion(const BodyOnPlane& a, const BodyOnPlane& b, const StateVector& x0, double size, double tol,
                        const std::string& what) {
  Recorder ra, rb;
  const RunSummary sa = simulate(a, x0, fixed_steps(1.0, 0.01), &ra);
  const RunSummary sb = simulate(b, x0, fixed_steps(1.0, 0.01), &rb);
  ASSERT_EQ(sa.reason, Termination::t_end) << what << ": " << sa.message;
  ASSERT_EQ(sb.reason, Termination::t_end) << what << ": " << sb.message;
  EXPECT_EQ(sa.steps, sb.steps) << what;
  EXPECT_LT(max_difference(ra, rb, std::sqrt(9.81 * size), std::sqrt(9.81 / size), size), tol) << what;
}

TEST(DynConvexBodyMotion, SphereAsEllipsoidFollowsTheSphereOfRevolution) {
  const auto law = friction::make_law("exact");
  constexpr double R = 0.05, m = 1.0, I = 0.4 * m * R * R;
  BodySpec rev;
  rev.preset = "sphere";
  rev.radius = R;
  rev.mass = m;
  const Body sphere = revolution_body(rev, 0.0, I, I);
  const Body ellipsoid = ellipsoid_body({R, R, R}, m, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * I);
  for (const PatchModel patch : {PatchModel::section, PatchModel::hertz}) {
    const StateVector x0 = make_state({0.2, 0.05, 0.0}, {3.0, -2.0, 20.0}, Eigen::Vector3d(0.3, 0.1, 0.95).normalized(),
                                      -2e-5);
    expect_same_motion(BodyOnPlane(sphere, plane(0.2, patch), *law), BodyOnPlane(ellipsoid, plane(0.2, patch), *law),
                       x0, R, kSphereAgreement, patch == PatchModel::hertz ? "hertz" : "section");
  }
}

TEST(DynConvexBodyMotion, SpheroidAsEllipsoidFollowsTheSpheroidOfRevolution) {
  const auto law = friction::make_law("exact");
  constexpr double a_eq = 0.03, c_pol = 0.05, m = 0.2;
  const double A = m / 5.0 * (a_eq * a_eq + c_pol * c_pol), C = m / 5.0 * 2.0 * a_eq * a_eq;
  BodySpec rev;
  rev.preset = "spheroid";
  rev.semi_axes = std::array<double, 2>{a_eq, c_pol};
  rev.mass = m;
  // The profile coordinate runs from the lower pole: the centre is at z = c (Profile::spheroid).
  const Body spheroid = make_body([&] {
    BodySpec s = rev;
    s.A = A;
    s.C = C;
    return s;
  }());
  ASSERT_TRUE(spheroid.axisymmetric.has_value());
  const double centre = 0.5 * (spheroid.axisymmetric->profile.z_lo() + spheroid.axisymmetric->profile.z_hi());
  const Body same = revolution_body(rev, centre, A, C);
  const Body ellipsoid =
      ellipsoid_body({a_eq, a_eq, c_pol}, m, Eigen::Vector3d::Zero(), Eigen::Vector3d(A, A, C).asDiagonal());
  const std::vector<std::pair<const char*, StateVector>> starts = {
      {"case a", make_state(Eigen::Vector3d::Zero(), {0.0, 0.0, 100.0}, {std::sqrt(1.0 - 0.97 * 0.97), 0.0, 0.97}, -0.3e-5)},
      // Tilted and rocking, in contact throughout (a start that bounces is chaotic: rounding grows
      // tenfold in 0.06 s there, whatever the geometry code).
      {"tilted", make_state({0.05, 0.0, 0.0}, {2.0, -1.0, 15.0}, Eigen::Vector3d(0.6, 0.3, 0.74).normalized(), -3e-5)}};
  for (const auto& [name, x0] : starts) {
    for (const PatchModel patch : {PatchModel::section, PatchModel::hertz}) {
      expect_same_motion(BodyOnPlane(same, plane(0.1, patch), *law), BodyOnPlane(ellipsoid, plane(0.1, patch), *law),
                         x0, c_pol, kSpheroidAgreement,
                         std::string(name) + (patch == PatchModel::hertz ? " hertz" : " section"));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Without friction the motion conserves E = kinetic + gravity + Hertz's spring energy exactly
// (with patch = "hertz" only through the orientation torque of dynamics/shapes/hertz_orientation_torque.h).
// The bound asked for: 1e-9 of m g c (c the smallest semi-axis; the disk's rim radius), at tolerance
// 1e-12. The ellipsoid over 10 s (a second of CPU); the disk over 2 s: its 10 s take
// 27 s of CPU, too long for a test (measured once, 2026-11-28: 2.4e-12 J = 1.6e-9 m g rho =
// 1.0e-10 m g (R + rho); docs/convex-bodies.md §12).
constexpr double kFrictionlessEnergyTol = 1e-9;

void expect_energy_conserved(const Body& body, const StateVector& x0, double length, double span, const char* what) {
  const auto law = friction::make_law("exact");
  for (const PatchModel patch : {PatchModel::section, PatchModel::hertz}) {
    const BodyOnPlane sys(body, plane(0.0, patch), *law);
    Recorder rec;
    const RunSummary s = simulate(sys, x0, tight(span, 0.05), &rec);
    ASSERT_TRUE(s.reason == Termination::t_end) << what << ": " << s.message;
    const double scale = body.mass * 9.81 * length;
    double worst = 0.0;
    for (const auto& r : rec.rows) worst = std::max(worst, std::abs(r.energy - rec.rows.front().energy));
    EXPECT_LT(worst, kFrictionlessEnergyTol * scale) << what << (patch == PatchModel::hertz ? " hertz" : " section");
    EXPECT_GT(s.steps, 100) << what;  // the contact was integrated, not skipped
  }
}

TEST(DynConvexBodyMotion, FrictionlessTriaxialEllipsoidConservesEnergy) {
  const Eigen::Vector3d ax(0.05, 0.035, 0.02);
  const Body body = [&] {
    BodySpec spec;
    spec.shape = "ellipsoid";
    spec.shape_parameters["semi_axes"] = {ax[0], ax[1], ax[2]};
    spec.mass = 0.3;
    return make_body(spec);
  }();
  const StateVector x0 =
      make_state({0.05, -0.02, 0.0}, {4.0, -6.0, 25.0}, Eigen::Vector3d(0.3, -0.2, 0.93).normalized(), -1e-5);
  expect_energy_conserved(body, x0, ax[2], 10.0, "ellipsoid");
}

TEST(DynConvexBodyMotion, FrictionlessDiskConservesEnergy) {
  const Body body = testing::toroidal_disk_body(0.02, 0.003, 0.05);
  const StateVector x0 =
      make_state({0.0, -0.3, 0.0}, {2.0, 0.5, -15.0}, Eigen::Vector3d(0.95, 0.1, 0.25).normalized(), -5e-6);
  expect_energy_conserved(body, x0, 0.003, 2.0, "disk");
}

// With friction the energy never rises and E + W_slide + W_spin stays E(0), as for the egg
// (tests/dynamics/body/simulation_test.cpp): the tolerance the egg's test uses.
constexpr double kEnergyRelTol = 1e-7;

void expect_energy_balanced(const Body& body, const StateVector& x0, const char* what) {
  const auto law = friction::make_law("exact");
  for (const PatchModel patch : {PatchModel::section, PatchModel::hertz}) {
    const BodyOnPlane sys(body, plane(0.3, patch), *law);
    Recorder rec;
    const RunSummary s = simulate(sys, x0, tight(0.05, 1e-4), &rec);
    ASSERT_TRUE(s.reason == Termination::t_end || s.reason == Termination::rest) << what << ": " << s.message;
    const double E0 = rec.rows.front().energy;
    const double scale = std::abs(E0) + sys.kinetic_energy(x0);
    for (std::size_t j = 1; j < rec.rows.size(); ++j) {
      EXPECT_LE(rec.rows[j].energy, rec.rows[j - 1].energy + kEnergyRelTol * scale) << what << " t = " << rec.rows[j].t;
      const double W = slide_work(rec.rows[j].x) + spin_work(rec.rows[j].x);
      EXPECT_NEAR(rec.rows[j].energy + W, E0, kEnergyRelTol * scale) << what << " t = " << rec.rows[j].t;
    }
    EXPECT_GT(slide_work(s.x_final) + spin_work(s.x_final), 0.0) << what;  // friction did work
  }
}

TEST(DynConvexBodyMotion, FrictionNeverAddsEnergyAndBalancesItsWork) {
  BodySpec spec;
  spec.shape = "ellipsoid";
  spec.shape_parameters["semi_axes"] = {0.05, 0.035, 0.02};
  spec.mass = 0.3;
  expect_energy_balanced(make_body(spec), make_state({0.2, -0.1, 0.0}, {4.0, -6.0, 25.0},
                                                     Eigen::Vector3d(0.3, -0.2, 0.93).normalized(), -1e-5),
                         "ellipsoid");
  expect_energy_balanced(testing::toroidal_disk_body(0.02, 0.003, 0.05),
                         make_state({0.1, -0.3, 0.0}, {2.0, 0.5, -15.0}, Eigen::Vector3d(0.95, 0.1, 0.25).normalized(),
                                    -5e-6),
                         "disk");
}

// ---------------------------------------------------------------------------------------------
// The full inertia tensor: a body whose J is diagonal in axes turned by Q against the frame it is
// described in moves as the same body described in those principal axes (v, omega, gamma turned
// by Q). The shape is a sphere about its centre, which no turn changes, with the centre of mass off
// the centre (turned too), so that gravity and the contact torque act on J's off-diagonal terms:
// the matrix form of Euler's equations against the component-wise one.
// Rounding in the turned inputs (Q v0, ...) and in J's matrix products, carried over 0.5 s.
constexpr double kFullInertiaAgreement = 1e-10;

TEST(DynConvexBodyMotion, FullInertiaTensorMatchesTheBodyInItsPrincipalAxes) {
  const auto law = friction::make_law("exact");
  constexpr double R = 0.04, m = 0.5;
  const Eigen::Vector3d moments(2.6e-4, 3.1e-4, 4.4e-4);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d com(0.004, -0.002, 0.006);
  const Body principal = ellipsoid_body({R, R, R}, m, com, moments.asDiagonal());
  const Body turned = ellipsoid_body({R, R, R}, m, Q * com, shapes::rotate_inertia(moments.asDiagonal(), Q));
  ASSERT_NE(turned.inertia(0, 1), 0.0);
  const Eigen::Vector3d v0(0.1, 0.05, 0.0), w0(3.0, -5.0, 30.0), g0 = Eigen::Vector3d(0.2, -0.3, 0.93).normalized();
  for (const PatchModel patch : {PatchModel::section, PatchModel::hertz}) {
    const BodyOnPlane a(principal, plane(0.2, patch), *law);
    const BodyOnPlane b(turned, plane(0.2, patch), *law);
    Recorder ra, rb;
    const RunSummary sa = simulate(a, make_state(v0, w0, g0, -1e-5), fixed_steps(0.5, 0.01), &ra);
    const RunSummary sb = simulate(b, make_state(Q * v0, Q * w0, Q * g0, -1e-5), fixed_steps(0.5, 0.01), &rb);
    EXPECT_EQ(sa.steps, sb.steps);
    ASSERT_EQ(sa.reason, Termination::t_end) << sa.message;
    ASSERT_EQ(sb.reason, Termination::t_end) << sb.message;
    ASSERT_EQ(ra.rows.size(), rb.rows.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < ra.rows.size(); ++i) {
      const StateVector& x = ra.rows[i].x;
      const StateVector& y = rb.rows[i].x;
      worst = std::max({worst, (Q * velocity(x) - velocity(y)).norm() / std::sqrt(9.81 * R),
                        (Q * angular_velocity(x) - angular_velocity(y)).norm() / std::sqrt(9.81 / R),
                        (Q * vertical(x) - vertical(y)).norm(), std::abs(height(x) - height(y)) / 1e-5});
    }
    EXPECT_LT(worst, kFullInertiaAgreement) << (patch == PatchModel::hertz ? "hertz" : "section");
  }
}

// ---------------------------------------------------------------------------------------------
// A homogeneous triaxial ellipsoid of a few centimetres (0.05 x 0.035 x 0.02 m, 0.3 kg).
Body small_ellipsoid() {
  BodySpec spec;
  spec.shape = "ellipsoid";
  spec.shape_parameters["semi_axes"] = {0.05, 0.035, 0.02};
  spec.mass = 0.3;
  return make_body(spec);
}

// The pose. Its quaternion is integrated apart from gamma; both describe the same turning, so the
// vertical seen from the body, R(q)^T e_z, stays gamma to the integration's accuracy.
TEST(DynConvexBodyMotion, OrientationQuaternionAgreesWithTheIntegratedVertical) {
  const auto law = friction::make_law("exact");
  const BodyOnPlane sys(small_ellipsoid(), plane(0.2, PatchModel::section), *law);
  StateVector x0 = make_state({0.2, -0.1, 0.0}, {4.0, -6.0, 25.0}, Eigen::Vector3d(0.3, -0.2, 0.93).normalized(), -1e-5);
  orientation(x0) = orientation_from(vertical(x0), 1.2);  // any heading
  Recorder rec;
  const RunSummary s = simulate(sys, x0, tight(0.5, 0.01), &rec);
  ASSERT_EQ(s.reason, Termination::t_end) << s.message;
  for (const auto& r : rec.rows) {
    const Eigen::Vector3d up = orientation_quaternion(r.x).conjugate() * Eigen::Vector3d::UnitZ();
    EXPECT_LT((up - vertical(r.x).normalized()).norm(), 1e-9) << "t = " << r.t;
  }
}

// A sphere launched sliding at v0 without spin: Coulomb friction k m g decelerates its centre at
// k g until it rolls at t_r = 2 v0/(7 k g) (the closed form of the sliding-sphere checks,
// docs/dynamics.md §8), so up to t_r its path is the straight line v0 t - k g t^2/2 along the
// heading it was launched in. It starts at the static compression (N = m g): no normal motion.
TEST(DynConvexBodyMotion, SlidingSpherePathFollowsTheClosedForm) {
  const auto law = friction::make_law("exact");
  constexpr double R = 0.05, m = 1.0, k = 0.2, g = 9.81, v0 = 0.5, heading = 0.6;
  const Body sphere = ellipsoid_body({R, R, R}, m, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 0.4 * m * R * R);
  const PlaneContact contact{k, 1e7, g};
  const BodyOnPlane sys(sphere, contact, *law);
  StateVector x0 = make_state({v0, 0.0, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                              contact.static_height(m * g));
  orientation(x0) = orientation_from(Eigen::Vector3d::UnitZ(), heading);
  position(x0) = Eigen::Vector2d(1.0, -2.0);
  const double T = 0.9 * 2.0 * v0 / (7.0 * k * g);  // still sliding
  const RunSummary s = simulate(sys, x0, tight(T, 0.01, 1e-10));
  ASSERT_EQ(s.reason, Termination::t_end) << s.message;
  const double along = v0 * T - 0.5 * k * g * T * T;
  const Eigen::Vector2d expected = Eigen::Vector2d(1.0, -2.0) + along * Eigen::Vector2d(std::cos(heading), std::sin(heading));
  EXPECT_LT((position(s.x_final) - expected).norm(), 1e-8 * along);
}

// The pose is not fed back and takes no part in the error control: a run from another position
// and heading has every other component equal to the last bit, with the same steps.
TEST(DynConvexBodyMotion, PoseChangesNoOtherComponent) {
  const auto law = friction::make_law("exact");
  const BodyOnPlane sys(small_ellipsoid(), plane(0.2, PatchModel::hertz), *law);
  const StateVector x0 = make_state({0.2, -0.1, 0.0}, {4.0, -6.0, 25.0}, Eigen::Vector3d(0.3, -0.2, 0.93).normalized(), -1e-5);
  StateVector moved = x0;
  position(moved) = Eigen::Vector2d(3.0, -7.0);
  orientation(moved) = orientation_from(vertical(x0), 2.5);
  RunOptions o = tight(0.2, 0.01, 1e-10);
  Recorder ra, rb;
  const RunSummary sa = simulate(sys, x0, o, &ra);
  const RunSummary sb = simulate(sys, moved, o, &rb);
  EXPECT_EQ(sa.steps, sb.steps);
  EXPECT_EQ(sa.rhs_calls, sb.rhs_calls);
  ASSERT_EQ(ra.rows.size(), rb.rows.size());
  for (std::size_t i = 0; i < ra.rows.size(); ++i)
    for (int j = 0; j < StateLayout::kPosition; ++j) EXPECT_EQ(ra.rows[i].x[j], rb.rows[i].x[j]) << "row " << i << " component " << j;
  EXPECT_NE(position(sa.x_final), position(sb.x_final));
}

// A disk lying down stops at the 'flat-face' event with its reason, never with a crash: the disk
// pushed over on its rim falls flat.
TEST(DynConvexBodyMotion, DiskFallingFlatStopsAtTheFlatFaceEvent) {
  const auto law = friction::make_law("exact");
  const BodyOnPlane sys(testing::toroidal_disk_body(0.02, 0.003, 0.05), plane(0.3, PatchModel::section), *law);
  // Pushed over (so that it does not start at rest), then left to fall.
  const StateVector x0 = make_state(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 4.0, 1.0),
                                    Eigen::Vector3d(0.8, 0.0, 0.6), PlaneContact{0.3, 1e7, 9.81}.static_height(0.05 * 9.81));
  RunOptions o = tight(3.0, 0.01, 1e-9);
  o.max_stagnant_steps = 0;
  o.chatter.max_steps = 0;
  const RunSummary s = simulate(sys, x0, o);
  EXPECT_EQ(s.reason, Termination::flat_face) << s.message;
  EXPECT_NE(s.message.find("face"), std::string::npos) << s.message;
  EXPECT_EQ(s.rule, BodyOnPlane::kFlatFaceRule);
}

}  // namespace
}  // namespace frictionlab::dynamics
