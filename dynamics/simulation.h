#pragma once
// One run: integrates the equations of motion (dynamics/equations_of_motion.h) with GSL odeiv2
// from t = 0 to an event, reporting samples to an observer, and returns a summary.
//
// Events, checked between accepted steps (docs/dynamics.md §5):
//   t_end       the end time was reached;
//   rest        the stagnation region (dynamics/rest_event.h);
//   rolling     the contact stopped slipping and spinning while the body still moves (a sliding
//               sphere starts to roll; an egg rocks on its pole): see dynamics/rest_event.h;
//   non-finite  the state or the right-hand side stopped being finite (e.g. a friction law's
//               pole) and GSL's retries with smaller steps, down to machine precision, did not help;
//   law-error   the friction law rejected its input (message attached);
//   integrator-failure  GSL gave up (message attached);
//   max-steps   run.max_steps accepted steps were taken;
//   interrupted the caller's cancel flag was raised (Ctrl-C on the command line).
// On every stop the last good state is kept, sampled, and returned.

#include <atomic>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/equations_of_motion.h"
#include "dynamics/observer.h"
#include "dynamics/rest_event.h"
#include "dynamics/state.h"

namespace frictionlab::dynamics {

struct IntegratorOptions {
  /// GSL odeiv2 stepper: rk8pd (default, embedded Runge-Kutta Prince-Dormand 8(9)), rkck, rkf45,
  /// rk4, rk2, msadams. Implicit steppers need a Jacobian and are not offered.
  std::string method = "rk8pd";
  double abs_tol = 1e-9;       ///< absolute local error per component (SI units of the component)
  double rel_tol = 1e-9;       ///< relative local error per component
  double initial_step = 1e-5;  ///< s, > 0
  double max_step = 0.0;       ///< s; 0 = no limit beyond the output interval
  long max_steps = 10'000'000;  ///< accepted steps before the run stops with reason max-steps

  void validate() const;  ///< std::invalid_argument naming the run.* key
};

/// The stepper names accepted by IntegratorOptions::method.
[[nodiscard]] std::vector<std::string> integrator_methods();

struct RunOptions {
  double t_end = 1.0;       ///< s, > 0
  double output_dt = 1e-3;  ///< s, > 0: the sample interval
  IntegratorOptions integrator;
  RestThresholds rest;
  bool stop_when_rolling = true;  ///< stop with reason "rolling" (dynamics/rest_event.h)
  const std::atomic<bool>* cancel = nullptr;  ///< checked between steps; may be null

  void validate() const;  ///< std::invalid_argument naming the run.* key
};

enum class Termination { t_end, rest, rolling, non_finite, law_error, integrator_failure, max_steps, interrupted };

/// "t_end", "rest", "rolling", "non-finite", "law-error", "integrator-failure", "max-steps",
/// "interrupted".
[[nodiscard]] std::string_view to_string(Termination t);

struct RunSummary {
  Termination reason = Termination::t_end;
  std::string message;          ///< why, in one line (empty for t_end)
  double t_final = 0.0;         ///< s
  StateVector x_final;          ///< the last good state
  long steps = 0;               ///< accepted steps
  long rejected_steps = 0;      ///< steps GSL retried with a smaller size
  long rhs_calls = 0;           ///< evaluations of the right-hand side
  double wall_time = 0.0;       ///< s
  long liftoffs = 0;            ///< contact -> no contact transitions (between steps)
  long landings = 0;            ///< no contact -> contact
  double min_normal_force = 0.0;  ///< min N over accepted steps, N
  double initial_energy = 0.0;  ///< J
  double final_energy = 0.0;    ///< J
  double max_gamma_drift = 0.0; ///< max | |gamma| - 1 | over accepted steps
};

/// Integrates from x0 at t = 0. `observer` may be null. Throws std::invalid_argument for invalid
/// options or a non-finite x0; every later failure ends the run with a reason instead.
/// Switches GSL's abort-on-error handler off (process-wide): errors are return codes here.
[[nodiscard]] RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options,
                                  Observer* observer = nullptr);

}  // namespace frictionlab::dynamics
