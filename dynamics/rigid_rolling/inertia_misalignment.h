#pragma once
// The misalignment of a rattleback: the angle, about the body z-axis (up at rest), between the
// body x-axis (the surface's long axis) and the horizontal principal axis of inertia of the smaller
// moment. Stated as an angle it needs no convention for products of inertia; as a tensor,
//
//   J = R(delta) diag(A0, B0) R(delta)^T in the x-y block,  J12 = (A0 - B0) sin(delta) cos(delta),
//
// so J12 (the tensor element; the product of inertia integral of x y dm is -J12) has the sign of
// -delta when A0 < B0.

#include <Eigen/Core>

namespace frictionlab::dynamics::rigid_rolling {

/// J with principal moments A0 (about the axis at angle delta from body x, counter-clockwise about
/// body z), B0 (about the axis at delta + pi/2) and C (about body z), kg m^2.
[[nodiscard]] Eigen::Matrix3d inertia_rotated_about_vertical(double a0, double b0, double c, double delta);

/// The angle delta (rad, in (-pi/2, pi/2]) from body x to the in-plane principal axis of the
/// smaller moment, counter-clockwise about body z: 2 delta = atan2(-2 J12, J22 - J11). Only the x-y
/// block of J is read.
[[nodiscard]] double misalignment_angle(const Eigen::Matrix3d& inertia);

}  // namespace frictionlab::dynamics::rigid_rolling
