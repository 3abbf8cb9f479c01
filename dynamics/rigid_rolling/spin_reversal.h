#pragma once
// Spin reversal of a rolling body (docs/rigid-rolling.md §3): the averaged slow-spin estimate and
// the reversal the nonlinear equations give.
//
// Estimate. At slow spin the oscillation energy E of the growing mode rises as E' = 2 sigma(n) E,
// sigma = alpha n (dynamics/rigid_rolling/steady_spin.h), and, the motion conserving energy, the
// spin energy C n^2/2 (C = J33) pays for it: C n n' = -E'. So n' = -alpha (n_inf^2 - n^2),
// n_inf^2 = n0^2 + 2 E0/C, and n(t) = n_inf tanh(alpha n_inf (t_r - t)) from n(0) = n0: the spin
// reverses at
//
//   t_r = q atanh(q) / sigma0,    q = sqrt(E_s/(E_s + E0)),  E_s = C n0^2/2,  sigma0 = alpha n0,
//       ~ ln(2 C n0^2/E0) / (2 sigma0)   for E0 << E_s,
//
// then settles towards -n_inf while the other mode, growing in the new sense, brings the next
// reversal (no dissipation: reversals repeat without end). This is the energy-balance form of the
// averaged (slow-spin, small-amplitude) theory of Moffatt & Tokieda, Proc. R. Soc. Edinb. A 138
// (2008) 361, for which Garcia & Hubbard, Proc. R. Soc. Lond. A 418 (1988) 165, gave a reversal-time
// formula and Kondo & Nakanishi, Phys. Rev. E 95 (2017) 062207, its product form; their printed
// formulas could not be checked here (docs §3), so this is the project's own derivation, tested
// against the nonlinear model in the slow-spin limit.

#include <limits>

#include "dynamics/rigid_rolling/rolling_equations.h"
#include "dynamics/rigid_rolling/rolling_integrator.h"
#include "dynamics/rigid_rolling/rolling_state.h"
#include "dynamics/rigid_rolling/steady_spin.h"

namespace frictionlab::dynamics::rigid_rolling {

/// t_r = q atanh(q)/sigma0, s (above). growth_rate sigma0 (1/s), spin_energy E_s (J) and
/// mode_energy E0 (J) finite and > 0; throws std::invalid_argument otherwise.
[[nodiscard]] double averaged_reversal_time(double growth_rate, double spin_energy, double mode_energy);

/// Steady spin n disturbed along the growing eigenmode of the linearisation.
struct PerturbedSteadySpin {
  RollingState state;        ///< omega = (w1, w2, n), gamma = (g1, g2, 1)/|.|
  double growth_rate = 0.0;  ///< max Re lambda(n), 1/s
  double spin_energy = 0.0;  ///< J33 n^2/2, J
  double mode_energy = 0.0;  ///< energy(state) - energy(steady spin), J
};

/// The real part of the eigenvector of the eigenvalue of largest real part of L(n) (its phase set so
/// that its larger tilt component is real), scaled so that max(|g1|, |g2|) = tilt (rad, > 0,
/// small). `model` must be the body `linearised` describes (its energy gives mode_energy).
[[nodiscard]] PerturbedSteadySpin perturbed_steady_spin(const RigidRollingModel& model, const SteadySpinBody& linearised,
                                                        double spin, double tilt);

struct ReversalSearch {
  double t_max = 0.0;                     ///< give up after this time, s, > 0
  RollingIntegratorOptions integrator;    ///< tolerances
  double time_tolerance = 1e-9;           ///< the reversal time is located to this, s, > 0
};

struct SpinReversal {
  bool reversed = false;                                   ///< the spin changed sign before t_max
  double time = std::numeric_limits<double>::quiet_NaN();  ///< when it first did (omega . gamma = 0), s
  RollingState state;                                      ///< the state then (at t_max if none)
  long steps = 0;                                          ///< accepted steps to get there
};

/// Integrates from `start` (spin omega . gamma != 0) until the spin first changes sign or t_max,
/// and locates the zero by regula falsi (Illinois) on re-integrations from the bracketing step's
/// start. Throws std::invalid_argument for a zero initial spin or invalid options.
[[nodiscard]] SpinReversal first_spin_reversal(const RigidRollingModel& model, const RollingState& start,
                                               const ReversalSearch& search);

}  // namespace frictionlab::dynamics::rigid_rolling
