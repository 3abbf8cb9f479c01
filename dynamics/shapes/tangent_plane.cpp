#include "dynamics/shapes/tangent_plane.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <cmath>

#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics::shapes {

TangentFrame tangent_frame(const Eigen::Vector3d& gamma) {
  const double rho2 = gamma.x() * gamma.x() + gamma.y() * gamma.y();
  TangentFrame f;
  if (rho2 == 0.0) {
    f.t1 = Eigen::Vector3d::UnitX();
  } else {
    const double rho = std::sqrt(rho2);
    const double g3 = gamma.z();
    f.t1 = Eigen::Vector3d(-g3 * gamma.x() / rho, -g3 * gamma.y() / rho, rho);
  }
  f.t2 = gamma.cross(f.t1);
  return f;
}

PrincipalRadii principal_radii(double m11, double m12, double m22, double det, const TangentFrame& frame) {
  PrincipalRadii p;
  const double m = 0.5 * (m11 + m22);
  const double d = 0.5 * (m11 - m22);
  // Not hypot: it cost a third of the ellipsoid's contact() (2026-11-27), and squared radii cannot overflow.
  const double rad = std::sqrt(d * d + m12 * m12);
  p.R_major = m + rad;
  p.R_minor = std::min(det / p.R_major, p.R_major);
  // The eigenvector of R_major: (d + rad, m12) or, equivalently, (m12, rad - d); take the one whose
  // components do not cancel. At an umbilic both vanish: t1 by rule.
  double c = 0.0, s = 0.0;
  if (d >= 0.0) {
    c = d + rad;
    s = m12;
  } else {
    c = m12;
    s = rad - d;
  }
  const double n = std::sqrt(c * c + s * s);
  p.umbilic = p.R_major - p.R_minor <= kUmbilicRelTol * p.R_major || !(n > 0.0);
  if (p.umbilic) {
    p.major = frame.t1;
    p.minor = frame.t2;
  } else {
    c /= n;
    s /= n;
    p.major = c * frame.t1 + s * frame.t2;
    p.minor = c * frame.t2 - s * frame.t1;  // gamma x major, as t2 = gamma x t1
  }
  return p;
}

PrincipalRadii principal_radii(double m11, double m12, double m22, const TangentFrame& frame) {
  return principal_radii(m11, m12, m22, m11 * m22 - m12 * m12, frame);
}

}  // namespace frictionlab::dynamics::shapes
