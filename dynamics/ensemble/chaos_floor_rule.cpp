#include "dynamics/ensemble/chaos_floor_rule.h"

#include <cmath>

namespace frictionlab::dynamics::ensemble {

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::changes: return "changes";
    case Verdict::within_chaos: return "within chaos";
    case Verdict::unclear: return "unclear";
    case Verdict::negligible: return "negligible";
    case Verdict::not_available: return "n/a";
  }
  return "n/a";
}

Verdict judge(double p_value, double distance, double floor_distance, double resolution) {
  if (std::isnan(p_value) || std::isnan(distance) || std::isnan(floor_distance)) return Verdict::not_available;
  if (resolution > 0.0 && distance <= resolution) return Verdict::negligible;
  const bool significant = p_value < kSignificance;
  const bool above_floor = distance > kFloorFactor * floor_distance;
  if (significant && above_floor) return Verdict::changes;
  if (!significant && !above_floor) return Verdict::within_chaos;
  return Verdict::unclear;
}

}  // namespace frictionlab::dynamics::ensemble
