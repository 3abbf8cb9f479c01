#pragma once
// The interface every friction law of frictionlab implements.
//
// Conventions (docs/model.md): the contact patch is an
// ellipse with semi-axes a >= b > 0 in the plane of contact, gamma the upward unit normal.
// e1 is the direction of the sliding velocity of the patch centre (speed U >= 0),
// e2 = gamma x e1, Omega = omega . gamma the signed spin, psi the angle from e1 to the major axis,
// counter-clockwise about gamma. The law returns F1, F2, M such that the friction force on the body
// is F = -F1 e1 - F2 e2 and the friction torque about the patch centre is -M gamma.

#include <string>
#include <string_view>

namespace frictionlab::friction {

/// The state of one contact, as a friction law sees it. SI units.
struct ContactInput {
  double U = 0.0;      ///< slip speed of the patch centre, m/s; finite, >= 0
  double Omega = 0.0;  ///< spin about the upward normal, 1/s; finite, either sign
  double a = 1.0;      ///< major semi-axis of the patch, m; finite, > 0
  double b = 1.0;      ///< minor semi-axis of the patch, m; finite, 0 < b <= a
  double psi = 0.0;    ///< angle from e1 to the major axis, rad, CCW about gamma; finite
  double N = 0.0;      ///< normal force, N; finite, >= 0
  double k = 0.0;      ///< Coulomb friction coefficient, dimensionless; finite, >= 0
};

/// What a law returns: F = -F1 e1 - F2 e2 (N) on the body, torque -M gamma (N m).
struct FrictionForces {
  double F1 = 0.0;  ///< N, along -e1
  double F2 = 0.0;  ///< N, along -e2
  double M = 0.0;   ///< N m, about -gamma
};

/// The denominators of a rational law's outputs at one contact, divided by (a Omega)^2 (a positive
/// factor: only their signs matter). A law is singular (has a pole) where one of them changes sign
/// along a motion; NaN marks an output that has no denominator there. Regular laws have none.
struct PoleDenominators {
  double F1, F2, M;
};

/// Throws std::invalid_argument naming the offending value and the rule it breaks.
void validate(const ContactInput& in);

/// A law of coupled dry friction. Implementations are `final`, stateless after construction,
/// and safe to call concurrently from several threads.
class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  /// Registry name, e.g. "exact", "pade-printed".
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// One line: what the law is and where it comes from.
  [[nodiscard]] virtual std::string_view summary() const = 0;

  /// True if the law has denominators that can vanish at valid input (its singular set), which
  /// pole_denominators() then returns. Callers watch their signs (simulation events, accuracy
  /// study) instead of branching on the law's name.
  [[nodiscard]] virtual bool has_poles() const { return false; }
  /// The denominators at `in` (validated input with Omega != 0); all NaN for a law without poles.
  [[nodiscard]] virtual PoleDenominators pole_denominators(const ContactInput& in) const;

  /// Validates `in` (std::invalid_argument on bad input), then evaluates the law.
  [[nodiscard]] FrictionForces evaluate(const ContactInput& in) const {
    validate(in);
    return do_evaluate(in);
  }

 protected:
  FrictionLaw() = default;
  FrictionLaw(const FrictionLaw&) = default;
  FrictionLaw& operator=(const FrictionLaw&) = default;

 private:
  /// Evaluates on validated input.
  [[nodiscard]] virtual FrictionForces do_evaluate(const ContactInput& in) const = 0;
};

}  // namespace frictionlab::friction
