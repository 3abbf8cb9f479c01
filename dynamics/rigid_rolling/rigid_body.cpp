#include "dynamics/rigid_rolling/rigid_body.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <span>
#include <stdexcept>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace {

// Symmetry and the triangle inequality are checked to this fraction of the largest moment: an
// inertia assembled from rounded inputs (a rotated diagonal) must pass.
constexpr double kInertiaTolerance = 1e-12;

}  // namespace

void RigidRollingBody::validate() const {
  if (!(std::isfinite(mass) && mass > 0.0)) throw support::invalid_value("body.mass", mass, "it must be finite and > 0 kg");
  if (!(std::isfinite(gravity) && gravity > 0.0))
    throw support::invalid_value("body.gravity", gravity, "it must be finite and > 0 m/s^2");
  if (!(std::isfinite(spin_damping) && spin_damping >= 0.0))
    throw support::invalid_value("body.spin_damping", spin_damping, "it must be finite and >= 0 N m s");
  if (!surface) throw std::invalid_argument("body.surface is required: the rigid rolling model needs a contact geometry");
  const std::span<const double> j(inertia.data(), 9);
  if (!inertia.allFinite()) throw support::invalid_value("body.inertia", j, "it must be finite (kg m^2)");
  const double scale = inertia.cwiseAbs().maxCoeff();
  if (!((inertia - inertia.transpose()).cwiseAbs().maxCoeff() <= kInertiaTolerance * scale))
    throw support::invalid_value("body.inertia", j, "it must be symmetric");
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues();
  if (!(moments.minCoeff() > 0.0)) throw support::invalid_value("body.inertia", j, "its principal moments must be > 0");
  if (!(2.0 * moments.maxCoeff() <= moments.sum() * (1.0 + kInertiaTolerance)))
    throw support::invalid_value("body.inertia", j,
                                 "its principal moments must satisfy the triangle inequality (as for any real body)");
}

}  // namespace frictionlab::dynamics::rigid_rolling
