#pragma once
// What to set in each physics engine for a sphere on a plane (docs/engines.md §4): the Hertz patch
// radius of the contact at its load, and each engine's spin-friction coefficient for it, exact at
// pure spin or least worst over the slip range (the calibration's circle rows, calibration.h).
//
// Hertz (Johnson, Contact Mechanics, 1985, §4.2, eq. 4.22): a sphere of radius R pressed on a
// plane by N touches it over a circle of radius
//   a = (3 N R / (4 E*))^(1/3),   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2   (a rigid plane: E2 = inf).
// The engines' settings for the dimensionless coefficient c of an engine law (engine_laws.h: the
// pure-spin torque per kNa, kN = k·N the friction bound, not kilonewtons), as docs/engines.md §4
// derives them from each engine's torque limit:
//   MuJoCo (condim 4, elliptic cone)  friction="k mu3 ...", mu3 = c k a   (law mujoco-elliptic)
//   Bullet    setSpinningFriction(s) on the sphere, lateral friction k on the ground, s = c a
//             (Bullet multiplies it by the ground's friction k)            (law decoupled)
//   Chrono (NSC)  SetSpinningFriction(c k a) on both materials              (law decoupled)
//   Gazebo classic (ODE)  <patch_radius> a, torsional <coefficient> c k / (3 pi/16)
//             (its torque is coefficient (3 pi/16) a N)                     (law decoupled)
// The coefficients scale with a, i.e. with N^(1/3): a value is right at one load only.

#include <string>
#include <vector>

namespace frictionlab::calibration {

/// A sphere on a plane, SI units.
struct SphereContact {
  double radius = 0.0;           ///< R, m, > 0
  double load = 0.0;             ///< N, N, > 0
  double modulus = 0.0;          ///< the sphere's Young's modulus E1, Pa, > 0
  double poisson = 0.3;          ///< its Poisson ratio nu1, in [0, 0.5]
  double plane_modulus = 0.0;    ///< the plane's E2, Pa, > 0, or 0: a rigid plane
  double plane_poisson = 0.3;    ///< nu2, in [0, 0.5]
  double friction = 0.0;         ///< the Coulomb coefficient k, > 0
};

/// std::invalid_argument naming the option (`--sphere`, `--load`, ...) and its rule.
void validate(const SphereContact& contact);

/// E*, Pa.
[[nodiscard]] double effective_modulus(const SphereContact& contact);
/// a = (3 N R / (4 E*))^(1/3), m.
[[nodiscard]] double hertz_radius(const SphereContact& contact);

/// The coefficients c of the two engine laws the engines use: exact at pure spin, and the least
/// largest torque error over the slip range on the circle (CalibrationRow::best, Hertz pressure).
struct CircleCoefficients {
  double mujoco_spin = 0.0;
  double mujoco_best = 0.0;
  double decoupled_spin = 0.0;
  double decoupled_best = 0.0;
};

/// The calibration's circle rows for the Hertz pressure (run_calibration with a grid whose axis
/// ratios include 1): about 0.1 s.
[[nodiscard]] CircleCoefficients hertz_circle_coefficients();

/// One engine's setting: the value exact at pure spin and the least worst one, in `unit`.
struct EngineSetting {
  std::string engine;   ///< "MuJoCo (condim 4, elliptic cone)"
  std::string setting;  ///< "friction=\"k mu3 ...\": mu3"
  std::string unit;     ///< "m", or "1" for a dimensionless coefficient
  double at_spin = 0.0;
  double best = 0.0;
};

/// The settings of MuJoCo, Bullet, Chrono and Gazebo classic for `contact` (validated), in that
/// order (Gazebo's patch radius is hertz_radius()).
[[nodiscard]] std::vector<EngineSetting> engine_settings(const SphereContact& contact, const CircleCoefficients& c);

}  // namespace frictionlab::calibration
