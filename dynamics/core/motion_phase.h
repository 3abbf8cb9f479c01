#pragma once
// The phases of a motion on the plane, state by state, for the statistics of the shadow laws
// (dynamics/core/shadow_laws.h; docs/dynamics.md §10). Defined with the run's own thresholds, so that
// the phases mean for every model what its stops mean:
//
//   airborne      out of contact (no patch, N = 0): no friction, no error; only its time counts
//   bouncing      in contact while the contact moves along the normal at |eps'| >= v_settle,
//                 run.settle_normal_speed (the body's lift-off speed scale; a rigid plane never)
//   sliding       otherwise, the slip U >= run.rest_slip_speed
//   rolling-spin  U < run.rest_slip_speed, |Omega| >= run.rest_spin: the slip has stopped, the spin
//                 has not (the egg rolling and turning, the sphere spinning in place)
//   near-rest     U < run.rest_slip_speed and |Omega| < run.rest_spin: the contact neither slips
//                 nor spins (the laws' set-valued point; stick is here)

#include <array>
#include <limits>
#include <string_view>

namespace frictionlab::dynamics {

enum class MotionPhase { airborne = 0, bouncing = 1, sliding = 2, rolling_spin = 3, near_rest = 4 };

inline constexpr int kMotionPhases = 5;

/// "airborne", "bouncing", "sliding", "rolling-spin", "near-rest".
[[nodiscard]] std::string_view to_string(MotionPhase p);
/// Every phase, in the order of their codes.
[[nodiscard]] const std::array<MotionPhase, kMotionPhases>& motion_phases();

/// The thresholds of the rule above, resolved for one run (SI units).
struct MotionPhaseRule {
  double rest_slip_speed = 0.0;  ///< m/s, run.rest_slip_speed
  double rest_spin = 0.0;        ///< 1/s, run.rest_spin
  /// m/s, run.settle_normal_speed; infinite for a model on a rigid plane (no bouncing)
  double settle_normal_speed = std::numeric_limits<double>::infinity();

  /// The phase of a state: in contact or not, its slip U (m/s), spin Omega (1/s) and the speed of
  /// the contact along the normal (m/s, any sign).
  [[nodiscard]] MotionPhase classify(bool in_contact, double U, double Omega, double normal_speed) const;
};

}  // namespace frictionlab::dynamics
