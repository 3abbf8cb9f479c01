#include "dynamics/rigid_rolling/ellipsoid_body.h"

#include <cmath>
#include <memory>

#include "dynamics/rigid_rolling/ellipsoid_surface.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {

RigidRollingBody rigid_body(const EllipsoidBody& body, double spin_damping) {
  if (!(std::isfinite(body.centre_height) && std::abs(body.centre_height) < body.semi_axes.z()))
    throw support::invalid_value("ellipsoid.centre_height", body.centre_height,
                                 "it must be finite and below the semi-axis a3 in magnitude (G inside the body)");
  RigidRollingBody out;
  out.mass = body.mass;
  out.inertia = body.inertia;
  out.surface = std::make_shared<EllipsoidSurface>(body.semi_axes, Eigen::Vector3d(0.0, 0.0, body.centre_height));
  out.gravity = body.gravity;
  out.spin_damping = spin_damping;
  out.validate();
  return out;
}

SteadySpinBody steady_spin_body(const EllipsoidBody& body) {
  const RigidRollingBody checked = rigid_body(body);  // the same checks, once
  const Eigen::Vector3d& a = body.semi_axes;
  SteadySpinBody out;
  out.mass = checked.mass;
  out.inertia = checked.inertia;
  out.height = a.z() - body.centre_height;
  out.radius_1 = a.x() * a.x() / a.z();
  out.radius_2 = a.y() * a.y() / a.z();
  out.gravity = checked.gravity;
  out.validate();
  return out;
}

}  // namespace frictionlab::dynamics::rigid_rolling
