#pragma once
// Integration of the rigid rolling model (dynamics/rigid_rolling/rolling_equations.h) with GSL's
// embedded Runge-Kutta Prince-Dormand 8(9) (rk8pd) under the standard error control: component i
// of the state may carry a local error abs_tol + rel_tol |x_i|. Self-contained on purpose (the
// reference does not share the compliant models' stepping core). GSL stays out of this header.

#include <functional>
#include <memory>

#include "dynamics/rigid_rolling/rolling_equations.h"
#include "dynamics/rigid_rolling/rolling_state.h"

namespace frictionlab::dynamics::rigid_rolling {

struct RollingIntegratorOptions {
  double abs_tol = 1e-12;      ///< absolute local error per component (1/s for omega, 1 for gamma), > 0
  double rel_tol = 1e-12;      ///< relative local error, >= 0
  double initial_step = 1e-4;  ///< first trial step, s, > 0

  /// Throws std::invalid_argument naming the value and the rule.
  void validate() const;
};

class RollingIntegrator {
 public:
  /// Called after each accepted step with its end (t, x); return false to stop there.
  using Observer = std::function<bool(double t, const RollingState& x)>;

  /// Keeps a reference to `model`, which must outlive the integrator. Throws std::invalid_argument
  /// for invalid options, std::runtime_error if GSL cannot allocate.
  explicit RollingIntegrator(const RigidRollingModel& model, const RollingIntegratorOptions& options = {});
  ~RollingIntegrator();
  RollingIntegrator(const RollingIntegrator&) = delete;
  RollingIntegrator& operator=(const RollingIntegrator&) = delete;

  /// Advances (t, x) to t_end in accepted steps (t ends at t_end unless the observer stopped it).
  /// Throws std::runtime_error if GSL fails (no step above machine precision is accepted), and
  /// rethrows what the model throws (e.g. a disk that lies flat).
  void integrate(double& t, RollingState& x, double t_end, const Observer& observer = {});
  /// The state at t1 reached from (t0, x0) (the integrator starts afresh from x0).
  [[nodiscard]] RollingState state_at(double t0, const RollingState& x0, double t1);

  /// Accepted steps and right-hand sides so far (all calls).
  [[nodiscard]] long steps() const;
  [[nodiscard]] long evaluations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frictionlab::dynamics::rigid_rolling
