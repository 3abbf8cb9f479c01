#pragma once
// The integrator of a run (the [run] keys integrator, abs_tol, rel_tol, initial_step, max_step,
// max_steps; docs/dynamics.md §4): shared by every model that integrates with the GSL stepping
// core (dynamics/core/ode_stepping.h).

#include <string>
#include <vector>

namespace frictionlab::dynamics {

struct IntegratorOptions {
  /// GSL odeiv2 stepper: rk8pd (default, embedded Runge-Kutta Prince-Dormand 8(9)), rkck, rkf45,
  /// rk4, rk2, msadams. Implicit steppers need a Jacobian and are not offered.
  std::string method = "rk8pd";
  /// Dimensionless: component i may carry a local error of abs_tol * scale_i + rel_tol * |x_i|,
  /// scale_i its magnitude in a motion of the body over its size (dynamics/body/tolerance_scales.h).
  double abs_tol = 1e-9;
  double rel_tol = 1e-9;       ///< relative local error per component
  double initial_step = 1e-5;  ///< s, > 0
  double max_step = 0.0;       ///< s; 0 = no limit
  long max_steps = 10'000'000;  ///< accepted steps before the run stops with reason max-steps

  void validate() const;  ///< std::invalid_argument naming the run.* key
};

/// The stepper names accepted by IntegratorOptions::method.
[[nodiscard]] std::vector<std::string> integrator_methods();

}  // namespace frictionlab::dynamics
