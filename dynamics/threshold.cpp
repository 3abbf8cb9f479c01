#include "dynamics/threshold.h"

#include <sstream>

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
  std::ostringstream s;
  s.precision(6);
  s << "default: " << factor << " " << scale_name << ", " << scale_note;
  t.source = s.str();
  return t;
}

}  // namespace frictionlab::dynamics
