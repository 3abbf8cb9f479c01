#include "dynamics/core/gsl_steppers.h"

namespace frictionlab::dynamics {
namespace {

struct Method {
  const char* name;
  const gsl_odeiv2_step_type* const* type;
  bool one_step;
};

const std::vector<Method>& methods() {
  static const std::vector<Method> all = {
      {"rk8pd", &gsl_odeiv2_step_rk8pd, true}, {"rkck", &gsl_odeiv2_step_rkck, true},
      {"rkf45", &gsl_odeiv2_step_rkf45, true}, {"rk4", &gsl_odeiv2_step_rk4, true},
      {"rk2", &gsl_odeiv2_step_rk2, true},     {"msadams", &gsl_odeiv2_step_msadams, false},
  };
  return all;
}

}  // namespace

std::vector<std::string> gsl_stepper_names() {
  std::vector<std::string> out;
  for (const auto& m : methods()) out.emplace_back(m.name);
  return out;
}

const gsl_odeiv2_step_type* gsl_stepper(std::string_view name) {
  for (const auto& m : methods())
    if (name == m.name) return *m.type;
  return nullptr;
}

bool is_one_step(std::string_view name) {
  for (const auto& m : methods())
    if (name == m.name) return m.one_step;
  return false;
}

}  // namespace frictionlab::dynamics
