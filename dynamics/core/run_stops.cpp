#include "dynamics/core/run_stops.h"

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

std::string law_pole_message(std::string_view output, std::string_view law, double h, double t,
                             const std::string& state) {
  return "the denominator of " + std::string(output) + " of friction law '" + std::string(law) +
         "' passes through 0 within " + support::message_number(h) + " s after t = " + support::message_number(t) +
         " s: the motion cannot be continued past this pole; at the last good state " + state;
}

std::string non_finite_step_message(double t) {
  return "the state became non-finite after the step from t = " + support::message_number(t) + " s";
}

std::string non_finite_message(const std::string& rhs_message) {
  return rhs_message + " (no step size down to machine precision avoids it)";
}

std::string integrator_failure_message(const std::string& gsl_message, double t, const std::string& state) {
  return "GSL: " + gsl_message + " (no step above machine precision meets the tolerance) at t = " +
         support::message_number(t) + " s; at that state " + state;
}

}  // namespace frictionlab::dynamics
