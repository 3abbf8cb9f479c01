#include "dynamics/core/stick_rule.h"

#include <algorithm>
#include <numbers>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

Threshold resolve_stick_hold(const std::optional<double>& given, const BodyScales& scales, double settle_time) {
  const double period = 2.0 * std::numbers::pi / scales.rate;
  Threshold t = resolve_threshold("run.stick_hold_time", "s", given, kStickHoldPeriods, period,
                                  "2 pi sqrt(R/g)", "R = " + support::significant(scales.size, 6) + " m (body size)");
  if (!given && t.value < settle_time) {
    t.value = settle_time;
    t.source += ", raised to run.settle_time";
  }
  return t;
}

}  // namespace frictionlab::dynamics
