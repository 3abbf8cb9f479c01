#include "dynamics/step_sampler.h"

#include <gsl/gsl_errno.h>

#include <stdexcept>

#include "dynamics/gsl_steppers.h"

namespace frictionlab::dynamics {
namespace {

struct SamplerContext {
  const BodyOnPlane* sys = nullptr;
  long calls = 0;
};

// The plain equations of motion; any failure (a throw, a non-finite value) aborts the sampling step.
int sampler_rhs(double t, const double y[], double f[], void* params) {
  auto& ctx = *static_cast<SamplerContext*>(params);
  ++ctx.calls;
  const StateVector x = Eigen::Map<const StateVector>(y);
  if (!x.allFinite()) return GSL_EBADFUNC;
  StateVector d;
  try {
    (*ctx.sys)(t, x, d);
  } catch (const std::exception&) {
    return GSL_EBADFUNC;
  }
  if (!d.allFinite()) return GSL_EBADFUNC;
  Eigen::Map<StateVector> out(f);
  out = d;
  return GSL_SUCCESS;
}

struct StepDeleter {
  void operator()(gsl_odeiv2_step* s) const { gsl_odeiv2_step_free(s); }
};

}  // namespace

StateVector cubic_hermite(const AcceptedStep& s, double t) {
  const double h = s.t1 - s.t0;
  const double u = (t - s.t0) / h;
  const double u2 = u * u, u3 = u2 * u;
  const double h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
  const double h10 = u3 - 2.0 * u2 + u;
  const double h01 = -2.0 * u3 + 3.0 * u2;
  const double h11 = u3 - u2;
  return h00 * s.x0 + (h10 * h) * s.f0 + h01 * s.x1 + (h11 * h) * s.f1;
}

struct StepSampler::Impl {
  std::string method;
  SamplerContext ctx;
  gsl_odeiv2_system system{};
  std::unique_ptr<gsl_odeiv2_step, StepDeleter> step;
  long fallbacks = 0;
};

StepSampler::StepSampler(std::string_view method, const BodyOnPlane& sys) : impl_(std::make_unique<Impl>()) {
  if (!gsl_stepper(method)) throw std::invalid_argument("run.integrator = '" + std::string(method) + "' is not a known stepper");
  impl_->method = is_one_step(method) ? std::string(method) : std::string("rk8pd");
  impl_->ctx.sys = &sys;
  impl_->system = gsl_odeiv2_system{&sampler_rhs, nullptr, StateLayout::kSize, &impl_->ctx};
  impl_->step.reset(gsl_odeiv2_step_alloc(gsl_stepper(impl_->method), StateLayout::kSize));
  if (!impl_->step) throw std::runtime_error("GSL could not allocate the sampling stepper");
}

StepSampler::~StepSampler() = default;

StateVector StepSampler::at(const AcceptedStep& s, double t) {
  if (t == s.t1) return s.x1;
  if (t == s.t0) return s.x0;
  StateVector x = s.x0;
  StateVector err;
  gsl_odeiv2_step_reset(impl_->step.get());
  const int status = gsl_odeiv2_step_apply(impl_->step.get(), s.t0, t - s.t0, x.data(), err.data(), s.f0.data(),
                                           nullptr, &impl_->system);
  if (status == GSL_SUCCESS && x.allFinite()) return x;
  ++impl_->fallbacks;
  return cubic_hermite(s, t);
}

const std::string& StepSampler::method() const { return impl_->method; }
long StepSampler::rhs_calls() const { return impl_->ctx.calls; }
long StepSampler::hermite_fallbacks() const { return impl_->fallbacks; }

}  // namespace frictionlab::dynamics
