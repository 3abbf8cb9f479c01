#pragma once
// Whether every component of a state is finite, checked at every evaluation of the right-hand side.

#include <Eigen/Core>

namespace frictionlab::dynamics {

/// True when no component is infinite or NaN: 0 x is 0 for a finite x and NaN otherwise, and a
/// NaN survives the sum. Eigen's allFinite() becomes a loop with a branch per component once a
/// vector is longer than its unrolling limit (the body's 18 components); the sum is Eigen's
/// vectorised reduction.
template <class Derived>
[[nodiscard]] bool all_finite(const Eigen::DenseBase<Derived>& x) {
  return (x.derived().array() * 0.0).sum() == 0.0;
}

}  // namespace frictionlab::dynamics
