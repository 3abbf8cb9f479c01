#include "bench/calibration/sphere_settings.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "bench/calibration/calibration.h"
#include "friction/support/errors.h"

namespace frictionlab::calibration {
namespace {

void positive(const char* option, double x) {
  if (!(std::isfinite(x) && x > 0.0)) throw support::invalid_value(option, x, "it must be a finite number > 0");
}
void poisson(const char* option, double x) {
  if (!(x >= 0.0 && x <= 0.5)) throw support::invalid_value(option, x, "a Poisson ratio must be in [0, 0.5]");
}

}  // namespace

void validate(const SphereContact& c) {
  positive("--sphere", c.radius);
  positive("--load", c.load);
  positive("--modulus", c.modulus);
  poisson("--poisson", c.poisson);
  if (c.plane_modulus != 0.0) positive("--plane-modulus", c.plane_modulus);
  poisson("--plane-poisson", c.plane_poisson);
  positive("--friction", c.friction);
}

double effective_modulus(const SphereContact& c) {
  double compliance = (1.0 - c.poisson * c.poisson) / c.modulus;
  if (c.plane_modulus > 0.0) compliance += (1.0 - c.plane_poisson * c.plane_poisson) / c.plane_modulus;
  return 1.0 / compliance;
}

double hertz_radius(const SphereContact& c) { return std::cbrt(3.0 * c.load * c.radius / (4.0 * effective_modulus(c))); }

CircleCoefficients hertz_circle_coefficients() {
  CalibrationOptions o;
  o.laws = {"mujoco-elliptic", "decoupled"};
  o.pressures = {"hertz"};
  o.grid.mu_points = 2;  // 0.05 and 1: the circle rows read mu = 1 only
  o.grid.psi_points = 3;
  o.threads = 1;
  const CalibrationResult r = run_calibration(o);
  CircleCoefficients c;
  for (const CalibrationRow& row : r.rows) {
    if (row.scope != Scope::circle) continue;
    if (row.law == "mujoco-elliptic") {
      c.mujoco_spin = row.at_spin.c;
      c.mujoco_best = row.best.c;
    } else if (row.law == "decoupled") {
      c.decoupled_spin = row.at_spin.c;
      c.decoupled_best = row.best.c;
    }
  }
  return c;
}

std::vector<EngineSetting> engine_settings(const SphereContact& contact, const CircleCoefficients& c) {
  const double a = hertz_radius(contact);
  const double k = contact.friction;
  const double hertz_spin = 3.0 * std::numbers::pi / 16.0;  // Gazebo's own pure-spin factor
  return {
      {"MuJoCo (condim 4, elliptic cone)", "friction=\"k mu3 ...\": mu3", "m", c.mujoco_spin * k * a, c.mujoco_best * k * a},
      {"Bullet", "setSpinningFriction(s) on the sphere: s", "m", c.decoupled_spin * a, c.decoupled_best * a},
      {"Chrono (NSC)", "SetSpinningFriction on both materials", "m", c.decoupled_spin * k * a, c.decoupled_best * k * a},
      {"Gazebo classic (ODE)", "torsional <coefficient> (with <patch_radius> a)", "1", c.decoupled_spin * k / hertz_spin,
       c.decoupled_best * k / hertz_spin},
  };
}

}  // namespace frictionlab::calibration
