#include "dynamics/body/tolerance_scales.h"

namespace frictionlab::dynamics {

StateVector absolute_tolerance_scales(const BodyScales& s) {
  StateVector scale;
  velocity(scale).setConstant(s.speed);
  angular_velocity(scale).setConstant(s.rate);
  vertical(scale).setConstant(1.0);
  height(scale) = s.compression;
  slide_work(scale) = s.energy;
  spin_work(scale) = s.energy;
  return scale;
}

}  // namespace frictionlab::dynamics
