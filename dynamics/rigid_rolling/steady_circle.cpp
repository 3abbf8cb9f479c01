#include "dynamics/rigid_rolling/steady_circle.h"

#include <cmath>
#include <memory>
#include <numbers>

#include "dynamics/rigid_rolling/rounded_disk_surface.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace {

// The coefficients of Omega^2 (a rc - b) = c, for tilt beta.
struct CircleTerms {
  double rolling_radius;  // Re
  double a, b, c;
};

CircleTerms circle_terms(const RevolutionBody& body, double tilt) {
  body.validate();
  if (!(std::isfinite(tilt) && tilt > 0.0 && tilt < std::numbers::pi / 2.0))
    throw support::invalid_value("tilt", tilt, "it must be in (0, pi/2) rad (0: upright; a disk lying flat has no steady circle)");
  const double rc_rim = body.radius - body.rim_radius;
  const double sb = std::sin(tilt), cb = std::cos(tilt);
  const double re = rc_rim + body.rim_radius * cb;
  const double ml = body.mass * (rc_rim * cb + body.rim_radius);
  const double a_inertia = body.transverse_inertia, c_inertia = body.axial_inertia;
  return {re, c_inertia * cb / re + ml, (c_inertia - a_inertia) * sb * cb + ml * rc_rim * sb,
          body.mass * body.gravity * rc_rim * sb};
}

SteadyCircle complete(const RevolutionBody& body, double tilt, double rc, double omega, double re) {
  SteadyCircle out;
  out.tilt = tilt;
  out.precession_rate = omega;
  out.spin_rate = -rc * omega / re;
  out.contact_circle_radius = rc;
  out.centre_circle_radius = rc - (body.radius - body.rim_radius) * std::sin(tilt);
  out.rolling_speed = std::abs(rc * omega);
  out.centre_speed = std::abs(out.centre_circle_radius * omega);
  return out;
}

}  // namespace

void RevolutionBody::validate() const {
  if (!(std::isfinite(mass) && mass > 0.0)) throw support::invalid_value("disk.mass", mass, "it must be finite and > 0 kg");
  if (!(std::isfinite(transverse_inertia) && transverse_inertia > 0.0))
    throw support::invalid_value("disk.transverse_inertia", transverse_inertia, "it must be finite and > 0 kg m^2");
  if (!(std::isfinite(axial_inertia) && axial_inertia > 0.0 && axial_inertia <= 2.0 * transverse_inertia))
    throw support::invalid_value("disk.axial_inertia", axial_inertia,
                                 "it must be finite, > 0 and <= 2 disk.transverse_inertia (kg m^2, as for any real body)");
  if (!(std::isfinite(radius) && radius > 0.0)) throw support::invalid_value("disk.radius", radius, "it must be finite and > 0 m");
  if (!(std::isfinite(rim_radius) && rim_radius >= 0.0 && rim_radius < radius))
    throw support::invalid_value("disk.rim_radius", rim_radius, "it must be finite, >= 0 m and < disk.radius");
  if (!(std::isfinite(gravity) && gravity > 0.0))
    throw support::invalid_value("disk.gravity", gravity, "it must be finite and > 0 m/s^2");
}

RigidRollingBody rigid_body(const RevolutionBody& body) {
  body.validate();
  RigidRollingBody out;
  out.mass = body.mass;
  out.inertia = Eigen::Vector3d(body.transverse_inertia, body.transverse_inertia, body.axial_inertia).asDiagonal();
  out.surface = std::make_shared<RoundedDiskSurface>(body.radius, body.rim_radius);
  out.gravity = body.gravity;
  out.validate();
  return out;
}

SteadyCircle steady_circle_for_radius(const RevolutionBody& body, double tilt, double rc) {
  const CircleTerms k = circle_terms(body, tilt);
  if (!std::isfinite(rc)) throw support::invalid_value("contact_circle_radius", rc, "it must be finite (m)");
  const double bracket = k.a * rc - k.b;
  if (!(bracket > 0.0))
    throw support::invalid_value("contact_circle_radius", rc,
                                 "no steady circle at this tilt: it must exceed " + support::message_number(k.b / k.a) + " m");
  return complete(body, tilt, rc, std::sqrt(k.c / bracket), k.rolling_radius);
}

SteadyCircle steady_circle_for_precession(const RevolutionBody& body, double tilt, double precession_rate) {
  const CircleTerms k = circle_terms(body, tilt);
  if (!(std::isfinite(precession_rate) && precession_rate != 0.0))
    throw support::invalid_value("precession_rate", precession_rate, "it must be finite and nonzero (rad/s)");
  const double omega = std::abs(precession_rate);
  return complete(body, tilt, (k.c / (omega * omega) + k.b) / k.a, omega, k.rolling_radius);
}

RollingState steady_circle_state(const SteadyCircle& c) {
  RollingState x;
  x.gamma = Eigen::Vector3d(std::cos(c.tilt), 0.0, std::sin(c.tilt));
  x.omega = c.precession_rate * x.gamma + c.spin_rate * Eigen::Vector3d::UnitZ();
  return x;
}

}  // namespace frictionlab::dynamics::rigid_rolling
