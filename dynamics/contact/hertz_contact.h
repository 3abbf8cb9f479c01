#pragma once
// The compliant plane: Hertz normal force, eq. (6), its potential, and the friction coefficient;
// and which contact model gives the patch and the normal force ([contact] patch).

#include <cmath>

namespace frictionlab::dynamics {

/// [contact] patch: the paper's section hypothesis (eq. (6) with one lambda; patch from
/// dynamics/shapes/contact_geometry.h), or Hertz's theory at the contact point (dynamics/contact/hertz_patch.h).
enum class PatchModel { section, hertz };

/// Parameters of the plane and of gravity. SI units.
struct PlaneContact {
  double k = 0.0;        ///< Coulomb friction coefficient, dimensionless, finite, >= 0
  double lambda = 0.0;   ///< Hertz stiffness, N/m^(3/2), finite, > 0
  double g = 9.81;       ///< gravitational acceleration, m/s^2, finite, >= 0
  PatchModel patch = PatchModel::section;
  /// Effective modulus E*, Pa (patch = hertz only, finite, > 0). `lambda` is then Hertz's
  /// stiffness at the reference orientation (docs/contact-models.md), used for the body's scales.
  double E_star = 0.0;

  /// Throws std::invalid_argument naming the scenario key (contact.k, ...) and the rule.
  void validate() const;

  /// Eq. (6): N = lambda |eps|^(3/2) for eps < 0, else 0 (N).
  [[nodiscard]] double normal_force(double eps) const {
    return eps < 0.0 ? lambda * (-eps) * std::sqrt(-eps) : 0.0;
  }
  /// The Hertz spring energy (2/5) lambda |eps|^(5/2) for eps < 0, else 0 (J): dV/d|eps| = N.
  [[nodiscard]] double spring_energy(double eps) const {
    return eps < 0.0 ? 0.4 * lambda * eps * eps * std::sqrt(-eps) : 0.0;
  }
  /// The static compression under a weight W (N): eps with N(eps) = W, i.e. -(W/lambda)^(2/3) (m).
  [[nodiscard]] double static_height(double weight) const { return -std::cbrt((weight / lambda) * (weight / lambda)); }
};

}  // namespace frictionlab::dynamics
