#include "dynamics/step_sampler.h"

#include <stdexcept>

namespace frictionlab::dynamics {
namespace {

// The plain equations of motion; any failure (a throw, a non-finite value) aborts the sampling step.
class SamplerRhs final : public OdeRhs {
 public:
  explicit SamplerRhs(const BodyOnPlane& sys) : sys_(sys) {}
  RhsStatus operator()(double t, const double* y, double* f) override {
    ++calls;
    const StateVector x = Eigen::Map<const StateVector>(y);
    if (!x.allFinite()) return RhsStatus::stop;
    StateVector d;
    try {
      sys_(t, x, d);
    } catch (const std::exception&) {
      return RhsStatus::stop;
    }
    if (!d.allFinite()) return RhsStatus::stop;
    Eigen::Map<StateVector> out(f);
    out = d;
    return RhsStatus::ok;
  }
  long calls = 0;

 private:
  const BodyOnPlane& sys_;
};

}  // namespace

struct StepSampler::Impl {
  Impl(std::string_view method, const BodyOnPlane& sys, SampleAccuracy a)
      : rhs(sys), sub(method, rhs, StateLayout::kSize), accuracy(a) {}
  SamplerRhs rhs;
  SubStepper sub;
  SampleAccuracy accuracy;
  long fallbacks = 0;
};

StepSampler::StepSampler(std::string_view method, const BodyOnPlane& sys, SampleAccuracy accuracy)
    : impl_(std::make_unique<Impl>(method, sys, accuracy)) {}

StepSampler::~StepSampler() = default;

StateVector StepSampler::at(const AcceptedStep& s, double t) {
  if (t == s.t1) return s.x1;
  if (t == s.t0) return s.x0;
  if (impl_->accuracy == SampleAccuracy::interpolated) return cubic_hermite(s, t);
  StateVector x;
  if (impl_->sub.step(s.t0, s.x0.data(), s.f0.data(), t - s.t0, x.data())) return x;
  ++impl_->fallbacks;
  return cubic_hermite(s, t);
}

const std::string& StepSampler::method() const { return impl_->sub.method(); }
long StepSampler::rhs_calls() const { return impl_->rhs.calls; }
long StepSampler::hermite_fallbacks() const { return impl_->fallbacks; }

}  // namespace frictionlab::dynamics
