#include "friction/patch_angle.h"

#include <cmath>
#include <numbers>

namespace frictionlab::friction {

double PatchAngle::direction_radians() const {
  double psi = std::atan2(sin_, cos_);
  if (psi < 0.0) psi += std::numbers::pi;  // the major axis is a line: psi in [0, pi)
  if (psi >= std::numbers::pi) psi -= std::numbers::pi;
  return psi;
}

}  // namespace frictionlab::friction
