#include "dynamics/core/chatter_watch.h"

#include <algorithm>
#include <cmath>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

using support::message_number;
using support::significant;

// Adds a collapsed step to `e` (rebounding or not), or ends the episode.
void record(ChatterEpisode& e, bool collapsed, bool rebounded, double t0, double h, double U, double Omega) {
  e.slip = U;
  e.spin = Omega;
  if (!collapsed) {
    e.steps = 0;
    e.rebounds = 0;
    return;
  }
  if (e.steps == 0) {
    e.since = t0;
    e.min_step = e.max_step = h;
  }
  ++e.steps;
  if (rebounded) ++e.rebounds;
  e.min_step = std::min(e.min_step, h);
  e.max_step = std::max(e.max_step, h);
}

}  // namespace

void ChatterThresholds::validate() const {
  if (max_steps < 0)
    throw support::invalid_value("run.max_chatter_steps", static_cast<long long>(max_steps), "it must be >= 0 (0: never)");
  if (step && !(std::isfinite(*step) && *step > 0.0))
    throw support::invalid_value("run.chatter_step", *step, "it must be finite and > 0 s");
}

long ChatterRule::rebounds_needed() const {
  return static_cast<long>(std::ceil(kChatterReboundFraction * max_steps.value));
}

ChatterRule resolve_chatter(const ChatterThresholds& given, const RestRule& rest, const BodyScales& s) {
  const std::string note = "R = " + significant(s.size, 6) + " m (body size), g = " + significant(s.gravity, 6) + " m/s^2";
  return {given_threshold("run.max_chatter_steps", static_cast<double>(given.max_steps), "steps"),
          resolve_threshold("run.chatter_step", "s", given.step, kChatterStepFactor, 1.0 / s.rate, "sqrt(R/g)", note),
          rest.slip_speed, rest.spin};
}

std::string_view to_string(ChatterChannel c) {
  switch (c) {
    case ChatterChannel::slip: return "slip";
    case ChatterChannel::spin: return "spin";
    case ChatterChannel::none: break;
  }
  return "none";
}

ChatterWatch::ChatterWatch(const ChatterRule& rule) : rule_(rule), rebounds_needed_(rule.rebounds_needed()) {}

ChatterChannel ChatterWatch::update(const ChatterProbe& p) {
  const double h = p.t1 - p.t0;
  const double U = p.slip.norm();
  const double Omega = p.spin;
  const bool short_step = h < rule_.step.value;
  const bool slip_small = U < rule_.slip_speed.value;
  const bool spin_small = std::abs(Omega) < rule_.spin.value;
  // Grew, or turned by more than a right angle (for the spin: changed sign), since the last step.
  const bool slip_rebounded = has_previous_ && (U > previous_slip_.norm() || p.slip.dot(previous_slip_) < 0.0);
  const bool spin_rebounded =
      has_previous_ && (std::abs(Omega) > std::abs(previous_spin_) || Omega * previous_spin_ < 0.0);
  record(slip_, p.in_contact && short_step && slip_small && !spin_small, slip_rebounded, p.t0, h, U, Omega);
  record(spin_, p.in_contact && short_step && spin_small && !slip_small, spin_rebounded, p.t0, h, U, Omega);
  has_previous_ = true;
  previous_slip_ = p.slip;
  previous_spin_ = Omega;

  const long budget = static_cast<long>(rule_.max_steps.value);
  if (budget <= 0) return ChatterChannel::none;
  for (const ChatterEpisode* e : {&slip_, &spin_})
    if (e->steps >= budget && e->rebounds >= rebounds_needed_) return e->channel;
  return ChatterChannel::none;
}

std::string chatter_rule_text(ChatterChannel c) {
  if (c == ChatterChannel::spin)
    return "in contact, |Omega| < run.rest_spin while U >= run.rest_slip_speed, at each of run.max_chatter_steps "
           "accepted steps in a row, each shorter than run.chatter_step, |Omega| growing again or changing sign on "
           "at least a quarter of them";
  return "in contact, U < run.rest_slip_speed while |Omega| >= run.rest_spin, at each of run.max_chatter_steps "
         "accepted steps in a row, each shorter than run.chatter_step, the slip growing again or reversing its "
         "direction (turning by more than 90 degrees) on at least a quarter of them";
}

std::string chatter_message(const ChatterEpisode& e, const ChatterRule& rule, std::string_view law) {
  const bool spin = e.channel == ChatterChannel::spin;
  const std::string what = spin ? "the spin" : "the slip";
  const std::string small = spin ? "|Omega| stayed below run.rest_spin = " + message_number(rule.spin.value) +
                                       " 1/s (now Omega = " + message_number(e.spin) + " 1/s) while U = " +
                                       message_number(e.slip) + " m/s"
                                 : "U stayed below run.rest_slip_speed = " + message_number(rule.slip_speed.value) +
                                       " m/s (now " + message_number(e.slip) + " m/s) while |Omega| = " +
                                       message_number(std::abs(e.spin)) + " 1/s";
  const std::string rebound = spin ? "grew again or changed sign" : "grew again or reversed its direction";
  const std::string zero = spin ? "Omega = 0" : "U = 0";
  return what + " chattered: since t = " + message_number(e.since) + " s, for " + std::to_string(e.steps) +
         " accepted steps in a row, " + small + ", the steps shrank to " + message_number(e.min_step) + " .. " +
         message_number(e.max_step) + " s (below run.chatter_step = " + message_number(rule.step.value) + " s), and " +
         what + " " + rebound + " on " + std::to_string(e.rebounds) + " of them: friction law '" +
         std::string(law) + "' is discontinuous at " + zero +
         " and the contact is not held there, so the integrator can only chatter there with ever smaller steps; use "
         "a law continuous at " + zero + " (e.g. exact, ellipsoidal), or set run.max_chatter_steps = 0 to go on to "
         "run.max_steps";
}

}  // namespace frictionlab::dynamics
