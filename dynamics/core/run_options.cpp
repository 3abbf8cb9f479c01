#include "dynamics/core/run_options.h"

#include <cmath>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

using support::invalid_value;
using support::message_number;

void RunOptions::validate() const {
  if (!(std::isfinite(t_end) && t_end > 0.0)) throw invalid_value("run.t_end", t_end, "it must be finite and > 0 s");
  if (!(std::isfinite(output_dt) && output_dt > 0.0))
    throw invalid_value("run.output_dt", output_dt, "it must be finite and > 0 s");
  if (max_samples <= 0) throw invalid_value("run.max_samples", static_cast<long long>(max_samples), "it must be > 0");
  if (max_output_bytes <= 0)
    throw invalid_value("run.max_output_bytes", static_cast<long long>(max_output_bytes), "it must be > 0 bytes");
  if (t_end / output_dt > static_cast<double>(max_samples))
    throw invalid_value("run.output_dt", output_dt,
                        "run.t_end/run.output_dt = " + message_number(t_end / output_dt) +
                            " samples exceeds run.max_samples = " + std::to_string(max_samples) +
                            " (raise run.output_dt, or run.max_samples if you mean it)");
  integrator.validate();
  if (integrator.max_step > 0.0 && integrator.max_step * static_cast<double>(integrator.max_steps) < t_end)
    throw invalid_value("run.max_step", integrator.max_step,
                        "run.max_steps = " + std::to_string(integrator.max_steps) +
                            " steps of at most run.max_step reach only t = " +
                            message_number(integrator.max_step * static_cast<double>(integrator.max_steps)) +
                            " s < run.t_end = " + message_number(t_end) + " s");
  if (max_stagnant_steps < 0)
    throw invalid_value("run.max_stagnant_steps", static_cast<long long>(max_stagnant_steps), "it must be >= 0 (0: never)");
  if (stick_hold_time && !(std::isfinite(*stick_hold_time) && *stick_hold_time > 0.0))
    throw invalid_value("run.stick_hold_time", *stick_hold_time, "it must be finite and > 0 s");
  chatter.validate();
  rest.validate();
  settle.validate();
}

std::string_view to_string(Termination t) {
  switch (t) {
    case Termination::t_end: return "t_end";
    case Termination::rest: return "rest";
    case Termination::rolling: return "rolling";
    case Termination::stagnation: return "stagnation";
    case Termination::chatter: return "chatter";
    case Termination::law_pole: return "law-pole";
    case Termination::non_finite: return "non-finite";
    case Termination::law_error: return "law-error";
    case Termination::integrator_failure: return "integrator-failure";
    case Termination::max_steps: return "max-steps";
    case Termination::interrupted: return "interrupted";
    case Termination::output_error: return "output-error";
    case Termination::output_limit: return "output-limit";
    case Termination::flat_face: return "flat-face";
  }
  return "unknown";
}

}  // namespace frictionlab::dynamics
