#pragma once
// The physically meaningful ranges of a scenario's values (docs/dynamics.md §7 gives each rule
// with its key), and their checks. A scenario is checked against them when it is resolved
// (dynamics/body/scenario.h): a value outside is std::invalid_argument (support::InvalidValue) naming
// its key, "KEY = VALUE is invalid: RULE".

#include <Eigen/Core>

#include "dynamics/body/body.h"
#include "dynamics/contact/hertz_contact.h"

namespace frictionlab::dynamics {

/// The physically meaningful ranges of scenario values, checked when a scenario is resolved
/// (docs/dynamics.md §7 gives each rule with its key). Beyond them the model of a rigid body on a
/// Hertz plane does not hold, and products the integration forms (m g, lambda |eps|^1.5,
/// omega^2 J, k N) would leave the range of doubles long before: a value outside is an error
/// naming its key, not a failure far downstream.
struct ScenarioLimits {
  static constexpr double kMinMass = 1e-6;  ///< kg: a grain of 1 mg
  static constexpr double kMaxMass = 1e6;   ///< kg: 1000 tonnes
  /// m: the body's length along its axis and its largest diameter (10 µm to 1 km).
  static constexpr double kMinSize = 1e-5;
  static constexpr double kMaxSize = 1e3;
  /// A >= this * m r_max^2 and C >= this * m rho_max^2 (r_max: the farthest surface point from the
  /// centre of mass, rho_max: the largest radius). Every body has A <= m r_max^2 and
  /// C <= m rho_max^2 (its mass lies inside it); far below, its rotation would be ~1/sqrt(this)
  /// faster than its size suggests.
  static constexpr double kMinInertiaFraction = 1e-6;
  static constexpr double kMaxFriction = 10.0;  ///< contact.k: measured dry friction stays below ~4
  static constexpr double kMinStiffness = 1e-3;  ///< N/m^1.5: softer than any gel of micrometre size
  static constexpr double kMaxStiffness = 1e15;  ///< N/m^1.5: stiffer than diamond at 1 km radius
  static constexpr double kMaxGravity = 1e3;     ///< m/s^2, ~100 g
  /// The static compression (m g / lambda)^(2/3) and a starting penetration -eps stay below this
  /// fraction of the body's smallest size: Hertz's law is one of small compressions.
  static constexpr double kMaxCompressionFraction = 0.05;
  static constexpr double kMaxHeight = 1e3;  ///< m: the highest start above the plane (initial.eps)
  /// m/s: the largest speed of the centre of mass (initial.v) and of a surface point about it
  /// (|omega| r_max): a rifle bullet's; faster impacts are not elastic.
  static constexpr double kMaxSpeed = 1e3;
};

/// The body's extent, from its profile (sampled like Profile::max_radius); for a body that is not
/// Body::axisymmetric, from its shape: `length` its smallest width, `rho_max` Shape::size().
struct BodyExtent {
  double length = 0.0;   ///< along the axis, m (the smallest width of another shape)
  double rho_max = 0.0;  ///< largest radius, m (another shape: its size)
  double r_max = 0.0;    ///< distance from the centre of mass to the farthest surface point, m
  /// min(length, largest diameter), m.
  [[nodiscard]] double smallest() const;
};
[[nodiscard]] BodyExtent extent_of(const Body& body);

/// [body] as written, before the body is built: body.mass; body.radius or body.semi_axes.
void check_body_spec(const BodySpec& spec);
/// The built body: its size (named by the key that gave it), body.A and body.C against its size.
void check_body(const BodySpec& spec, const Body& body, const BodyExtent& extent);
/// [contact]: contact.k, contact.lambda (also against the body's weight), contact.g.
void check_contact(const PlaneContact& contact, const Body& body, const BodyExtent& extent);
/// [initial]: initial.v, initial.omega (its surface speed), initial.eps.
void check_initial(const Eigen::Vector3d& v, const Eigen::Vector3d& omega, double eps, const BodyExtent& extent);

}  // namespace frictionlab::dynamics
