#include "dynamics/core/shadow_laws.h"

#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool all_finite(const friction::FrictionForces& f) {
  return std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M);
}

double power(const friction::FrictionForces& f, const friction::ContactInput& in) { return f.F1 * in.U + f.M * in.Omega; }

}  // namespace

const std::array<const char*, kShadowOutputs>& shadow_output_names() {
  static const std::array<const char*, kShadowOutputs> names{"F1", "F2", "F", "M", "P"};
  return names;
}

ShadowLaws::ShadowLaws(const friction::FrictionLaw& own, std::vector<const friction::FrictionLaw*> shadows,
                       const MotionPhaseRule& rule)
    : own_(own),
      shadows_(std::move(shadows)),
      rule_(rule),
      stats_(shadows_.size()),
      scratch_(shadows_.size()),
      last_dP_(shadows_.size(), 0.0) {}

MotionPhase ShadowLaws::phase(const ShadowPoint& p) const {
  return rule_.classify(p.in_contact, p.input.U, p.input.Omega, p.normal_speed);
}

bool ShadowLaws::own_forces(const ShadowPoint& p, friction::FrictionForces& f) const {
  if (p.own_known) {
    f = p.own;
    return true;
  }
  try {
    f = own_.evaluate(p.input);
  } catch (const std::exception&) {
    return false;
  }
  return all_finite(f);
}

void ShadowLaws::evaluate(const ShadowPoint& p, std::span<ShadowError> out) const {
  if (!p.in_contact) {
    for (ShadowError& e : out) e = ShadowError{};
    return;
  }
  const ShadowError failed{kNaN, kNaN, kNaN, kNaN, kNaN};
  friction::FrictionForces f0;
  if (!own_forces(p, f0)) {
    for (ShadowError& e : out) e = failed;
    return;
  }
  const double kN = p.input.k * p.input.N;
  const double kNa = kN * p.input.a;
  for (std::size_t i = 0; i < shadows_.size() && i < out.size(); ++i) {
    friction::FrictionForces f;
    try {
      f = shadows_[i]->evaluate(p.input);
    } catch (const std::exception&) {
      out[i] = failed;
      continue;
    }
    if (!all_finite(f)) {
      out[i] = failed;
      continue;
    }
    ShadowError& e = out[i];
    const double d1 = f.F1 - f0.F1;
    const double d2 = f.F2 - f0.F2;
    const double dm = f.M - f0.M;
    // kN = 0 (no load, or k = 0): every law gives no friction, the errors are 0.
    e.dF1 = kN > 0.0 ? d1 / kN : 0.0;
    e.dF2 = kN > 0.0 ? d2 / kN : 0.0;
    e.dF = std::hypot(e.dF1, e.dF2);
    e.dM = kNa > 0.0 ? dm / kNa : 0.0;
    e.dP = d1 * p.input.U + dm * p.input.Omega;
  }
}

void ShadowLaws::record_step(double t, const ShadowPoint& p) {
  const double h = opened_ ? t - last_t_ : 0.0;  // the first state opens the record
  const MotionPhase ph = phase(p);

  // The run's law and every shadow law at p, their powers (NaN where one failed).
  friction::FrictionForces f0;
  const bool own_ok = !p.in_contact || own_forces(p, f0);
  if (!own_ok) ++own_failures_;
  const double own_power = !p.in_contact ? 0.0 : own_ok ? power(f0, p.input) : kNaN;
  evaluate(p, scratch_);

  if (h > 0.0) phase_time_[static_cast<std::size_t>(ph)] += h;
  if (std::isfinite(own_power) && std::isfinite(last_own_power_)) own_dissipated_ += 0.5 * h * (own_power + last_own_power_);
  last_own_power_ = own_power;

  for (std::size_t i = 0; i < shadows_.size(); ++i) {
    const ShadowError& e = scratch_[i];
    ShadowLawStatistics& s = stats_[i];
    const bool ok = std::isfinite(e.dF1);
    if (!ok && p.in_contact && own_ok) {
      ++s.failures;
      if (s.first_failure_time < 0.0) {
        s.first_failure_time = t;
        try {
          (void)shadows_[i]->evaluate(p.input);
          s.first_failure = "a non-finite value at U = " + support::message_number(p.input.U) +
                            " m/s, Omega = " + support::message_number(p.input.Omega) + " 1/s";
        } catch (const std::exception& ex) {
          s.first_failure = ex.what();
        }
      }
    }
    const double dP = ok ? e.dP : kNaN;
    if (std::isfinite(dP) && std::isfinite(last_dP_[i])) {
      s.difference += 0.5 * h * (dP + last_dP_[i]);
    } else {
      s.skipped_time += h;
    }
    last_dP_[i] = dP;
    if (!ok || !p.in_contact) continue;
    const std::array<double, kShadowOutputs> values{std::abs(e.dF1), std::abs(e.dF2), e.dF, std::abs(e.dM),
                                                    std::abs(e.dP)};
    for (int k = 0; k < kShadowOutputs; ++k) {
      s.errors[static_cast<std::size_t>(ph)][static_cast<std::size_t>(k)].add(values[static_cast<std::size_t>(k)], h);
      s.errors[kMotionPhases][static_cast<std::size_t>(k)].add(values[static_cast<std::size_t>(k)], h);
    }
  }
  last_t_ = t;
  if (opened_) ++steps_;
  opened_ = true;
}

}  // namespace frictionlab::dynamics
