#pragma once
// The sliding-spinning puck (docs/puck.md): a flat rigid body on a rigid horizontal plane, touching
// it over a fixed elliptic patch centred under its centre of mass, with semi-axes a >= b along the
// body's own axes (the major axis along body x). Three degrees of freedom: the velocity of the
// centre in the plane and the spin about the vertical. The normal force is the weight, N = m g, and
// its distribution over the patch is the friction law's pressure model (friction/law.h): the puck
// has no tilting moment, the classical assumption of Contensou-Erismann analyses (a real puck's
// friction, acting at its face, tilts it and shifts the pressure forward; ignored here).

#include <cmath>

namespace frictionlab::dynamics::puck {

struct Puck {
  double mass = 0.0;     ///< kg, > 0
  double inertia = 0.0;  ///< moment of inertia about the vertical through the centre, kg m^2, > 0
  double a = 0.0;        ///< major semi-axis of the patch, along body x, m
  double b = 0.0;        ///< minor semi-axis, along body y, m; 0 < b <= a

  /// Throws std::invalid_argument naming the scenario key (puck.mass, ...) and the rule.
  void validate() const;

  /// I/(m a^2): the inertia ratio that decides the terminal motion (dynamics/puck/terminal_ratio.h).
  [[nodiscard]] double inertia_ratio() const { return inertia / (mass * a * a); }
};

/// The inertia of a uniform elliptic plate (or cylinder) of semi-axes a, b about its axis:
/// m (a^2 + b^2)/4 (a uniform disk: m a^2/2). The default of puck.inertia.
[[nodiscard]] inline double uniform_plate_inertia(double mass, double a, double b) {
  return mass * (a * a + b * b) / 4.0;
}

}  // namespace frictionlab::dynamics::puck
