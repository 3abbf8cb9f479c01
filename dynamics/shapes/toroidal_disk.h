#pragma once
// A disk with a toroidal rim (Euler's disk, the rolling disk; docs/convex-bodies.md §5): the set of
// points within `rim_radius` rho of the flat disk of radius R in the mid-plane xi3 = 0 centred at the
// shape origin — two flat faces xi3 = ±rho (distance from the axis <= R) joined by the outer half
// of the torus whose tube of radius rho runs round the circle of radius R. Symmetry axis e3.
//
// Support function h(u) = R |u_h| + rho |u| (u_h = (u1, u2, 0)): with sigma = |gamma_h| > 0 the
// point with outward normal -gamma is unique and lies on the torus,
//     r = -R gamma_h/sigma - rho gamma,
// the tube point at azimuth -gamma_h/sigma whose tube angle phi has cos phi = sigma (outer half).
// Principal radii (meridian and parallel are lines of curvature of a surface of revolution):
//     across the tube (meridian):  rho;
//     along the parallel:           (R + rho sigma)/sigma = R/sigma + rho   (Meusnier: the parallel
//                                   circle of radius R + rho cos phi, seen at cos phi = sigma);
// the parallel's is the larger (R > 0), so `major` is the horizontal tangent (gamma2, -gamma1, 0)/sigma
// (= gamma x meridian, as for a body of revolution). Vertical disk (sigma = 1): rho and R + rho.
// Gradients: grad R_minor = 0; R_major depends on gamma3 alone (sigma^2 = 1 - gamma3^2):
//     grad R_major = (R gamma3/sigma^3) (e3 - gamma3 gamma).
//
// Domain: at sigma = 0 (the axis vertical) a whole face has the normal -gamma: no point contact.
// contact() throws FlatFaceContact when sigma < kMinTilt. Long before, a face touches the plane
// beside the rim: at penetration depth delta the face's rim is in the section once
// delta >= face_clearance(gamma) = rho (1 - |gamma3|) (the height of the lowest face-edge point over
// the contact point), where the point-contact model stops describing the contact.
//
// Homogeneous solid (Pappus-Guldin and direct integration over the half disk of the tube):
//     V = 2 pi R^2 rho + pi^2 R rho^2 + (4/3) pi rho^3,
//     ∫ s^2 dV = pi R^4 rho + 2 pi (pi R^3 rho^2/2 + 2 R^2 rho^3 + 3 pi R rho^4/8 + 4 rho^5/15),
//     ∫ z^2 dV = (2/3) pi R^2 rho^3 + 2 pi (pi R rho^4/8 + 2 rho^5/15),
// C = (m/V) ∫ s^2 dV (s the distance from the axis), A = (m/V) (∫ s^2 dV/2 + ∫ z^2 dV), centroid 0.

#include <stdexcept>
#include <string_view>

#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics::shapes {

/// The toroidal disk's contact for an orientation where it lies on a flat face (sigma < kMinTilt).
class FlatFaceContact : public std::domain_error {
 public:
  FlatFaceContact(double sigma, double limit);
  /// |gamma_h| = sin(tilt of the axis from the vertical) at the failing call.
  [[nodiscard]] double sigma() const noexcept { return sigma_; }

 private:
  double sigma_;
};

class ToroidalDisk final : public Shape {
 public:
  /// contact() needs |gamma_h| = sin(tilt of the axis from the vertical) >= kMinTilt: at 1e-6 the
  /// parallel radius is already 1e6 R, and the face touches far earlier (face_clearance()).
  static constexpr double kMinTilt = 1e-6;

  /// `radius` R (m, to the centre circle of the rim's tube) and `rim_radius` rho (m), each finite
  /// and > 0; std::invalid_argument naming `radius_key` or `rim_key` and the rule otherwise.
  ToroidalDisk(double radius, double rim_radius, std::string_view radius_key = "toroidal disk radius",
               std::string_view rim_key = "toroidal disk rim_radius");

  [[nodiscard]] std::string_view kind() const override { return "toroidal-disk"; }
  /// Throws FlatFaceContact when |gamma_h| < kMinTilt (message: the tilt and the rule).
  [[nodiscard]] SurfaceContact contact(const Eigen::Vector3d& gamma) const override;
  [[nodiscard]] RadiiGradient radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact& c) const override;
  [[nodiscard]] SolidMassProperties homogeneous(double mass) const override;
  /// R + rho (the rim's equator).
  [[nodiscard]] double size() const override;
  /// The farthest point of a disk plus a ball: sqrt((R + |p_h|)^2 + p3^2) + rho.
  [[nodiscard]] double radius_about(const Eigen::Vector3d& point) const override;
  [[nodiscard]] bool contains(const Eigen::Vector3d& point) const override;

  /// How far the lowest point of the lower face's edge lies above the contact point, measured
  /// along gamma (m): rho (1 - |gamma3|) = rho sigma^2/(1 + |gamma3|). A penetration depth at or
  /// beyond it puts the face on the plane too. Any gamma (0 at sigma = 0).
  [[nodiscard]] double face_clearance(const Eigen::Vector3d& gamma) const;

  [[nodiscard]] double radius() const { return R_; }
  [[nodiscard]] double rim_radius() const { return rho_; }

 private:
  double R_;
  double rho_;
};

}  // namespace frictionlab::dynamics::shapes
