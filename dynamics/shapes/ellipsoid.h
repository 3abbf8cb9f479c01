#pragma once
// The triaxial ellipsoid xi^T D^-2 xi = 1, D = diag(a1, a2, a3), centred at the shape origin with
// its semi-axes along the shape axes (docs/convex-bodies.md §3). Everything in closed form:
//
// Support function h(u) = sqrt(u^T D^2 u) (u an outward normal). The point with outward normal u is
// grad h(u), so with u = -gamma and w = sqrt(gamma^T D^2 gamma):
//     r = -D^2 gamma / w.
// The radii matrix (the inverse of the shape operator on the tangent plane) is the Hessian of h:
//     W = (D^2 - r r^T) / w,   W gamma = 0,
// whose two non-zero eigenvalues are the principal radii. In a tangent basis (t1, t2 = gamma x t1)
// its entries are sums without cancellation (Binet-Cauchy on D t_i x D gamma):
//     W11 = P^2 (t2^T D^-2 t2)/w^3,  W22 = P^2 (t1^T D^-2 t1)/w^3,  W12 = -P^2 (t1^T D^-2 t2)/w^3,
// P = a1 a2 a3, i.e. (P^2/w^3) times the adjugate of the Hessian of f = xi^T D^-2 xi - 1 restricted
// to the tangent plane (over |grad f| this is the shape operator; W is its inverse), and
//     R_major R_minor = P^2 / w^4          (1/Gaussian curvature).
// Vertex a1 (gamma = ∓e1): radii a2^2/a1 and a3^2/a1. Umbilics (a1 > a2 > a3: four, in the e1-e3
// plane): both radii a2^3/(a1 a3); there the major direction is t1 (tangent_plane.h).
// Radii gradients (Hellmann-Feynman: dR = e^T dW e for the unit eigenvector e, at fixed e), with
// v = D^2 gamma, E = e^T D^2 e, c = e . v:
//     grad (e^T W e) = -E v/w^3 - 2 c D^2 e/w^3 + 3 c^2 v/w^5,  projected on the tangent plane;
// at an umbilic both are the gradient of the mean radius (W's trace over 2).
// Homogeneous solid: V = (4/3) pi a1 a2 a3, J = (m/5) diag(a2^2 + a3^2, a1^2 + a3^2, a1^2 + a2^2).

#include <string_view>

#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics::shapes {

class Ellipsoid final : public Shape {
 public:
  /// `semi_axes` (a1, a2, a3) along e1, e2, e3, m, each finite and > 0; std::invalid_argument
  /// naming `key` (e.g. "body.semi_axes") and the rule otherwise.
  explicit Ellipsoid(const Eigen::Vector3d& semi_axes, std::string_view key = "ellipsoid semi_axes");

  [[nodiscard]] std::string_view kind() const override { return "ellipsoid"; }
  [[nodiscard]] SurfaceContact contact(const Eigen::Vector3d& gamma) const override;
  [[nodiscard]] RadiiGradient radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact& c) const override;
  [[nodiscard]] SolidMassProperties homogeneous(double mass) const override;
  /// max(a1, a2, a3).
  [[nodiscard]] double size() const override;
  /// The farthest point from p solves (xi - p) = mu D^-2 xi with mu >= max a_i^2 (the trust-region
  /// condition of the maximum): a secular equation in mu, solved by safeguarded Newton; the
  /// degenerate ("hard") case mu = max a_i^2 in closed form.
  [[nodiscard]] double radius_about(const Eigen::Vector3d& point) const override;
  [[nodiscard]] bool contains(const Eigen::Vector3d& point) const override;

  [[nodiscard]] const Eigen::Vector3d& semi_axes() const { return a_; }

 private:
  [[nodiscard]] Eigen::Vector3d rayleigh_gradient(const Eigen::Vector3d& gamma, const Eigen::Vector3d& v, double w,
                                                  const Eigen::Vector3d& e) const;
  Eigen::Vector3d a_;        ///< semi-axes, m
  Eigen::Vector3d a2_;       ///< their squares, m^2
  Eigen::Vector3d inv_a2_;   ///< 1/a_i^2, 1/m^2
  double P2_ = 0.0;          ///< (a1 a2 a3)^2, m^6
};

}  // namespace frictionlab::dynamics::shapes
