#pragma once
// Helpers shared by the shape tests: orientations, moves on the sphere of directions, central
// differences there, and the curvature of an implicit surface by finite differences (an
// independent route to the principal radii: nothing of dynamics/shapes/ is used).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "tests/support/eigen_near.h"

namespace frictionlab::testing {

/// `n` deterministic random unit vectors (seeded).
inline std::vector<Eigen::Vector3d> random_directions(int n, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> out;
  while (static_cast<int>(out.size()) < n) {
    const Eigen::Vector3d v(g(rng), g(rng), g(rng));
    if (v.norm() > 1e-3) out.push_back(v.normalized());
  }
  return out;
}

/// Two orthonormal vectors orthogonal to the unit vector `gamma` (any; not the shapes' frame).
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> any_tangents(const Eigen::Vector3d& gamma) {
  const Eigen::Vector3d helper = std::abs(gamma.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = gamma.cross(helper).normalized();
  return {u, gamma.cross(u)};
}

/// The point of the unit sphere reached from `gamma` along the tangent `tau` by the angle h.
inline Eigen::Vector3d turned(const Eigen::Vector3d& gamma, const Eigen::Vector3d& tau, double h) {
  return std::cos(h) * gamma + std::sin(h) * tau;
}

/// d/dh f(turned(gamma, tau, h)) at h = 0 by Richardson-extrapolated central differences
/// (error O(h^4)).
inline double sphere_derivative(const std::function<double(const Eigen::Vector3d&)>& f, const Eigen::Vector3d& gamma,
                                const Eigen::Vector3d& tau, double h) {
  const auto central = [&](double s) { return (f(turned(gamma, tau, s)) - f(turned(gamma, tau, -s))) / (2.0 * s); };
  return (4.0 * central(0.5 * h) - central(h)) / 3.0;
}

/// The same for a vector-valued function.
inline Eigen::Vector3d sphere_derivative3(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& f,
                                          const Eigen::Vector3d& gamma, const Eigen::Vector3d& tau, double h) {
  const auto central = [&](double s) -> Eigen::Vector3d {
    return (f(turned(gamma, tau, s)) - f(turned(gamma, tau, -s))) / (2.0 * s);
  };
  return (4.0 * central(0.5 * h) - central(h)) / 3.0;
}

/// The curvature matrix (second fundamental form, positive for a convex surface) of the implicit
/// surface f = 0 at its point `r`, whose inward unit normal is `inward`, in the tangent basis
/// (u, v): the surface near r is r + x u + y v + h(x, y) inward, h solved from f = 0 by Newton, and
/// its second derivatives come from Richardson-extrapolated central differences with step `s` (m).
inline Eigen::Matrix2d implicit_curvature(const std::function<double(const Eigen::Vector3d&)>& f,
                                          const Eigen::Vector3d& r, const Eigen::Vector3d& inward,
                                          const Eigen::Vector3d& u, const Eigen::Vector3d& v, double s) {
  const auto height = [&](double x, double y) {
    const Eigen::Vector3d base = r + x * u + y * v;
    double h = 0.0;
    const double dh = 1e-6 * s;
    for (int it = 0; it < 50; ++it) {
      const double fh = f(base + h * inward);
      const double slope = (f(base + (h + dh) * inward) - f(base + (h - dh) * inward)) / (2.0 * dh);
      const double step = fh / slope;
      h -= step;
      if (std::abs(step) < 1e-17 + 1e-15 * std::abs(h)) break;
    }
    return h;
  };
  const auto hessian = [&](double t) {
    const double h0 = height(0.0, 0.0);
    Eigen::Matrix2d H;
    H(0, 0) = (height(t, 0.0) - 2.0 * h0 + height(-t, 0.0)) / (t * t);
    H(1, 1) = (height(0.0, t) - 2.0 * h0 + height(0.0, -t)) / (t * t);
    H(0, 1) = H(1, 0) = (height(t, t) - height(t, -t) - height(-t, t) + height(-t, -t)) / (4.0 * t * t);
    return H;
  };
  return (4.0 * hessian(0.5 * s) - hessian(s)) / 3.0;
}

/// The radii matrix R_major e e^T + R_minor e' e'^T (e' = gamma x e) written in the basis (u, v).
inline Eigen::Matrix2d radii_matrix(double R_major, double R_minor, const Eigen::Vector3d& major,
                                    const Eigen::Vector3d& gamma, const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const Eigen::Vector3d minor = gamma.cross(major);
  const Eigen::Vector2d e(major.dot(u), major.dot(v)), f(minor.dot(u), minor.dot(v));
  return R_major * e * e.transpose() + R_minor * f * f.transpose();
}

}  // namespace frictionlab::testing
