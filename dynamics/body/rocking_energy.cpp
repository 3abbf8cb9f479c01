#include "dynamics/body/rocking_energy.h"

#include <algorithm>
#include <cmath>

namespace frictionlab::dynamics {

double rocking_energy(const Eigen::Vector3d& r, const Eigen::Vector3d& gamma, double R1, double R2, double m,
                      double g) {
  const double R_max = std::max(R1, R2);
  if (!(R_max > 0.0) || !std::isfinite(R_max)) return 0.0;
  const Eigen::Vector3d horizontal = r - r.dot(gamma) * gamma;
  return m * g * horizontal.squaredNorm() / (2.0 * R_max);
}

}  // namespace frictionlab::dynamics
