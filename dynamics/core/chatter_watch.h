#pragma once
// Watches a run for the chatter of a friction law that is discontinuous where the slip or the
// spin passes through 0 (docs/dynamics.md §5, reason "chatter"). Model- and law-agnostic: it reads
// only what each accepted step ended with (its size, whether the contact is closed, the slip
// velocity of the contact and its spin) and knows nothing of the equations.
//
// Why. A law whose force keeps its full size however small the slip (`decoupled`: F1 = kN along
// the slip; its spin moment M0 sign(Omega) likewise), when nothing holds the contact where the
// slip reaches 0 while the spin does not (or the reverse: the body holds a stopped slip or spin
// where the law's limit allows it, with run.slip_hold, dynamics/body/slip_hold.h), jumps whenever the slip
// passes through 0, and an adaptive integrator follows it with steps of ~tol sqrt(R/g)/(c k) and
// below (tol the integrator's tolerance, c ~ 1..4 from the inertia; 1e-11 to 1e-8 s in the
// shipped runs). The stagnation event
// (dynamics/body/simulation.h) needs both the slip and the spin small, so without this watch such a run
// was bounded only by run.max_steps: egg-homogeneous case c with `decoupled:r_spin=0` took 6.27 M
// steps (162 s of wall time) for 2 simulated seconds.
//
// The rule, per channel (slip: the vector U e1; spin: Omega). An accepted step "collapses" in the
// slip channel when at its end the contact is closed, U < slip_speed while |Omega| >= spin (both
// small is the stagnation region, left to rest, rolling and stagnation), and the step is shorter
// than `step`; it "rebounds" when the slip grew since the previous accepted step or turned by more
// than a right angle (slip . slip_prev < 0). The spin channel is the same with the roles exchanged
// (|Omega| < spin while U >= slip_speed; a rebound: |Omega| grew or changed sign). The watch fires
// when `max_steps` accepted steps in a row collapse in one channel and at least a quarter of them
// (kChatterReboundFraction, rounded up) rebound. A smooth law takes the slip to 0 with steps far
// above `step`, and monotonically: it neither collapses nor rebounds. A chatter does both: the slip
// either flips through 0 (the sphere of sphere-slide-spin) or stays at ~1e-9 m/s in a sawtooth,
// growing on every other step (egg-printed case c; a test of reversals alone would take 15 000
// steps there). Measured on the decoupled runs of every shipped body scenario (both r_spin
// variants, 2026-11-28): the slip rebounds on 49-63 % of the chattering steps (reverses on 0.6-50 %).
//
// Defaults (dynamics/core/scales.h, R the body's size):
//   max_steps  1000 steps: the chatter is caught within ~1e-6 s of simulated time and ~0.1 s of
//              wall time; run.max_stagnant_steps is the same budget for the stagnation region.
//   step       3e-6 sqrt(R/g) (egg 4.9e-7 s, 5 cm sphere 2.1e-7 s, the tippe top 1.3e-7 s). Two
//              step sizes bound it. The chattering steps, ~tol sqrt(R/g)/(c k) and below, were
//              1e-11 to 1e-8 s in the decoupled runs of the shipped scenarios at the default
//              tolerances 1e-9: at most 1/15 of `step`. A smooth law near U = 0 is stiff when
//              the spin is slow (F1 ~ kN U/(a |Omega|)): its steps stop at the stepper's
//              stability limit, a few a |Omega|/(c k g), whatever the tolerance; every step of a
//              smooth law that the watch looks at (the slip or the spin below its bound, the
//              other not) was >= 3.2e-6 s, 25 `step`s (the printed Padé law on the tippe top, as
//              it rolls to its end). Hence a fixed fraction of sqrt(R/g), not one that follows the
//              tolerance: scaled as 3e3 tol sqrt(R/g), at tolerances 1e-6 it stopped that Padé run
//              0.14 s before its end, in its stiff, stability-limited steps of 1.4e-5..1.3e-4 s
//              whose slip oscillates. At tolerances looser than ~1e-8 the chattering steps pass
//              `step` and the run is bounded by run.max_steps as before (its steps are longer,
//              so it is cheaper); a given run.chatter_step catches it, if kept below the stiff
//              steps of the laws compared.
// The slip and spin bounds are the rest thresholds (run.rest_slip_speed, run.rest_spin: 0 disables
// the channel that compares against them).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

#include "dynamics/core/scales.h"
#include "dynamics/core/rest_event.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics {

inline constexpr long kDefaultMaxChatterSteps = 1000;  ///< default run.max_chatter_steps
inline constexpr double kChatterStepFactor = 3e-6;     ///< default run.chatter_step / sqrt(R/g)
inline constexpr double kChatterReboundFraction = 0.25;  ///< rebounds needed per collapsed step

/// What the scenario says ([run] max_chatter_steps, chatter_step); an unset step takes the scaled
/// default above.
struct ChatterThresholds {
  long max_steps = kDefaultMaxChatterSteps;  ///< run.max_chatter_steps, >= 0 (0: never)
  std::optional<double> step;                ///< run.chatter_step, s, > 0

  /// Throws std::invalid_argument naming the key and the rule.
  void validate() const;
};

/// The thresholds as applied to one run.
struct ChatterRule {
  Threshold max_steps;   ///< run.max_chatter_steps, steps (0: never)
  Threshold step;        ///< run.chatter_step, s
  Threshold slip_speed;  ///< run.rest_slip_speed, m/s
  Threshold spin;        ///< run.rest_spin, 1/s

  /// The rebounds a run of max_steps collapsed steps needs: ceil(kChatterReboundFraction max_steps).
  [[nodiscard]] long rebounds_needed() const;
};

[[nodiscard]] ChatterRule resolve_chatter(const ChatterThresholds& given, const RestRule& rest,
                                          const BodyScales& scales);

/// What an accepted step ended with.
struct ChatterProbe {
  double t0 = 0.0;               ///< s, the step's start
  double t1 = 0.0;               ///< s, its end
  bool in_contact = false;       ///< the contact is closed at t1
  Eigen::Vector3d slip = Eigen::Vector3d::Zero();  ///< m/s, the slip velocity U e1 at t1 (any frame
                                                   ///< that turns little within a step)
  double spin = 0.0;             ///< 1/s, Omega at t1
};

enum class ChatterChannel { none, slip, spin };

/// "slip", "spin" ("none" for none).
[[nodiscard]] std::string_view to_string(ChatterChannel c);

/// The current run of collapsed steps of one channel.
struct ChatterEpisode {
  ChatterChannel channel = ChatterChannel::none;
  long steps = 0;           ///< collapsed steps in a row
  long rebounds = 0;        ///< of which rebounded (the slip grew or reversed; |Omega| grew or changed sign)
  double since = 0.0;       ///< s, the start of the first of them
  double min_step = 0.0;    ///< s, the shortest and longest of them
  double max_step = 0.0;
  double slip = 0.0;        ///< m/s, U at the latest step
  double spin = 0.0;        ///< 1/s, Omega at the latest step
};

/// Follows the accepted steps of one run.
class ChatterWatch {
 public:
  explicit ChatterWatch(const ChatterRule& rule);

  /// Records an accepted step (in order). Returns the channel that has now chattered for the
  /// budget (the run should stop), or none.
  ChatterChannel update(const ChatterProbe& p);

  [[nodiscard]] const ChatterEpisode& episode(ChatterChannel c) const { return c == ChatterChannel::spin ? spin_ : slip_; }

 private:
  ChatterRule rule_;
  long rebounds_needed_;
  bool has_previous_ = false;
  Eigen::Vector3d previous_slip_ = Eigen::Vector3d::Zero();
  double previous_spin_ = 0.0;
  ChatterEpisode slip_{ChatterChannel::slip};
  ChatterEpisode spin_{ChatterChannel::spin};
};

/// The rule of a channel in words (summary.json termination.rule).
[[nodiscard]] std::string chatter_rule_text(ChatterChannel c);

/// Why the run stopped, what to do, in one line: `law` is the friction law's name.
[[nodiscard]] std::string chatter_message(const ChatterEpisode& e, const ChatterRule& rule, std::string_view law);

}  // namespace frictionlab::dynamics
