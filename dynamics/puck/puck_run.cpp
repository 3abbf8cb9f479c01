#include "dynamics/puck/puck_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dynamics/ode_stepping.h"
#include "dynamics/pole_watch.h"
#include "dynamics/run_stops.h"
#include "dynamics/rest_event.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {
namespace {

using Step = AcceptedStepOf<PuckState>;

// Bisections that locate a stop inside its step: 2^-60 of the step, below rounding.
constexpr int kLocateBisections = 60;
// The kinetic-energy levels at which the ratio U/(a|Omega|) is recorded: 1e-1 ... 1e-12.
constexpr int kRatioLevels = 12;

std::string num(double x) { return support::message_number(x); }

enum class RhsFailure { none, pole, nonfinite, law_error };

// The friction at a state, in one line (for failure messages only).
std::string describe_friction(const PuckOnPlane& sys, const PuckState& x, Holds holds) {
  std::ostringstream m;
  try {
    const PuckContact c = sys.contact(x, holds);
    m << "friction law '" << sys.law().name() << "' gives F1 = " << num(c.friction.F1) << " N, F2 = "
      << num(c.friction.F2) << " N, M = " << num(c.friction.M) << " N m at U = " << num(c.U) << " m/s, Omega = "
      << num(c.Omega) << " 1/s, psi = " << num(c.psi);
  } catch (const std::exception& e) {
    m << e.what();
  }
  return m.str();
}

PoleWatch::Point pole_point(const PuckOnPlane& sys, const PuckContact& c) {
  return PoleWatch::patch_point(c.U, c.Omega, sys.puck().a, sys.puck().b, c.psi);
}

// The right-hand side for the integrator: counts calls, refuses non-finite states and states across
// a pole of the law (GSL halves the step), stops on a law error.
class PuckRhs final : public OdeRhs {
 public:
  PuckRhs(const PuckOnPlane& sys, const PoleWatch* poles, const Holds& holds) : sys_(sys), poles_(poles), holds_(holds) {}

  RhsStatus operator()(double t, const double* y, double* f) override {
    ++calls;
    const PuckState x = Eigen::Map<const PuckState>(y);
    if (!x.allFinite()) return fail_nonfinite(t, x);
    PuckState d;
    try {
      const PuckContact c = sys_.contact(x, holds_);
      if (poles_) {
        const int crossed = poles_->crossing(pole_point(sys_, c));
        if (crossed >= 0) {
          last = RhsFailure::pole;
          pole_output = crossed;
          return RhsStatus::retry;
        }
      }
      sys_.derivatives(x, c, holds_, d);
    } catch (const std::exception& e) {
      last = RhsFailure::law_error;
      message = "at t = " + num(t) + " s: " + e.what();
      return RhsStatus::stop;
    }
    if (!d.allFinite()) return fail_nonfinite(t, x);
    last = RhsFailure::none;
    Eigen::Map<PuckState> out(f);
    out = d;
    return RhsStatus::ok;
  }

  long calls = 0;
  RhsFailure last = RhsFailure::none;
  int pole_output = -1;
  std::string message;

 private:
  RhsStatus fail_nonfinite(double t, const PuckState& x) {
    last = RhsFailure::nonfinite;
    message = "the right-hand side is not finite at t = " + num(t) + " s" +
              (x.allFinite() ? ": " + describe_friction(sys_, x, holds_) : std::string(" (the trial state is not finite)"));
    return RhsStatus::retry;
  }
  const PuckOnPlane& sys_;
  const PoleWatch* poles_;
  const Holds& holds_;
};

// The plain equations for sub-steps (samples, locating the stops): any failure aborts the sub-step.
class PlainRhs final : public OdeRhs {
 public:
  PlainRhs(const PuckOnPlane& sys, const Holds& holds) : sys_(sys), holds_(holds) {}
  RhsStatus operator()(double, const double* y, double* f) override {
    ++calls;
    const PuckState x = Eigen::Map<const PuckState>(y);
    if (!x.allFinite()) return RhsStatus::stop;
    PuckState d;
    try {
      sys_(x, holds_, d);
    } catch (const std::exception&) {
      return RhsStatus::stop;
    }
    if (!d.allFinite()) return RhsStatus::stop;
    Eigen::Map<PuckState> out(f);
    out = d;
    return RhsStatus::ok;
  }
  long calls = 0;

 private:
  const PuckOnPlane& sys_;
  const Holds& holds_;
};

// The state inside an accepted step: a sub-step of the run's method from its start (the cubic
// Hermite interpolant where that fails), as for the body (dynamics/step_sampler.h).
class Sampler {
 public:
  Sampler(std::string_view method, const PuckOnPlane& sys, const Holds& holds)
      : rhs_(sys, holds), sub_(method, rhs_, PuckLayout::kSize) {}
  PuckState at(const Step& s, double t) {
    if (t == s.t1) return s.x1;
    if (t == s.t0) return s.x0;
    PuckState x;
    if (sub_.step(s.t0, s.x0.data(), s.f0.data(), t - s.t0, x.data())) return x;
    ++fallbacks;
    return cubic_hermite(s, t);
  }
  [[nodiscard]] long calls() const { return rhs_.calls; }
  long fallbacks = 0;

 private:
  PlainRhs rhs_;
  SubStepper sub_;
};

// The first time in (t0, t1] at which `below` holds, given that it holds at t1 (bisection on
// sub-steps), and the state there.
template <class Below>
std::pair<double, PuckState> locate(const Step& s, Sampler& sampler, Below below) {
  if (below(s.x0)) return {s.t0, s.x0};
  double lo = s.t0, hi = s.t1;
  PuckState x_hi = s.x1;
  for (int i = 0; i < kLocateBisections && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const PuckState x = sampler.at(s, mid);
    if (below(x)) {
      hi = mid;
      x_hi = x;
    } else {
      lo = mid;
    }
  }
  return {hi, x_hi};
}

}  // namespace

double aitken_limit(const std::vector<RatioAtEnergy>& r) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = r.size();
  if (n < 5) return nan;
  // The last three contractions q = d_i/d_{i-1} of the differences d_i = r_i - r_{i-1}.
  double q[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t k = n - 3 + i;
    const double d = r[k].ratio - r[k - 1].ratio, d_before = r[k - 1].ratio - r[k - 2].ratio;
    if (!(std::isfinite(d) && std::isfinite(d_before)) || d_before == 0.0) return nan;
    q[i] = d / d_before;
    if (!(q[i] > 0.0 && q[i] < 1.0)) return nan;
  }
  // Geometric: the same q to 5 % (an algebraic drift such as 1/sqrt(n) has q rising towards 1).
  if (std::max({q[0], q[1], q[2]}) > 1.05 * std::min({q[0], q[1], q[2]})) return nan;
  const double d2 = r[n - 2].ratio - r[n - 3].ratio, d3 = r[n - 1].ratio - r[n - 2].ratio;
  return r[n - 1].ratio - d3 * d3 / (d3 - d2);
}

namespace {

}  // namespace

BodyScales puck_scales(const Puck& puck, double g) {
  BodyScales s;
  s.size = puck.a;
  s.mass = puck.mass;
  s.gravity = g > 0.0 ? g : kReferenceGravity;
  s.speed = std::sqrt(s.gravity * s.size);
  s.rate = std::sqrt(s.gravity / s.size);
  s.energy = s.mass * s.gravity * s.size;
  return s;  // no Hertz contact: compression, frequency and lift-off speed stay 0
}

PuckState puck_tolerance_scales(const BodyScales& s) {
  PuckState scale;
  position(scale).setConstant(s.size);
  heading(scale) = 1.0;
  velocity(scale).setConstant(s.speed);
  spin(scale) = s.rate;
  slide_work(scale) = s.energy;
  spin_work(scale) = s.energy;
  return scale;
}

PuckRunSummary simulate_puck(const PuckOnPlane& sys, const PuckState& x0, const RunOptions& options,
                             PuckObserver* observer) {
  options.validate();
  if (!x0.allFinite()) throw std::invalid_argument("the initial state is not finite");
  const auto wall_start = std::chrono::steady_clock::now();
  const IntegratorOptions& io = options.integrator;
  const Puck& puck = sys.puck();

  PuckRunSummary s;
  const BodyScales scales = puck_scales(puck, sys.g());
  const RestRule rest = resolve_rest(options.rest, scales);
  s.slip_speed = rest.slip_speed;
  s.spin = rest.spin;
  const PuckState abs_scale = puck_tolerance_scales(scales);
  s.abs_tol = io.abs_tol * abs_scale;

  Holds holds;
  PoleWatch poles(sys.law(), sys.k());
  PuckRhs rhs(sys, poles.active() ? &poles : nullptr, holds);
  FreeStepper stepper(rhs, PuckLayout::kSize, io, abs_scale.data());
  Sampler sampler(io.method, sys, holds);

  const auto stop = [&](Termination why, std::string message) {
    s.reason = why;
    s.message = std::move(message);
    s.rule.clear();
    s.thresholds.clear();
  };
  double last_sample_t = -1.0;
  const auto emit = [&](double time, const PuckState& state) {
    if (!observer) return true;
    try {
      const PuckContact c = sys.contact(state, holds);
      observer->sample(PuckSample{time, state, c, sys.energy(state), holds});
    } catch (const OutputFailure& e) {
      stop(Termination::output_error, "the output failed at t = " + num(time) + " s: " + e.what());
      return false;
    } catch (const OutputLimitReached& e) {
      stop(Termination::output_limit, "the output reached its limit at t = " + num(time) + " s: " + e.what());
      return false;
    }
    ++s.samples;
    last_sample_t = time;
    return true;
  };
  const auto ratio = [&](const PuckState& x) { return velocity(x).norm() / (puck.a * std::abs(spin(x))); };
  const auto slip_below = [&](const PuckState& x) { return velocity(x).norm() < s.slip_speed.value; };
  const auto spin_below = [&](const PuckState& x) { return std::abs(spin(x)) < s.spin.value; };
  // Holds what has stopped at (t, x), records the stops; true if anything changed.
  const auto hold_stopped = [&](double t, PuckState& x) {
    const bool slip_now = !holds.slip && slip_below(x);
    const bool spin_now = !holds.spin && spin_below(x);
    if (!slip_now && !spin_now) return false;
    if (std::isnan(s.terminal_ratio)) s.terminal_ratio = ratio(x);
    if (slip_now) {
      s.slip_stop_time = t;
      s.held_slide_energy = 0.5 * puck.mass * velocity(x).squaredNorm();
      slide_work(x) += s.held_slide_energy;
      velocity(x).setZero();
      holds.slip = true;
    }
    if (spin_now) {
      s.spin_stop_time = t;
      s.held_spin_energy = 0.5 * puck.inertia * spin(x) * spin(x);
      spin_work(x) += s.held_spin_energy;
      spin(x) = 0.0;
      holds.spin = true;
    }
    return true;
  };

  PuckState x = x0;
  double t = 0.0;
  double h = io.initial_step;
  const double max_step = io.max_step > 0.0 ? io.max_step : std::numeric_limits<double>::infinity();
  const PuckContact c0 = sys.contact(x, holds);  // throws here (not mid-run) if the law rejects x0
  (void)c0;
  s.initial_energy = sys.energy(x);
  const double kinetic0 = s.initial_energy;
  int next_level = 1;

  bool output_ok = emit(t, x);
  (void)hold_stopped(t, x);
  const auto f_at = [&](const PuckState& state) {
    PuckState f = PuckState::Zero();
    try {
      sys(state, holds, f);
    } catch (const std::exception&) {
      // the next integrator step reports it (law-error)
    }
    return f;
  };
  if (!holds.slip || !holds.spin) poles.set_reference(pole_point(sys, sys.contact(x, holds)));
  Step step;
  step.t1 = t;
  step.x1 = x;
  step.f1 = f_at(x);
  long next_sample = 1;

  while (output_ok) {
    if (holds.slip && holds.spin) {
      stop(Termination::rest, "the slip stopped at t = " + num(s.slip_stop_time) + " s and the spin at t = " +
                                  num(s.spin_stop_time) + " s");
      s.rule = "U < run.rest_slip_speed and |Omega| < run.rest_spin (each located inside its step, then held at 0)";
      s.thresholds = {s.slip_speed, s.spin};
      break;
    }
    if (stop_at_t_end(t, options.t_end, s, stop)) break;
    step.t0 = step.t1;
    step.x0 = step.x1;
    step.f0 = step.f1;
    h = std::min(h, max_step);
    rhs.last = RhsFailure::none;
    const StepOutcome outcome = stepper.advance(t, options.t_end, h, x.data());
    if (outcome.kind == StepOutcome::accepted) {
      ++s.steps;
      if (!x.allFinite()) {
        x = step.x0;
        t = step.t0;
        stop(Termination::non_finite, non_finite_step_message(t));
        break;
      }
      step.t1 = t;
      step.x1 = x;
      step.f1 = Eigen::Map<const PuckState>(stepper.derivative_at_end());

      // A stop inside the step: the step ends there (the earlier of the two if both occur).
      const bool slip_crossed = !holds.slip && slip_below(x);
      const bool spin_crossed = !holds.spin && spin_below(x);
      if (slip_crossed || spin_crossed) {
        std::pair<double, PuckState> at{t, x};
        if (slip_crossed) at = locate(step, sampler, slip_below);
        if (spin_crossed) {
          const auto spin_at = locate(step, sampler, spin_below);
          if (!slip_crossed || spin_at.first < at.first) at = spin_at;
        }
        t = step.t1 = at.first;
        x = step.x1 = at.second;
      }

      for (;;) {
        const double ts = static_cast<double>(next_sample) * options.output_dt;
        if (ts > t) break;
        if (!(output_ok = emit(ts, sampler.at(step, ts)))) break;
        ++next_sample;
      }
      if (!output_ok) break;
      if (observer) observer->step(t);

      // The ratio where the kinetic energy crosses each decade, located inside the step, while both
      // motions go on.
      while (!holds.slip && !holds.spin && next_level <= kRatioLevels && kinetic0 > 0.0 &&
             sys.energy(x) < std::pow(10.0, -next_level) * kinetic0) {
        const double level = std::pow(10.0, -next_level);
        const auto at = locate(step, sampler, [&](const PuckState& y) { return sys.energy(y) < level * kinetic0; });
        s.ratio_by_energy.push_back({level, at.first, sys.energy(at.second) / kinetic0, ratio(at.second)});
        ++next_level;
      }
      if (hold_stopped(t, x)) {
        // The state jumped (a component set to 0): the steps start afresh from it.
        stepper.reset();
        step.x1 = x;
        step.f1 = f_at(x);
      }
      if (!holds.slip || !holds.spin) poles.set_reference(pole_point(sys, sys.contact(x, holds)));
      if (stop_at_step_limits(s.steps, io.max_steps, options.cancel, s, stop)) break;
      continue;
    }

    x = step.x0;
    t = step.t0;
    if (outcome.kind == StepOutcome::stopped_by_rhs) {
      stop(Termination::law_error, rhs.message);
    } else if (rhs.last == RhsFailure::pole) {
      stop(Termination::law_pole, law_pole_message(PoleWatch::output_name(rhs.pole_output), sys.law().name(),
                                                   std::abs(h), t, describe_friction(sys, x, holds)));
      s.rule = kLawPoleRule;
    } else if (rhs.last == RhsFailure::nonfinite) {
      stop(Termination::non_finite, non_finite_message(rhs.message));
    } else {
      stop(Termination::integrator_failure,
           integrator_failure_message(outcome.gsl_message, t, describe_friction(sys, x, holds)));
    }
    break;
  }

  if (output_ok && last_sample_t != t) (void)emit(t, x);
  s.terminal_ratio_limit = aitken_limit(s.ratio_by_energy);
  s.t_final = t;
  s.x_final = x;
  s.holds = holds;
  s.rhs_calls = rhs.calls;
  s.sample_rhs_calls = sampler.calls();
  s.hermite_samples = sampler.fallbacks;
  s.rejected_steps = stepper.failed_steps();
  s.final_energy = sys.energy(x);
  s.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return s;
}

}  // namespace frictionlab::dynamics::puck
