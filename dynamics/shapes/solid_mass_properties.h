#pragma once
// Mass properties of a rigid body with a full inertia tensor (docs/convex-bodies.md §6): mass,
// volume, centre of mass anywhere, and the symmetric inertia tensor about the centre of mass.
//
// Sign convention: the tensor's off-diagonal elements are J_ij = -∫ xi_i xi_j dm (i != j), so that
// the angular momentum is J omega; the *products of inertia* ∫ xi_i xi_j dm are their negatives
// (a rattleback's literature gives either: say which).
//
// A tensor is physical iff it is symmetric and its principal moments I1, I2, I3 are positive and
// obey the triangle inequalities I_i <= I_j + I_k (I_j + I_k - I_i = 2 ∫ x_i^2 dm >= 0 in principal
// axes; then J_ii <= J_jj + J_kk holds in every frame). validate_inertia() checks exactly that.

#include <Eigen/Core>
#include <string_view>

namespace frictionlab::dynamics::shapes {

/// A rigid body's mass properties. SI units; vectors and the tensor in one frame (the shape frame).
struct SolidMassProperties {
  double mass = 0.0;                                          ///< kg
  double volume = 0.0;                                        ///< m^3 (0 if not known)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();         ///< centre of mass, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();          ///< about the centre of mass, kg m^2

  /// The inertia tensor about `point` (same frame, m), by the parallel-axis theorem:
  /// J_p = J_c + m (|d|^2 I - d d^T), d = centroid - point.
  [[nodiscard]] Eigen::Matrix3d inertia_about(const Eigen::Vector3d& point) const;
};

/// The principal moments (ascending) and axes (the columns of `axes`, a proper rotation:
/// J = axes diag(moments) axes^T) of a symmetric tensor.
struct PrincipalInertia {
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();  ///< kg m^2, ascending
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
};

/// The principal moments and axes of the symmetric tensor `J` (kg m^2). Assumes symmetry (only the
/// lower triangle is read).
[[nodiscard]] PrincipalInertia principal_inertia(const Eigen::Matrix3d& J);

/// The tensor Q J Q^T: `J` (kg m^2) expressed in a frame where its axes are turned by the rotation
/// matrix `Q` (a body turned by Q has the inertia Q J Q^T in the unturned frame).
[[nodiscard]] Eigen::Matrix3d rotate_inertia(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Q);

/// The tensor whose principal axes are the shape axes e1, e2, e3 turned by `angle` (rad, counter-
/// clockwise about `axis`, right-hand rule) and whose principal moments about them are
/// `moments` (kg m^2, in the order of e1, e2, e3): Q diag(moments) Q^T, Q = rotation(angle, axis).
/// A rattleback's principal axes turned by delta about the vertical e3: (moments, e3, delta).
/// The result is symmetric exactly (J_ji = J_ij to the bit).
/// `axis` need not be unit (it is normalised); std::invalid_argument if it is zero or not finite.
[[nodiscard]] Eigen::Matrix3d inertia_from_principal(const Eigen::Vector3d& moments, const Eigen::Vector3d& axis,
                                                     double angle);

/// Throws std::invalid_argument naming `key` (e.g. "body.inertia") and the rule unless `J` is
/// finite, symmetric (|J_ij - J_ji| <= 1e-12 max|J|), positive definite, and its principal moments
/// obey the triangle inequalities (to a relative slack of 1e-12, for rounding in given values).
void validate_inertia(const Eigen::Matrix3d& J, std::string_view key = "body.inertia");

/// Throws std::invalid_argument naming `key` unless mass is finite and > 0 kg.
void validate_mass(double mass, std::string_view key = "body.mass");

}  // namespace frictionlab::dynamics::shapes
