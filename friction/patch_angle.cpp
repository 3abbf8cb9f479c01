#include "friction/patch_angle.h"

#include <cmath>
#include <numbers>

namespace frictionlab::friction {

// Out of line on purpose: std::cos and std::sin run here, at run time, for every angle, as they
// ran inside each law before; a compiler folding them for a constant angle elsewhere could round
// differently.
PatchAngle::PatchAngle(double radians) : radians_(radians), cos_(std::cos(radians)), sin_(std::sin(radians)) {}

double PatchAngle::direction_radians() const {
  double psi = std::atan2(sin_, cos_);
  if (psi < 0.0) psi += std::numbers::pi;  // the major axis is a line: psi in [0, pi)
  if (psi >= std::numbers::pi) psi -= std::numbers::pi;
  return psi;
}

}  // namespace frictionlab::friction
