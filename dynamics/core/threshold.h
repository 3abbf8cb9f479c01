#pragma once
// A threshold of a run as it was applied: the run.* key that sets it, its value, its unit and
// where the value came from (the scenario, or a default scaled to the body, with the scale).
// Runs record the thresholds that decided their end (summary.json, "termination").

#include <optional>
#include <string>

namespace frictionlab::dynamics {

struct Threshold {
  std::string key;     ///< e.g. "run.rest_slip_speed"
  double value = 0.0;  ///< in `unit`
  std::string unit;    ///< e.g. "m/s"
  std::string source;  ///< e.g. "given" or "default: 1e-3 sqrt(g R), R = 0.024 m (body size)"
};

/// The given value if any (source "given"), else `factor` times `scale` with the source
/// "default: <factor> <scale_name>, <scale_note>".
[[nodiscard]] Threshold resolve_threshold(std::string key, std::string unit, const std::optional<double>& given,
                                          double factor, double scale, const std::string& scale_name,
                                          const std::string& scale_note);

/// A run option as given, that decided a run's end (source "given"), e.g. run.max_steps.
[[nodiscard]] Threshold given_threshold(std::string key, double value, std::string unit);

}  // namespace frictionlab::dynamics
