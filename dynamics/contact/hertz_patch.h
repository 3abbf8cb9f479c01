#pragma once
// The contact model `[contact] patch = "hertz"` (docs/contact-models.md): the patch and the
// normal force of a body of revolution on the flat plane from Hertz's theory at the contact
// point, instead of the paper's section hypothesis (dynamics/shapes/contact_geometry.h, eq. (6)).
//
// At the contact point the body's principal radii are R_meridian and R_parallel
// (dynamics/shapes/contact_geometry.h; the plane's curvature is 0), so Hertz's ellipse
// (dynamics/contact/hertz_ellipse.h) has its axes along the meridian and the parallel, the major one along
// the larger radius, and for the approach delta = |eps|
//     a = sqrt(a2_per_depth delta),  b = mu a,  N = lambda(gamma3) delta^(3/2),
//     lambda(gamma3) = E* S(R_meridian, R_parallel):
// the stiffness depends on where the body touches. N derives from the potential
// V = (2/5) lambda(gamma3) delta^(5/2): dV/d(delta) = N, and turning the body at fixed delta
// changes V, which is the work of the torque
//     T = (2/5) delta^(5/2) lambda'(gamma3) gamma x e3          (body frame, about the centre of mass)
// (gamma' = gamma x omega, so dV/dt at fixed delta = -T . omega). With T the normal contact is
// conservative and E' = -(F1 U + M Omega) holds as in docs/model.md §5. T is of relative order
// delta/R beside the torque of N (the order of the terms Hertz's theory neglects). lambda' is
// analytic: lambda (d ln S/d ln R_meridian R_meridian'/R_meridian + the same for R_parallel), with
// the elasticities of dynamics/contact/hertz_ellipse.h and the radii's slopes of ContactGeometry::radii_slope.

#include <Eigen/Core>

#include "dynamics/shapes/contact_geometry.h"

namespace frictionlab::dynamics {

/// The Hertz contact at one state.
struct HertzContact {
  PatchShape patch;       ///< semi-axes (m) and major axis; a = b = 0 out of contact
  double N = 0.0;         ///< normal force, N
  double stiffness = 0.0; ///< lambda(gamma3), N/m^1.5
  double energy = 0.0;    ///< V = (2/5) lambda delta^(5/2), J
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  ///< T above, body frame, N m
};

class HertzNormalContact {
 public:
  /// `E_star`: effective modulus, Pa, finite, > 0 (dynamics/contact/hertz_ellipse.h: effective_modulus).
  explicit HertzNormalContact(double E_star);

  /// The contact at the contact point `c` of the upward vertical `gamma` (unit), contact height
  /// `eps` (m; in contact when eps < 0). No allocation.
  [[nodiscard]] HertzContact evaluate(const ContactGeometry& geometry, const ContactPoint& c,
                                      const Eigen::Vector3d& gamma, double eps) const;
  /// V at (gamma, eps) (J), the same number evaluate() returns.
  [[nodiscard]] double energy(const ContactPoint& c, double eps) const;

  /// lambda at the contact point `c` (N/m^1.5).
  [[nodiscard]] double stiffness(const ContactPoint& c) const;
  /// lambda where the upward vertical has third component gamma3 in [-1, 1] (N/m^1.5).
  [[nodiscard]] double stiffness(const ContactGeometry& geometry, double gamma3) const;
  /// d lambda / d gamma3 (N/m^1.5), analytic (finite at the poles).
  [[nodiscard]] double stiffness_slope(const ContactGeometry& geometry, double gamma3) const;

  [[nodiscard]] double modulus() const { return E_star_; }

 private:
  double E_star_;
};

/// The effective modulus (Pa) for which Hertz's stiffness equals `lambda` (N/m^1.5, > 0) where the
/// upward vertical has third component `gamma3` in [-1, 1] (1: the body rests on its lower pole).
[[nodiscard]] double modulus_matching_stiffness(const ContactGeometry& geometry, double lambda, double gamma3);

}  // namespace frictionlab::dynamics
