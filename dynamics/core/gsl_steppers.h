#pragma once
// The GSL odeiv2 steppers a run may use, by name (run.integrator). Internal to dynamics/: the
// public headers do not expose GSL.

#include <gsl/gsl_odeiv2.h>

#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::dynamics {

/// rk8pd (default, embedded Runge-Kutta Prince-Dormand 8(9)), rkck, rkf45, rk4, rk2, msadams.
/// Implicit steppers need a Jacobian and are not offered.
[[nodiscard]] std::vector<std::string> gsl_stepper_names();

/// The stepper type of a name, or nullptr if unknown.
[[nodiscard]] const gsl_odeiv2_step_type* gsl_stepper(std::string_view name);

/// True for the one-step (Runge-Kutta) methods, whose step from a state depends on nothing else;
/// false for msadams (a multistep method that carries its history).
[[nodiscard]] bool is_one_step(std::string_view name);

}  // namespace frictionlab::dynamics
