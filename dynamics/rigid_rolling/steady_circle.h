#pragma once
// Steady rolling in a circle of a body of revolution with a toroidal rim (docs/rigid-rolling.md §4):
// the disk of dynamics/rigid_rolling/rounded_disk_surface.h (outer radius R, rim radius rho, rim
// centres on the circle of radius Rc = R - rho) with its centre of mass at its centre, inertia
// diag(A, A, C), leaning at the constant angle beta from the vertical (0: upright), while its axis
// turns about the vertical at the precession rate Omega and it spins at s about its axis relative to
// the turning frame (omega = Omega z + s k). With Re = Rc + rho cos beta (the rolling radius: the
// distance of the contact point from the axis) and l = Rc cos beta + rho (the height of G), no slip
// makes the contact point run on a circle of radius rc = -s Re/Omega (positive: centred on the side
// the disk leans to) and G on one of radius rG = rc - Rc sin beta; Euler's equation about G gives
//
//   Omega^2 [rc (C cos beta/Re + m l) - (C - A) sin beta cos beta - m l Rc sin beta] = m g Rc sin beta.
//
// Checks (tests): the thin disk (rho = 0) with G at rest (rG = 0) gives Omega^2 = m g R/(A cos beta),
// for a uniform disk (A = m R^2/4) Moffatt's Omega^2 = 4 g/(R sin alpha) of Euler's disk (Nature 404
// (2000) 833; alpha = pi/2 - beta the angle to the table); a large circle gives tan beta ->
// (3/2) V^2/(g rc) for the uniform thin disk (the rolling coin: Kleppner & Kolenkow, An Introduction
// to Mechanics; McDonald, "The rolling motion of a disk on a horizontal plane", arXiv
// physics/0008227, its limit b -> infinity).

#include <Eigen/Core>

#include "dynamics/rigid_rolling/rigid_body.h"
#include "dynamics/rigid_rolling/rolling_state.h"

namespace frictionlab::dynamics::rigid_rolling {

struct RevolutionBody {
  double mass = 0.0;                ///< m, kg, > 0
  double transverse_inertia = 0.0;  ///< A about a diameter through G, kg m^2, > 0
  double axial_inertia = 0.0;       ///< C about the axis, kg m^2, 0 < C <= 2 A
  double radius = 0.0;              ///< R, outer radius, m, > 0
  double rim_radius = 0.0;          ///< rho, m, 0 <= rho < R
  double gravity = 9.81;            ///< g, m/s^2, > 0

  /// Throws std::invalid_argument naming the value and the rule.
  void validate() const;
};

/// The rigid rolling body: the disk's axis along body z, G at its centre.
[[nodiscard]] RigidRollingBody rigid_body(const RevolutionBody& body);

struct SteadyCircle {
  double tilt = 0.0;                   ///< beta, from the vertical, rad, in (0, pi/2)
  double precession_rate = 0.0;        ///< Omega, rad/s, > 0 (counter-clockwise seen from above; the mirror motion has -Omega, -s)
  double spin_rate = 0.0;              ///< s, about the axis relative to the turning frame, rad/s
  double contact_circle_radius = 0.0;  ///< rc, m (positive: centre on the side the disk leans to)
  double centre_circle_radius = 0.0;   ///< rG = rc - Rc sin beta, m (0: G at rest, Euler's disk)
  double rolling_speed = 0.0;          ///< |rc Omega|, the speed of the contact point, m/s
  double centre_speed = 0.0;           ///< |rG Omega|, the speed of G, m/s
};

/// The steady circle at tilt beta whose contact point runs on radius rc. Throws
/// std::invalid_argument when no steady circle has that radius (the bracket above <= 0).
[[nodiscard]] SteadyCircle steady_circle_for_radius(const RevolutionBody& body, double tilt, double contact_circle_radius);
/// The steady circle at tilt beta with precession rate Omega (finite, != 0; its sign is ignored).
[[nodiscard]] SteadyCircle steady_circle_for_precession(const RevolutionBody& body, double tilt, double precession_rate);
/// Its state in the body frame of rigid_body(body) at the instant the lowest rim point is on body -x:
/// gamma = (cos beta, 0, sin beta), omega = Omega gamma + s e3.
[[nodiscard]] RollingState steady_circle_state(const SteadyCircle& circle);

}  // namespace frictionlab::dynamics::rigid_rolling
