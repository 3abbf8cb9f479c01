#pragma once
// Shadow laws: other friction laws evaluated along a run at the contact of every state the run
// visits, without changing the run (the run's own law drives the motion). The question they answer
// is how wrong a law's friction is *along a motion*: at the states a real motion passes through, in
// the proportions it spends there (docs/dynamics.md §10).
//
// At a state with the contact input `in` (U, Omega, a, b, psi, N, k: bit for bit what the run's law
// saw) and the run's law L0, each shadow law L gives, per unit of the scales every law shares,
//   dF1 = (F1_L - F1_L0)/(k N),  dF2 = (F2_L - F2_L0)/(k N),  dM = (M_L - M_L0)/(k N a),
//   dF  = hypot(dF1, dF2)  (the error of the tangential force as a vector),
//   dP  = (F1_L - F1_L0) U + (M_L - M_L0) Omega  (W: the difference in dissipated power).
// A shadow law that throws or returns a non-finite value at a state (a pole of pade-printed) gives
// NaN there, which is counted, and the run goes on.
//
// Statistics (record_step): at the end of every accepted step, weighted by the step's length, so
// that each phase of the motion (dynamics/core/motion_phase.h) counts by the time it lasts, not by
// how many steps the integrator needed there (a bounce takes hundreds of steps a millisecond). The
// median, 95th percentile and largest |error| per law, per output and per phase
// (dynamics/core/log_histogram.h: quantiles within 2.3 %, the largest exact), and the energy each
// law would have dissipated along the same path: the run's own dissipation (its friction work,
// integrated with the state) plus the integral of dP, by the trapezoidal rule over the accepted
// steps. The rule is applied to the difference only: on the run's own power it is ~1 % off over a
// bouncing egg's steps (the check own_dissipated() against the work), on dP, far smaller and as
// smooth, proportionally less.

#include <array>
#include <span>
#include <string>
#include <vector>

#include "dynamics/core/log_histogram.h"
#include "dynamics/core/motion_phase.h"
#include "dynamics/core/shadow_point.h"
#include "friction/law.h"

namespace frictionlab::dynamics {

/// One shadow law's errors at one state (see the header comment); NaN where it failed.
struct ShadowError {
  double dF1 = 0.0;
  double dF2 = 0.0;
  double dF = 0.0;
  double dM = 0.0;
  double dP = 0.0;  ///< W
};

/// The outputs whose |error| the statistics follow, in this order: dF1, dF2, dF, dM, dP.
inline constexpr int kShadowOutputs = 5;
/// "F1", "F2", "F", "M", "P".
[[nodiscard]] const std::array<const char*, kShadowOutputs>& shadow_output_names();

/// The statistics of one shadow law over a run.
struct ShadowLawStatistics {
  /// [phase][output]: |error| weighted by time; phase kMotionPhases is every contact state.
  std::array<std::array<LogHistogram, kShadowOutputs>, kMotionPhases + 1> errors;
  long failures = 0;               ///< states where the law threw or returned non-finite values
  double first_failure_time = -1;  ///< s; negative if none
  std::string first_failure;       ///< what the law said there
  double difference = 0.0;         ///< J: trapezoidal rule of dP over the accepted steps
  double skipped_time = 0.0;       ///< s of steps left out of `difference` (a failure at an end)
};

class ShadowLaws {
 public:
  /// `own`: the run's law; `shadows`: the laws to evaluate beside it (non-null; they and `own`
  /// outlive this). `rule`: the phases' thresholds for this run.
  ShadowLaws(const friction::FrictionLaw& own, std::vector<const friction::FrictionLaw*> shadows,
             const MotionPhaseRule& rule);

  [[nodiscard]] std::size_t size() const { return shadows_.size(); }
  [[nodiscard]] const friction::FrictionLaw& law(std::size_t i) const { return *shadows_[i]; }
  [[nodiscard]] const friction::FrictionLaw& own() const { return own_; }
  [[nodiscard]] const MotionPhaseRule& rule() const { return rule_; }

  /// The phase of a state (the rule's).
  [[nodiscard]] MotionPhase phase(const ShadowPoint& p) const;
  /// Every shadow law's errors at p, into out[0..size()); all zero out of contact. Never throws.
  void evaluate(const ShadowPoint& p, std::span<ShadowError> out) const;

  /// Records the state at the end of an accepted step at time t (non-decreasing; the first call
  /// opens the record at its time). Never throws.
  void record_step(double t, const ShadowPoint& p);

  [[nodiscard]] const ShadowLawStatistics& statistics(std::size_t i) const { return stats_[i]; }
  /// The run's own law along the same steps: J dissipated by the trapezoidal rule (a check of the
  /// rule against the run's friction work).
  [[nodiscard]] double own_dissipated() const { return own_dissipated_; }
  /// Time spent in each phase, s (step lengths, by the phase at the step's end).
  [[nodiscard]] const std::array<double, kMotionPhases>& phase_time() const { return phase_time_; }
  /// Accepted steps recorded (after the opening state).
  [[nodiscard]] long steps() const { return steps_; }
  /// States where the run's own law could not be evaluated at the input (a held contact): their
  /// errors are NaN for every law.
  [[nodiscard]] long own_failures() const { return own_failures_; }

 private:
  // The run's law at p (p.own if known); false if it failed.
  bool own_forces(const ShadowPoint& p, friction::FrictionForces& f) const;

  const friction::FrictionLaw& own_;
  std::vector<const friction::FrictionLaw*> shadows_;
  MotionPhaseRule rule_;
  std::vector<ShadowLawStatistics> stats_;
  std::vector<ShadowError> scratch_;
  std::vector<double> last_dP_;  // each law's dP at the previous step (NaN: failed)
  double last_own_power_ = 0.0;
  double own_dissipated_ = 0.0;
  std::array<double, kMotionPhases> phase_time_{};
  double last_t_ = 0.0;
  bool opened_ = false;
  long steps_ = 0;
  long own_failures_ = 0;
};

}  // namespace frictionlab::dynamics
