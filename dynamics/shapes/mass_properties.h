#pragma once
// Mass properties of the homogeneous solid bounded by a profile (dynamics/shapes/profile.h), by
// Gauss-Legendre quadrature over slices: with P = chi^2 and density rho = m / V,
//   V   = pi   ∫ P dz                         (volume)
//   z_c = pi   ∫ z P dz / V                   (centroid, profile coordinate)
//   C   = rho pi/2 ∫ P^2 dz                   (axial moment: discs, m r^2/2)
//   A_p = rho pi ∫ P (P/4 + (z - p)^2) dz     (transverse moment about the point z = p on the axis)
// The integrands are polynomials and the rule has enough nodes to integrate them exactly.

#include "dynamics/shapes/profile.h"

namespace frictionlab::dynamics {

/// The homogeneous solid of a given mass. SI units.
struct MassProperties {
  double mass = 0.0;       ///< kg
  double volume = 0.0;     ///< m^3
  double centroid = 0.0;   ///< profile coordinate z of the centre of mass, m
  double A = 0.0;          ///< transverse moment of inertia about the centroid, kg m^2
  double C = 0.0;          ///< axial moment of inertia, kg m^2

  /// Transverse moment about the point z = `point` on the axis (parallel axes), kg m^2.
  [[nodiscard]] double transverse_about(double point) const {
    const double d = point - centroid;
    return A + mass * d * d;
  }
};

/// Mass properties of the homogeneous solid of mass `mass` (kg, finite, > 0) bounded by `profile`.
[[nodiscard]] MassProperties homogeneous_mass_properties(const Profile& profile, double mass);

}  // namespace frictionlab::dynamics
