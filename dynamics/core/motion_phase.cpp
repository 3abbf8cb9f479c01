#include "dynamics/core/motion_phase.h"

#include <cmath>

namespace frictionlab::dynamics {

std::string_view to_string(MotionPhase p) {
  switch (p) {
    case MotionPhase::airborne:
      return "airborne";
    case MotionPhase::bouncing:
      return "bouncing";
    case MotionPhase::sliding:
      return "sliding";
    case MotionPhase::rolling_spin:
      return "rolling-spin";
    case MotionPhase::near_rest:
      return "near-rest";
  }
  return "?";
}

const std::array<MotionPhase, kMotionPhases>& motion_phases() {
  static const std::array<MotionPhase, kMotionPhases> all{MotionPhase::airborne, MotionPhase::bouncing,
                                                          MotionPhase::sliding, MotionPhase::rolling_spin,
                                                          MotionPhase::near_rest};
  return all;
}

MotionPhase MotionPhaseRule::classify(bool in_contact, double U, double Omega, double normal_speed) const {
  if (!in_contact) return MotionPhase::airborne;
  if (std::abs(normal_speed) >= settle_normal_speed) return MotionPhase::bouncing;
  if (U >= rest_slip_speed) return MotionPhase::sliding;
  if (std::abs(Omega) >= rest_spin) return MotionPhase::rolling_spin;
  return MotionPhase::near_rest;
}

}  // namespace frictionlab::dynamics
