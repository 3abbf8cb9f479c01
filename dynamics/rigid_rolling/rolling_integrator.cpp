#include "dynamics/rigid_rolling/rolling_integrator.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include "friction/gsl_error_policy.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::rigid_rolling {

void RollingIntegratorOptions::validate() const {
  if (!(std::isfinite(abs_tol) && abs_tol > 0.0))
    throw support::invalid_value("integrator.abs_tol", abs_tol, "it must be finite and > 0");
  if (!(std::isfinite(rel_tol) && rel_tol >= 0.0))
    throw support::invalid_value("integrator.rel_tol", rel_tol, "it must be finite and >= 0");
  if (!(std::isfinite(initial_step) && initial_step > 0.0))
    throw support::invalid_value("integrator.initial_step", initial_step, "it must be finite and > 0 s");
}

struct RollingIntegrator::Impl {
  const RigidRollingModel& model;
  RollingIntegratorOptions options;
  gsl_odeiv2_system system{};
  gsl_odeiv2_driver* driver = nullptr;
  long evaluations = 0;
  long steps = 0;
  std::exception_ptr error;  // what the model threw inside GSL (C code must not unwind)

  static int rhs(double /*t*/, const double y[], double f[], void* params) {
    auto& self = *static_cast<Impl*>(params);
    ++self.evaluations;
    try {
      const RollingState d = self.model.derivative(RollingState::unpacked(y));
      Eigen::Map<Eigen::Matrix<double, RollingState::kSize, 1>> out(f);
      out = d.packed();
      return GSL_SUCCESS;
    } catch (...) {
      self.error = std::current_exception();
      return GSL_EBADFUNC;
    }
  }

  Impl(const RigidRollingModel& m, const RollingIntegratorOptions& o) : model(m), options(o) {
    options.validate();
    use_gsl_status_codes();
    system = gsl_odeiv2_system{&Impl::rhs, nullptr, RollingState::kSize, this};
    driver = gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, options.initial_step, options.abs_tol,
                                           options.rel_tol);
    if (driver == nullptr) throw std::runtime_error("GSL could not allocate the rk8pd integrator");
  }
  ~Impl() { gsl_odeiv2_driver_free(driver); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  // One accepted step towards t_end (never past it).
  void step(double& t, double t_end, double& h, double* y) {
    const int status = gsl_odeiv2_evolve_apply(driver->e, driver->c, driver->s, &system, &t, t_end, &h, y);
    if (error) std::rethrow_exception(std::exchange(error, nullptr));
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("the rigid rolling integration failed at t = ") +
                               support::message_number(t) + " s: " + gsl_strerror(status));
    ++steps;
  }
};

RollingIntegrator::RollingIntegrator(const RigidRollingModel& model, const RollingIntegratorOptions& options)
    : impl_(std::make_unique<Impl>(model, options)) {}

RollingIntegrator::~RollingIntegrator() = default;

void RollingIntegrator::integrate(double& t, RollingState& x, double t_end, const Observer& observer) {
  Eigen::Matrix<double, RollingState::kSize, 1> y = x.packed();
  gsl_odeiv2_driver_reset(impl_->driver);
  double h = t_end >= t ? impl_->options.initial_step : -impl_->options.initial_step;
  while (t != t_end) {
    impl_->step(t, t_end, h, y.data());
    x = RollingState::unpacked(y);
    if (observer && !observer(t, x)) return;
  }
}

RollingState RollingIntegrator::state_at(double t0, const RollingState& x0, double t1) {
  double t = t0;
  RollingState x = x0;
  integrate(t, x, t1);
  return x;
}

long RollingIntegrator::steps() const { return impl_->steps; }
long RollingIntegrator::evaluations() const { return impl_->evaluations; }

}  // namespace frictionlab::dynamics::rigid_rolling
