#pragma once
// What a run reports while it goes: samples on the output grid (and at the end), and progress.
// The same for every model (dynamics/core/run_loop.h); a model's observers see its own state, contact
// and mode: ObserverOf<Model> receives SampleOf<Model>.

#include <stdexcept>

namespace frictionlab::dynamics {

/// One output sample of a model with these state, contact and mode types.
template <class State, class Contact, class Mode>
struct SampleT {
  double t = 0.0;             ///< s
  const State& x;             ///< the state as integrated (the body's gamma not renormalised)
  const Contact& contact;     ///< the contact quantities at x
  double energy = 0.0;        ///< total mechanical energy, J
  double kinetic = 0.0;       ///< kinetic energy, J
  Mode mode{};                ///< the discrete mode at x (held components, stick)
};

/// The sample type of a model (dynamics/core/run_loop.h).
template <class Model>
using SampleOf = SampleT<typename Model::State, typename Model::Contact, typename Model::Mode>;

/// Thrown by an observer whose output failed (a write or close error, a full disk): the run stops
/// at once with reason "output-error", keeping the last good state.
class OutputFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by an observer whose output would exceed its documented size limit: the run stops with
/// reason "output-limit" (what was written stays valid).
class OutputLimitReached : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How the samples inside an accepted step are computed (dynamics/core/step_sampler.h).
enum class SampleAccuracy {
  method_step,  ///< one step of the run's method from the step's start: as accurate as the step ends
  interpolated  ///< the step's cubic Hermite interpolant: no RHS call, order 4 (for slow quantities)
};

template <class SampleType>
class ObserverT {
 public:
  using Sample = SampleType;
  virtual ~ObserverT() = default;
  /// At t = 0, at every multiple of the output interval, and once at the final time. May throw
  /// OutputFailure or OutputLimitReached (the run stops; see above).
  virtual void sample(const SampleType& s) = 0;
  /// After every accepted step (cheap; for progress display).
  virtual void step(double /*t*/) {}
  /// The state at the end of every accepted step, with its contact and mode (its energy and
  /// kinetic energy are not computed: NaN), for an observer that asks for it
  /// (wants_accepted_steps()): the shadow laws (dynamics/core/shadow_observer.h) read the contact of
  /// every step the integrator took. Must not throw; the run does not depend on it.
  virtual void accepted(const SampleType& /*s*/) {}
  /// Whether accepted() should be called (asked once at the start of a run).
  [[nodiscard]] virtual bool wants_accepted_steps() const { return false; }
  /// What the observer needs of its samples, asked once at the start of a run. An observer that
  /// reads only quantities that vary slowly over a step (the orientation, for features measured
  /// against thresholds far above 1e-5) may take interpolated samples, which cost nothing.
  [[nodiscard]] virtual SampleAccuracy sample_accuracy() const { return SampleAccuracy::method_step; }
};

/// The observer of a model's runs.
template <class Model>
using ObserverOf = ObserverT<SampleOf<Model>>;

}  // namespace frictionlab::dynamics
