#pragma once
// One run of the puck (docs/puck.md): integrates dynamics/puck/puck_equations.h on the integration
// loop every model shares (dynamics/core/run_loop.h: free steps under scaled error control, samples
// inside accepted steps, the law's poles, limits and failures) from t = 0 to an event, and returns
// a summary. The puck adds its own events: the stops of slip and spin, located and held.
//
// The laws are singular at U = Omega = 0, where both go to zero together at the end of a coupled
// motion; and a discontinuous law (a decoupled Coulomb law) chatters where one of them reaches 0
// while the other does not. So the end is made of explicit events, each located inside its step
// (bisection on sub-steps from the step's start, to ~1e-15 of the time):
//   slip stops  U falls below run.rest_slip_speed (default 1e-3 sqrt(g a)): v is set to 0 and held
//               there (dynamics/puck/puck_equations.h); the kinetic energy m U^2/2 it had (below
//               5e-7 m g a at the default) is counted as sliding work, so E + W = E(0) still holds;
//   spin stops  |Omega| falls below run.rest_spin (default 1e-3 sqrt(g/a)): the same for omega
//               (I Omega^2/2 counted as spinning work);
//   rest        both have stopped: the run ends (reason "rest").
// The thresholds scale with the puck as those of the body do with its size (dynamics/core/rest_event.h),
// the size being the patch's major semi-axis a; at the defaults U/(a |Omega|) = 1 on both
// thresholds. The other reasons are the body's (dynamics/body/simulation.h): t_end, law-pole (watched
// as for the body, dynamics/core/pole_watch.h), non-finite, law-error, integrator-failure, max-steps,
// interrupted, output-error, output-limit.
//
// The terminal ratio: U/(a |Omega|) at the first of the two stops (the last moment both motions
// are resolved); the ratio where the kinetic energy crosses 1e-1, 1e-2, ... of its initial value
// (located inside the steps), which shows whether the ratio settles on a constant
// (dynamics/puck/terminal_ratio.h) or still drifts; and the limit extrapolated from the last three
// of those (aitken_limit). Near an attracting ratio the approach is a power of the speed, often a
// slow one (r - r* ~ v^0.35 for the uniform disk), so the ratio at the stop is not yet the limit.

#include <Eigen/Core>
#include <atomic>
#include <limits>
#include <string>
#include <vector>

#include "dynamics/body/body_scales.h"
#include "dynamics/core/motion_phase.h"
#include "dynamics/core/observer.h"
#include "dynamics/puck/puck_equations.h"
#include "dynamics/core/run_options.h"
#include "dynamics/core/run_summary.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics::puck {

/// The ratio U/(a |Omega|) where the kinetic energy crossed `level` times its initial value.
struct RatioAtEnergy {
  double level = 0.0;     ///< 1e-1, 1e-2, ...
  double t = 0.0;         ///< s
  double fraction = 0.0;  ///< the kinetic energy's fraction there (= level, to the bisection)
  double ratio = 0.0;     ///< U/(a |Omega|)
};

/// The puck's run: the core's summary (dynamics/core/run_summary.h) and what the puck's events record.
struct PuckRunSummary : RunSummaryOf<PuckState> {
  Holds holds;                 ///< at the end
  Threshold slip_speed;        ///< as applied
  Threshold spin;              ///< as applied
  double slip_stop_time = std::numeric_limits<double>::quiet_NaN();  ///< U fell below slip_speed (NaN: never)
  double spin_stop_time = std::numeric_limits<double>::quiet_NaN();  ///< |Omega| fell below spin
  double terminal_ratio = std::numeric_limits<double>::quiet_NaN();  ///< U/(a|Omega|) at the first stop
  /// The limit of the ratio estimated from its last three decades (aitken_limit); NaN if it does
  /// not converge geometrically there (it drifts to 0 or infinity, or too few decades).
  double terminal_ratio_limit = std::numeric_limits<double>::quiet_NaN();
  double held_slide_energy = 0.0;  ///< m U^2/2 removed when the slip was held (in W_slide), J
  double held_spin_energy = 0.0;   ///< I Omega^2/2 removed when the spin was held (in W_spin), J
  std::vector<RatioAtEnergy> ratio_by_energy;
};

/// Integrates from x0 at t = 0. Uses of RunOptions: t_end, output_dt, max_samples, integrator,
/// rest.slip_speed, rest.spin, cancel (the settling and rolling keys belong to the body).
/// Throws std::invalid_argument for invalid options or a non-finite x0.
[[nodiscard]] PuckRunSummary simulate_puck(const PuckOnPlane& sys, const PuckState& x0, const RunOptions& options,
                                           PuckObserver* observer = nullptr);

/// The limit of the ratio from its values at the last decades of the kinetic energy (Aitken's
/// delta-squared on the last three): near an attracting ratio r* the distance r - r* falls like
/// v^lambda (dynamics/puck/terminal_ratio.h), i.e. by a fixed factor q per decade, and
/// r_n - (r_n - r_{n-1})^2/((r_n - r_{n-1}) - (r_{n-1} - r_{n-2})) removes it. NaN unless the last
/// five values contract geometrically (the same q in (0, 1) over the last three decades, to 5 %):
/// a ratio still far from its limit, or drifting to 0 or infinity (the Hertz disk's r ~ 1/sqrt(ln
/// 1/v), whose q creeps towards 1), has none.
[[nodiscard]] double aitken_limit(const std::vector<RatioAtEnergy>& ratios);

/// The phases of the puck's motion for the shadow laws (dynamics/core/motion_phase.h): the run's
/// rest thresholds as the run resolves them; a rigid plane has no bouncing.
[[nodiscard]] MotionPhaseRule motion_phase_rule(const PuckOnPlane& sys, const RunOptions& options);

/// The scales of a puck (dynamics/body/body_scales.h) with the patch's major semi-axis a as its size.
[[nodiscard]] BodyScales puck_scales(const Puck& puck, double g);

/// The absolute tolerance scales of the puck's state: position a, heading 1, v sqrt(g a),
/// omega sqrt(g/a), work m g a.
[[nodiscard]] PuckState puck_tolerance_scales(const BodyScales& scales);

}  // namespace frictionlab::dynamics::puck
