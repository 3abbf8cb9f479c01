#include "dynamics/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "dynamics/ode_stepping.h"
#include "dynamics/pole_watch.h"
#include "dynamics/run_stops.h"
#include "dynamics/step_sampler.h"
#include "dynamics/tolerance_scales.h"
#include "friction/gsl_error_policy.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

using support::invalid_value;
using support::message_number;

// Why the last evaluation of the right-hand side failed.
enum class RhsFailure { none, pole, nonfinite, law_error };

// The friction at a state, in one line (for failure messages only).
std::string describe_friction(const BodyOnPlane& sys, const StateVector& x) {
  try {
    const ContactState c = sys.contact_state(x);
    return "friction law '" + std::string(sys.law().name()) + "' gives F1 = " + message_number(c.friction.F1) +
           " N, F2 = " + message_number(c.friction.F2) + " N, M = " + message_number(c.friction.M) +
           " N m at U = " + message_number(c.U) + " m/s, Omega = " + message_number(c.Omega) +
           " 1/s, a = " + message_number(c.a) + " m, b = " + message_number(c.b) +
           " m, psi = " + message_number(c.psi.radians()) + ", N = " + message_number(c.N) + " N";
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string describe_nonfinite(const BodyOnPlane& sys, double t, const StateVector& x) {
  const std::string m = "the right-hand side is not finite at t = " + message_number(t) + " s";
  if (!x.allFinite()) return m + " (the trial state is not finite)";
  return m + ": " + describe_friction(sys, x);
}

// The right-hand side as the stepping core calls it, for accepted steps and their trial stages
// alike; counts calls and records why an evaluation failed. A state on the far side of a pole of
// the law (dynamics/pole_watch.h) is refused like a non-finite one: GSL then halves the step, so
// no accepted step and no stage of it crosses the pole.
class BodyRhs final : public OdeRhs {
 public:
  BodyRhs(const BodyOnPlane& sys, const PoleWatch* poles) : sys_(sys), poles_(poles) {}

  RhsStatus operator()(double t, const double* y, double* f) override {
    ++rhs_calls;
    has_last_ = false;
    StateVector& x = last_x_;
    x = Eigen::Map<const StateVector>(y);
    if (!x.allFinite()) {
      last = RhsFailure::nonfinite;
      message = describe_nonfinite(sys_, t, x);
      return RhsStatus::retry;
    }
    StateVector d;
    try {
      ContactState& c = last_contact_;
      sys_.contact_state(x, c);
      if (poles_) {
        const int crossed = poles_->crossing(c);
        if (crossed >= 0) {
          last = RhsFailure::pole;
          pole_output = crossed;
          return RhsStatus::retry;
        }
      }
      sys_.derivatives(x, c, d);
    } catch (const std::exception& e) {
      // A trial stage of a step that reaches far past a landing sinks the body deep into the plane,
      // and its next stages grow without bound: to a state that is still finite (~1e165) but whose
      // slip or normal force overflows, which the law's input check refuses (friction/law.h
      // validate). Such a state is non-finite in effect, and refused like one: GSL halves the step.
      // Its kinetic energy has overflowed too (the slip is at most |v| + |omega| R). A refusal at a
      // state of finite energy is the law's own: the run stops at once.
      if (!std::isfinite(sys_.kinetic_energy(x))) {
        last = RhsFailure::nonfinite;
        message = std::string("the law refuses the trial state at t = ") + message_number(t) +
                  " s, whose kinetic energy overflows: " + e.what();
        return RhsStatus::retry;
      }
      last = RhsFailure::law_error;
      message = std::string("at t = ") + message_number(t) + " s: " + e.what();
      return RhsStatus::stop;
    }
    if (!d.allFinite()) {
      last = RhsFailure::nonfinite;
      message = describe_nonfinite(sys_, t, x);
      return RhsStatus::retry;
    }
    last = RhsFailure::none;
    Eigen::Map<StateVector> out(f);
    out = d;
    has_last_ = true;
    return RhsStatus::ok;
  }

  // The contact state of the latest successful evaluation if it was at exactly `x` (bit for bit),
  // else null. The one-step methods evaluate x' at the end of every accepted step last (it is the
  // next step's first stage, FreeStepper::derivative_at_end): the events between steps reuse that
  // evaluation instead of computing the same contact state again (one law evaluation a step).
  [[nodiscard]] const ContactState* contact_at(const StateVector& x) const {
    if (!has_last_ || std::memcmp(last_x_.data(), x.data(), sizeof(double) * StateLayout::kSize) != 0) return nullptr;
    return &last_contact_;
  }

  long rhs_calls = 0;
  RhsFailure last = RhsFailure::none;  // the outcome of the latest evaluation
  int pole_output = -1;                // which denominator (PoleWatch::output_name) on a refusal
  std::string message;                 // what went wrong, for the summary

 private:
  const BodyOnPlane& sys_;
  const PoleWatch* poles_;  // null when the law has none
  bool has_last_ = false;   // the latest evaluation succeeded: last_x_, last_contact_ are its
  StateVector last_x_;      // the state of the latest evaluation
  ContactState last_contact_;
};

}  // namespace

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
  }
  return "unknown";
}

RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options, Observer* observer) {
  options.validate();
  if (!x0.allFinite()) throw std::invalid_argument("the initial state is not finite");
  use_gsl_status_codes();

  const auto wall_start = std::chrono::steady_clock::now();
  const IntegratorOptions& io = options.integrator;

  RunSummary s;
  s.scales = body_scales(sys.body(), sys.plane());
  s.rest = resolve_rest(options.rest, s.scales);
  s.settle = resolve_settling(options.settle, s.scales);
  s.chatter = resolve_chatter(options.chatter, s.rest, s.scales);
  const StateVector abs_scale = absolute_tolerance_scales(s.scales);
  s.abs_tol = io.abs_tol * abs_scale;

  PoleWatch poles(sys.law(), sys.plane().k);
  BodyRhs ctx(sys, poles.active() ? &poles : nullptr);
  FreeStepper stepper(ctx, StateLayout::kSize, io, abs_scale.data());
  StepSampler sampler(io.method, sys, observer ? observer->sample_accuracy() : SampleAccuracy::method_step);

  StateVector x = x0;
  double t = 0.0;
  double h = io.initial_step;
  const double max_step = io.max_step > 0.0 ? io.max_step : std::numeric_limits<double>::infinity();

  const auto stop = [&](Termination why, std::string message) {
    s.reason = why;
    s.message = std::move(message);
    s.rule.clear();
    s.thresholds.clear();
  };
  // Reports a sample; false (and the run stops) if the observer's output failed.
  double last_sample_t = -1.0;
  const auto emit = [&](double time, const StateVector& state) {
    if (!observer) return true;
    try {
      const ContactState c = sys.contact_state(state);
      observer->sample(Sample{time, state, c, sys.energy(state, c), sys.kinetic_energy(state)});
    } catch (const OutputFailure& e) {
      stop(Termination::output_error, "the output failed at t = " + message_number(time) + " s: " + e.what());
      return false;
    } catch (const OutputLimitReached& e) {
      stop(Termination::output_limit,
           "the output reached its limit at t = " + message_number(time) + " s: " + e.what());
      return false;
    }
    ++s.samples;
    last_sample_t = time;
    return true;
  };

  const ContactState c0 = sys.contact_state(x);  // throws here (not mid-run) if the law rejects x0
  s.initial_energy = sys.energy(x, c0);
  s.min_normal_force = c0.N;
  s.max_gamma_drift = std::abs(vertical(x).norm() - 1.0);
  bool in_contact = c0.in_contact;
  poles.set_reference(c0);
  ContactSettling settling(s.settle);
  ChatterWatch chatter(s.chatter);
  settling.update(t, c0.in_contact, c0.u.dot(c0.gamma));

  // The step being sampled: its start is the previous step's end.
  AcceptedStep step;
  step.t1 = t;
  step.x1 = x;
  step.f1.setZero();
  try {
    sys(t, x, step.f1);
  } catch (const std::exception&) {
    // The first integrator step reports it (law-error).
  }

  bool output_ok = emit(t, x);
  long next_sample = 1;
  long stagnant_unsettled = 0;  // accepted steps in a row in the stagnation region, not settled

  while (output_ok) {
    if (stop_at_t_end(t, options.t_end, s, stop)) break;
    step.t0 = step.t1;
    step.x0 = step.x1;
    step.f0 = step.f1;
    h = std::min(h, max_step);
    ctx.last = RhsFailure::none;
    const StepOutcome outcome = stepper.advance(t, options.t_end, h, x.data());
    if (outcome.kind == StepOutcome::accepted) {
      ++s.steps;
      if (!x.allFinite()) {
        x = step.x0;
        t = step.t0;
        stop(Termination::non_finite, non_finite_step_message(t));
        break;
      }
      step.t1 = t;
      step.x1 = x;
      step.f1 = Eigen::Map<const StateVector>(stepper.derivative_at_end());

      // Samples on the output grid inside (t0, t1], from the step (never by cutting it); none
      // computed without an observer.
      while (observer) {
        const double ts = static_cast<double>(next_sample) * options.output_dt;
        if (ts > t) break;
        if (!(output_ok = emit(ts, sampler.at(step, ts)))) break;
        ++next_sample;
      }
      if (!output_ok) break;
      if (observer) observer->step(t);

      // Events between steps, from the contact state of the step's last evaluation when it was at x.
      const ContactState* cached = ctx.contact_at(x);
      ContactState computed;
      if (!cached) computed = sys.contact_state(x);
      const ContactState& c = cached ? *cached : computed;
      if (c.in_contact != in_contact) (c.in_contact ? s.landings : s.liftoffs) += 1;
      in_contact = c.in_contact;
      s.min_normal_force = std::min(s.min_normal_force, c.N);
      s.max_gamma_drift = std::max(s.max_gamma_drift, std::abs(vertical(x).norm() - 1.0));
      poles.set_reference(c);
      settling.update(t, c.in_contact, c.u.dot(c.gamma));
      const bool settled = settling.settled(t);
      const double kinetic = sys.kinetic_energy(x);
      const auto stagnation_rule = [&](const char* energy_clause) {
        s.rule = std::string("settled contact (in contact with |eps'| < run.settle_normal_speed at every step of the "
                             "last run.settle_time), U < run.rest_slip_speed, |Omega| < run.rest_spin, kinetic "
                             "energy ") +
                 energy_clause;
        s.thresholds = {s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin, s.rest.kinetic_energy};
      };
      if (settled && s.rest.at_rest(c.in_contact, c.U, c.Omega, kinetic)) {
        stop(Termination::rest, "settled since t = " + message_number(settling.since()) +
                                    " s; U = " + message_number(c.U) + " m/s, |Omega| = " +
                                    message_number(std::abs(c.Omega)) + " 1/s and kinetic energy " +
                                    message_number(kinetic) + " J are below the rest thresholds");
        stagnation_rule("< run.rest_kinetic_energy");
        break;
      }
      if (settled && options.stop_when_rolling && s.rest.contact_stagnant(c.in_contact, c.U, c.Omega)) {
        stop(Termination::rolling, "the contact, settled since t = " + message_number(settling.since()) +
                                       " s, neither slips (U = " + message_number(c.U) +
                                       " m/s) nor spins (Omega = " + message_number(c.Omega) +
                                       " 1/s) but the kinetic energy " + message_number(kinetic) +
                                       " J is above run.rest_kinetic_energy = " +
                                       message_number(s.rest.kinetic_energy.value) +
                                       " J: the body rolls without slip");
        stagnation_rule(">= run.rest_kinetic_energy");
        break;
      }
      stagnant_unsettled =
          !settled && s.rest.contact_stagnant(c.in_contact, c.U, c.Omega) ? stagnant_unsettled + 1 : 0;
      if (options.max_stagnant_steps > 0 && stagnant_unsettled >= options.max_stagnant_steps) {
        stop(Termination::stagnation,
             "the contact has stayed in the stagnation region (U = " + message_number(c.U) + " m/s, |Omega| = " +
                 message_number(std::abs(c.Omega)) + " 1/s) for " + std::to_string(stagnant_unsettled) +
                 " steps while its normal motion has not settled (unsettled at t = " +
                 message_number(settling.since()) +
                 " s; now |eps'| = " + message_number(std::abs(c.u.dot(c.gamma))) +
                 " m/s): a bounce reached the laws' singular set U = Omega = 0, where the integrator only "
                 "chatters and the model has no sticking branch");
        s.rule = "in contact, not settled, U < run.rest_slip_speed and |Omega| < run.rest_spin for "
                 "run.max_stagnant_steps accepted steps in a row";
        s.thresholds = {given_threshold("run.max_stagnant_steps", static_cast<double>(options.max_stagnant_steps), "steps"),
                        s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin};
        break;
      }
      const ChatterChannel chattered = chatter.update({step.t0, t, c.in_contact, c.U * c.e1, c.Omega});
      if (chattered != ChatterChannel::none) {
        stop(Termination::chatter, chatter_message(chatter.episode(chattered), s.chatter, sys.law().name()));
        s.rule = chatter_rule_text(chattered);
        s.thresholds = {s.chatter.max_steps, s.chatter.step, s.chatter.slip_speed, s.chatter.spin};
        break;
      }
      if (stop_at_step_limits(s.steps, io.max_steps, options.cancel, s, stop)) break;
      continue;
    }

    // Failure: GSL already retried with ever smaller steps down to machine precision.
    x = step.x0;
    t = step.t0;
    if (outcome.kind == StepOutcome::stopped_by_rhs) {
      stop(Termination::law_error, ctx.message);
    } else if (ctx.last == RhsFailure::pole) {
      stop(Termination::law_pole, law_pole_message(PoleWatch::output_name(ctx.pole_output), sys.law().name(),
                                                   std::abs(h), t, describe_friction(sys, x)));
      s.rule = kLawPoleRule;
    } else if (ctx.last == RhsFailure::nonfinite) {
      stop(Termination::non_finite, non_finite_message(ctx.message));
    } else {
      stop(Termination::integrator_failure, integrator_failure_message(outcome.gsl_message, t, describe_friction(sys, x)));
    }
    break;
  }

  if (output_ok && last_sample_t != t) (void)emit(t, x);
  s.t_final = t;
  s.x_final = x;
  s.rhs_calls = ctx.rhs_calls;
  s.sample_rhs_calls = sampler.rhs_calls();
  s.hermite_samples = sampler.hermite_fallbacks();
  s.rejected_steps = stepper.failed_steps();
  s.final_energy = sys.energy(x);
  s.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return s;
}

}  // namespace frictionlab::dynamics
