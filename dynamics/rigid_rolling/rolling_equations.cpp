#include "dynamics/rigid_rolling/rolling_equations.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <utility>

namespace frictionlab::dynamics::rigid_rolling {

RigidRollingModel::RigidRollingModel(RigidRollingBody body) : body_(std::move(body)) { body_.validate(); }

RollingState RigidRollingModel::derivative(const RollingState& x) const {
  const double m = body_.mass;
  const Eigen::Vector3d& w = x.omega;
  const Eigen::Vector3d& g = x.gamma;
  const Eigen::Vector3d g_rate = g.cross(w);
  const Eigen::Vector3d r = body_.surface->contact_point(g);
  const Eigen::Vector3d r_rate = body_.surface->contact_point_rate(g, g_rate);
  // The inertia about the contact point (J plus the parallel-axis term): symmetric positive definite.
  const Eigen::Matrix3d inertia_at_contact = body_.inertia + m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  const Eigen::Vector3d torque = -w.cross(body_.inertia * w) - m * r.cross(w.cross(r_rate)) -
                                 m * r.cross(w.cross(w.cross(r))) + m * body_.gravity * r.cross(g) -
                                 body_.spin_damping * w.dot(g) * g;
  return {inertia_at_contact.llt().solve(torque), g_rate};
}

double RigidRollingModel::energy(const RollingState& x) const {
  const Eigen::Vector3d r = contact_point(x);
  const Eigen::Vector3d v = x.omega.cross(r);
  return 0.5 * x.omega.dot(body_.inertia * x.omega) + 0.5 * body_.mass * v.squaredNorm() -
         body_.mass * body_.gravity * r.dot(x.gamma) / x.gamma.norm();  // -r.gamma/|gamma|: the height of G
}

double RigidRollingModel::dissipation(const RollingState& x) const {
  const double n = x.omega.dot(x.gamma);
  return body_.spin_damping * n * n;
}

Eigen::Vector3d RigidRollingModel::centre_velocity(const RollingState& x) const { return -x.omega.cross(contact_point(x)); }

Eigen::Vector3d RigidRollingModel::contact_force(const RollingState& x) const {
  const RollingState d = derivative(x);
  const Eigen::Vector3d r = contact_point(x);
  const Eigen::Vector3d r_rate = body_.surface->contact_point_rate(x.gamma, d.gamma);
  const Eigen::Vector3d v = -x.omega.cross(r);
  const Eigen::Vector3d v_rate = -d.omega.cross(r) - x.omega.cross(r_rate);  // body-frame rate of v's components
  return body_.mass * (v_rate + x.omega.cross(v) + body_.gravity * x.gamma);
}

}  // namespace frictionlab::dynamics::rigid_rolling
