#pragma once
// The characteristic scales (dynamics/core/scales.h) of a body on the Hertz plane: the yardsticks that make the run's
// default thresholds (dynamics/core/rest_event.h, dynamics/core/settling.h) and the integrator's absolute
// tolerances (dynamics/body/tolerance_scales.h) mean the same for a 15 g top and a 2 kg egg
// (docs/dynamics.md §4, §5).
//
//   R        the body's size: the largest distance from the centre of mass to the surface,
//            max over the profile of sqrt(chi(z)^2 + (z - com)^2) (the radius of the smallest
//            sphere about the centre of mass that holds the body; a sphere about its centre: R;
//            for a shape other than today's bodies of revolution, Shape::radius_about(centre of mass));
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

#include "dynamics/body/body.h"
#include "dynamics/core/scales.h"
#include "dynamics/contact/hertz_contact.h"

namespace frictionlab::dynamics {

/// R of the header comment: max over [z_lo, z_hi] of sqrt(P(z) + (z - com)^2), at the poles or at
/// a real root of P' + 2 (z - com) inside (m).
[[nodiscard]] double body_size(const Profile& profile, double com);

[[nodiscard]] BodyScales body_scales(const Body& body, const PlaneContact& plane);

}  // namespace frictionlab::dynamics
