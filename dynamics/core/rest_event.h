#pragma once
// The stagnation region of the paper (end of section 2). The friction laws are singular at
// U = Omega = 0 (Coulomb's sign function: the local Coulomb law has no sticking branch), so once
// the contact point neither slips nor spins an adaptive integrator can only chatter with ever
// smaller steps. Checked between accepted steps (never inside the RHS), in contact, and only once
// the normal motion has settled (dynamics/core/settling.h: rest and rolling are states of persistent
// contact, not moments of a bounce):
//   rest     U < slip_speed, |Omega| < spin and kinetic energy < kinetic_energy;
//   rolling  U < slip_speed and |Omega| < spin but the kinetic energy is larger: the body rolls
//            (or rocks) without slip and spin, which this model does not dissipate (there is no
//            rolling resistance), so it would roll for ever; the run stops there too unless
//            run.stop_when_rolling = false (then it chatters on, bounded by run.max_steps).
//
// Each threshold is given in the scenario (absolute, SI) or defaults to a fixed fraction of the
// body's own scale (dynamics/core/scales.h, R the body's size), so that "at rest" means the same
// for a 15 g top and a 2 kg egg:
//   slip speed  1e-3 sqrt(g R)   (egg-printed, R = 0.278 m: 1.65 mm/s; 15 g top, R = 2.4 cm: 0.49 mm/s)
//   spin        1e-3 sqrt(g/R)   (egg: 6e-3 1/s; top: 0.020 1/s)
//   kinetic     1e-4 m g R       (egg: 5.4e-4 J; top: 3.5e-7 J): a body moving at v has
//               m v^2/2 below it only if v < 0.014 sqrt(g R) (egg 2.3 cm/s, top 0.7 cm/s).
// The speeds and the spin are three orders below those of a body that rocks or falls over its
// own size (sqrt(g R), sqrt(g/R)); the energy is that of lifting it by 1e-4 of its size.

#include <cmath>
#include <optional>

#include "dynamics/core/scales.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics {

inline constexpr double kRestSlipSpeedFactor = 1e-3;      ///< default run.rest_slip_speed / sqrt(g R)
inline constexpr double kRestSpinFactor = 1e-3;           ///< default run.rest_spin / sqrt(g/R)
inline constexpr double kRestKineticEnergyFactor = 1e-4;  ///< default run.rest_kinetic_energy / (m g R)

/// What the scenario says ([run] rest_*); an unset value takes the scaled default above. 0
/// disables (all three 0: no rest and no rolling event).
struct RestThresholds {
  std::optional<double> slip_speed;      ///< run.rest_slip_speed, m/s, >= 0
  std::optional<double> spin;            ///< run.rest_spin, 1/s, >= 0
  std::optional<double> kinetic_energy;  ///< run.rest_kinetic_energy, J, >= 0

  /// Throws std::invalid_argument naming the key (run.rest_slip_speed, ...) and the rule.
  void validate() const;
};

/// The thresholds as applied to one body.
struct RestRule {
  Threshold slip_speed;
  Threshold spin;
  Threshold kinetic_energy;

  /// The contact neither slips nor spins (the laws' singular set).
  [[nodiscard]] bool contact_stagnant(bool in_contact, double U, double Omega) const {
    return in_contact && U < slip_speed.value && std::abs(Omega) < spin.value;
  }
  [[nodiscard]] bool at_rest(bool in_contact, double U, double Omega, double kinetic) const {
    return contact_stagnant(in_contact, U, Omega) && kinetic < kinetic_energy.value;
  }
};

[[nodiscard]] RestRule resolve_rest(const RestThresholds& given, const BodyScales& scales);

}  // namespace frictionlab::dynamics
