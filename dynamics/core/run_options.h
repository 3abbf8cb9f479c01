#pragma once
// What every run of every model is given ([run] of a scenario: docs/dynamics.md §7) and why it
// ended (docs/dynamics.md §5). The integration loop is dynamics/run_loop.h.

#include <atomic>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/core/chatter_watch.h"
#include "dynamics/core/integrator_options.h"
#include "dynamics/core/output_limit.h"
#include "dynamics/core/rest_event.h"
#include "dynamics/core/settling.h"

namespace frictionlab::dynamics {

/// Default run.max_samples: 1e7 samples, ten times what the paper's scenario files once planned
/// (t_end = 1000 s at output_dt = 1e-3 s). It bounds the samples a run may plan whatever keeps
/// them (in memory too); the size of the trajectory file has its own, tighter limit
/// (max_output_bytes, dynamics/core/output_limit.h).
inline constexpr long kDefaultMaxSamples = 10'000'000;

struct RunOptions {
  double t_end = 1.0;       ///< s, > 0
  double output_dt = 1e-3;  ///< s, > 0: the sample interval; t_end/output_dt <= max_samples
  long max_samples = kDefaultMaxSamples;  ///< > 0: the most samples a run may plan
  /// > 0, bytes: the largest trajectory file a run may write (dynamics/core/output_limit.h); enforced
  /// by the writers (dynamics/body/trajectory_csv.h), not by the run loop.
  long max_output_bytes = kDefaultMaxOutputBytes;
  IntegratorOptions integrator;
  RestThresholds rest;
  SettleThresholds settle;
  bool stop_when_rolling = true;  ///< stop with reason "rolling" (dynamics/core/rest_event.h)
  /// run.stick: a contact that stops slipping and spinning (in settled contact, with more kinetic
  /// energy than rest) enters the body's stick mode and rolls without slip and spin for as long as
  /// the law's limit set holds the wrench that needs (docs/dynamics.md §5 "stick"); false: the run
  /// stops there with reason "rolling" as before stick existed (or chatters on, with
  /// stop_when_rolling = false).
  bool stick = true;
  /// run.slip_hold: where the contact rolls with a small slip while it spins and the slip's own
  /// dynamics is stiff, the slip is held on its slow manifold; under a law discontinuous at zero
  /// slip (or spin), a stopped slip (or spin) is held at zero while the law's limit allows it
  /// (docs/dynamics.md §5 "slip hold", dynamics/body/slip_hold.h); false: the integrator follows
  /// the stiff slip, and a discontinuous law chatters.
  bool slip_hold = true;
  /// run.pose: the body's pose (its position on the plane and its orientation, dynamics/body/state.h)
  /// integrated beside the state; false: not integrated (the pose columns of trajectory.csv and
  /// the final pose of summary.json are left out), which saves the body 3-8 % of a run's time
  /// (docs/benchmarks.md). The pose is never fed back: the rest of the state, its
  /// steps and its events are the same to the last bit either way. A body's key only: the puck's
  /// position and heading are its state.
  bool pose = true;
  /// run.stick_hold_time, s, > 0: a run in stick ends "rolling" (stop_when_rolling) once stick has
  /// held that long; unset: the default of dynamics/core/stick_rule.h (scaled to the body).
  std::optional<double> stick_hold_time;
  /// >= 0 (0: never): accepted steps in a row in the stagnation region, in contact but not settled,
  /// before the run stops with reason "stagnation". A bounce that merely passes through the region
  /// (a vertical drop without slip or spin stays in it during every impact, where the friction is
  /// 0) takes a few tens of steps per impact; the chatter of a discontinuous law at U = Omega = 0
  /// takes ~1e6 steps per millisecond (steps of ~tolerance/(k g) s).
  long max_stagnant_steps = 1000;
  /// run.max_chatter_steps, run.chatter_step: when the chatter of a discontinuous law stops the
  /// run (dynamics/core/chatter_watch.h).
  ChatterThresholds chatter;
  /// run.shadow: friction-law specs evaluated along the run beside its own law, without changing it
  /// (dynamics/core/shadow_laws.h; the scenario readers check each spec against the registry).
  std::vector<std::string> shadow;
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
  output_limit,
  flat_face
};

/// "t_end", "rest", "rolling", "stagnation", "chatter", "law-pole", "non-finite", "law-error", "integrator-failure",
/// "max-steps", "interrupted", "output-error", "output-limit", "flat-face".
[[nodiscard]] std::string_view to_string(Termination t);

}  // namespace frictionlab::dynamics
