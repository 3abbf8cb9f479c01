#include "dynamics/core/threshold.h"

#include <utility>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

Threshold resolve_threshold(std::string key, std::string unit, const std::optional<double>& given, double factor,
                            double scale, const std::string& scale_name, const std::string& scale_note) {
  Threshold t{std::move(key), 0.0, std::move(unit), ""};
  if (given) {
    t.value = *given;
    t.source = "given";
    return t;
  }
  t.value = factor * scale;
  t.source = "default: " + support::significant(factor, 6) + " " + scale_name + ", " + scale_note;
  return t;
}

Threshold given_threshold(std::string key, double value, std::string unit) {
  return {std::move(key), value, std::move(unit), "given"};
}

}  // namespace frictionlab::dynamics
