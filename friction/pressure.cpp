#include "friction/pressure.h"

#include <numbers>
#include <stdexcept>

namespace frictionlab::friction {

std::string_view pressure_name(Pressure p) {
  switch (p) {
    case Pressure::hertz: return "hertz";
    case Pressure::uniform: return "uniform";
    case Pressure::punch: return "punch";
  }
  return "hertz";
}

std::vector<std::string> pressure_names() { return {"hertz", "uniform", "punch"}; }

Pressure parse_pressure(std::string_view name) {
  for (const Pressure p : {Pressure::hertz, Pressure::uniform, Pressure::punch}) {
    if (pressure_name(p) == name) return p;
  }
  throw std::invalid_argument("pressure = '" + std::string(name) + "' is not a pressure model: use hertz, uniform or punch");
}

double pressure_exponent(Pressure p) {
  switch (p) {
    case Pressure::hertz: return 0.5;
    case Pressure::uniform: return 0.0;
    case Pressure::punch: return -0.5;
  }
  return 0.5;
}

double pressure_second_moment(Pressure p) { return 1.0 / (2.0 * (pressure_exponent(p) + 2.0)); }

double pressure_pure_spin_factor(Pressure p) {
  switch (p) {
    case Pressure::hertz: return 3.0 / 8.0;
    case Pressure::uniform: return 4.0 / (3.0 * std::numbers::pi);
    case Pressure::punch: return 0.5;
  }
  return 3.0 / 8.0;
}

}  // namespace frictionlab::friction
