// The stick wrench and projection of dynamics/body/stick.h: what they must do follows from their
// definitions, checked independently here — the constrained accelerations keep the slip and the
// spin at zero for a general (non-diagonal) inertia and contact point (an RK4 integration of the
// constrained motion of an eccentric sphere keeps them at zero to the method's error, and without
// the wrench they grow), a homogeneous sphere rolling steadily needs no wrench at all, the contact
// point's rate matches finite differences of a real shape's contact point, and the projection
// zeroes slip and spin and removes exactly the kinetic energy it reports.
#include "dynamics/body/stick.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "dynamics/shapes/contact_geometry.h"
#include "dynamics/shapes/profile.h"

namespace frictionlab::dynamics {
namespace stick_test {

// An eccentric sphere: radius R, geometric centre at c0 from the centre of mass (body frame), a
// full inertia tensor; the contact point r = c0 - R gamma; gravity and a given normal force.
struct EccentricSphere {
  double m = 1.3;
  double R = 0.05;
  double g = 9.81;
  double N = 1.3 * 9.81;
  Eigen::Vector3d c0{0.004, -0.003, 0.01};
  Eigen::Matrix3d J;
  EccentricSphere() {
    J << 1.1e-3, 0.12e-3, -0.05e-3,  //
        0.12e-3, 0.9e-3, 0.08e-3,    //
        -0.05e-3, 0.08e-3, 1.4e-3;
  }
  [[nodiscard]] Eigen::Vector3d r(const Eigen::Vector3d& gamma) const { return c0 - R * gamma; }
};

// State y = (v, omega, gamma).
using Vec9 = Eigen::Matrix<double, 9, 1>;

// The stick problem of the sphere at y, its accelerations without friction (N = b.N along gamma).
StickProblem problem_at(const EccentricSphere& b, const Vec9& y) {
  const Eigen::Vector3d v = y.segment<3>(0), w = y.segment<3>(3), gamma = y.segment<3>(6).normalized();
  const Eigen::Vector3d r = b.r(gamma);
  StickProblem p;
  p.mass = b.m;
  p.inertia = b.J;
  p.r = r;
  p.r_rate = -b.R * gamma.cross(w);  // a sphere: dr/dgamma = -R on the tangent plane
  p.gamma = gamma;
  p.omega = w;
  p.u = v + w.cross(r);
  p.accel_free = -w.cross(v) - b.g * gamma + b.N / b.m * gamma;
  p.angular_accel_free = b.J.inverse() * (r.cross(b.N * gamma) - w.cross(b.J * w));
  return p;
}

// y' under the stick wrench (or none).
Vec9 rhs(const EccentricSphere& b, const Vec9& y, bool with_wrench) {
  const Eigen::Vector3d w = y.segment<3>(3), gamma = y.segment<3>(6).normalized();
  const Eigen::Vector3d r = b.r(gamma);
  const StickProblem p = problem_at(b, y);
  const Eigen::Vector3d a_v = p.accel_free, a_w = p.angular_accel_free;
  StickWrench f;
  if (with_wrench) f = stick_wrench(p);
  Vec9 d;
  d.segment<3>(0) = a_v + f.force / b.m;
  d.segment<3>(3) = a_w + b.J.inverse() * (r.cross(f.force) - f.M * gamma);
  d.segment<3>(6) = y.segment<3>(6).cross(w);
  return d;
}

// |slip| + R |spin| at y.
double residue(const EccentricSphere& b, const Vec9& y) {
  const Eigen::Vector3d v = y.segment<3>(0), w = y.segment<3>(3), gamma = y.segment<3>(6).normalized();
  const Eigen::Vector3d u = v + w.cross(b.r(gamma));
  return (u - u.dot(gamma) * gamma).norm() + b.R * std::abs(w.dot(gamma));
}

Vec9 rolling_start(const EccentricSphere& b) {
  const Eigen::Vector3d gamma = Eigen::Vector3d(0.3, -0.2, 0.93).normalized();
  Eigen::Vector3d w(4.0, 7.0, -2.0);
  w -= w.dot(gamma) * gamma;  // no spin
  const Eigen::Vector3d v = -w.cross(b.r(gamma));  // no slip (and no normal velocity)
  Vec9 y;
  y << v, w, gamma;
  return y;
}

double integrate(const EccentricSphere& b, bool with_wrench, double h, int n) {
  Vec9 y = rolling_start(b);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec9 k1 = rhs(b, y, with_wrench), k2 = rhs(b, y + 0.5 * h * k1, with_wrench),
               k3 = rhs(b, y + 0.5 * h * k2, with_wrench), k4 = rhs(b, y + h * k3, with_wrench);
    y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    worst = std::max(worst, residue(b, y));
  }
  return worst;
}

TEST(DynStick, WrenchKeepsSlipAndSpinZeroForAFullInertiaTensor) {
  const EccentricSphere b;
  // 0.1 s in RK4 steps of 1e-4 s: with the wrench the residue stays at rounding (RK4 keeps an
  // invariant whose rate is zero at every stage to rounding), without it grows to ~cm/s.
  const double held = integrate(b, true, 1e-4, 1000);
  const double free = integrate(b, false, 1e-4, 1000);
  EXPECT_LT(held, 1e-13);
  EXPECT_GT(free, 1e-4);
}

// The slip-hold force (slip_hold_force): with the spin moment M given and a slip and a spin that
// are not zero, the tangential slip P u changes at the target rate (finite differences of the
// state along its derivative), whatever M: the force's part in M compensates the moment's effect.
TEST(DynStick, SlipHoldForceSetsTheSlipsRateWithTheSpinMomentGiven) {
  const EccentricSphere b;
  Vec9 y = rolling_start(b);
  const Eigen::Vector3d gamma = y.segment<3>(6).normalized();
  const Eigen::Vector3d t1 = gamma.unitOrthogonal(), t2 = gamma.cross(t1);
  y.segment<3>(0) += 0.02 * t1 - 0.01 * t2;  // a slip of 2.2 cm/s
  y.segment<3>(3) += 1.5 * gamma;             // and a spin of 1.5 1/s
  const Eigen::Vector3d target = 0.3 * t1 - 0.7 * t2;  // m/s^2
  const auto slip = [&](const Vec9& z) {
    const Eigen::Vector3d g = z.segment<3>(6).normalized();
    const Eigen::Vector3d u = z.segment<3>(0) + z.segment<3>(3).cross(b.r(g));
    return Eigen::Vector3d(u - u.dot(g) * g);
  };
  for (const double M : {0.0, 0.013, -0.4}) {
    const Eigen::Vector3d w = y.segment<3>(3);
    const Eigen::Vector3d r = b.r(gamma);
    const StickProblem p = problem_at(b, y);
    const SlipHoldForce hold = slip_hold_force(p, target);
    const Eigen::Vector3d F = hold.force0 + M * hold.force_per_M;
    EXPECT_LT(std::abs(F.dot(gamma)), 1e-12 * F.norm());  // tangential
    Vec9 d;
    d.segment<3>(0) = p.accel_free + F / b.m;
    d.segment<3>(3) = p.angular_accel_free + b.J.inverse() * (r.cross(F) - M * gamma);
    d.segment<3>(6) = gamma.cross(w);
    const double h = 1e-5;  // central differences: error ~h^2
    const Eigen::Vector3d rate = (slip(y + h * d) - slip(y - h * d)) / (2.0 * h);
    const Eigen::Vector3d tangential = rate - rate.dot(gamma) * gamma;
    EXPECT_LT((tangential - target).norm(), 1e-7 * target.norm()) << "M = " << M << ": " << tangential.transpose();
  }
}

// The spin-hold moment (spin_hold_moment): with the tangential force given and a slip and a spin
// that are not zero, the spin Omega = omega.gamma changes at the target rate (finite differences
// of the state along its derivative), whatever the force.
TEST(DynStick, SpinHoldMomentSetsTheSpinsRateWithTheForceGiven) {
  const EccentricSphere b;
  Vec9 y = rolling_start(b);
  const Eigen::Vector3d gamma = y.segment<3>(6).normalized();
  const Eigen::Vector3d t1 = gamma.unitOrthogonal(), t2 = gamma.cross(t1);
  y.segment<3>(0) += 0.02 * t1 - 0.01 * t2;
  y.segment<3>(3) += 1.5 * gamma;
  const double target = -0.9;  // 1/s^2
  const auto spin = [](const Vec9& z) { return z.segment<3>(3).dot(z.segment<3>(6).normalized()); };
  for (const Eigen::Vector3d& F : {Eigen::Vector3d(Eigen::Vector3d::Zero()), Eigen::Vector3d(0.4 * t1 - 1.1 * t2)}) {
    const Eigen::Vector3d w = y.segment<3>(3);
    const Eigen::Vector3d r = b.r(gamma);
    const StickProblem p = problem_at(b, y);
    const double M = spin_hold_moment(p, F, target);
    Vec9 d;
    d.segment<3>(0) = p.accel_free + F / b.m;
    d.segment<3>(3) = p.angular_accel_free + b.J.inverse() * (r.cross(F) - M * gamma);
    d.segment<3>(6) = gamma.cross(w);
    const double h = 1e-5;  // central differences: error ~h^2
    const double rate = (spin(y + h * d) - spin(y - h * d)) / (2.0 * h);
    EXPECT_NEAR(rate, target, 1e-7 * std::abs(target)) << "F = " << F.transpose();
  }
}

TEST(DynStick, HomogeneousSphereRollingSteadilyNeedsNoWrench) {
  const double m = 2.0, R = 0.1, g = 9.81;
  StickProblem p;
  p.mass = m;
  p.inertia = 0.4 * m * R * R * Eigen::Matrix3d::Identity();
  p.gamma = Eigen::Vector3d(0.2, 0.5, -0.8).normalized();
  p.r = -R * p.gamma;
  p.omega = Eigen::Vector3d(3.0, -1.0, 2.0);
  p.omega -= p.omega.dot(p.gamma) * p.gamma;
  const Eigen::Vector3d v = -p.omega.cross(p.r);
  p.u = v + p.omega.cross(p.r);
  p.r_rate = contact_point_rate(p.gamma, p.omega, R, p.gamma.unitOrthogonal(), R);
  p.accel_free = -p.omega.cross(v) - g * p.gamma + g * p.gamma;  // N = m g
  p.angular_accel_free = Eigen::Vector3d::Zero();  // r x N gamma = 0, omega x J omega = 0
  const StickWrench w = stick_wrench(p);
  EXPECT_LT(w.force.norm(), 1e-12 * m * g);
  EXPECT_LT(std::abs(w.M), 1e-12 * m * g * R);
}

TEST(DynStick, ContactPointRateMatchesFiniteDifferencesOfAnEgg) {
  // The paper's egg (docs/model.md): its principal radii differ, so both terms of dr/dgamma count.
  const ContactGeometry egg(Profile::paper_egg(), 0.07);
  const Eigen::Vector3d gamma = Eigen::Vector3d(0.4, 0.3, 0.6).normalized();
  const Eigen::Vector3d omega(2.0, -3.0, 1.5);
  const ContactPoint c = egg.contact_point(gamma);
  const PatchShape patch = ContactGeometry::patch(c, gamma, 1e-5);
  const Eigen::Vector3d rate = contact_point_rate(gamma, omega, std::max(c.R_meridian, c.R_parallel), patch.major,
                                                  std::min(c.R_meridian, c.R_parallel));
  const Eigen::Vector3d gamma_rate = gamma.cross(omega);
  const double h = 1e-5;  // s: central differences, error ~h^2 of the third derivative
  const Eigen::Vector3d ahead = egg.contact_point((gamma + h * gamma_rate).normalized()).r;
  const Eigen::Vector3d behind = egg.contact_point((gamma - h * gamma_rate).normalized()).r;
  const Eigen::Vector3d fd = (ahead - behind) / (2.0 * h);
  EXPECT_LT((rate - fd).norm(), 1e-6 * fd.norm()) << rate.transpose() << " vs " << fd.transpose();
  EXPECT_GT(std::abs(c.R_meridian - c.R_parallel), 0.01);  // the radii really differ here
}

TEST(DynStick, ProjectionZeroesSlipAndSpinAndRemovesTheReportedEnergy) {
  const EccentricSphere b;
  Vec9 y = rolling_start(b);
  const Eigen::Vector3d gamma = y.segment<3>(6).normalized();
  Eigen::Vector3d v = y.segment<3>(0) + Eigen::Vector3d(1e-3, -2e-3, 0.5e-3);
  Eigen::Vector3d w = y.segment<3>(3) + 0.05 * gamma + Eigen::Vector3d(0.01, 0.0, 0.0);
  StickProblem p;
  p.mass = b.m;
  p.inertia = b.J;
  p.r = b.r(gamma);
  p.gamma = gamma;
  p.omega = w;
  p.u = v + w.cross(p.r);
  const auto kinetic = [&](const Eigen::Vector3d& vv, const Eigen::Vector3d& ww) {
    return 0.5 * b.m * vv.squaredNorm() + 0.5 * ww.dot(b.J * ww);
  };
  const double before = kinetic(v, w);
  const StickProjection j = stick_projection(p);
  v += j.dv;
  w += j.domega;
  const Eigen::Vector3d u = v + w.cross(p.r);
  EXPECT_LT((u - u.dot(gamma) * gamma).norm(), 1e-15);
  EXPECT_LT(std::abs(w.dot(gamma)), 1e-14);
  EXPECT_GT(j.slide_loss + j.spin_loss, 0.0);
  EXPECT_NEAR(before - kinetic(v, w), j.slide_loss + j.spin_loss, 1e-15);
}

// The slip response of a homogeneous sphere (r = -R gamma, J = (2/5) m R^2): a unit resistance
// along t1 slows the contact point by 1/m (the centre) + R^2/J (the turn), the spin by 0 and a
// unit spin moment the spin by 1/J: G = diag(1/m + R^2/J, 1/m + R^2/J, 1/J) in any tangent basis.
TEST(DynStick, SlipResponseOfAHomogeneousSphereIsTheClosedForm) {
  const double m = 2.0, R = 0.1, J = 0.4 * m * R * R;
  StickProblem p;
  p.mass = m;
  p.inertia = J * Eigen::Matrix3d::Identity();
  p.gamma = Eigen::Vector3d(0.2, 0.5, -0.8).normalized();
  p.r = -R * p.gamma;
  const Eigen::Vector3d t1 = p.gamma.cross(Eigen::Vector3d(1.0, 2.0, 0.3)).normalized();
  const Eigen::Matrix3d G = slip_response(p, t1);
  const Eigen::Vector3d expected(1.0 / m + R * R / J, 1.0 / m + R * R / J, 1.0 / J);
  EXPECT_LT((G - Eigen::Matrix3d(expected.asDiagonal())).norm(), 1e-12 * expected.norm()) << G;
}

// For a full inertia tensor and an eccentric contact point G is symmetric positive definite (it is
// B M^-1 B^T), and it predicts the change of the slip and spin rates that a friction wrench makes
// in the stick problem's own right-hand side (the eccentric sphere's rhs above).
TEST(DynStick, SlipResponseIsSymmetricPositiveDefiniteAndPredictsTheRhs) {
  const EccentricSphere b;
  const Vec9 y = rolling_start(b);
  const Eigen::Vector3d gamma = y.segment<3>(6).normalized();
  StickProblem p;
  p.mass = b.m;
  p.inertia = b.J;
  p.r = b.r(gamma);
  p.gamma = gamma;
  const Eigen::Vector3d t1 = gamma.unitOrthogonal(), t2 = gamma.cross(t1);
  const Eigen::Matrix3d G = slip_response(p, t1);
  EXPECT_LT((G - G.transpose()).norm(), 1e-12 * G.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(G).eigenvalues().minCoeff(), 0.0);
  // The resistance rho = (0.3, -0.7, 0.002): force -(0.3 t1 - 0.7 t2), torque -0.002 gamma.
  const Eigen::Vector3d rho(0.3, -0.7, 0.002);
  const Eigen::Vector3d F = -(rho[0] * t1 + rho[1] * t2);
  const Eigen::Vector3d dv = F / b.m;
  const Eigen::Vector3d dw = b.J.inverse() * (p.r.cross(F) - rho[2] * gamma);
  const Eigen::Vector3d du = dv + dw.cross(p.r);
  const Eigen::Vector3d response(t1.dot(du), t2.dot(du), gamma.dot(dw));
  EXPECT_LT((response + G * rho).norm(), 1e-12 * (G * rho).norm());
}

}  // namespace
}  // namespace frictionlab::dynamics
