#pragma once
// One run of the body: integrates the equations of motion (dynamics/body/equations_of_motion.h) on the
// integration loop every model shares (dynamics/core/run_loop.h) from t = 0 to an event, reporting
// samples to an observer, and returns a summary. The loop owns the stepping, sampling and the
// events every model has; the body adds lift-offs, landings, settling, rest, stick, rolling and
// stagnation.
//
// Steps are free: each is the step GSL's error control chooses towards run.t_end (only the last is
// cut to land on t_end exactly, and run.max_step caps them); samples on the output grid are taken
// inside accepted steps (dynamics/core/step_sampler.h), so the output interval never changes the steps.
// The absolute tolerance is scaled per state component (dynamics/body/tolerance_scales.h).
//
// Events (docs/dynamics.md §5):
//   t_end       the end time was reached;
//   rest        the stagnation region with little kinetic energy, in settled contact
//               (dynamics/core/rest_event.h, dynamics/core/settling.h);
//   rolling     with run.stick (default): the body rolled in stick (without slip and spin, the
//               wrench inside the law's limit set, the energy constant) for run.stick_hold_time
//               without a break; with run.stick = false, or a law whose limit set has no
//               interior: the contact stopped slipping and spinning while the body still moves (a
//               sliding sphere starts to roll; an egg rocks on its pole), in settled contact;
//   stagnation  the contact stayed in the stagnation region for run.max_stagnant_steps steps in a
//               row while its normal motion had not settled (a bounce reaching U = Omega = 0):
//               the integrator can only chatter there;
//   chatter     the slip (or the spin) stayed below its rest threshold while the other did not, with
//               collapsed steps and repeated reversals, for run.max_chatter_steps steps in a row:
//               a law discontinuous at U = 0 (or Omega = 0) chatters there (dynamics/core/chatter_watch.h);
//   law-pole    a denominator of the friction law passes through 0 (dynamics/core/pole_watch.h): no
//               step, not even a trial stage, may cross it, so the integrator closes in on the
//               pole until no step above rounding avoids it, and the run stops there;
//   non-finite  the state or the right-hand side stopped being finite and GSL's retries with
//               smaller steps, down to machine precision, did not help;
//   law-error   the friction law rejected its input (message attached);
//   integrator-failure  GSL gave up (message attached);
//   max-steps   run.max_steps accepted steps were taken;
//   flat-face   a toroidal disk's face reached the plane (BodyOnPlane::point_contact_end): the
//               point contact of its rim, the model's, ends there;
//   interrupted the caller's cancel flag was raised (Ctrl-C on the command line);
//   output-error / output-limit  the observer's sample() threw OutputFailure / OutputLimitReached
//               (dynamics/core/observer.h): the run stops at once.
// Events are checked between accepted steps. On every stop the last good state is kept, sampled
// (unless the output failed) and returned.

#include "dynamics/body/body_scales.h"
#include "dynamics/core/chatter_watch.h"
#include "dynamics/body/equations_of_motion.h"
#include "dynamics/core/observer.h"
#include "dynamics/core/output_limit.h"
#include "dynamics/core/rest_event.h"
#include "dynamics/core/motion_phase.h"
#include "dynamics/core/run_options.h"
#include "dynamics/core/run_summary.h"
#include "dynamics/core/settling.h"
#include "dynamics/body/state.h"

namespace frictionlab::dynamics {

/// The body's run: the core's summary (dynamics/core/run_summary.h) and what the body's events record.
struct RunSummary : RunSummaryOf<StateVector> {
  long liftoffs = 0;            ///< contact -> no contact transitions (between steps)
  long landings = 0;            ///< no contact -> contact
  double min_normal_force = 0.0;  ///< min N over accepted steps, N
  double max_gamma_drift = 0.0; ///< max | |gamma| - 1 | over accepted steps
  BodyScales scales;            ///< the body's scales (thresholds and tolerances)
  RestRule rest;                ///< the rest thresholds as applied
  SettleRule settle;            ///< the settling thresholds as applied
  ChatterRule chatter;          ///< the chatter thresholds as applied
  // Stick (docs/dynamics.md §5 "stick").
  long stick_entries = 0;       ///< entries into stick
  long stick_exits = 0;         ///< exits from stick (located: the wrench left the law's limit set)
  long stick_projections = 0;   ///< projections of the residue of slip and spin (entries, creep, drift)
  long creep_entries = 0;       ///< refused entries that started a creep at the limit
  long creep_unresolved = 0;    ///< creep directions without a consistent slow manifold (the search's kept)
  double stick_time = 0.0;      ///< total time in stick, s
  double first_stick_entry = -1.0;  ///< s; -1: none
  double first_stick_exit = -1.0;   ///< s (located); -1: none
  double stick_projection_loss = 0.0;  ///< kinetic energy the projections removed (in W_slide + W_spin), J
  long limit_set_evaluations = 0;      ///< law evaluations spent on limit-set tests
  bool stick_degenerate = false;       ///< stick was refused: the law's limit set has no interior
  // The slip held on its slow manifold (docs/dynamics.md §5 "slip hold").
  long hold_entries = 0;               ///< entries into the mode
  long hold_exits = 0;                 ///< exits from it
  long hold_evaluations = 0;           ///< law evaluations spent on the manifold's solves
  double hold_time = 0.0;              ///< total time in the mode, s
  double first_hold_entry = -1.0;      ///< s; -1: none
  long hold_zero_entries = 0;          ///< of the entries, those at zero slip (a law discontinuous there)
  long hold_force_exits = 0;           ///< exits where the force holding the zero slip reached the law's limit
  double first_force_exit = -1.0;      ///< s, the first of those exits; -1: none
  // The spin of a law discontinuous in the spin held at zero (docs/dynamics.md §5 "slip hold").
  long spin_hold_entries = 0;          ///< entries into the mode
  long spin_hold_exits = 0;            ///< exits from it
  long spin_moment_exits = 0;          ///< of the exits, those where the holding moment reached the law's limit
  double spin_hold_time = 0.0;         ///< total time in the mode, s
  double first_spin_hold_entry = -1.0; ///< s; -1: none
  Threshold stick_hold;                ///< run.stick_hold_time as applied
};

/// The phases of the body's motion for the shadow laws (dynamics/core/motion_phase.h): the run's
/// rest thresholds and settling speed, resolved as the run resolves them.
[[nodiscard]] MotionPhaseRule motion_phase_rule(const BodyOnPlane& sys, const RunOptions& options);

/// Integrates from x0 at t = 0. `observer` may be null. Throws std::invalid_argument for invalid
/// options or a non-finite x0; every later failure ends the run with a reason instead.
/// Switches GSL's abort-on-error handler off (process-wide): errors are return codes here.
[[nodiscard]] RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options,
                                  Observer* observer = nullptr);

}  // namespace frictionlab::dynamics
