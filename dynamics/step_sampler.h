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
// (Observer::sample_accuracy, dynamics/observer.h): each sample is then the step's cubic Hermite
// interpolant, at no RHS call. The ensemble's feature samples do (docs/dynamics.md §4 gives why
// and what it changes).

#include <memory>
#include <string>
#include <string_view>

#include "dynamics/equations_of_motion.h"
#include "dynamics/observer.h"
#include "dynamics/ode_stepping.h"
#include "dynamics/state.h"

namespace frictionlab::dynamics {

/// An accepted step of the body: its ends and the derivatives there (x' = f(x)). Its cubic Hermite
/// interpolant is cubic_hermite(step, t) (dynamics/ode_stepping.h).
using AcceptedStep = AcceptedStepOf<StateVector>;

class StepSampler {
 public:
  /// `method`: the run's stepper (IntegratorOptions::method). Throws std::invalid_argument if unknown.
  /// `accuracy`: interpolated takes every sample from the cubic Hermite interpolant.
  StepSampler(std::string_view method, const BodyOnPlane& sys,
              SampleAccuracy accuracy = SampleAccuracy::method_step);
  ~StepSampler();
  StepSampler(const StepSampler&) = delete;
  StepSampler& operator=(const StepSampler&) = delete;

  /// The state at t in [t0, t1]: x0 or x1 at the ends (exactly), else one step of size t - t0 from x0
  /// (or the cubic Hermite interpolant, if so constructed).
  [[nodiscard]] StateVector at(const AcceptedStep& step, double t);

  /// The method that takes the sampling steps.
  [[nodiscard]] const std::string& method() const;
  /// Right-hand-side evaluations made for samples.
  [[nodiscard]] long rhs_calls() const;
  /// Samples that fell back on the cubic Hermite interpolant (never counts interpolated samples).
  [[nodiscard]] long hermite_fallbacks() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frictionlab::dynamics
