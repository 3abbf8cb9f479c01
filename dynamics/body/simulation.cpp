#include "dynamics/body/simulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "dynamics/core/run_loop.h"
#include "dynamics/body/tolerance_scales.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

using support::message_number;

// The body's events between steps (docs/dynamics.md §5): lift-offs and landings, the settling of
// the contact, rest, rolling and stagnation; and its records (min N, the drift of |gamma|).
class BodyOnPlane::Monitor {
 public:
  Monitor(const BodyOnPlane& sys, const RunOptions& options, RunSummary& s)
      : sys_(sys), options_(options), s_(s), settling_(resolve_settle(sys, options, s)), chatter_(s.chatter) {
    abs_scale_ = absolute_tolerance_scales(s.scales);
  }

  [[nodiscard]] StateVector tolerance_scales() const { return abs_scale_; }

  template <class Stop>
  After start(double t, StateVector& x, const ContactState& c0, BodyMode& /*mode*/, Stop&& /*stop*/) {
    s_.min_normal_force = c0.N;
    s_.max_gamma_drift = std::abs(vertical(x).norm() - 1.0);
    in_contact_ = c0.in_contact;
    settling_.update(t, c0.in_contact, c0.u.dot(c0.gamma));
    return After::go_on;
  }

  template <class Stop>
  bool before_step(double /*t*/, const StateVector& /*x*/, const BodyMode& /*mode*/, Stop&& /*stop*/) {
    return false;
  }

  template <class Step, class Sampler>
  bool locate(Step& /*step*/, Sampler& /*sampler*/, double& /*t*/, StateVector& /*x*/, BodyMode& /*mode*/) {
    return false;
  }

  template <class Step, class Sampler, class Stop>
  After after_step(double t, StateVector& x, const ContactState& c, BodyMode& /*mode*/, Step& step,
                   Sampler& /*sampler*/, Stop&& stop) {
    RunSummary& s = s_;
    if (std::string face = sys_.point_contact_end(x, c); !face.empty()) {  // the shape's point contact ends
      stop(Termination::flat_face, std::move(face));
      s.rule = BodyOnPlane::kFlatFaceRule;
      return After::stopped;
    }
    if (c.in_contact != in_contact_) (c.in_contact ? s.landings : s.liftoffs) += 1;
    in_contact_ = c.in_contact;
    s.min_normal_force = std::min(s.min_normal_force, c.N);
    s.max_gamma_drift = std::max(s.max_gamma_drift, std::abs(vertical(x).norm() - 1.0));
    settling_.update(t, c.in_contact, c.u.dot(c.gamma));
    const bool settled = settling_.settled(t);
    const double kinetic = kinetic_energy_(x);
    const auto stagnation_rule = [&](const char* energy_clause) {
      s.rule = std::string("settled contact (in contact with |eps'| < run.settle_normal_speed at every step of the "
                           "last run.settle_time), U < run.rest_slip_speed, |Omega| < run.rest_spin, kinetic "
                           "energy ") +
               energy_clause;
      s.thresholds = {s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin, s.rest.kinetic_energy};
    };
    if (settled && s.rest.at_rest(c.in_contact, c.U, c.Omega, kinetic)) {
      stop(Termination::rest, "settled since t = " + message_number(settling_.since()) +
                                  " s; U = " + message_number(c.U) + " m/s, |Omega| = " +
                                  message_number(std::abs(c.Omega)) + " 1/s and kinetic energy " +
                                  message_number(kinetic) + " J are below the rest thresholds");
      stagnation_rule("< run.rest_kinetic_energy");
      return After::stopped;
    }
    if (settled && options_.stop_when_rolling && s.rest.contact_stagnant(c.in_contact, c.U, c.Omega)) {
      stop(Termination::rolling, "the contact, settled since t = " + message_number(settling_.since()) +
                                     " s, neither slips (U = " + message_number(c.U) +
                                     " m/s) nor spins (Omega = " + message_number(c.Omega) +
                                     " 1/s) but the kinetic energy " + message_number(kinetic) +
                                     " J is above run.rest_kinetic_energy = " +
                                     message_number(s.rest.kinetic_energy.value) +
                                     " J: the body rolls without slip");
      stagnation_rule(">= run.rest_kinetic_energy");
      return After::stopped;
    }
    stagnant_unsettled_ =
        !settled && s.rest.contact_stagnant(c.in_contact, c.U, c.Omega) ? stagnant_unsettled_ + 1 : 0;
    if (options_.max_stagnant_steps > 0 && stagnant_unsettled_ >= options_.max_stagnant_steps) {
      stop(Termination::stagnation,
           "the contact has stayed in the stagnation region (U = " + message_number(c.U) + " m/s, |Omega| = " +
               message_number(std::abs(c.Omega)) + " 1/s) for " + std::to_string(stagnant_unsettled_) +
               " steps while its normal motion has not settled (unsettled at t = " +
               message_number(settling_.since()) + " s; now |eps'| = " + message_number(std::abs(c.u.dot(c.gamma))) +
               " m/s): a bounce reached the laws' singular set U = Omega = 0, where the integrator only "
               "chatters and the model has no sticking branch");
      s.rule = "in contact, not settled, U < run.rest_slip_speed and |Omega| < run.rest_spin for "
               "run.max_stagnant_steps accepted steps in a row";
      s.thresholds = {given_threshold("run.max_stagnant_steps", static_cast<double>(options_.max_stagnant_steps), "steps"),
                      s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin};
      return After::stopped;
    }
    const ChatterChannel chattered = chatter_.update({step.t0, t, c.in_contact, c.U * c.e1, c.Omega});
    if (chattered != ChatterChannel::none) {
      stop(Termination::chatter, chatter_message(chatter_.episode(chattered), s.chatter, sys_.law().name()));
      s.rule = chatter_rule_text(chattered);
      s.thresholds = {s.chatter.max_steps, s.chatter.step, s.chatter.slip_speed, s.chatter.spin};
      return After::stopped;
    }
    return After::go_on;
  }

  void finish(const StateVector& /*x*/, const BodyMode& /*mode*/) {}

 private:
  // Resolves the body's scales and thresholds into the summary; the settling rule.
  static const SettleRule& resolve_settle(const BodyOnPlane& sys, const RunOptions& options, RunSummary& s) {
    s.scales = body_scales(sys.body(), sys.plane());
    s.rest = resolve_rest(options.rest, s.scales);
    s.settle = resolve_settling(options.settle, s.scales);
    s.chatter = resolve_chatter(options.chatter, s.rest, s.scales);
    return s.settle;
  }
  double kinetic_energy_(const StateVector& x) const { return sys_.kinetic_energy(x); }

  const BodyOnPlane& sys_;
  const RunOptions& options_;
  RunSummary& s_;
  ContactSettling settling_;
  ChatterWatch chatter_;
  StateVector abs_scale_;
  bool in_contact_ = false;
  long stagnant_unsettled_ = 0;  // accepted steps in a row in the stagnation region, not settled
};

RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options, Observer* observer) {
  return run_model(sys, x0, options, observer);
}

}  // namespace frictionlab::dynamics
