#pragma once
// The GSL odeiv2 stepping core that every model of frictionlab integrates with (the body of
// revolution, dynamics/body/simulation.h; the puck, dynamics/puck/): free steps under per-component
// scaled error control, and sub-steps from the start of an accepted step, which is how samples are
// taken inside steps (docs/dynamics.md §4). What a model adds is its right-hand side, its events
// and its output; the core owns the GSL objects (GSL stays out of this header).
//
//   FreeStepper  each accepted step is the one GSL's error control chooses towards t_end
//                (gsl_odeiv2_evolve_apply with gsl_odeiv2_control_scaled_new: component i may
//                carry a local error of abs_tol * scale_i + rel_tol * |x_i|); a right-hand side
//                that refuses a trial state makes GSL halve the step; one that stops fails it.
//   SubStepper   one step of size tau <= h of a one-step method from the start (t0, x0, x0') of
//                an accepted step, by a stepper of its own, so that the integrator is untouched
//                (its error is the method's local error for a step of size tau: samples are as
//                accurate as the step ends; dynamics/core/step_sampler.h).
//   AcceptedStepOf, cubic_hermite  an accepted step and its cubic Hermite interpolant (order 4),
//                the fallback where a sub-step fails.

#include <memory>
#include <string>
#include <string_view>

#include "dynamics/core/integrator_options.h"

namespace frictionlab::dynamics {

/// What an evaluation of a right-hand side tells the stepping core.
enum class RhsStatus {
  ok,     ///< the derivative was written
  retry,  ///< this trial state is not acceptable (non-finite, across a pole): GSL halves the step
  stop    ///< the model cannot be evaluated here (a law threw): the step fails at once
};

/// A right-hand side x' = f(t, x) of a fixed dimension, as the stepping core calls it (for accepted
/// steps and their trial stages alike).
class OdeRhs {
 public:
  virtual ~OdeRhs() = default;
  [[nodiscard]] virtual RhsStatus operator()(double t, const double* x, double* f) = 0;
};

/// An accepted step: its ends and the derivatives there (x' = f(x)).
template <class Vector>
struct AcceptedStepOf {
  double t0 = 0.0;
  Vector x0;
  Vector f0;
  double t1 = 0.0;
  Vector x1;
  Vector f1;
};

/// The cubic Hermite interpolant of the step at t in [t0, t1] (order 4, error <= h^4/384 max|x''''|).
template <class Vector>
[[nodiscard]] Vector cubic_hermite(const AcceptedStepOf<Vector>& s, double t) {
  const double h = s.t1 - s.t0;
  const double u = (t - s.t0) / h;
  const double u2 = u * u, u3 = u2 * u;
  const double h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
  const double h10 = u3 - 2.0 * u2 + u;
  const double h01 = -2.0 * u3 + 3.0 * u2;
  const double h11 = u3 - u2;
  return h00 * s.x0 + (h10 * h) * s.f0 + h01 * s.x1 + (h11 * h) * s.f1;
}

/// The outcome of FreeStepper::advance.
struct StepOutcome {
  enum Kind {
    accepted,        ///< (t, x) moved to the end of an accepted step
    stopped_by_rhs,  ///< the right-hand side returned RhsStatus::stop
    failed           ///< GSL gave up: no step above machine precision is accepted
  };
  Kind kind = accepted;
  std::string gsl_message;  ///< GSL's text for its status (failed only)
};

class FreeStepper {
 public:
  /// `abs_scale`: `dimension` per-component scales of io.abs_tol (copied). The options must be
  /// valid (IntegratorOptions::validate). Throws std::runtime_error if GSL cannot allocate.
  FreeStepper(OdeRhs& rhs, int dimension, const IntegratorOptions& io, const double* abs_scale);
  ~FreeStepper();
  FreeStepper(const FreeStepper&) = delete;
  FreeStepper& operator=(const FreeStepper&) = delete;

  /// One accepted step from (t, x) towards t_end, with trial size h; t, x and h are updated as
  /// gsl_odeiv2_evolve_apply updates them (on failure x and t are left as GSL left them: restore
  /// them from the step's start).
  StepOutcome advance(double& t, double t_end, double& h, double* x);
  /// x' at the end of the last accepted step (valid after an accepted advance).
  [[nodiscard]] const double* derivative_at_end() const;
  /// Trial steps GSL retried with a smaller size, so far (since construction: resets keep the count).
  [[nodiscard]] long failed_steps() const;
  /// Forgets the stepper's history (multistep methods) after a discontinuous change of the state.
  /// The count of failed_steps() goes on.
  void reset();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class SubStepper {
 public:
  /// `method`: the run's stepper; a multistep method (msadams) is replaced by rk8pd. Throws
  /// std::invalid_argument for an unknown method, std::runtime_error if GSL cannot allocate.
  SubStepper(std::string_view method, OdeRhs& rhs, int dimension);
  ~SubStepper();
  SubStepper(const SubStepper&) = delete;
  SubStepper& operator=(const SubStepper&) = delete;

  /// Writes into `out` one step of size tau from (t0, x0) with x0' = f0; false if the right-hand
  /// side refused a stage (out is then unspecified).
  [[nodiscard]] bool step(double t0, const double* x0, const double* f0, double tau, double* out);
  /// The method that takes the sub-steps.
  [[nodiscard]] const std::string& method() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frictionlab::dynamics
