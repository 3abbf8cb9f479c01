#include "dynamics/body/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dynamics/body/stick.h"
#include "dynamics/body/rocking_energy.h"
#include "dynamics/body/slip_hold.h"
#include "dynamics/body/tolerance_scales.h"
#include "dynamics/core/limit_set.h"
#include "dynamics/core/run_loop.h"
#include "dynamics/core/stick_rule.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

using support::message_number;

// The body's events between steps (docs/dynamics.md §5): lift-offs and landings, the settling of
// the contact, rest, stick (entry between steps, exit located inside the step), rolling and
// stagnation; and its records (min N, the drift of |gamma|, the stick counts).
class BodyOnPlane::Monitor {
 public:
  Monitor(const BodyOnPlane& sys, const RunOptions& options, RunSummary& s)
      : sys_(sys), options_(options), s_(s), settling_(resolve_settle(sys, options, s)), chatter_(s.chatter) {
    abs_scale_ = absolute_tolerance_scales(s.scales);
  }

  [[nodiscard]] StateVector tolerance_scales() const { return abs_scale_; }

  template <class Stop>
  After start(double t, StateVector& x, const ContactState& c0, BodyMode& mode, Stop&& /*stop*/) {
    s_.min_normal_force = c0.N;
    s_.max_gamma_drift = std::abs(vertical(x).norm() - 1.0);
    in_contact_ = c0.in_contact;
    settling_.update(t, c0.in_contact, c0.u.dot(c0.gamma));
    t_now_ = t;
    // Only with run.settle_time = 0 can a run start settled, and so start in stick.
    if (stick_may_enter(t, x, c0) && enter_stick(t, x, c0, mode)) return After::jumped;
    return After::go_on;
  }

  template <class Stop>
  bool before_step(double t, const StateVector& /*x*/, const BodyMode& /*mode*/, Stop&& /*stop*/) {
    t_now_ = t;
    return false;
  }

  // In stick: the first time inside the step at which the stick wrench leaves the law's limit set
  // (bisection on the step's samples, dynamics/core/step_sampler.h): the step ends there.
  template <class Step, class Sampler>
  bool locate(Step& step, Sampler& sampler, double& t, StateVector& x, BodyMode& mode) {
    if (mode.spin_hold) {
      // The spin held: the first time inside the step at which the moment that holds it leaves
      // what the law resists at zero spin.
      if (zero_spin_margin(x, 0.0, nullptr) >= 0.0) return false;
      const auto at = locate_first(step, sampler, [&](const StateVector& y) { return zero_spin_margin(y, 0.0, nullptr) < 0.0; });
      t = step.t1 = at.first;
      x = step.x1 = at.second;
      zero_spin_margin(x, 0.0, &spin_exit_);
      pending_spin_exit_ = true;
      return true;
    }
    if (mode.hold && hold_at_zero_) {
      // The zero slip held: the first time inside the step at which the force that holds it leaves
      // what the law resists at zero slip.
      const Eigen::Vector3d none = Eigen::Vector3d::Zero();
      if (zero_slip_margin(x, none, nullptr) >= 0.0) return false;
      const auto at =
          locate_first(step, sampler, [&](const StateVector& y) { return zero_slip_margin(y, none, nullptr) < 0.0; });
      t = step.t1 = at.first;
      x = step.x1 = at.second;
      zero_slip_margin(x, none, &slip_exit_);
      pending_slip_exit_ = true;
      return true;
    }
    if (!mode.stick) return false;
    const LimitSetTest at_end = stick_test(x, mode);
    if (at_end.inside()) {
      warm_ = at_end.direction;
      return false;
    }
    const auto at = locate_first(step, sampler, [&](const StateVector& y) { return !stick_test(y, mode).inside(); });
    t = step.t1 = at.first;
    x = step.x1 = at.second;
    exit_ = stick_test(x, mode);
    pending_exit_ = true;
    return true;
  }

  template <class Step, class Sampler, class Stop>
  After after_step(double t, StateVector& x, const ContactState& c, BodyMode& mode, Step& step,
                   Sampler& /*sampler*/, Stop&& stop) {
    RunSummary& s = s_;
    t_now_ = t;
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
    const double kinetic = motion_energy_(x, c);
    const auto stagnation_rule = [&](const char* energy_clause) {
      s.rule = std::string("settled contact (in contact with |eps'| < run.settle_normal_speed at every step of the "
                           "last run.settle_time), U < run.rest_slip_speed, |Omega| < run.rest_spin, energy of "
                           "motion (kinetic + rocking, dynamics/body/rocking_energy.h) ") +
               energy_clause;
      s.thresholds = {s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin, s.rest.kinetic_energy};
    };
    if (settled && s.rest.at_rest(c.in_contact, c.U, c.Omega, kinetic)) {
      stop(Termination::rest, "settled since t = " + message_number(settling_.since()) +
                                  " s; U = " + message_number(c.U) + " m/s, |Omega| = " +
                                  message_number(std::abs(c.Omega)) + " 1/s and energy of motion (kinetic + rocking) " +
                                  message_number(kinetic) + " J are below the rest thresholds");
      stagnation_rule("< run.rest_kinetic_energy");
      return After::stopped;
    }
    if (mode.stick) return stick_step(t, x, c, mode, stop);
    if (mode.hold) return hold_step(t, x, c, mode, t - step.t0);
    if (mode.spin_hold) return spin_hold_step(t, x, c, mode, t - step.t0);
    if (mode.spin_departing) {
      // The spin has started (or has turned back: the hold may take it again).
      if (!c.in_contact || std::abs(c.Omega) >= mode.departure_spin || !(c.Omega * mode.spin_exit > 0.0)) {
        mode.spin_departing = false;
        return After::jumped;
      }
    }
    // Creep (docs/dynamics.md §5): out of the stagnation region the slip's own direction is stiff no
    // more and the law sees it again.
    if (mode.departing && !s.rest.contact_stagnant(c.in_contact, c.U, c.Omega)) mode.departing = false;
    if (mode.slip_departing) {
      // The slip has started (or has turned back: the hold may take it again).
      const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
      if (!c.in_contact || c.U >= mode.departure_slip || !(slip.dot(mode.slip_exit) > 0.0)) {
        mode.slip_departing = false;
        return After::jumped;
      }
    }
    if (stick_may_enter(t, x, c)) {
      // Entry is tried at every step (a refusal costs one law evaluation when the wrench is outside
      // in the direction of the latest test); refused (the wrench it needs is outside the law's
      // limit set), the contact creeps at the limit in the direction of creep, which follows the
      // wrench from step to step (docs/dynamics.md §5).
      if (enter_stick(t, x, c, mode)) return After::jumped;
      const long unresolved = s.creep_unresolved;
      const After after = creep(x, c, mode);
      unresolved_in_row_ = s.creep_unresolved > unresolved ? unresolved_in_row_ + 1 : 0;
      if (s.chatter.max_steps.value > 0 && unresolved_in_row_ >= s.chatter.max_steps.value) {
        // No direction along which the slip can grow consistently with the law (LimitSet::creep_direction):
        // the slip's direction turns at a rate ~k g/|c| and the steps collapse, as in a chatter.
        stop(Termination::chatter,
             "the contact creeps at the limit of " + std::string(sys_.law().name()) + "'s set without a direction of creep: for " +
                 std::to_string(unresolved_in_row_) +
                 " steps in a row no slip/spin direction d had the slip's rate G (rho* - rho(d)) along d (the law's "
                 "resistance is not the gradient of its dissipation there), so the slip's direction turns at the "
                 "rate k g/|c| and the integrator only chatters (U = " + message_number(c.U) + " m/s, Omega = " +
                 message_number(c.Omega) + " 1/s)");
        s.rule = "creep at the limit (settled contact, U < run.rest_slip_speed, |Omega| < run.rest_spin, stick refused) "
                 "without a consistent direction of creep for run.max_chatter_steps accepted steps in a row";
        s.thresholds = {s.chatter.max_steps, s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin};
        return After::stopped;
      }
      return after;
    }
    unresolved_in_row_ = 0;
    if (hold_may_enter(t, x, c, mode, t - step.t0) && enter_hold(t, x, mode, t - step.t0)) return After::jumped;
    if (spin_hold_may_enter(x, c, mode) && enter_spin_hold(t, x, mode, t - step.t0)) return After::jumped;
    if (settled && options_.stop_when_rolling && s.rest.contact_stagnant(c.in_contact, c.U, c.Omega)) {
      stop(Termination::rolling, "the contact, settled since t = " + message_number(settling_.since()) +
                                     " s, neither slips (U = " + message_number(c.U) +
                                     " m/s) nor spins (Omega = " + message_number(c.Omega) +
                                     " 1/s) but the energy of motion (kinetic + rocking) " + message_number(kinetic) +
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

  void finish(const StateVector& /*x*/, const BodyMode& mode) {
    if (mode.stick) s_.stick_time += t_now_ - stick_since_;
    if (mode.hold) s_.hold_time += t_now_ - hold_since_;
    if (mode.spin_hold) s_.spin_hold_time += t_now_ - spin_hold_since_;
  }

 private:
  // Stick may be entered at (t, x): run.stick, a law whose limit set has an interior, and the
  // contact settled in the stagnation region with more kinetic energy than rest (rest is checked
  // first): exactly where the run stopped "rolling" before stick existed.
  bool stick_may_enter(double t, const StateVector& x, const ContactState& c) {
    if (!options_.stick || s_.stick_degenerate) return false;
    if (!(settling_.settled(t) && s_.rest.contact_stagnant(c.in_contact, c.U, c.Omega))) return false;
    if (s_.rest.at_rest(c.in_contact, c.U, c.Omega, motion_energy_(x, c))) return false;
    if (sys_.law().has_poles() || LimitSet(sys_.law(), sys_.plane().k, c.N, c.a, c.b).degenerate()) {
      // No limit set to hold the contact (no interior, or D is not a support function across a
      // pole of the law): the run goes on as without stick (docs/dynamics.md §5).
      s_.stick_degenerate = true;
      return false;
    }
    return true;
  }

  // The projection of the residue of slip and spin (dynamics/body/stick.h) at x: the velocities
  // jump, the kinetic energy removed is added to the friction work.
  void project(StateVector& x, const ContactState& c) {
    StickProblem p;
    p.mass = sys_.body().mass;
    p.inertia = sys_.inertia_tensor();
    p.r = c.point.r;
    p.gamma = c.gamma;
    p.omega = angular_velocity(x);
    p.u = c.u;
    const StickProjection j = stick_projection(p);
    velocity(x) += j.dv;
    angular_velocity(x) += j.domega;
    slide_work(x) += j.slide_loss;
    spin_work(x) += j.spin_loss;
    s_.stick_projection_loss += j.slide_loss + j.spin_loss;
    ++s_.stick_projections;
  }

  // Enters stick if the stick wrench at the projected state lies in the law's limit set.
  bool enter_stick(double t, StateVector& x, const ContactState& c, BodyMode& mode) {
    StateVector y = x;
    const long projections = s_.stick_projections;
    const double loss = s_.stick_projection_loss;
    project(y, c);
    BodyMode held = mode;
    held.stick = true;
    held.departing = false;
    const LimitSetTest test = stick_test(y, held, /*quick_reject=*/true);
    if (!test.inside()) {  // the contact cannot hold: it slips on
      s_.stick_projections = projections;
      s_.stick_projection_loss = loss;
      return false;
    }
    x = y;
    mode = held;
    warm_ = test.direction;
    ++s_.stick_entries;
    if (s_.stick_entries == 1) s_.first_stick_entry = t;
    stick_since_ = t;
    energy_at_entry_ = sys_.energy(x);
    return true;
  }

  // Between steps in stick: the located exit, the drift projection, the end in rolling.
  template <class Stop>
  After stick_step(double t, StateVector& x, const ContactState& c, BodyMode& mode, Stop&& stop) {
    RunSummary& s = s_;
    if (pending_exit_) {
      pending_exit_ = false;
      s.stick_time += t - stick_since_;
      ++s.stick_exits;
      if (s.stick_exits == 1) s.first_stick_exit = t;
      mode.stick = false;
      mode.departing = true;
      mode.departure_alpha = exit_.direction.alpha;
      mode.departure_beta = exit_.direction.beta;
      mode.departure_slip = s.rest.slip_speed.value;
      mode.departure_spin = s.rest.spin.value;
      return After::jumped;
    }
    if (c.U > kStickDriftFactor * s.rest.slip_speed.value || std::abs(c.Omega) > kStickDriftFactor * s.rest.spin.value) {
      project(x, c);
      return After::jumped;
    }
    const double energy = sys_.energy(x, c);
    if (!(std::abs(energy - energy_at_entry_) <= kStickEnergyDrift * s.rest.kinetic_energy.value)) {
      // Not constant: the hold starts again (the integrator's error over a long stick).
      s.stick_time += t - stick_since_;
      stick_since_ = t;
      energy_at_entry_ = energy;
    }
    if (options_.stop_when_rolling && t - stick_since_ >= s.stick_hold.value) {
      stop(Termination::rolling,
           "the body has rolled without slip and spin (stick) since t = " + message_number(stick_since_) +
               " s with its energy constant (" + message_number(energy) + " J, kinetic " +
               message_number(kinetic_energy_(x)) + " J, above run.rest_kinetic_energy = " +
               message_number(s.rest.kinetic_energy.value) + " J), its friction wrench inside the law's limit set");
      s.rule = "in stick (entered in settled contact with U < run.rest_slip_speed and |Omega| < run.rest_spin) "
               "without a break for run.stick_hold_time, the energy within 1e-3 run.rest_kinetic_energy of its "
               "value at entry";
      s.thresholds = {s.stick_hold, s.settle.time, s.settle.normal_speed, s.rest.slip_speed, s.rest.spin,
                      s.rest.kinetic_energy};
      return After::stopped;
    }
    return After::go_on;
  }

  // Creep at the limit, after a refused entry: on the first such step the residue of slip and spin
  // is removed (as at an entry: its energy counts as friction work) and the law is evaluated in
  // the direction of creep from then on (BodyMode::departing), where the slip grows along its own
  // direction; on later steps that direction follows the wrench (a local search from the last).
  After creep(StateVector& x, const ContactState& c, BodyMode& mode) {
    if (!mode.departing) {
      StateVector y = x;
      project(y, c);
      BodyMode held = mode;
      held.stick = true;
      const LimitSetTest test = stick_test(y, held, /*quick_reject=*/false, /*follow=*/false, /*creep=*/true);
      if (test.inside()) return After::go_on;  // the quick test of the entry erred: retry next step
      x = y;
      mode.departing = true;
      mode.departure_slip = s_.rest.slip_speed.value;
      mode.departure_spin = s_.rest.spin.value;
      set_direction(mode, test.direction);
      ++s_.creep_entries;
      return After::jumped;
    }
    BodyMode held = mode;
    held.stick = true;
    held.departing = false;
    const LimitSetTest test = stick_test(x, held, /*quick_reject=*/false, /*follow=*/true, /*creep=*/true);
    if (test.direction.alpha == mode.departure_alpha && test.direction.beta == mode.departure_beta) return After::go_on;
    set_direction(mode, test.direction);
    return After::jumped;
  }
  void set_direction(BodyMode& mode, const SlipDirection& d) {
    mode.departure_alpha = d.alpha;
    mode.departure_beta = d.beta;
    warm_ = d;
  }

  // The slip held on its slow manifold (dynamics/body/slip_hold.h; docs/dynamics.md §5 "slip hold").
  // The body's slow time: its pendulum time sqrt(R/g), or a turn of its rotation if faster.
  double slow_time(const StateVector& x) const {
    const double turn = angular_velocity(x).norm();
    return std::min(1.0 / s_.scales.rate, turn > 0.0 ? 1.0 / turn : std::numeric_limits<double>::infinity());
  }
  // Cheap gates first: run.slip_hold, settled contact, spin above run.rest_spin, a slip ratio below
  // kHoldEntryRatio; then the slip's relaxation rate lambda (the law's secant stiffness |F|/U times
  // the slip response): stiff against the body's slow time (lambda T >= kHoldStiffness: the
  // reduction is accurate) and against the step just taken (lambda h >= kHoldStepStiffness: the
  // integrator's steps are held by it).
  // A law discontinuous at zero slip (slip_hold.h) is held at zero slip instead, from where its
  // slip has fallen below run.rest_slip_speed, settled or not (the hold is then the law's own
  // sliding mode, not a reduction); whether the law is discontinuous is read once, at the first
  // state that passes the cheap gates (one law evaluation).
  bool hold_may_enter(double t, const StateVector& x, const ContactState& c, const BodyMode& mode, double h) {
    if (!options_.slip_hold || mode.departing) return false;
    if (!c.in_contact || !(c.N > 0.0) || !(c.a > 0.0)) return false;
    const double spin = std::abs(c.Omega);
    const bool small_slip = c.U < s_.rest.slip_speed.value;
    const bool on_manifold = c.U > 0.0 && c.U < kHoldEntryRatio * c.a * spin;
    if (!(spin >= s_.rest.spin.value) || !(small_slip || on_manifold)) return false;
    if (law_jumps_ < 0) {
      ContactState free;
      sys_.contact_state(x, free, false);
      law_jumps_ = zero_slip_resistance(sys_, free, free.major) >= kDiscontinuousResistance * sys_.plane().k * free.N;
    }
    hold_at_zero_ = law_jumps_ == 1;
    if (hold_at_zero_) return small_slip;  // also while the slip starts after an exit: it may stop again
    if (!on_manifold || mode.slip_departing || !settling_.settled(t)) return false;
    ContactState free;
    sys_.contact_state(x, free, false);
    const double secant = std::hypot(c.friction.F1, c.friction.F2) / c.U;
    const double lambda = largest_slip_response(sys_.stick_problem(x, free), free.major) * secant;
    return lambda * slow_time(x) >= kHoldStiffness && lambda * h >= kHoldStepStiffness;
  }
  // Solves for the held slip w* from the state's slip; refused where there is none or where the
  // relaxation at w* is not stiff enough.
  bool enter_hold(double t, StateVector& x, BodyMode& mode, double h) {
    if (hold_at_zero_) {
      // The slip's residue closes over a step like the last, or kZeroClosing of the slow time if
      // longer (the steps of a chattering slip are tiny): entered only where the force that does
      // that is within what the law resists (else the law brings the slip closer first).
      ContactState free;
      sys_.contact_state(x, free, false);
      const Eigen::Vector3d closing = -(free.u - free.u.dot(free.gamma) * free.gamma) / zero_closing_time(x, h);
      if (!(zero_slip_margin(x, closing, nullptr) >= 0.0)) return false;
      mode.hold = true;
      mode.slip_departing = false;
      drift_.setZero();
      held_.setZero();
      mode.slip_rate = closing;
      held_at_ = t;
      hold_since_ = t;
      ++s_.hold_entries;
      ++s_.hold_zero_entries;
      if (s_.hold_entries == 1) s_.first_hold_entry = t;
      return true;
    }
    ContactState free;
    sys_.contact_state(x, free, false);
    const StickProblem p = sys_.stick_problem(x, free);
    const Eigen::Vector3d slip = free.u - free.u.dot(free.gamma) * free.gamma;
    const HeldSlip held = held_slip(sys_, free, p, Eigen::Vector3d::Zero(), slip);
    s_.hold_evaluations += held.evaluations;
    if (!held.found || held.stiffness * slow_time(x) < kHoldStiffness) return false;
    mode.hold = true;
    drift_.setZero();
    mode.slip_rate = (held.slip - slip) / h;  // the slip reaches w* over a step like the last
    held_ = held.slip;
    held_at_ = t;
    hold_since_ = t;
    ++s_.hold_entries;
    if (s_.hold_entries == 1) s_.first_hold_entry = t;
    return true;
  }
  // Between steps in the mode: leave it where the contact opens or unsettles, the spin falls below
  // run.rest_spin (the stagnation region, where stick takes over), or the manifold is lost or no
  // longer stiff; otherwise the slip's rate for the next step is the rate of w* since the last
  // step plus the rate that closes the slip's gap to w* over a step like the last (no impulse: the
  // holding force does that work, and it is friction's).
  After hold_step(double t, StateVector& x, const ContactState& c, BodyMode& mode, double h) {
    const auto leave = [&] {
      mode.hold = false;
      mode.slip_rate.setZero();
      s_.hold_time += t - hold_since_;
      ++s_.hold_exits;
      return After::jumped;
    };
    if (pending_slip_exit_) {
      // The force that holds the zero slip reached what the law resists there (located): the slip
      // starts in the direction of that force's deficit.
      pending_slip_exit_ = false;
      ++s_.hold_force_exits;
      if (s_.hold_force_exits == 1) s_.first_force_exit = t;
      mode.slip_departing = true;
      mode.slip_exit = slip_exit_;
      mode.departure_slip = s_.rest.slip_speed.value;
      return leave();
    }
    if (!c.in_contact || !(c.N > 0.0) || !(c.a > 0.0) || !(std::abs(c.Omega) >= s_.rest.spin.value) ||
        (!hold_at_zero_ && !settling_.settled(t))) {
      return leave();
    }
    if (hold_at_zero_) {
      ContactState free;
      sys_.contact_state(x, free, false);
      mode.slip_rate = -(free.u - free.u.dot(free.gamma) * free.gamma) / zero_closing_time(x, h);
      return After::jumped;
    }
    ContactState free;
    sys_.contact_state(x, free, false);
    const StickProblem p = sys_.stick_problem(x, free);
    const Eigen::Vector3d slip = free.u - free.u.dot(free.gamma) * free.gamma;
    const HeldSlip held = held_slip(sys_, free, p, drift_, slip);
    s_.hold_evaluations += held.evaluations;
    if (!held.found || held.stiffness * slow_time(x) < kHoldStayFactor * kHoldStiffness) return leave();
    drift_ = t > held_at_ ? Eigen::Vector3d((held.slip - held_) / (t - held_at_)) : Eigen::Vector3d::Zero();
    mode.slip_rate = drift_ + (held.slip - slip) / h;
    held_ = held.slip;
    held_at_ = t;
    return After::jumped;  // the slip's rate changed: the steps start afresh
  }

  // The time over which the zero slip's residue closes: the step just taken, or kZeroClosing of the
  // body's slow time if longer.
  static constexpr double kZeroClosing = 1e-3;
  double zero_closing_time(const StateVector& x, double h) const { return std::max(h, kZeroClosing * slow_time(x)); }

  // At zero slip held (a law discontinuous there): what the law resists in the direction e in which
  // the slip would start (zero_slip_resistance) less the size of the force that sets the slip's rate
  // to `slip_rate` with the law's spin moment (slip_hold_force; zero: the force that holds the slip
  // at zero), N; e = -F/|F| is written to `exit` if given. Exact for a law whose resistance at zero
  // slip is the same in every direction (the disk |F| <= kN of `decoupled`); -inf out of contact.
  double zero_slip_margin(const StateVector& x, const Eigen::Vector3d& slip_rate, Eigen::Vector3d* exit) const {
    ContactState free;
    sys_.contact_state(x, free, false);
    if (!free.in_contact || !(free.N > 0.0) || !(free.a > 0.0)) return -std::numeric_limits<double>::infinity();
    const StickProblem p = sys_.stick_problem(x, free);
    const Eigen::Vector3d slip = free.u - free.u.dot(free.gamma) * free.gamma;
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const double M = sys_.law_at_slip(free, slip, free.Omega, e1, psi).M;
    const SlipHoldForce hold = slip_hold_force(p, slip_rate);
    const Eigen::Vector3d F = hold.force0 + M * hold.force_per_M;
    const double size = F.norm();
    const Eigen::Vector3d e = size > 0.0 ? Eigen::Vector3d(-F / size) : free.major;
    if (exit) *exit = e;
    return zero_slip_resistance(sys_, free, e) - size;
  }

  // The spin of a law discontinuous in the spin held at zero (slip_hold.h), the mirror of the zero
  // slip's hold: entered where |Omega| < run.rest_spin while the body slips (U >= run.rest_slip_speed:
  // both small is stick's), the law discontinuous in the spin (read once) and the moment that closes
  // the spin's residue within the closing time inside the law's limit; left where that moment
  // reaches the limit (located), the body stops slipping, or the contact opens.
  bool spin_hold_may_enter(const StateVector& x, const ContactState& c, const BodyMode& mode) {
    if (!options_.slip_hold || mode.departing || mode.hold || mode.spin_hold) return false;
    if (!c.in_contact || !(c.N > 0.0) || !(c.a > 0.0)) return false;
    if (!(std::abs(c.Omega) < s_.rest.spin.value) || !(c.U >= s_.rest.slip_speed.value)) return false;
    if (law_spin_jumps_ < 0) {
      ContactState free;
      sys_.contact_state(x, free, false);
      law_spin_jumps_ =
          zero_spin_resistance(sys_, free, 1.0) >= kDiscontinuousResistance * sys_.plane().k * free.N * free.a;
    }
    return law_spin_jumps_ == 1;
  }
  bool enter_spin_hold(double t, StateVector& x, BodyMode& mode, double h) {
    ContactState free;
    sys_.contact_state(x, free, false);
    const double closing = -free.Omega / zero_closing_time(x, h);
    if (!(zero_spin_margin(x, closing, nullptr) >= 0.0)) return false;
    mode.spin_hold = true;
    mode.spin_departing = false;
    mode.spin_rate = closing;
    spin_hold_since_ = t;
    ++s_.spin_hold_entries;
    if (s_.spin_hold_entries == 1) s_.first_spin_hold_entry = t;
    return true;
  }
  After spin_hold_step(double t, StateVector& x, const ContactState& c, BodyMode& mode, double h) {
    const auto leave = [&] {
      mode.spin_hold = false;
      mode.spin_rate = 0.0;
      s_.spin_hold_time += t - spin_hold_since_;
      ++s_.spin_hold_exits;
      return After::jumped;
    };
    if (pending_spin_exit_) {
      pending_spin_exit_ = false;
      ++s_.spin_moment_exits;
      mode.spin_departing = true;
      mode.spin_exit = spin_exit_;
      mode.departure_spin = s_.rest.spin.value;
      return leave();
    }
    if (!c.in_contact || !(c.N > 0.0) || !(c.a > 0.0) || !(c.U >= s_.rest.slip_speed.value)) return leave();
    mode.spin_rate = -c.Omega / zero_closing_time(x, h);
    return After::jumped;
  }
  // What the law resists at zero spin with the sign of the spin that would start (zero_spin_resistance)
  // less the size of the moment that sets the spin's rate to `spin_rate` with the law's force at zero
  // spin (spin_hold_moment), N m; that sign, sign(M), is written to `exit` if given; -inf out of contact.
  double zero_spin_margin(const StateVector& x, double spin_rate, double* exit) const {
    ContactState free;
    sys_.contact_state(x, free, false);
    if (!free.in_contact || !(free.N > 0.0) || !(free.a > 0.0)) return -std::numeric_limits<double>::infinity();
    const Eigen::Vector3d slip = free.u - free.u.dot(free.gamma) * free.gamma;
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const friction::FrictionForces f = sys_.law_at_slip(free, slip, 0.0, e1, psi);
    const double M = spin_hold_moment(sys_.stick_problem(x, free), -f.F1 * e1 - f.F2 * free.gamma.cross(e1), spin_rate);
    const double sign = M < 0.0 ? -1.0 : 1.0;
    if (exit) *exit = sign;
    return zero_spin_resistance(sys_, free, sign) - std::abs(M);
  }

  // The metric of the direction of creep at the contact c (dynamics/core/limit_set.h): Q = (S G S)^-1
  // for the slip response G (dynamics/body/stick.h) in the patch frame (major axis, gamma x major,
  // spin) and S = diag(1, 1, a), which scales it to the coordinates (u_t, a Omega).
  Eigen::Matrix3d creep_metric(const ContactState& c) const {
    StickProblem p;
    p.mass = sys_.body().mass;
    p.inertia = sys_.inertia_tensor();
    p.r = c.point.r;
    p.gamma = c.gamma;
    const Eigen::Matrix3d G = slip_response(p, c.major);
    const Eigen::DiagonalMatrix<double, 3> S(1.0, 1.0, c.a);
    return (S * G * S).inverse();
  }

  // The stick wrench at x (in stick) against the law's limit set; margin -inf out of contact.
  // With quick_reject, a negative margin in the direction of the latest test (one law evaluation)
  // answers "outside" at once: the entry attempts of a creeping contact cost that much.
  // The direction returned is the direction of creep (weighted by creep_metric); with `follow`,
  // only the local search from the latest direction runs.
  // With `creep`, a wrench outside gets the direction of creep of the slow manifold
  // (LimitSet::creep_direction, from the search's direction): for a law of maximum dissipation the
  // same direction, for another law its own where the search's is not consistent.
  LimitSetTest stick_test(const StateVector& x, const BodyMode& mode, bool quick_reject = false, bool follow = false,
                          bool creep = false) {
    ContactState c;
    sys_.contact(x, mode, c);
    LimitSetTest out;
    out.margin = -std::numeric_limits<double>::infinity();
    if (!c.in_contact || !(c.N > 0.0) || !(c.a > 0.0)) return out;
    const LimitSet set(sys_.law(), sys_.plane().k, c.N, c.a, c.b);
    const Eigen::Vector3d minor = c.gamma.cross(c.major);
    const Eigen::Vector3d rho = c.friction.F1 * c.e1 + c.friction.F2 * c.gamma.cross(c.e1);
    const PatchWrench w{rho.dot(c.major), rho.dot(minor), c.friction.M};
    if (quick_reject) {
      const double m = set.margin_at(w, warm_);
      ++s_.limit_set_evaluations;
      if (!(m >= 0.0)) {
        out.margin = m;
        out.direction = warm_;
        return out;
      }
    }
    const Eigen::Matrix3d metric = creep_metric(c);
    out = follow ? set.follow(w, warm_, metric) : set.test(w, &warm_, metric);
    s_.limit_set_evaluations += out.evaluations;
    if (creep && !out.inside()) {
      bool found = false;
      long evaluations = 0;
      const SlipDirection d = set.creep_direction(w, out.direction, metric.inverse(), found, evaluations);
      s_.limit_set_evaluations += evaluations;
      if (found) {
        out.direction = d;
      } else {
        ++s_.creep_unresolved;
      }
    }
    return out;
  }

  // Resolves the body's scales and thresholds into the summary; the settling rule.
  static const SettleRule& resolve_settle(const BodyOnPlane& sys, const RunOptions& options, RunSummary& s) {
    s.scales = body_scales(sys.body(), sys.plane());
    s.rest = resolve_rest(options.rest, s.scales);
    s.settle = resolve_settling(options.settle, s.scales);
    s.chatter = resolve_chatter(options.chatter, s.rest, s.scales);
    s.stick_hold = resolve_stick_hold(options.stick_hold_time, s.scales, s.settle.time.value);
    return s.settle;
  }
  double kinetic_energy_(const StateVector& x) const { return sys_.kinetic_energy(x); }
  // What the rest rule compares with run.rest_kinetic_energy: the kinetic energy and the rocking's
  // potential energy (dynamics/body/rocking_energy.h), so that a turning point of a rocking, where
  // the kinetic energy, the slip and the spin pass near zero together, is not taken for rest.
  double motion_energy_(const StateVector& x, const ContactState& c) const {
    return sys_.kinetic_energy(x) + rocking_energy(c.point.r, c.gamma, c.point.R_meridian, c.point.R_parallel,
                                                   sys_.body().mass, sys_.plane().g);
  }

  const BodyOnPlane& sys_;
  const RunOptions& options_;
  RunSummary& s_;
  ContactSettling settling_;
  ChatterWatch chatter_;
  StateVector abs_scale_;
  bool in_contact_ = false;
  long stagnant_unsettled_ = 0;  // accepted steps in a row in the stagnation region, not settled
  long unresolved_in_row_ = 0;   // accepted steps in a row of creep without a consistent direction
  // Stick.
  static constexpr double kStickEnergyDrift = 1e-3;  // of run.rest_kinetic_energy: "constant" in the hold rule
  double t_now_ = 0.0;
  double stick_since_ = 0.0;      // start of the current stick (or of its hold window)
  double energy_at_entry_ = 0.0;  // J, at stick_since_
  SlipDirection warm_;            // the latest minimising direction: the next search starts there
  bool pending_exit_ = false;     // locate() found an exit: after_step leaves stick
  // Slip hold.
  double hold_since_ = 0.0;       // start of the current hold
  Eigen::Vector3d held_ = Eigen::Vector3d::Zero();  // w* at the latest solve (body frame, m/s)
  double held_at_ = 0.0;          // its time
  Eigen::Vector3d drift_ = Eigen::Vector3d::Zero();  // w*'s own rate, m/s^2 (the manifold's slip rate)
  int law_jumps_ = -1;            // the law is discontinuous at zero slip: 1 yes, 0 no, -1 not read yet
  int law_spin_jumps_ = -1;       // the law is discontinuous at zero spin: likewise
  double spin_hold_since_ = 0.0;  // start of the current spin hold
  bool pending_spin_exit_ = false;  // locate() found the spin hold's exit
  double spin_exit_ = 0.0;        // the sign with which the spin starts there
  bool hold_at_zero_ = false;     // the mode holds the zero slip (a law discontinuous there)
  bool pending_slip_exit_ = false;  // locate() found the zero slip's exit: after_step leaves the hold
  Eigen::Vector3d slip_exit_ = Eigen::Vector3d::Zero();  // the direction in which the slip starts there
  LimitSetTest exit_;
};

MotionPhaseRule motion_phase_rule(const BodyOnPlane& sys, const RunOptions& options) {
  const BodyScales scales = body_scales(sys.body(), sys.plane());
  const RestRule rest = resolve_rest(options.rest, scales);
  MotionPhaseRule rule;
  rule.rest_slip_speed = rest.slip_speed.value;
  rule.rest_spin = rest.spin.value;
  rule.settle_normal_speed = resolve_settling(options.settle, scales).normal_speed.value;
  return rule;
}

RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options, Observer* observer) {
  return run_model(sys, x0, options, observer);
}

}  // namespace frictionlab::dynamics
