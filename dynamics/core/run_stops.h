#pragma once
// The ends of a run that the one run loop (dynamics/core/run_loop.h) gives every model: the limits
// checked after every accepted step (run.max_steps, a cancelled job), and the messages of a step
// that failed for good (a pole of the law, a non-finite state, the integrator). One wording, one
// rule text, in every model's summary.json.

#include <atomic>
#include <string>
#include <string_view>

#include "dynamics/core/run_options.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics {

/// The rule a run stopped at a pole of its law records.
inline constexpr const char* kLawPoleRule =
    "a denominator of the friction law's outputs passes through 0 (friction/law.h pole_denominators)";

/// Before a step: stops the run with reason t_end (and its rule and threshold) once `t` reached
/// `t_end`; returns whether it did.
template <class Summary, class Stop>
bool stop_at_t_end(double t, double t_end, Summary& summary, Stop&& stop) {
  if (t < t_end) return false;
  stop(Termination::t_end, "");
  summary.rule = "t = run.t_end";
  summary.thresholds = {given_threshold("run.t_end", t_end, "s")};
  return true;
}

/// After an accepted step: stops the run (`stop(Termination, message)`, and the rule and
/// thresholds into `summary`) when `steps` reached `max_steps`, or when `cancel` is set; returns
/// whether it did. `Summary` has `rule` and `thresholds` (RunSummary, PuckRunSummary).
template <class Summary, class Stop>
bool stop_at_step_limits(long steps, long max_steps, const std::atomic<bool>* cancel, Summary& summary, Stop&& stop) {
  if (steps >= max_steps) {
    stop(Termination::max_steps, "run.max_steps = " + std::to_string(max_steps) + " steps reached");
    summary.rule = "accepted steps = run.max_steps";
    summary.thresholds = {given_threshold("run.max_steps", static_cast<double>(max_steps), "steps")};
    return true;
  }
  if (cancel && cancel->load(std::memory_order_relaxed)) {
    stop(Termination::interrupted, "interrupted");
    return true;
  }
  return false;
}

/// A denominator (`output`: "F1", "F2", "M") of `law` passes through 0 within `h` s after `t`;
/// `state` describes the friction at the last good state.
[[nodiscard]] std::string law_pole_message(std::string_view output, std::string_view law, double h, double t,
                                           const std::string& state);

/// An accepted step from `t` ended on a non-finite state.
[[nodiscard]] std::string non_finite_step_message(double t);

/// No step size down to machine precision avoids a non-finite state; `rhs_message` says where.
[[nodiscard]] std::string non_finite_message(const std::string& rhs_message);

/// GSL found no step above machine precision that meets the tolerance at `t`.
[[nodiscard]] std::string integrator_failure_message(const std::string& gsl_message, double t, const std::string& state);

}  // namespace frictionlab::dynamics
