#pragma once
// The energy of a body's rocking about the equilibrium it is near, for the rest rule
// (dynamics/core/rest_event.h, docs/dynamics.md §5).
//
// At a turning point of a rocking the kinetic energy, the slip and the spin can all pass near zero
// at once while the body is far from rest: the rattleback at its spin reversal pitches through such
// a point (its spin crosses zero as its pitch velocity does). Rest must not be declared there, so
// the rest rule compares the kinetic energy *plus* the rocking's potential energy with
// run.rest_kinetic_energy.
//
// The estimate: a body rolling on a principal radius of curvature R_c, its centre of mass G at the
// height l above the contact point, tilted by theta from its equilibrium, has the contact point at
// the horizontal distance d = (R_c - l) sin(theta) from below G and the potential energy
// m g (R_c - l)(1 - cos(theta)) = m g d^2 / (2 (R_c - l)) (1 + O(theta^2)). With R_max, the larger
// principal radius at the contact, in place of R_c - l (R_max >= R_c > R_c - l for l > 0) this is
//
//   E_rock = m g d^2 / (2 R_max),   d = |r - (r . gamma) gamma|,
//
// a lower bound of the rocking energy (so it never holds back a body at rest: at an equilibrium
// d = 0). r is the contact point from G, gamma the upward vertical, both in the body frame.
// A flat contact (R_max infinite) or no gravity gives 0.

#include <Eigen/Core>

namespace frictionlab::dynamics {

/// E_rock (J) for the contact point `r` (m, from the centre of mass), the upward vertical `gamma`
/// (unit), the principal radii `R1`, `R2` at the contact (m, > 0; infinite for a flat contact), the
/// mass `m` (kg) and gravity `g` (m/s^2).
[[nodiscard]] double rocking_energy(const Eigen::Vector3d& r, const Eigen::Vector3d& gamma, double R1, double R2,
                                    double m, double g);

}  // namespace frictionlab::dynamics
