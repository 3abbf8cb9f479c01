#pragma once
// Where a convex body of revolution touches the plane, and the shape of its Hertz patch
// (docs/dynamics.md §2 has the derivation; docs/model.md §5).
//
// With P(z) = chi(z)^2 (dynamics/shapes/profile.h), the outward normal of the surface x^2 + y^2 = P(z) is
// (2x, 2y, -P') / s, s = sqrt(4P + P'^2). The contact point has outward normal -gamma, gamma the
// upward unit vertical in the body frame, so its profile coordinate z solves
//     g(z) := P'(z) / s(z) = gamma3,                                        (contact equation)
// g falls monotonically from +1 at the lower pole to -1 at the upper pole (g' = 2G/s^3 < 0 with
// G = 2 P P'' - P'^2 < 0 for a convex body), and is smooth through the poles; then
//     r = (-gamma1 q, -gamma2 q, z - z_com),   q = s/2,
// with no division by sqrt(1 - gamma3^2) anywhere. Principal radii of curvature:
//     R_parallel = q,   R_meridian = s^3 / (2 |G|),   both = P'/2 at a pole.
// Patch by the paper's section hypothesis, to first order in the depth (the Dupin indicatrix):
// semi-axes sqrt(2 |eps| R_meridian) along the meridian and sqrt(2 |eps| R_parallel) along the
// parallel. The meridian direction in the contact plane is the projection of the body axis e3,
// (e3 - gamma3 gamma)/sqrt(1 - gamma3^2); the parallel direction is gamma x meridian.
// (Formula (11) of the paper is garbled: see docs/dynamics.md for the sphere check.)

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <vector>

#include "dynamics/shapes/profile.h"

namespace frictionlab::dynamics {

/// The contact point for one orientation.
struct ContactPoint {
  double z = 0.0;              ///< profile coordinate of the contact point, m
  Eigen::Vector3d r;           ///< contact point from the centre of mass, body frame, m
  double R_meridian = 0.0;     ///< principal radius of curvature along the meridian, m
  double R_parallel = 0.0;     ///< principal radius of curvature along the parallel, m
};

/// How the principal radii change with the orientation: d/dgamma3 of each, m.
struct RadiiSlope {
  double meridian = 0.0;
  double parallel = 0.0;
};

/// The contact ellipse (section hypothesis).
struct PatchShape {
  double a = 0.0;              ///< major semi-axis, m
  double b = 0.0;              ///< minor semi-axis, m (b <= a)
  Eigen::Vector3d major;       ///< unit vector along the major axis, in the contact plane
  bool circle = false;         ///< a == b (pole, sphere, or radii equal to kCircleRelTol)
};

class ContactGeometry {
 public:
  /// Principal radii closer than this (relative) give a circular patch: b = a, major axis = the
  /// meridian direction (or body e1 at a pole). The law then sees psi = 0, which a circle ignores.
  static constexpr double kCircleRelTol = 1e-12;

  /// `com`: profile coordinate of the centre of mass, m.
  ContactGeometry(const Profile& profile, double com);

  /// The contact point for the upward unit vertical `gamma` (body frame; must be unit length).
  /// Exact poles for gamma3 = ±1 (gamma1 = gamma2 = 0). No allocation.
  [[nodiscard]] ContactPoint contact_point(const Eigen::Vector3d& gamma) const;

  /// d/dgamma3 of the principal radii at the contact point `c` (from contact_point), analytic:
  /// with s' = P'(2 + P'')/s and G' = 2 P P''' along z, and dz/dgamma3 = s^3/(2G),
  ///     dR_parallel/dz = s'/2,   dR_meridian/dz = -s^2 (3 s' G - s G')/(2 G^2).
  /// Finite through the poles. No allocation.
  [[nodiscard]] RadiiSlope radii_slope(const ContactPoint& c) const;

  /// The patch at penetration depth `depth` = |eps| (m, >= 0) for the contact point `c` of `gamma`.
  [[nodiscard]] static PatchShape patch(const ContactPoint& c, const Eigen::Vector3d& gamma, double depth);

  [[nodiscard]] const Profile& profile() const { return profile_; }
  [[nodiscard]] double com() const { return com_; }

  /// Solves the contact equation g(z) = gamma3 (exposed for tests).
  [[nodiscard]] double solve_contact_z(double gamma3) const;

 private:
  Profile profile_;
  Polynomial third_derivative_;  ///< P'''
  double com_;
  [[nodiscard]] double solve(double gamma3, double z_start, double step_tolerance) const;

  /// At gamma3 = -1 + 2 i / (n - 1): z and dz/dgamma3, interleaved (Newton's starting points).
  std::vector<double> guess_;
};

}  // namespace frictionlab::dynamics
