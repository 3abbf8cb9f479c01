#include "dynamics/shapes/hertz_orientation_torque.h"

#include <Eigen/Geometry>  // cross products
#include <cmath>

namespace frictionlab::dynamics::shapes {

Eigen::Vector3d log_stiffness_gradient(const SurfaceContact& c, const RadiiGradient& g, const HertzEllipse& e) {
  return (e.dlnS_dlnR1 / c.R_major) * g.major + (e.dlnS_dlnR2 / c.R_minor) * g.minor;
}

Eigen::Vector3d hertz_orientation_torque(const Eigen::Vector3d& gamma, double delta, double lambda,
                                         const Eigen::Vector3d& grad_ln_lambda) {
  return (0.4 * delta * delta * std::sqrt(delta) * lambda) * gamma.cross(grad_ln_lambda);
}

}  // namespace frictionlab::dynamics::shapes
