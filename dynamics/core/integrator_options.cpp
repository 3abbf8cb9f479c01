#include "dynamics/core/integrator_options.h"

#include <cmath>
#include <stdexcept>

#include "dynamics/core/gsl_steppers.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics {
namespace {

[[noreturn]] void fail(const char* key, double value, const char* rule) { throw support::invalid_value(key, value, rule); }

}  // namespace

std::vector<std::string> integrator_methods() { return gsl_stepper_names(); }

void IntegratorOptions::validate() const {
  if (!gsl_stepper(method)) {
    std::string list;
    for (const auto& m : integrator_methods()) list += (list.empty() ? "" : ", ") + m;
    throw std::invalid_argument("run.integrator = '" + method + "' is not a known stepper; known: " + list);
  }
  if (!(std::isfinite(abs_tol) && abs_tol > 0.0)) fail("run.abs_tol", abs_tol, "it must be finite and > 0");
  if (!(std::isfinite(rel_tol) && rel_tol >= 0.0)) fail("run.rel_tol", rel_tol, "it must be finite and >= 0");
  if (!(std::isfinite(initial_step) && initial_step > 0.0))
    fail("run.initial_step", initial_step, "it must be finite and > 0 s");
  if (!(std::isfinite(max_step) && max_step >= 0.0))
    fail("run.max_step", max_step, "it must be finite and >= 0 s (0: no limit)");
  if (max_steps <= 0) throw support::invalid_value("run.max_steps", static_cast<long long>(max_steps), "it must be > 0");
}

}  // namespace frictionlab::dynamics
