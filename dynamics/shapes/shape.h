#pragma once
// A convex body's geometry as the model on the plane needs it: for the upward vertical `gamma`
// (a unit vector in the shape frame), the contact point, the two principal radii of curvature
// there, the direction of the larger one, and how the radii change as the body turns; plus the
// homogeneous solid's mass properties. docs/convex-bodies.md derives each piece and shows how to
// add a shape.
//
// Conventions (docs/convex-bodies.md §1):
//  * The shape frame is the frame the shape is described in (its axes and its origin: the centre
//    of an ellipsoid, profile coordinate z = 0 of a body of revolution, the mid-plane centre of a
//    disk). The body frame of the equations of motion has its origin at the centre of mass; a
//    caller subtracts the centre of mass (shape frame) from the contact point.
//  * gamma is the upward unit vertical; the contact point r is the surface point whose outward
//    normal is -gamma (the lowest point of the body when gamma points up).
//  * The principal radii R_major >= R_minor > 0 are the eigenvalues of the inverse of the shape
//    operator on the tangent plane (the Hessian of the support function). The Dupin indicatrix
//    (section hypothesis) has semi-axes sqrt(2 |eps| R_i) along the principal directions, and
//    Hertz's ellipse has its major axis along `major` (docs/contact-models.md §1).
//  * At an umbilic (R_major - R_minor <= kUmbilicRelTol R_major) every tangent direction is
//    principal; each shape states which it returns (a fixed rule, never a rounding accident), and
//    the split of the gradient between the two radii is a convention there: only the sum
//    grad R_major + grad R_minor is defined, which is all Hertz's torque needs (its two
//    elasticities are equal at equal radii, dynamics/contact/hertz_ellipse.h).
//
// Shapes are immutable after construction, safe to share between threads, and make no heap
// allocation in contact() and radii_gradient() (tested).

#include <Eigen/Core>
#include <string_view>

#include "dynamics/shapes/solid_mass_properties.h"

namespace frictionlab::dynamics::shapes {

/// Principal radii closer than this (relative to R_major) are equal: the point is an umbilic.
/// The same tolerance as the circular patch of dynamics/shapes/contact_geometry.h (kCircleRelTol).
inline constexpr double kUmbilicRelTol = 1e-12;

/// Where the body touches the plane for one orientation.
struct SurfaceContact {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  ///< contact point, shape frame, m (outward normal -gamma)
  double R_major = 0.0;                         ///< larger principal radius of curvature at r, m
  double R_minor = 0.0;                         ///< smaller one, m (0 < R_minor <= R_major)
  /// Unit principal direction of R_major, tangent (orthogonal to gamma), shape frame. A line: its
  /// sign carries no meaning (psi is pi-periodic), but each shape fixes it deterministically.
  Eigen::Vector3d major = Eigen::Vector3d::UnitX();
};

/// The gradients of R_major and R_minor with respect to gamma on the unit sphere (tangent vectors,
/// orthogonal to gamma), m per radian: R(gamma + d gamma) = R + grad . d gamma + O(|d gamma|^2) for
/// d gamma tangent.
struct RadiiGradient {
  Eigen::Vector3d major = Eigen::Vector3d::Zero();
  Eigen::Vector3d minor = Eigen::Vector3d::Zero();
};

class Shape {
 public:
  virtual ~Shape() = default;
  Shape() = default;
  Shape(const Shape&) = delete;
  Shape& operator=(const Shape&) = delete;

  /// The registry's name of the shape family ("ellipsoid", ...).
  [[nodiscard]] virtual std::string_view kind() const = 0;

  /// The contact point and principal radii for the upward unit vertical `gamma` (shape frame; unit
  /// length, which the caller keeps). No heap allocation.
  [[nodiscard]] virtual SurfaceContact contact(const Eigen::Vector3d& gamma) const = 0;

  /// The gradients of the radii at `gamma`, whose contact() is `c`. No heap allocation.
  [[nodiscard]] virtual RadiiGradient radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact& c) const = 0;

  /// The homogeneous solid of mass `mass` (kg, finite, > 0; std::invalid_argument otherwise):
  /// volume, centroid (shape frame) and inertia tensor about the centroid in shape axes.
  [[nodiscard]] virtual SolidMassProperties homogeneous(double mass) const = 0;

  /// A length scale: the largest distance of the surface from the shape origin, m.
  [[nodiscard]] virtual double size() const = 0;

  /// The largest distance of the surface from `point` (shape frame, m): the radius of the smallest
  /// ball about the point that holds the body (the body's size about its centre of mass).
  [[nodiscard]] virtual double radius_about(const Eigen::Vector3d& point) const = 0;

  /// Whether `point` (shape frame, m) lies strictly inside the body.
  [[nodiscard]] virtual bool contains(const Eigen::Vector3d& point) const = 0;
};

}  // namespace frictionlab::dynamics::shapes
