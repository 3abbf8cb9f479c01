#pragma once
// The one integration loop of frictionlab: every model (the body on the plane, the puck, ...) runs
// on it. The loop owns what is the same for every model — free steps under scaled error control
// (dynamics/core/ode_stepping.h), samples inside accepted steps (dynamics/core/step_sampler.h), the watch of
// the law's poles (dynamics/core/pole_watch.h), refusal of non-finite trial states, law errors,
// integrator failures, the limits (run.t_end, run.max_steps, interrupts) and failing outputs
// (dynamics/core/observer.h) — and the model brings what is its own: its state and right-hand side,
// its contact quantities, its discrete mode (held components, stick), its events between and
// inside steps, and its summary fields (docs/dynamics.md §4–§5 describe them for the body).
//
// A model M provides (a compile-time interface; see dynamics/body/equations_of_motion.h and
// dynamics/puck/puck_equations.h for the two models):
//
//   M::State, M::kSize                       fixed-size Eigen vector of the state
//
// and may provide a pose that rides along (run.pose, docs/dynamics.md §7):
//
//   M::kPoseFreeSize                         the state's leading components that never read the
//                                            rest (the pose); with run.pose = false the stepper
//                                            integrates only those and the rest keeps x0's values
//   void derivatives_without_pose(const State&, const Contact&, const Mode&, State&) const
//                                            derivatives' leading kPoseFreeSize components, the
//                                            same to the last bit (the others are not read)
//   M::Contact                               the contact quantities at a state
//   M::Mode                                  the discrete mode the right-hand side depends on
//   void contact(const State&, const Mode&, Contact&) const      throws what the law throws
//   void derivatives(const State&, const Contact&, const Mode&, State&) const
//   double energy(const State&, const Contact&) const            total mechanical energy, J
//   double energy(const State&, const Mode&) const               the same from the state alone
//   double kinetic_energy(const State&) const                    J
//   PoleWatch::Point pole_point(const Contact&) const            for dynamics/core/pole_watch.h
//   std::string describe_friction(const State&, const Mode&) const   one line, for messages
//   const friction::FrictionLaw& law() const;  double friction_coefficient() const;
//
// and a per-run monitor M::Monitor, constructed as Monitor(model, options, summary), with
//
//   State tolerance_scales() const             per-component scales of the absolute tolerance
//   After start(double t, State& x, const Contact& c0, Mode& mode, Stop&& stop)
//                                              after the first sample: go on, jumped (x or the
//                                              mode changed) or stopped
//   bool before_step(double t, const State& x, const Mode& mode, Stop&& stop)   true: stopped
//   bool locate(Step& step, Sampler& sampler, double& t, State& x, Mode& mode)
//                                              an event inside the accepted step: cut the step
//                                              there (step.t1, step.x1, t, x); true if cut
//   After after_step(double t, State& x, const Contact& c, Mode& mode, Step& step, Sampler& sampler,
//                    Stop&& stop)
//                                              events between steps: continue, jumped (x or the
//                                              mode changed: the steps start afresh), or stopped
//   void finish(const State& x, const Mode& mode)
//
// where Stop is `stop(Termination, std::string message)`; rule and thresholds go into the summary.
// M::Summary derives from RunSummaryOf<State> (dynamics/core/run_summary.h).

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dynamics/core/all_finite.h"
#include "dynamics/core/observer.h"
#include "dynamics/core/ode_stepping.h"
#include "dynamics/core/pole_watch.h"
#include "dynamics/core/run_stops.h"
#include "dynamics/core/run_summary.h"
#include "dynamics/core/step_sampler.h"
#include "friction/gsl_error_policy.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

/// What a monitor's after_step decided.
enum class After { go_on, jumped, stopped };

/// The number of components the stepper integrates for `model` under run.pose (`pose`): all of
/// them, or the leading ones that do not depend on the pose (M::kPoseFreeSize) when the model has
/// a pose and it is off.
template <class Model>
constexpr int integrated_size(bool pose) {
  if constexpr (requires { Model::kPoseFreeSize; }) {
    return pose ? Model::kSize : Model::kPoseFreeSize;
  } else {
    return Model::kSize;
  }
}

namespace run_loop_detail {

// Why the last evaluation of the right-hand side failed.
enum class RhsFailure { none, pole, nonfinite, law_error };

// The right-hand side as the stepping core calls it, for accepted steps and their trial stages
// alike; counts calls and records why an evaluation failed. A state on the far side of a pole of
// the law (dynamics/core/pole_watch.h) is refused like a non-finite one: GSL then halves the step, so
// no accepted step and no stage of it crosses the pole.
template <class Model>
class ModelRhs final : public OdeRhs {
 public:
  using State = typename Model::State;
  using Contact = typename Model::Contact;
  using Mode = typename Model::Mode;

  // `x0`: the run's initial state, whose pose the evaluations keep when the pose is not integrated.
  ModelRhs(const Model& model, const PoleWatch* poles, const Mode& mode, const State& x0, bool pose)
      : model_(model), poles_(poles), mode_(mode), last_x_(x0), size_(integrated_size<Model>(pose)) {}

  // The stepper's state holds size() components: all (the pose integrated) or the leading ones.
  RhsStatus operator()(double t, const double* y, double* f) override {
    if (size_ == Model::kSize) return evaluate<Model::kSize>(t, y, f);
    return evaluate<integrated_size<Model>(false)>(t, y, f);
  }

  [[nodiscard]] int size() const { return size_; }

  // The contact of the latest successful evaluation if it was at exactly `x` (bit for bit, in the
  // integrated components), else null. The one-step methods evaluate x' at the end of every
  // accepted step last (it is the next step's first stage, FreeStepper::derivative_at_end): the
  // events between steps reuse that evaluation instead of computing the same contact again (one
  // law evaluation a step).
  [[nodiscard]] const Contact* contact_at(const State& x) const {
    if (!has_last_ || std::memcmp(last_x_.data(), x.data(), sizeof(double) * static_cast<std::size_t>(size_)) != 0) {
      return nullptr;
    }
    return &last_contact_;
  }

  long rhs_calls = 0;
  RhsFailure last = RhsFailure::none;  // the outcome of the latest evaluation
  int pole_output = -1;                // which denominator (PoleWatch::output_name) on a refusal
  std::string message;                 // what went wrong, for the summary

 private:
  // One evaluation at a stepper state of N components (N fixed: the copies stay unrolled).
  template <int N>
  RhsStatus evaluate(double t, const double* y, double* f) {
    using Part = Eigen::Matrix<double, N, 1>;
    ++rhs_calls;
    has_last_ = false;
    State& x = last_x_;
    x.template head<N>() = Eigen::Map<const Part>(y);
    if (!all_finite(x.template head<N>())) return fail_nonfinite(t, x);
    State d;
    try {
      Contact& c = last_contact_;
      model_.contact(x, mode_, c);
      if (poles_) {
        const int crossed = poles_->crossing(model_.pole_point(c));
        if (crossed >= 0) {
          last = RhsFailure::pole;
          pole_output = crossed;
          return RhsStatus::retry;
        }
      }
      if constexpr (N == Model::kSize) {
        model_.derivatives(x, c, mode_, d);
      } else {
        model_.derivatives_without_pose(x, c, mode_, d);
      }
    } catch (const std::exception& e) {
      // A trial stage of a step that reaches far past a landing sinks the body deep into the plane,
      // and its next stages grow without bound: to a state that is still finite (~1e165) but whose
      // slip or normal force overflows, which the law's input check refuses (friction/law.h
      // validate). Such a state is non-finite in effect, and refused like one: GSL halves the step.
      // Its kinetic energy has overflowed too (the slip is at most |v| + |omega| R). A refusal at a
      // state of finite energy is the law's own: the run stops at once.
      if (!std::isfinite(model_.kinetic_energy(x))) {
        last = RhsFailure::nonfinite;
        message = std::string("the law refuses the trial state at t = ") + support::message_number(t) +
                  " s, whose kinetic energy overflows: " + e.what();
        return RhsStatus::retry;
      }
      last = RhsFailure::law_error;
      message = std::string("at t = ") + support::message_number(t) + " s: " + e.what();
      return RhsStatus::stop;
    }
    const auto rate = d.template head<N>();
    if (!all_finite(rate)) return fail_nonfinite(t, x);
    last = RhsFailure::none;
    Eigen::Map<Part> out(f);
    out = rate;
    has_last_ = true;
    return RhsStatus::ok;
  }

  RhsStatus fail_nonfinite(double t, const State& x) {
    last = RhsFailure::nonfinite;
    message = "the right-hand side is not finite at t = " + support::message_number(t) + " s" +
              (all_finite(x) ? ": " + model_.describe_friction(x, mode_) : std::string(" (the trial state is not finite)"));
    return RhsStatus::retry;
  }

  const Model& model_;
  const PoleWatch* poles_;  // null when the law has none
  const Mode& mode_;
  bool has_last_ = false;   // the latest evaluation succeeded: last_x_, last_contact_ are its
  State last_x_;            // outside the integrated components: x0's
  Contact last_contact_;
  int size_;                // the components the stepper integrates
};

}  // namespace run_loop_detail

/// Integrates `model` from x0 at t = 0 to an event (see the header comment), reporting samples to
/// `observer` (may be null). Throws std::invalid_argument for invalid options or a non-finite x0,
/// and what the law throws at x0; every later failure ends the run with a reason instead.
/// Switches GSL's abort-on-error handler off (process-wide): errors are return codes here.
template <class Model>
typename Model::Summary run_model(const Model& model, const typename Model::State& x0, const RunOptions& options,
                                  ObserverOf<Model>* observer = nullptr) {
  using State = typename Model::State;
  using Contact = typename Model::Contact;
  using Mode = typename Model::Mode;
  using Step = AcceptedStepOf<State>;
  using run_loop_detail::RhsFailure;

  options.validate();
  if (!all_finite(x0)) throw std::invalid_argument("the initial state is not finite");
  use_gsl_status_codes();
  const auto wall_start = std::chrono::steady_clock::now();
  const IntegratorOptions& io = options.integrator;

  typename Model::Summary s;
  typename Model::Monitor monitor(model, options, s);
  const State abs_scale = monitor.tolerance_scales();
  s.abs_tol = io.abs_tol * abs_scale;

  Mode mode{};
  PoleWatch poles(model.law(), model.friction_coefficient());
  run_loop_detail::ModelRhs<Model> rhs(model, poles.active() ? &poles : nullptr, mode, x0, options.pose);
  FreeStepper stepper(rhs, rhs.size(), io, abs_scale.data());
  StepSamplerOf<Model> sampler(io.method, model, mode,
                               observer ? observer->sample_accuracy() : SampleAccuracy::method_step);

  const auto stop = [&](Termination why, std::string message) {
    s.reason = why;
    s.message = std::move(message);
    s.rule.clear();
    s.thresholds.clear();
  };
  // Reports a sample; false (and the run stops) if the observer's output failed.
  double last_sample_t = -1.0;
  const auto emit = [&](double time, const State& state) {
    if (!observer) return true;
    try {
      Contact c;
      model.contact(state, mode, c);
      observer->sample(SampleOf<Model>{time, state, c, model.energy(state, c), model.kinetic_energy(state), mode});
    } catch (const OutputFailure& e) {
      stop(Termination::output_error,
           "the output failed at t = " + support::message_number(time) + " s: " + e.what());
      return false;
    } catch (const OutputLimitReached& e) {
      stop(Termination::output_limit,
           "the output reached its limit at t = " + support::message_number(time) + " s: " + e.what());
      return false;
    }
    ++s.samples;
    last_sample_t = time;
    return true;
  };
  // x' at a state (zero if the model cannot be evaluated there: the next step reports it), zero
  // outside the integrated components.
  const auto derivative_at = [&](const State& state) {
    State f = State::Zero();
    try {
      Contact c;
      model.contact(state, mode, c);
      model.derivatives(state, c, mode, f);
    } catch (const std::exception&) {
      // The first integrator step reports it (law-error).
    }
    f.tail(Model::kSize - rhs.size()).setZero();
    return f;
  };

  State x = x0;
  double t = 0.0;
  double h = io.initial_step;
  const double max_step = io.max_step > 0.0 ? io.max_step : std::numeric_limits<double>::infinity();

  Contact c0;
  model.contact(x, mode, c0);  // throws here (not mid-run) if the law rejects x0
  s.initial_energy = model.energy(x, c0);
  bool output_ok = emit(t, x);
  const After started = monitor.start(t, x, c0, mode, stop);
  if (poles.active()) {
    if (started == After::go_on) {
      poles.set_reference(model.pole_point(c0));
    } else {
      Contact c;
      model.contact(x, mode, c);
      poles.set_reference(model.pole_point(c));
    }
  }

  // The step being sampled: its start is the previous step's end.
  Step step;
  step.t1 = t;
  step.x1 = x;
  step.f1 = derivative_at(x);
  long next_sample = 1;
  const bool wants_steps = observer && observer->wants_accepted_steps();

  while (output_ok && started != After::stopped) {
    if (monitor.before_step(t, x, mode, stop)) break;
    if (stop_at_t_end(t, options.t_end, s, stop)) break;
    step.t0 = step.t1;
    step.x0 = step.x1;
    step.f0 = step.f1;
    h = std::min(h, max_step);
    rhs.last = RhsFailure::none;
    const StepOutcome outcome = stepper.advance(t, options.t_end, h, x.data());
    if (outcome.kind == StepOutcome::accepted) {
      ++s.steps;
      if (!all_finite(x)) {
        x = step.x0;
        t = step.t0;
        stop(Termination::non_finite, non_finite_step_message(t));
        break;
      }
      step.t1 = t;
      step.x1 = x;
      // Outside the integrated components (a pose not integrated) x keeps x0's values, rate 0.
      step.f1.head(rhs.size()) = Eigen::Map<const Eigen::VectorXd>(stepper.derivative_at_end(), rhs.size());
      // An event inside the step ends the step there.
      (void)monitor.locate(step, sampler, t, x, mode);

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

      // Events between steps, from the contact of the step's last evaluation when it was at x.
      const Contact* cached = rhs.contact_at(x);
      Contact computed;
      if (!cached) model.contact(x, mode, computed);
      if (wants_steps) {
        constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();
        observer->accepted(SampleOf<Model>{t, x, cached ? *cached : computed, kNotComputed, kNotComputed, mode});
      }
      const After after = monitor.after_step(t, x, cached ? *cached : computed, mode, step, sampler, stop);
      if (after == After::stopped) break;
      if (after == After::jumped) {
        // The state or the mode jumped: the steps start afresh from it.
        stepper.reset();
        step.x1 = x;
        step.f1 = derivative_at(x);
        if (poles.active()) {
          Contact c;
          model.contact(x, mode, c);
          poles.set_reference(model.pole_point(c));
        }
      } else if (poles.active()) {
        poles.set_reference(model.pole_point(cached ? *cached : computed));
      }
      if (stop_at_step_limits(s.steps, io.max_steps, options.cancel, s, stop)) break;
      continue;
    }

    // Failure: GSL already retried with ever smaller steps down to machine precision.
    x = step.x0;
    t = step.t0;
    if (outcome.kind == StepOutcome::stopped_by_rhs) {
      stop(Termination::law_error, rhs.message);
    } else if (rhs.last == RhsFailure::pole) {
      stop(Termination::law_pole, law_pole_message(PoleWatch::output_name(rhs.pole_output), model.law().name(),
                                                   std::abs(h), t, model.describe_friction(x, mode)));
      s.rule = kLawPoleRule;
    } else if (rhs.last == RhsFailure::nonfinite) {
      stop(Termination::non_finite, non_finite_message(rhs.message));
    } else {
      stop(Termination::integrator_failure,
           integrator_failure_message(outcome.gsl_message, t, model.describe_friction(x, mode)));
    }
    break;
  }

  if (output_ok && last_sample_t != t) (void)emit(t, x);
  monitor.finish(x, mode);
  s.t_final = t;
  s.x_final = x;
  s.rhs_calls = rhs.rhs_calls;
  s.sample_rhs_calls = sampler.rhs_calls();
  s.hermite_samples = sampler.hermite_fallbacks();
  s.rejected_steps = stepper.failed_steps();
  s.final_energy = model.energy(x, mode);
  s.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return s;
}

}  // namespace frictionlab::dynamics
