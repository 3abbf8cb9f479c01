#pragma once
// The numbers of the stick mode (docs/dynamics.md §5 "stick"), scaled to the body like the rest
// thresholds (dynamics/core/rest_event.h):
//   hold time   run.stick_hold_time, default one period 2 pi sqrt(R/g) of a pendulum of the body's
//               size (at least run.settle_time): a run in stick ends "rolling" once stick has held
//               that long without a break, the energy constant (egg-printed, R = 0.278 m: 1.06 s;
//               15 g top, R = 2.4 cm: 0.31 s; 5 cm sphere: 0.45 s). A body whose rolling needs more
//               wrench than the contact holds leaves stick within such a period (a rocking egg's
//               wrench peaks twice per rocking period, which is of that order).
//   drift       in stick the constrained equations keep U and Omega at 0 up to the integrator's
//               error; a residue above kStickDriftFactor times the rest thresholds is projected
//               away between steps (as at entry: its kinetic energy counts as friction work).
//   creep       after an exit or a refused entry, while U and |Omega| are below the rest
//               thresholds, the law sees the direction of creep (dynamics/core/limit_set.h), not
//               the slip's own direction, whose dynamics is stiff there.

#include <optional>

#include "dynamics/core/scales.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics {

inline constexpr double kStickHoldPeriods = 1.0;       ///< default run.stick_hold_time / (2 pi sqrt(R/g))
inline constexpr double kStickDriftFactor = 1e-6;      ///< projection above this fraction of the rest thresholds

/// run.stick_hold_time as applied: given, or the default above (not below `settle_time`, s).
[[nodiscard]] Threshold resolve_stick_hold(const std::optional<double>& given, const BodyScales& scales,
                                           double settle_time);

}  // namespace frictionlab::dynamics
