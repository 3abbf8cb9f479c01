#include "dynamics/body/body_scales.h"

#include <algorithm>
#include <cmath>

namespace frictionlab::dynamics {

double body_size(const Profile& profile, double com) {
  // Q(z) = |r|^2 on the meridian = P(z) + (z - com)^2.
  const Polynomial Q = profile.chi2() + Polynomial({com * com, -2.0 * com, 1.0});
  const auto r2 = [&](double z) { return std::max(0.0, Q(z)); };
  double best = std::max(r2(profile.z_lo()), r2(profile.z_hi()));
  const Polynomial dQ = Q.derivative();
  if (dQ.degree() >= 1) {
    for (const double z : real_roots(dQ))
      if (z > profile.z_lo() && z < profile.z_hi()) best = std::max(best, r2(z));
  }
  return std::sqrt(best);
}

BodyScales body_scales(const Body& body, const PlaneContact& plane) {
  BodyScales s;
  s.size = body.axisymmetric ? body_size(body.axisymmetric->profile, body.axisymmetric->com)
                             : body.shape->radius_about(body.centre_of_mass);
  s.mass = body.mass;
  s.gravity = plane.g > 0.0 ? plane.g : kReferenceGravity;
  s.speed = std::sqrt(s.gravity * s.size);
  s.rate = std::sqrt(s.gravity / s.size);
  s.energy = s.mass * s.gravity * s.size;
  s.compression = -plane.static_height(s.mass * s.gravity);
  s.hertz_frequency = std::sqrt(1.5 * s.gravity / s.compression);
  s.liftoff_speed = std::sqrt(1.5 * s.gravity * s.compression);
  return s;
}

}  // namespace frictionlab::dynamics
