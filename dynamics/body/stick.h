#pragma once
// Stick of a rigid body on the plane: the friction wrench that keeps the contact from slipping and
// spinning (rolling without slip and without spin; docs/dynamics.md §5 "stick", docs/model.md).
//
// Body frame, centre of mass at the origin, any symmetric positive definite inertia J (3x3) and
// any contact point r. The friction wrench is a tangential force F (F.gamma = 0) at r and a torque
// -M gamma. With the accelerations the other forces give, a_v and a_w (gravity, the normal force,
// the gyroscopic terms: the free right-hand side without friction),
//     v' = a_v + F/m,      omega' = a_w + J^-1 (r x F - M gamma).
// The contact point's velocity u = v + omega x r has no tangential part and the spin
// Omega = omega.gamma is 0 at all times iff, with gamma' = gamma x omega (eq. (4)) and r' the rate
// of the contact point (r' = dr/dgamma gamma', dr/dgamma = -(R1 d1 d1^T + R2 d2 d2^T) on the
// tangent plane: principal radii R_i along d_i),
//     P (v' + omega' x r + omega x r') = (u.gamma) gamma',        gamma.omega' = 0,
// P = I - gamma gamma^T the projection on the contact plane (the normal motion stays free: the
// Hertz contact is compliant). Both conditions are linear in (F, M): a 3x3 solve with the
// Delassus matrix W (symmetric positive definite up to the sign of M), the response of
// (tangential acceleration of the contact point, spin acceleration) to unit wrenches.
//
// The same matrix gives the impulse that removes a small slip and spin at once (the projection on
// entry to stick): the kinetic energy falls by (1/2) c^T W^-1 c >= 0, c = (slip, spin), and the
// impulse's work is split into the slide part -(1/2) P.u_t and the spin part (1/2) L Omega.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace frictionlab::dynamics {

/// What the stick solve needs about the body at one state (SI, body frame).
struct StickProblem {
  double mass = 0.0;                 ///< kg
  Eigen::Matrix3d inertia;           ///< J about the centre of mass, kg m^2 (any SPD tensor)
  Eigen::Vector3d r;                 ///< contact point from the centre of mass, m
  Eigen::Vector3d r_rate;            ///< r' (the contact point's motion over the surface), m/s
  Eigen::Vector3d gamma;             ///< upward unit vertical
  Eigen::Vector3d omega;             ///< angular velocity, 1/s
  Eigen::Vector3d u;                 ///< velocity of the contact point, m/s
  Eigen::Vector3d accel_free;        ///< a_v: v' without friction, m/s^2
  Eigen::Vector3d angular_accel_free;  ///< a_w: omega' without friction, 1/s^2
};

/// A friction wrench: force on the body (tangential, N) and the torque -M gamma (N m).
struct StickWrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double M = 0.0;
};

/// The wrench that keeps slip and spin at zero (see the header comment).
[[nodiscard]] StickWrench stick_wrench(const StickProblem& p);

/// r' = dr/dgamma gamma' for principal radii R1 along the unit tangent d1 and R2 along gamma x d1
/// (m), gamma' = gamma x omega.
[[nodiscard]] Eigen::Vector3d contact_point_rate(const Eigen::Vector3d& gamma, const Eigen::Vector3d& omega,
                                                 double R1, const Eigen::Vector3d& d1, double R2);

/// The response G of the contact's slip and spin accelerations to the friction as resistance, in
/// the basis (t1, t2 = gamma x t1, spin) for a unit tangent t1: with the friction force on the
/// body -(rho_1 t1 + rho_2 t2) at r and the torque -rho_3 gamma,
///     (t1.u', t2.u', Omega') = c_free - G rho.
/// G = B M^-1 B^T for the map B of the wrench to the body's velocities: symmetric positive
/// definite (a homogeneous sphere, r = -R gamma: G = diag(1/m + R^2/J, 1/m + R^2/J, 1/J)).
/// For p.mass, p.inertia, p.r, p.gamma.
[[nodiscard]] Eigen::Matrix3d slip_response(const StickProblem& p, const Eigen::Vector3d& t1);

/// The force that holds the slip while the spin stays free (the slip held on its slow manifold,
/// dynamics/body/slip_hold.h): the first two rows of the stick solve with the spin moment M given,
///     P (v' + omega' x r + omega x r') = (u.gamma) gamma' + P slip_accel,
/// which keeps the tangential slip's rate at slip_accel (m/s^2; zero: the slip is held as it is,
/// which need not be zero). Affine in M: the force on the body is force0 + M force_per_M (N; N per
/// N m), tangential.
struct SlipHoldForce {
  Eigen::Vector3d force0 = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_per_M = Eigen::Vector3d::Zero();
};
[[nodiscard]] SlipHoldForce slip_hold_force(const StickProblem& p, const Eigen::Vector3d& slip_accel);

/// The spin moment that holds the spin while the slip stays free (the spin of a law discontinuous
/// there held at zero, dynamics/body/slip_hold.h): the third row of the stick solve with the
/// tangential force on the body `force` (N) given, which keeps the spin's rate Omega' = gamma.omega'
/// at spin_accel (1/s^2). N m, the law's sign: the torque on the body is -M gamma.
[[nodiscard]] double spin_hold_moment(const StickProblem& p, const Eigen::Vector3d& force, double spin_accel);

/// The impulse that makes the slip and the spin zero at once (velocities jump, nothing else).
struct StickProjection {
  Eigen::Vector3d dv = Eigen::Vector3d::Zero();      ///< velocity change, m/s
  Eigen::Vector3d domega = Eigen::Vector3d::Zero();  ///< angular velocity change, 1/s
  double slide_loss = 0.0;  ///< -(1/2) P.u_t, J: work counted against sliding
  double spin_loss = 0.0;   ///< (1/2) L Omega, J: work counted against spinning
};

/// For p.mass, p.inertia, p.r, p.gamma, p.omega, p.u (the rest unused).
[[nodiscard]] StickProjection stick_projection(const StickProblem& p);

}  // namespace frictionlab::dynamics
