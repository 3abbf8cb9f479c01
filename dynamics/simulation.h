#pragma once
// One run: integrates the equations of motion (dynamics/equations_of_motion.h) with GSL odeiv2
// from t = 0 to an event, reporting samples to an observer, and returns a summary.
//
// Steps are free: each is the step GSL's error control chooses towards run.t_end (only the last is
// cut to land on t_end exactly, and run.max_step caps them); samples on the output grid are taken
// inside accepted steps (dynamics/step_sampler.h), so the output interval never changes the steps.
// The absolute tolerance is scaled per state component (dynamics/tolerance_scales.h).
//
// Events (docs/dynamics.md §5):
//   t_end       the end time was reached;
//   rest        the stagnation region with little kinetic energy, in settled contact
//               (dynamics/rest_event.h, dynamics/settling.h);
//   rolling     the contact stopped slipping and spinning while the body still moves (a sliding
//               sphere starts to roll; an egg rocks on its pole), in settled contact;
//   stagnation  the contact stayed in the stagnation region for run.max_stagnant_steps steps in a
//               row while its normal motion had not settled (a bounce reaching U = Omega = 0):
//               the integrator can only chatter there, and the model has no sticking branch;
//   chatter     the slip (or the spin) stayed below its rest threshold while the other did not, with
//               collapsed steps and repeated reversals, for run.max_chatter_steps steps in a row:
//               a law discontinuous at U = 0 (or Omega = 0) chatters there (dynamics/chatter_watch.h);
//   law-pole    a denominator of the friction law passes through 0 (dynamics/pole_watch.h): no
//               step, not even a trial stage, may cross it, so the integrator closes in on the
//               pole until no step above rounding avoids it, and the run stops there;
//   non-finite  the state or the right-hand side stopped being finite and GSL's retries with
//               smaller steps, down to machine precision, did not help;
//   law-error   the friction law rejected its input (message attached);
//   integrator-failure  GSL gave up (message attached);
//   max-steps   run.max_steps accepted steps were taken;
//   interrupted the caller's cancel flag was raised (Ctrl-C on the command line);
//   output-error / output-limit  the observer's sample() threw OutputFailure / OutputLimitReached
//               (dynamics/observer.h): the run stops at once.
// Events are checked between accepted steps. On every stop the last good state is kept, sampled
// (unless the output failed) and returned.

#include <atomic>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/body_scales.h"
#include "dynamics/chatter_watch.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/integrator_options.h"
#include "dynamics/observer.h"
#include "dynamics/output_limit.h"
#include "dynamics/rest_event.h"
#include "dynamics/settling.h"
#include "dynamics/state.h"
#include "dynamics/threshold.h"

namespace frictionlab::dynamics {

/// Default run.max_samples: 1e7 samples, ten times what the paper's scenario files once planned
/// (t_end = 1000 s at output_dt = 1e-3 s). It bounds the samples a run may plan whatever keeps
/// them (in memory too); the size of the trajectory file has its own, tighter limit
/// (max_output_bytes, dynamics/output_limit.h).
inline constexpr long kDefaultMaxSamples = 10'000'000;

struct RunOptions {
  double t_end = 1.0;       ///< s, > 0
  double output_dt = 1e-3;  ///< s, > 0: the sample interval; t_end/output_dt <= max_samples
  long max_samples = kDefaultMaxSamples;  ///< > 0: the most samples a run may plan
  /// > 0, bytes: the largest trajectory file a run may write (dynamics/output_limit.h); enforced
  /// by the writers (dynamics/trajectory_csv.h), not by simulate().
  long max_output_bytes = kDefaultMaxOutputBytes;
  IntegratorOptions integrator;
  RestThresholds rest;
  SettleThresholds settle;
  bool stop_when_rolling = true;  ///< stop with reason "rolling" (dynamics/rest_event.h)
  /// >= 0 (0: never): accepted steps in a row in the stagnation region, in contact but not settled,
  /// before the run stops with reason "stagnation". A bounce that merely passes through the region
  /// (a vertical drop without slip or spin stays in it during every impact, where the friction is
  /// 0) takes a few tens of steps per impact; the chatter of a discontinuous law at U = Omega = 0
  /// takes ~1e6 steps per millisecond (steps of ~tolerance/(k g) s).
  long max_stagnant_steps = 1000;
  /// run.max_chatter_steps, run.chatter_step: when the chatter of a discontinuous law stops the
  /// run (dynamics/chatter_watch.h).
  ChatterThresholds chatter;
  const std::atomic<bool>* cancel = nullptr;  ///< checked between steps; may be null

  /// std::invalid_argument naming the run.* key and the rule: besides each value's own range,
  /// t_end/output_dt must not exceed max_samples (the output would be absurdly large), and a
  /// max_step > 0 must let max_steps steps reach t_end (max_step * max_steps >= t_end).
  void validate() const;
};

enum class Termination {
  t_end,
  rest,
  rolling,
  stagnation,
  chatter,
  law_pole,
  non_finite,
  law_error,
  integrator_failure,
  max_steps,
  interrupted,
  output_error,
  output_limit
};

/// "t_end", "rest", "rolling", "stagnation", "chatter", "law-pole", "non-finite", "law-error", "integrator-failure",
/// "max-steps", "interrupted", "output-error", "output-limit".
[[nodiscard]] std::string_view to_string(Termination t);

struct RunSummary {
  Termination reason = Termination::t_end;
  std::string message;          ///< why, in one line (empty for t_end)
  std::string rule;             ///< the rule that ended the run, in words (empty if none applies)
  std::vector<Threshold> thresholds;  ///< the thresholds of that rule, as applied
  double t_final = 0.0;         ///< s
  StateVector x_final;          ///< the last good state
  long steps = 0;               ///< accepted steps
  long rejected_steps = 0;      ///< steps GSL retried with a smaller size
  long rhs_calls = 0;           ///< evaluations of the right-hand side by the integrator
  long samples = 0;             ///< samples the observer took
  long sample_rhs_calls = 0;    ///< evaluations of the right-hand side for samples inside steps
  long hermite_samples = 0;     ///< samples that fell back on cubic Hermite (dynamics/step_sampler.h)
  double wall_time = 0.0;       ///< s
  long liftoffs = 0;            ///< contact -> no contact transitions (between steps)
  long landings = 0;            ///< no contact -> contact
  double min_normal_force = 0.0;  ///< min N over accepted steps, N
  double initial_energy = 0.0;  ///< J
  double final_energy = 0.0;    ///< J
  double max_gamma_drift = 0.0; ///< max | |gamma| - 1 | over accepted steps
  BodyScales scales;            ///< the body's scales (thresholds and tolerances)
  RestRule rest;                ///< the rest thresholds as applied
  SettleRule settle;            ///< the settling thresholds as applied
  ChatterRule chatter;          ///< the chatter thresholds as applied
  StateVector abs_tol;          ///< the absolute tolerance of each component (abs_tol * scale)
};

/// Integrates from x0 at t = 0. `observer` may be null. Throws std::invalid_argument for invalid
/// options or a non-finite x0; every later failure ends the run with a reason instead.
/// Switches GSL's abort-on-error handler off (process-wide): errors are return codes here.
[[nodiscard]] RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options,
                                  Observer* observer = nullptr);

}  // namespace frictionlab::dynamics
