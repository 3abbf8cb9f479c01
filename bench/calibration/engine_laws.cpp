#include "bench/calibration/engine_laws.h"

#include <stdexcept>

#include "friction/registry.h"
#include "friction/support/number_format.h"

namespace frictionlab::calibration {

const std::vector<EngineLaw>& engine_laws() {
  static const std::vector<EngineLaw> all = {
      {"ellipsoidal", "Rb", false, "Möller, Leine & Glocker's ellipsoidal law"},
      {"mujoco-elliptic", "torsional", true, "MuJoCo (condim 4, elliptic cone)"},
      {"decoupled", "r_spin", true, "Bullet, Chrono, Gazebo (torsional limit)"},
  };
  return all;
}

const EngineLaw& engine_law(const std::string& name) {
  std::string known;
  for (const auto& law : engine_laws()) {
    if (law.name == name) return law;
    known += (known.empty() ? "" : ", ") + law.name;
  }
  throw std::invalid_argument("unknown engine law '" + name + "'; known: " + known);
}

double parameter_value(const EngineLaw& law, double c, double a, double k) {
  return law.per_unit_load ? c * k * a : c * a;
}

std::string engine_spec(const EngineLaw& law, double c, double a, double k) {
  return law.name + ":" + law.key + "=" + support::shortest(parameter_value(law, c, a, k));
}

std::unique_ptr<friction::FrictionLaw> make_engine_law(const EngineLaw& law, double c, double a, double k) {
  return friction::make_law(engine_spec(law, c, a, k));
}

}  // namespace frictionlab::calibration
