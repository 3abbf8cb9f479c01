#include "dynamics/body/stick.h"

#include <Eigen/LU>

namespace frictionlab::dynamics {
namespace {

// The tangent basis (t1, t2) of the contact plane and the Delassus matrix: column j is the
// response (t1.(v' + omega' x r), t2.(v' + omega' x r), gamma.omega') to the unit wrench j of
// (F = t1, F = t2, M = 1); the same map takes impulses to velocity jumps.
struct Delassus {
  Eigen::Vector3d t1, t2;
  Eigen::Matrix3d W;
  Eigen::Matrix3d J_inv;
};

Delassus delassus(const StickProblem& p, const Eigen::Vector3d& t1) {
  Delassus d;
  d.t1 = t1;
  d.t2 = p.gamma.cross(d.t1);
  d.J_inv = p.inertia.inverse();
  const Eigen::Vector3d forces[3] = {d.t1, d.t2, Eigen::Vector3d::Zero()};
  const double moments[3] = {0.0, 0.0, 1.0};
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d dv = forces[j] / p.mass;
    const Eigen::Vector3d dw = d.J_inv * (p.r.cross(forces[j]) - moments[j] * p.gamma);
    const Eigen::Vector3d du = dv + dw.cross(p.r);
    d.W.col(j) << d.t1.dot(du), d.t2.dot(du), p.gamma.dot(dw);
  }
  return d;
}

// The tangential acceleration of the contact point and the spin acceleration without friction,
// less what the constraint needs ((u.gamma) gamma' keeps the projected slip as it is as the
// contact plane turns; slip_accel the slip's own rate), in the basis (t1, t2, gamma) of d.
Eigen::Vector3d free_slip_rate(const StickProblem& p, const Delassus& d, const Eigen::Vector3d& slip_accel) {
  const Eigen::Vector3d gamma_rate = p.gamma.cross(p.omega);  // eq. (4)
  const Eigen::Vector3d du = p.accel_free + p.angular_accel_free.cross(p.r) + p.omega.cross(p.r_rate) -
                             p.u.dot(p.gamma) * gamma_rate - slip_accel;
  return {d.t1.dot(du), d.t2.dot(du), p.gamma.dot(p.angular_accel_free)};
}

}  // namespace

StickWrench stick_wrench(const StickProblem& p) {
  const Delassus d = delassus(p, p.gamma.unitOrthogonal());
  const Eigen::Vector3d c0 = free_slip_rate(p, d, Eigen::Vector3d::Zero());
  const Eigen::Vector3d x = d.W.partialPivLu().solve(-c0);
  StickWrench w;
  w.force = x[0] * d.t1 + x[1] * d.t2;
  w.M = x[2];
  return w;
}

Eigen::Matrix3d slip_response(const StickProblem& p, const Eigen::Vector3d& t1) {
  // Delassus's columns answer the force t_j on the body and the torque -gamma; resistance rho_j
  // (j = 1, 2) pushes the body along -t_j, rho_3 turns it by -rho_3 gamma.
  Eigen::Matrix3d G = delassus(p, t1).W;
  G.col(2) = -G.col(2);
  return G;
}

Eigen::Vector3d contact_point_rate(const Eigen::Vector3d& gamma, const Eigen::Vector3d& omega, double R1,
                                   const Eigen::Vector3d& d1, double R2) {
  const Eigen::Vector3d gamma_rate = gamma.cross(omega);
  const Eigen::Vector3d d2 = gamma.cross(d1);
  // The Gauss map: the outward normal -gamma turns by -dgamma = S dr, S the shape operator.
  return -(R1 * d1.dot(gamma_rate) * d1 + R2 * d2.dot(gamma_rate) * d2);
}

StickProjection stick_projection(const StickProblem& p) {
  const Delassus d = delassus(p, p.gamma.unitOrthogonal());
  const Eigen::Vector3d c(d.t1.dot(p.u), d.t2.dot(p.u), p.gamma.dot(p.omega));
  const Eigen::Vector3d x = d.W.partialPivLu().solve(-c);
  const Eigen::Vector3d P = x[0] * d.t1 + x[1] * d.t2;
  StickProjection out;
  out.dv = P / p.mass;
  out.domega = d.J_inv * (p.r.cross(P) - x[2] * p.gamma);
  // A linear impulse works against the mean of the velocities before (c) and after (0).
  out.slide_loss = -0.5 * (x[0] * c[0] + x[1] * c[1]);
  out.spin_loss = 0.5 * x[2] * c[2];
  return out;
}

SlipHoldForce slip_hold_force(const StickProblem& p, const Eigen::Vector3d& slip_accel) {
  const Delassus d = delassus(p, p.gamma.unitOrthogonal());
  const Eigen::Vector3d c0 = free_slip_rate(p, d, slip_accel);
  // Rows 1-2 of W x = -c0 with x2 = M given: W_tt x_t = -c0_t - W_tM M.
  const Eigen::PartialPivLU<Eigen::Matrix2d> lu(Eigen::Matrix2d(d.W.topLeftCorner<2, 2>()));
  const Eigen::Vector2d x0 = lu.solve(-c0.head<2>());
  const Eigen::Vector2d x1 = lu.solve(-d.W.topRightCorner<2, 1>());
  SlipHoldForce f;
  f.force0 = x0[0] * d.t1 + x0[1] * d.t2;
  f.force_per_M = x1[0] * d.t1 + x1[1] * d.t2;
  return f;
}

double spin_hold_moment(const StickProblem& p, const Eigen::Vector3d& force, double spin_accel) {
  const Delassus d = delassus(p, p.gamma.unitOrthogonal());
  // Row 3 of W x = spin_accel - c0_3 with x_t = (force.t1, force.t2) given.
  const double c3 = p.gamma.dot(p.angular_accel_free);
  return (spin_accel - c3 - d.W(2, 0) * force.dot(d.t1) - d.W(2, 1) * force.dot(d.t2)) / d.W(2, 2);
}

}  // namespace frictionlab::dynamics
