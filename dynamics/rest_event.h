#pragma once
// The stagnation region of the paper (end of section 2). The friction laws are singular at
// U = Omega = 0 (Coulomb's sign function: the local Coulomb law has no sticking branch), so once
// the contact point neither slips nor spins an adaptive integrator can only chatter with ever
// smaller steps. Checked between accepted steps (never inside the RHS), in contact:
//   rest     U < slip_speed, |Omega| < spin and kinetic energy < kinetic_energy;
//   rolling  U < slip_speed and |Omega| < spin but the kinetic energy is larger: the body rolls
//            (or rocks) without slip and spin, which this model does not dissipate (there is no
//            rolling resistance), so it would roll for ever; the run stops there too unless
//            run.stop_when_rolling = false (then it chatters on, bounded by run.max_steps).

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

  /// The contact neither slips nor spins (the laws' singular set).
  [[nodiscard]] bool contact_stagnant(bool in_contact, double U, double Omega) const {
    return in_contact && U < slip_speed && std::abs(Omega) < spin;
  }
  [[nodiscard]] bool at_rest(bool in_contact, double U, double Omega, double kinetic) const {
    return contact_stagnant(in_contact, U, Omega) && kinetic < kinetic_energy;
  }
};

}  // namespace frictionlab::dynamics
