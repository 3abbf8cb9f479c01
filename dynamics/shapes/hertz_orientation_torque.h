#pragma once
// The torque that makes Hertz's normal contact conservative on any convex shape
// (docs/convex-bodies.md §2.4; docs/contact-models.md §3 for the body of revolution).
//
// The normal force derives from the potential V = (2/5) lambda(gamma) delta^(5/2), whose stiffness
// lambda = E* S(R_major, R_minor) (dynamics/contact/hertz_ellipse.h) depends on the orientation through the
// principal radii at the contact point. Turning the body at fixed approach delta changes V: with
// gamma' = gamma x omega (the upward vertical seen from the body),
//     dV/dt|delta = (2/5) delta^(5/2) grad lambda . (gamma x omega) = -omega . T,
//     T = (2/5) delta^(5/2) gamma x grad lambda          (body frame, about the centre of mass),
//     grad lambda = lambda sum_i (d ln S/d ln R_i) grad R_i / R_i.
// (Only the tangent part of grad lambda counts: gamma x gamma = 0.) For a body of revolution the
// radii depend on gamma3 alone, grad R = R'(gamma3) (e3 - gamma3 gamma), and
// gamma x (e3 - gamma3 gamma) = gamma x e3: T = (2/5) delta^(5/2) lambda'(gamma3) gamma x e3.

#include <Eigen/Core>

#include "dynamics/contact/hertz_ellipse.h"
#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics::shapes {

/// grad ln lambda = sum_i (d ln S/d ln R_i) grad R_i / R_i (1/rad, tangent), with `e` =
/// hertz_ellipse(c.R_major, c.R_minor): its first radius is the major one.
[[nodiscard]] Eigen::Vector3d log_stiffness_gradient(const SurfaceContact& c, const RadiiGradient& g,
                                                     const HertzEllipse& e);

/// T = (2/5) delta^(5/2) lambda gamma x grad ln lambda (N m, shape axes): `gamma` the upward unit
/// vertical, `delta` the approach (m, >= 0), `lambda` the stiffness (N/m^1.5).
[[nodiscard]] Eigen::Vector3d hertz_orientation_torque(const Eigen::Vector3d& gamma, double delta, double lambda,
                                                       const Eigen::Vector3d& grad_ln_lambda);

}  // namespace frictionlab::dynamics::shapes
