#pragma once
// The tangent plane at the contact point (orthogonal to gamma): a reference basis, and the
// principal radii and directions of a symmetric 2x2 radii matrix written in it
// (docs/convex-bodies.md §2). Shared by the shapes whose radii come as a matrix (the ellipsoid,
// a user's shape).

#include <Eigen/Core>

namespace frictionlab::dynamics::shapes {

/// An orthonormal basis (t1, t2) of the plane orthogonal to gamma, with t2 = gamma x t1.
struct TangentFrame {
  Eigen::Vector3d t1;
  Eigen::Vector3d t2;
};

/// The reference basis at the unit vector `gamma`: t1 = (e3 - gamma3 gamma)/rho, the projection of
/// the shape axis e3 (the meridian direction of a body with axis e3; the same expression as
/// dynamics/shapes/contact_geometry.cpp), rho = sqrt(gamma1^2 + gamma2^2); t1 = e1 at gamma = ±e3 exactly.
[[nodiscard]] TangentFrame tangent_frame(const Eigen::Vector3d& gamma);

/// Principal radii and directions.
struct PrincipalRadii {
  double R_major = 0.0;  ///< m
  double R_minor = 0.0;  ///< m, <= R_major
  Eigen::Vector3d major; ///< unit, tangent
  Eigen::Vector3d minor; ///< unit, tangent, gamma x major
  bool umbilic = false;  ///< R_major - R_minor <= kUmbilicRelTol R_major: then major = t1, minor = t2
};

/// The eigen-decomposition of the symmetric positive definite radii matrix [[m11, m12], [m12, m22]]
/// (m) in the basis `frame`, whose determinant R_major R_minor is `det` (m^2): R_major = m + rad
/// with m = (m11 + m22)/2, rad = sqrt(((m11 - m22)/2)^2 + m12^2) (no cancellation), R_minor = det/R_major
/// (pass a closed form for det where a shape has one: m - rad would lose digits when
/// R_minor << R_major). The major direction is the eigenvector written in the form that does not
/// cancel; at an umbilic it is t1 (a fixed rule, not an accident of rounding).
[[nodiscard]] PrincipalRadii principal_radii(double m11, double m12, double m22, double det, const TangentFrame& frame);

/// The same with det = m11 m22 - m12^2.
[[nodiscard]] PrincipalRadii principal_radii(double m11, double m12, double m22, const TangentFrame& frame);

}  // namespace frictionlab::dynamics::shapes
