#pragma once
// A convex body of revolution xi1^2 + xi2^2 = P(z), P = chi^2 a polynomial (dynamics/shapes/profile.h), as
// a Shape: the shape frame has its axis e3 along the symmetry axis and its origin at profile
// coordinate z = 0 (docs/convex-bodies.md §4).
//
// A thin wrapper of dynamics/shapes/contact_geometry.h (ContactGeometry built with com = 0), so the same
// floating-point operations give the same bits:
//   * r = (-gamma1 q, -gamma2 q, z - 0), and r - (0, 0, com) is ContactGeometry(profile,
//     com).contact_point(gamma).r bit for bit (x - 0 and y - 0 are exact; z - com is the one
//     subtraction ContactGeometry makes; tested);
//   * R_major = max(R_meridian, R_parallel), R_minor the other, and `major` is the major axis of
//     ContactGeometry::patch() (the meridian, or gamma x meridian, whichever radius is larger; the
//     meridian within kCircleRelTol and body e1 at a pole) — the very same call;
//   * the radii depend on gamma through gamma3 alone, so their gradients on the sphere are
//     dR/dgamma3 (ContactGeometry::radii_slope) times grad gamma3 = e3 - gamma3 gamma.
// The homogeneous solid: dynamics/shapes/mass_properties.h (centroid on the axis, J = diag(A, A, C)).

#include <string_view>

#include "dynamics/shapes/contact_geometry.h"
#include "dynamics/shapes/profile.h"
#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics::shapes {

class BodyOfRevolution final : public Shape {
 public:
  explicit BodyOfRevolution(const Profile& profile);

  [[nodiscard]] std::string_view kind() const override { return "revolution"; }
  [[nodiscard]] SurfaceContact contact(const Eigen::Vector3d& gamma) const override;
  /// The radius whose direction is `c.major` gets its own slope: the meridian's when c.major is
  /// the meridian direction (vertical component rho), the parallel's when it is gamma x meridian
  /// (no vertical component). At a pole both gradients are zero.
  [[nodiscard]] RadiiGradient radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact& c) const override;
  [[nodiscard]] SolidMassProperties homogeneous(double mass) const override;
  /// The largest distance of the surface from the origin (z = 0 on the axis): body_size(profile, 0).
  [[nodiscard]] double size() const override;
  /// On the axis: dynamics/body/body_scales.h's body_size(profile, point.z) (the same bits). Off the
  /// axis, at distance s from it: the farthest point lies on the parallel through a z where
  /// d/dz [(chi + s)^2 + (z - p3)^2] = 0, i.e. among the real roots of the polynomial
  /// 4 P (P'/2 + z - p3)^2 - s^2 P'^2 (and the poles).
  [[nodiscard]] double radius_about(const Eigen::Vector3d& point) const override;
  [[nodiscard]] bool contains(const Eigen::Vector3d& point) const override;

  [[nodiscard]] const Profile& profile() const { return geometry_.profile(); }
  /// The contact geometry this shape wraps (com = 0), for callers that keep today's formulas.
  [[nodiscard]] const ContactGeometry& geometry() const { return geometry_; }

 private:
  ContactGeometry geometry_;
};

}  // namespace frictionlab::dynamics::shapes
