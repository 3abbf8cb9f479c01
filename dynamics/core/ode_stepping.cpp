#include "dynamics/core/ode_stepping.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dynamics/core/gsl_steppers.h"
#include "friction/gsl_error_policy.h"

namespace frictionlab::dynamics {
namespace {

// The right-hand side as GSL calls it: retry is a plain failure (GSL halves the step), stop is
// GSL_EBADFUNC (GSL gives up at once).
int evolve_rhs(double t, const double y[], double f[], void* params) {
  switch ((*static_cast<OdeRhs*>(params))(t, y, f)) {
    case RhsStatus::ok: return GSL_SUCCESS;
    case RhsStatus::retry: return GSL_FAILURE;
    case RhsStatus::stop: return GSL_EBADFUNC;
  }
  return GSL_EBADFUNC;
}

// Inside a sub-step any refusal aborts it.
int substep_rhs(double t, const double y[], double f[], void* params) {
  return (*static_cast<OdeRhs*>(params))(t, y, f) == RhsStatus::ok ? GSL_SUCCESS : GSL_EBADFUNC;
}

struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};
struct StepDeleter {
  void operator()(gsl_odeiv2_step* s) const { gsl_odeiv2_step_free(s); }
};

}  // namespace

struct FreeStepper::Impl {
  gsl_odeiv2_system system{};
  std::unique_ptr<gsl_odeiv2_driver, DriverDeleter> driver;
  long failed_before_reset = 0;  // GSL's count starts again at 0 with every reset
};

FreeStepper::FreeStepper(OdeRhs& rhs, int dimension, const IntegratorOptions& io, const double* abs_scale)
    : impl_(std::make_unique<Impl>()) {
  use_gsl_status_codes();
  impl_->system = gsl_odeiv2_system{&evolve_rhs, nullptr, static_cast<std::size_t>(dimension), &rhs};
  // GSL copies the scales. a_y = 1, a_dydt = 0: the error is measured on the state only.
  impl_->driver.reset(gsl_odeiv2_driver_alloc_scaled_new(&impl_->system, gsl_stepper(io.method), io.initial_step,
                                                          io.abs_tol, io.rel_tol, 1.0, 0.0, abs_scale));
  if (!impl_->driver) throw std::runtime_error("GSL could not allocate the integrator");
}

FreeStepper::~FreeStepper() = default;

StepOutcome FreeStepper::advance(double& t, double t_end, double& h, double* x) {
  gsl_odeiv2_driver& d = *impl_->driver;
  const int status = gsl_odeiv2_evolve_apply(d.e, d.c, d.s, &impl_->system, &t, t_end, &h, x);
  if (status == GSL_SUCCESS) return {};
  if (status == GSL_EBADFUNC) return {StepOutcome::stopped_by_rhs, ""};
  return {StepOutcome::failed, gsl_strerror(status)};
}

const double* FreeStepper::derivative_at_end() const { return impl_->driver->e->dydt_out; }

long FreeStepper::failed_steps() const {
  return impl_->failed_before_reset + static_cast<long>(impl_->driver->e->failed_steps);
}

void FreeStepper::reset() {
  // gsl_odeiv2_driver_reset zeroes the evolve object's counts (gsl_odeiv2_evolve_reset).
  impl_->failed_before_reset += static_cast<long>(impl_->driver->e->failed_steps);
  gsl_odeiv2_driver_reset(impl_->driver.get());
}

struct SubStepper::Impl {
  std::string method;
  gsl_odeiv2_system system{};
  std::unique_ptr<gsl_odeiv2_step, StepDeleter> step;
  std::vector<double> error;
};

SubStepper::SubStepper(std::string_view method, OdeRhs& rhs, int dimension) : impl_(std::make_unique<Impl>()) {
  use_gsl_status_codes();
  if (!gsl_stepper(method)) throw std::invalid_argument("run.integrator = '" + std::string(method) + "' is not a known stepper");
  impl_->method = is_one_step(method) ? std::string(method) : std::string("rk8pd");
  impl_->system = gsl_odeiv2_system{&substep_rhs, nullptr, static_cast<std::size_t>(dimension), &rhs};
  impl_->step.reset(gsl_odeiv2_step_alloc(gsl_stepper(impl_->method), static_cast<std::size_t>(dimension)));
  if (!impl_->step) throw std::runtime_error("GSL could not allocate the sampling stepper");
  impl_->error.resize(static_cast<std::size_t>(dimension));
}

SubStepper::~SubStepper() = default;

bool SubStepper::step(double t0, const double* x0, const double* f0, double tau, double* out) {
  const std::size_t n = impl_->system.dimension;
  for (std::size_t i = 0; i < n; ++i) out[i] = x0[i];
  gsl_odeiv2_step_reset(impl_->step.get());
  const int status =
      gsl_odeiv2_step_apply(impl_->step.get(), t0, tau, out, impl_->error.data(), f0, nullptr, &impl_->system);
  if (status != GSL_SUCCESS) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(out[i])) return false;
  return true;
}

const std::string& SubStepper::method() const { return impl_->method; }

}  // namespace frictionlab::dynamics
