#pragma once
// Samples the solution inside an accepted step, so that output times never shape the steps
// (docs/dynamics.md §4 and §6).
//
// The sample at t0 + tau inside an accepted step [t0, t1] is one step of size tau of the run's own
// Runge-Kutta method (for msadams, a multistep method: of rk8pd) from the step's start (t0, x0),
// taken by a separate stepper: the integrator's steps, state and counters are untouched, so two
// output intervals give the same steps and the same final state bit for bit.
//
// Order and error: the sample is the method's own approximation of the flow from x0 over tau, so
// its error is the method's local truncation error for a step of size tau <= h = t1 - t0, of order
// p + 1 in tau (p = 8 for rk8pd), below the error the controller accepted for the whole step (to
// leading order, by the factor (tau/h)^(p+1)): samples are as accurate as the step ends. A
// polynomial interpolant through the step is not: the cubic Hermite interpolant from x and x' at
// both ends (order 4, error <= h^4/384 max|x''''|) is wrong by ~1e-6 of the state in free flight at
// tolerance 1e-12 (h omega ~ 0.3), and by the whole Hertz vibration where the step is limited by the
// stepper's stability on it (h omega_n up to ~4).
// Cost: one step of the method per sample (12 RHS calls for rk8pd, which reuses x'(t0)) — what the
// steps cut at sample times cost before. If the right-hand side fails inside a sampling step (a law
// that throws or overflows at a state the integrator never visited), that sample falls back on the
// cubic Hermite interpolant and the fallback is counted.
//
// An observer that reads only slowly varying quantities may ask for interpolated samples instead
// (Observer::sample_accuracy, dynamics/core/observer.h): each sample is then the step's cubic Hermite
// interpolant, at no RHS call. The ensemble's feature samples do (docs/dynamics.md §4 gives why
// and what it changes).

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <utility>

#include "dynamics/core/all_finite.h"
#include "dynamics/core/observer.h"
#include "dynamics/core/ode_stepping.h"

namespace frictionlab::dynamics {

/// The state of a model (dynamics/core/run_loop.h) inside its accepted steps.
template <class Model>
class StepSamplerOf {
 public:
  using State = typename Model::State;
  using Step = AcceptedStepOf<State>;

  /// `method`: the run's stepper (IntegratorOptions::method). Throws std::invalid_argument if unknown.
  /// `mode`: the model's mode, read at every evaluation (it outlives the sampler).
  /// `accuracy`: interpolated takes every sample from the cubic Hermite interpolant.
  StepSamplerOf(std::string_view method, const Model& model, const typename Model::Mode& mode,
                SampleAccuracy accuracy = SampleAccuracy::method_step)
      : rhs_(model, mode), sub_(method, rhs_, Model::kSize), accuracy_(accuracy) {}
  StepSamplerOf(const StepSamplerOf&) = delete;
  StepSamplerOf& operator=(const StepSamplerOf&) = delete;

  /// The state at t in [t0, t1]: x0 or x1 at the ends (exactly), else one step of size t - t0 from x0
  /// (or the cubic Hermite interpolant, if so constructed).
  [[nodiscard]] State at(const Step& s, double t) {
    if (t == s.t1) return s.x1;
    if (t == s.t0) return s.x0;
    if (accuracy_ == SampleAccuracy::interpolated) return cubic_hermite(s, t);
    State x;
    if (sub_.step(s.t0, s.x0.data(), s.f0.data(), t - s.t0, x.data())) return x;
    ++fallbacks_;
    return cubic_hermite(s, t);
  }

  /// The method that takes the sampling steps.
  [[nodiscard]] const std::string& method() const { return sub_.method(); }
  /// Right-hand-side evaluations made for samples.
  [[nodiscard]] long rhs_calls() const { return rhs_.calls; }
  /// Samples that fell back on the cubic Hermite interpolant (never counts interpolated samples).
  [[nodiscard]] long hermite_fallbacks() const { return fallbacks_; }

 private:
  // The plain equations of motion; any failure (a throw, a non-finite value) aborts the sampling step.
  class Rhs final : public OdeRhs {
   public:
    Rhs(const Model& model, const typename Model::Mode& mode) : model_(model), mode_(mode) {}
    RhsStatus operator()(double /*t*/, const double* y, double* f) override {
      ++calls;
      const State x = Eigen::Map<const State>(y);
      if (!all_finite(x)) return RhsStatus::stop;
      State d;
      try {
        typename Model::Contact c;
        model_.contact(x, mode_, c);
        model_.derivatives(x, c, mode_, d);
      } catch (const std::exception&) {
        return RhsStatus::stop;
      }
      if (!all_finite(d)) return RhsStatus::stop;
      Eigen::Map<State> out(f);
      out = d;
      return RhsStatus::ok;
    }
    long calls = 0;

   private:
    const Model& model_;
    const typename Model::Mode& mode_;
  };

  Rhs rhs_;
  SubStepper sub_;
  SampleAccuracy accuracy_;
  long fallbacks_ = 0;
};

/// The first time in (t0, t1] at which `holds` is true, given that it is true at t1, and the state
/// there: bisection on samples of the step (dynamics/core/step_sampler.h) down to 2^-60 of the step,
/// below rounding. If it already holds at t0, (t0, x0).
template <class Model, class Predicate>
std::pair<double, typename Model::State> locate_first(const AcceptedStepOf<typename Model::State>& s,
                                                      StepSamplerOf<Model>& sampler, Predicate holds) {
  constexpr int kLocateBisections = 60;
  if (holds(s.x0)) return {s.t0, s.x0};
  double lo = s.t0, hi = s.t1;
  typename Model::State x_hi = s.x1;
  for (int i = 0; i < kLocateBisections && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const typename Model::State x = sampler.at(s, mid);
    if (holds(x)) {
      hi = mid;
      x_hi = x;
    } else {
      lo = mid;
    }
  }
  return {hi, x_hi};
}

}  // namespace frictionlab::dynamics
