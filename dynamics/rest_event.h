#pragma once
// The stagnation region of the paper (end of section 2): the friction laws are singular at
// U = Omega = 0 (Coulomb's sign function), so near rest an adaptive integrator would chatter with
// ever smaller steps. The run stops instead, with reason "rest", as soon as an accepted step lands
// in contact with all three below their thresholds (checked between steps, never inside the RHS).

#include <cmath>

namespace frictionlab::dynamics {

struct RestThresholds {
  /// Slip speed U of the contact point, m/s. Default: 1 mm/s, two orders below the slip speeds of
  /// the paper's runs (~0.1-10 m/s) and above the micro-slip the stiff regularised law allows.
  double slip_speed = 1e-3;
  /// Spin |Omega| about the vertical, 1/s (default 0.01 1/s: one turn per ~10 min).
  double spin = 1e-2;
  /// Kinetic energy m v^2/2 + omega.J omega/2, J. Default 1e-3 J: for the 2 kg egg, ~3 cm/s or a
  /// rocking of ~0.2 1/s; below the energy of the Hertz vertical oscillation the paper's initial
  /// compression eps0 = -3e-5 m excites (~1.3e-3 J), which nothing in the model damps.
  double kinetic_energy = 1e-3;

  /// Throws std::invalid_argument naming the key (run.rest_slip_speed, ...) and the rule.
  void validate() const;

  [[nodiscard]] bool at_rest(bool in_contact, double U, double Omega, double kinetic) const {
    return in_contact && U < slip_speed && std::abs(Omega) < spin && kinetic < kinetic_energy;
  }
};

}  // namespace frictionlab::dynamics
