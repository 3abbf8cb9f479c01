#include "dynamics/body/tolerance_scales.h"

#include <limits>

namespace frictionlab::dynamics {

StateVector absolute_tolerance_scales(const BodyScales& s) {
  StateVector scale;
  velocity(scale).setConstant(s.speed);
  angular_velocity(scale).setConstant(s.rate);
  vertical(scale).setConstant(1.0);
  height(scale) = s.compression;
  slide_work(scale) = s.energy;
  spin_work(scale) = s.energy;
  // The pose is not fed back: out of the error control, so that it changes no step (an infinite
  // scale makes GSL's error ratio 0 for those components).
  position(scale).setConstant(std::numeric_limits<double>::infinity());
  orientation(scale).setConstant(std::numeric_limits<double>::infinity());
  return scale;
}

}  // namespace frictionlab::dynamics
