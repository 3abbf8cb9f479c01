#pragma once
// Whether the normal motion of the contact has settled: rest and rolling (dynamics/core/rest_event.h)
// are states of persistent contact, so neither may fire during a bounce (a sphere released above
// the plane reaches U = 0 in the middle of an impact while its centre still moves into the plane).
//
// The contact has settled at time t when, at every accepted step of the last `time` seconds, the
// body was in contact (eps < 0: no lift-off) and its normal speed |eps'| = |u.gamma| (the contact
// point's velocity along the vertical, eq. (5)) stayed below `normal_speed`. A run starts
// unsettled: the window opens at t = 0.
//
// The Hertz spring of the model is lossless, so a vibration of the contact may never die out;
// "settled" therefore means "the contact stays closed", not "the vibration stopped". Defaults
// (dynamics/core/scales.h):
//   normal_speed  1 v_lift = sqrt(1.5 g |eps_s|), the peak normal speed of the vertical vibration
//                 (linearised about the static compression) whose amplitude just reaches lift-off:
//                 faster normal motion opens the contact within half a period. The vibration of a
//                 body released from eps = 0 peaks at sqrt(1.2 g |eps_s|) = 0.89 v_lift and passes;
//                 an impact at 0.43 m/s (a 5 cm sphere: 11 v_lift) does not.
//   time          5 periods 2 pi/omega_n of that vibration: an impact keeps the contact closed for at
//                 most about one period, and the normal speed, checked at accepted steps (at most
//                 ~1.5 per period when the step is limited by the stepper's stability on this
//                 mode), is seen at several phases of the vibration.
// Caveat: a body that rocks with a lift-off every rocking period longer than `time` is settled
// between its lift-offs; raise run.settle_time above that period to exclude it.

#include <cmath>
#include <optional>

#include "dynamics/core/scales.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics {

inline constexpr double kSettleTimePeriods = 5.0;         ///< default run.settle_time / (2 pi/omega_n)
inline constexpr double kSettleNormalSpeedFactor = 1.0;   ///< default run.settle_normal_speed / v_lift

/// What the scenario says ([run] settle_*); unset values take the scaled defaults above.
struct SettleThresholds {
  std::optional<double> time;          ///< run.settle_time, s, >= 0 (0: no wait)
  std::optional<double> normal_speed;  ///< run.settle_normal_speed, m/s, > 0

  /// Throws std::invalid_argument naming the key and the rule.
  void validate() const;
};

struct SettleRule {
  Threshold time;
  Threshold normal_speed;
};

[[nodiscard]] SettleRule resolve_settling(const SettleThresholds& given, const BodyScales& scales);

/// Follows the contact from accepted step to accepted step.
class ContactSettling {
 public:
  explicit ContactSettling(const SettleRule& rule) : time_(rule.time.value), speed_(rule.normal_speed.value) {}

  /// Records the state at an accepted step (t non-decreasing). The first call opens the window.
  void update(double t, bool in_contact, double normal_speed) {
    if (!in_contact || !(std::abs(normal_speed) < speed_) || !started_) since_ = t;
    started_ = true;
    in_contact_ = in_contact;
  }
  /// In contact, and in contact with a slow normal motion at every step of the last `time` s.
  [[nodiscard]] bool settled(double t) const { return started_ && in_contact_ && t - since_ >= time_; }
  /// The start of the current settled window, s.
  [[nodiscard]] double since() const { return since_; }

 private:
  double time_;
  double speed_;
  double since_ = 0.0;
  bool started_ = false;
  bool in_contact_ = false;
};

}  // namespace frictionlab::dynamics
