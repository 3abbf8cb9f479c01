#include "dynamics/rigid_rolling/numerical_jacobian.h"

#include <algorithm>
#include <cmath>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {

RollingJacobian numerical_jacobian(const RigidRollingModel& model, const RollingState& x, double step) {
  if (!(std::isfinite(step) && step > 0.0))
    throw support::invalid_value("jacobian step", step, "it must be finite and > 0");
  const Eigen::Matrix<double, RollingState::kSize, 1> x0 = x.packed();
  RollingJacobian jac;
  const auto f = [&](int j, double offset) {
    Eigen::Matrix<double, RollingState::kSize, 1> y = x0;
    y[j] += offset;
    return model.derivative(RollingState::unpacked(y)).packed();
  };
  for (int j = 0; j < RollingState::kSize; ++j) {
    const double h = step * std::max(1.0, std::abs(x0[j]));
    jac.col(j) = (f(j, -2.0 * h) - 8.0 * f(j, -h) + 8.0 * f(j, h) - f(j, 2.0 * h)) / (12.0 * h);
  }
  return jac;
}

}  // namespace frictionlab::dynamics::rigid_rolling
