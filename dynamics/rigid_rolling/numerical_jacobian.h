#pragma once
// The Jacobian d(x')/dx of the rigid rolling model at a state by central differences of its
// right-hand side, independent of the closed-form linearisation (dynamics/rigid_rolling/
// steady_spin.h) it checks. Five-point stencil (fourth order), step for component i:
// h_i = step * max(1, |x_i|). The error is O((h/L)^4) truncation, L the scale on which the
// right-hand side varies (for the Kane-Levinson rattleback ~a3/a1 = 0.1 in gamma: the contact
// point runs R1 = 2 m per radian of tilt), plus O(eps/h) rounding: ~1e-11 relative at the default
// step 1e-4 (second-order differences with any step would be ~1e-7 here).

#include <Eigen/Core>

#include "dynamics/rigid_rolling/rolling_equations.h"
#include "dynamics/rigid_rolling/rolling_state.h"

namespace frictionlab::dynamics::rigid_rolling {

using RollingJacobian = Eigen::Matrix<double, RollingState::kSize, RollingState::kSize>;

/// Column j is (f(x - 2h e_j) - 8 f(x - h e_j) + 8 f(x + h e_j) - f(x + 2h e_j)) / (12 h), h = h_j,
/// in the packed order (omega, gamma). Throws std::invalid_argument unless step is finite and > 0.
[[nodiscard]] RollingJacobian numerical_jacobian(const RigidRollingModel& model, const RollingState& x, double step = 1e-4);

}  // namespace frictionlab::dynamics::rigid_rolling
