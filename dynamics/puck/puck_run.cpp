#include "dynamics/puck/puck_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dynamics/core/rest_event.h"
#include "dynamics/core/run_loop.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {
namespace {

// The kinetic-energy levels at which the ratio U/(a|Omega|) is recorded: 1e-1 ... 1e-12.
constexpr int kRatioLevels = 12;

std::string num(double x) { return support::message_number(x); }

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

MotionPhaseRule motion_phase_rule(const PuckOnPlane& sys, const RunOptions& options) {
  const RestRule rest = resolve_rest(options.rest, puck_scales(sys.puck(), sys.g()));
  MotionPhaseRule rule;
  rule.rest_slip_speed = rest.slip_speed.value;
  rule.rest_spin = rest.spin.value;
  return rule;
}

// The puck's events: the stops of slip and spin, each located inside its step and then held; rest
// once both are held; the ratio U/(a |Omega|) at the decades of the kinetic energy.
class PuckOnPlane::Monitor {
 public:
  Monitor(const PuckOnPlane& sys, const RunOptions& options, PuckRunSummary& s) : sys_(sys), s_(s) {
    const BodyScales scales = puck_scales(sys.puck(), sys.g());
    const RestRule rest = resolve_rest(options.rest, scales);
    s.slip_speed = rest.slip_speed;
    s.spin = rest.spin;
    abs_scale_ = puck_tolerance_scales(scales);
  }

  [[nodiscard]] PuckState tolerance_scales() const { return abs_scale_; }

  template <class Stop>
  After start(double t, PuckState& x, const PuckContact& /*c0*/, Holds& holds, Stop&& /*stop*/) {
    kinetic0_ = s_.initial_energy;
    return hold_stopped(t, x, holds) ? After::jumped : After::go_on;
  }

  template <class Stop>
  bool before_step(double /*t*/, const PuckState& /*x*/, const Holds& holds, Stop&& stop) {
    if (!(holds.slip && holds.spin)) return false;
    stop(Termination::rest, "the slip stopped at t = " + num(s_.slip_stop_time) + " s and the spin at t = " +
                                num(s_.spin_stop_time) + " s");
    s_.rule = "U < run.rest_slip_speed and |Omega| < run.rest_spin (each located inside its step, then held at 0)";
    s_.thresholds = {s_.slip_speed, s_.spin};
    return true;
  }

  // A stop inside the step: the step ends there (the earlier of the two if both occur).
  template <class Step, class Sampler>
  bool locate(Step& step, Sampler& sampler, double& t, PuckState& x, Holds& holds) {
    const bool slip_crossed = !holds.slip && slip_below(x);
    const bool spin_crossed = !holds.spin && spin_below(x);
    if (!slip_crossed && !spin_crossed) return false;
    std::pair<double, PuckState> at{t, x};
    if (slip_crossed) at = locate_first(step, sampler, [&](const PuckState& y) { return slip_below(y); });
    if (spin_crossed) {
      const auto spin_at = locate_first(step, sampler, [&](const PuckState& y) { return spin_below(y); });
      if (!slip_crossed || spin_at.first < at.first) at = spin_at;
    }
    t = step.t1 = at.first;
    x = step.x1 = at.second;
    return true;
  }

  template <class Step, class Sampler, class Stop>
  After after_step(double t, PuckState& x, const PuckContact& /*c*/, Holds& holds, Step& step, Sampler& sampler,
                   Stop&& /*stop*/) {
    // The ratio where the kinetic energy crosses each decade, located inside the step, while both
    // motions go on.
    while (!holds.slip && !holds.spin && next_level_ <= kRatioLevels && kinetic0_ > 0.0 &&
           sys_.energy(x) < std::pow(10.0, -next_level_) * kinetic0_) {
      const double level = std::pow(10.0, -next_level_);
      const auto at =
          locate_first(step, sampler, [&](const PuckState& y) { return sys_.energy(y) < level * kinetic0_; });
      s_.ratio_by_energy.push_back({level, at.first, sys_.energy(at.second) / kinetic0_, ratio(at.second)});
      ++next_level_;
    }
    // A held component is set to 0: the steps start afresh from the new state.
    return hold_stopped(t, x, holds) ? After::jumped : After::go_on;
  }

  void finish(const PuckState& /*x*/, const Holds& holds) {
    s_.terminal_ratio_limit = aitken_limit(s_.ratio_by_energy);
    s_.holds = holds;
  }

 private:
  [[nodiscard]] double ratio(const PuckState& x) const {
    return velocity(x).norm() / (sys_.puck().a * std::abs(spin(x)));
  }
  [[nodiscard]] bool slip_below(const PuckState& x) const { return velocity(x).norm() < s_.slip_speed.value; }
  [[nodiscard]] bool spin_below(const PuckState& x) const { return std::abs(spin(x)) < s_.spin.value; }

  // Holds what has stopped at (t, x), records the stops; true if anything changed.
  bool hold_stopped(double t, PuckState& x, Holds& holds) {
    const bool slip_now = !holds.slip && slip_below(x);
    const bool spin_now = !holds.spin && spin_below(x);
    if (!slip_now && !spin_now) return false;
    const Puck& puck = sys_.puck();
    if (std::isnan(s_.terminal_ratio)) s_.terminal_ratio = ratio(x);
    if (slip_now) {
      s_.slip_stop_time = t;
      s_.held_slide_energy = 0.5 * puck.mass * velocity(x).squaredNorm();
      slide_work(x) += s_.held_slide_energy;
      velocity(x).setZero();
      holds.slip = true;
    }
    if (spin_now) {
      s_.spin_stop_time = t;
      s_.held_spin_energy = 0.5 * puck.inertia * spin(x) * spin(x);
      spin_work(x) += s_.held_spin_energy;
      spin(x) = 0.0;
      holds.spin = true;
    }
    return true;
  }

  const PuckOnPlane& sys_;
  PuckRunSummary& s_;
  PuckState abs_scale_;
  double kinetic0_ = 0.0;
  int next_level_ = 1;
};

PuckRunSummary simulate_puck(const PuckOnPlane& sys, const PuckState& x0, const RunOptions& options,
                             PuckObserver* observer) {
  return run_model(sys, x0, options, observer);
}

}  // namespace frictionlab::dynamics::puck
