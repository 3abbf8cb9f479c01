#pragma once
// The characteristic scales of a model: the yardsticks that make a run's default thresholds
// (dynamics/core/rest_event.h, dynamics/core/settling.h, dynamics/core/chatter_watch.h) and the
// integrator's absolute tolerances mean the same for a 15 g top and a 2 kg egg (docs/dynamics.md
// §4, §5). Each model computes them from its own size: the body on the plane
// (dynamics/body/body_scales.h), the puck (dynamics/puck/puck_run.h).
//
//   R        the body's size (the radius of the smallest sphere about the centre of mass that
//            holds the body; for the puck, the patch's major semi-axis);
//   sqrt(g R)      speed of a fall over the body's size;   sqrt(g/R)  rate of a rocking over it;
//   m g R          energy of lifting the body by its size;
//   |eps_s| = (m g / lambda)^(2/3)   the static Hertz compression;
//   omega_n = sqrt(1.5 g / |eps_s|)  the frequency of the vertical Hertz vibration linearised
//            about it (N' = 1.5 lambda |eps_s|^(1/2) = 1.5 m g / |eps_s|, normal mass m);
//   v_lift = omega_n |eps_s| = sqrt(1.5 g |eps_s|)  the peak normal speed of that vibration when
//            its amplitude reaches |eps_s|, i.e. when the contact starts to open.
//
// With g = 0 (free-flight tests) every scale would vanish; they are then computed with standard
// gravity kReferenceGravity so that they stay finite and non-zero (they are yardsticks, not forces).

namespace frictionlab::dynamics {

/// Standard gravity (m/s^2), used for the scales only when the plane's g is 0.
inline constexpr double kReferenceGravity = 9.80665;

struct BodyScales {
  double size = 0.0;            ///< R, m
  double mass = 0.0;            ///< m, kg
  double gravity = 0.0;         ///< g used for the scales (the plane's, or kReferenceGravity if 0), m/s^2
  double speed = 0.0;           ///< sqrt(g R), m/s
  double rate = 0.0;            ///< sqrt(g / R), 1/s
  double energy = 0.0;          ///< m g R, J
  double compression = 0.0;     ///< |eps_s| = (m g / lambda)^(2/3), m
  double hertz_frequency = 0.0; ///< omega_n = sqrt(1.5 g / |eps_s|), rad/s
  double liftoff_speed = 0.0;   ///< v_lift = sqrt(1.5 g |eps_s|), m/s
};

}  // namespace frictionlab::dynamics
