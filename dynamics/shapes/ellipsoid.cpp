#include "dynamics/shapes/ellipsoid.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "dynamics/shapes/tangent_plane.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::shapes {
namespace {

constexpr int kMaxSecularIterations = 200;

// The tangent part of g at the unit vector gamma.
Eigen::Vector3d tangent(const Eigen::Vector3d& g, const Eigen::Vector3d& gamma) { return g - g.dot(gamma) * gamma; }

}  // namespace

Ellipsoid::Ellipsoid(const Eigen::Vector3d& semi_axes, std::string_view key) : a_(semi_axes) {
  if (!(a_.allFinite() && a_.minCoeff() > 0.0))
    throw support::invalid_value(key, std::array{a_.x(), a_.y(), a_.z()},
                                 "the semi-axes a1, a2, a3 must be finite and > 0 m");
  a2_ = a_.cwiseProduct(a_);
  inv_a2_ = a2_.cwiseInverse();
  const double P = a_.prod();
  P2_ = P * P;
}

SurfaceContact Ellipsoid::contact(const Eigen::Vector3d& gamma) const {
  const Eigen::Vector3d v = a2_.cwiseProduct(gamma);
  const double w2 = gamma.dot(v);
  const double w = std::sqrt(w2);
  const TangentFrame f = tangent_frame(gamma);
  const Eigen::Vector3d it1 = inv_a2_.cwiseProduct(f.t1);
  const double k = P2_ / (w2 * w);
  const PrincipalRadii p = principal_radii(k * f.t2.dot(inv_a2_.cwiseProduct(f.t2)), -k * f.t2.dot(it1),
                                           k * f.t1.dot(it1), P2_ / (w2 * w2), f);
  return {-v / w, p.R_major, p.R_minor, p.major};
}

Eigen::Vector3d Ellipsoid::rayleigh_gradient(const Eigen::Vector3d& gamma, const Eigen::Vector3d& v, double w,
                                             const Eigen::Vector3d& e) const {
  const Eigen::Vector3d De = a2_.cwiseProduct(e);
  const double E = e.dot(De);
  const double c = e.dot(v);
  const double w3 = w * w * w;
  return tangent((3.0 * c * c / (w * w) - E) * v / w3 - 2.0 * c * De / w3, gamma);
}

RadiiGradient Ellipsoid::radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact& c) const {
  const Eigen::Vector3d v = a2_.cwiseProduct(gamma);
  const double w = std::sqrt(gamma.dot(v));
  if (c.R_major - c.R_minor <= kUmbilicRelTol * c.R_major) {
    // Every tangent direction is principal: the gradient of the mean radius, for both.
    const TangentFrame f = tangent_frame(gamma);
    const Eigen::Vector3d mean = 0.5 * (rayleigh_gradient(gamma, v, w, f.t1) + rayleigh_gradient(gamma, v, w, f.t2));
    return {mean, mean};
  }
  return {rayleigh_gradient(gamma, v, w, c.major), rayleigh_gradient(gamma, v, w, gamma.cross(c.major))};
}

SolidMassProperties Ellipsoid::homogeneous(double mass) const {
  validate_mass(mass);
  SolidMassProperties m;
  m.mass = mass;
  m.volume = 4.0 / 3.0 * std::numbers::pi * a_.prod();
  m.inertia = (mass / 5.0 * Eigen::Vector3d(a2_.y() + a2_.z(), a2_.x() + a2_.z(), a2_.x() + a2_.y())).asDiagonal();
  return m;
}

double Ellipsoid::size() const { return a_.maxCoeff(); }

bool Ellipsoid::contains(const Eigen::Vector3d& point) const { return point.cwiseProduct(point).dot(inv_a2_) < 1.0; }

double Ellipsoid::radius_about(const Eigen::Vector3d& p) const {
  // Maximise |xi - p| on the surface: xi_i = -a_i^2 p_i/(mu - a_i^2), with mu > A = max a_i^2
  // solving phi(mu) = sum a_i^2 p_i^2/(mu - a_i^2)^2 = 1 (phi falls from its value at A to 0), and
  // |xi - p|^2 = sum p_i^2 mu^2/(mu - a_i^2)^2.
  const double A = a2_.maxCoeff();
  const Eigen::Vector3d c = a2_.cwiseProduct(p.cwiseProduct(p));  // a_i^2 p_i^2
  // Components along the largest axes (a_i^2 == A) with p_i = 0 drop out of phi.
  double c_top = 0.0, phi_rest_at_A = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (a2_(i) == A) c_top += c(i);
    else phi_rest_at_A += c(i) / ((A - a2_(i)) * (A - a2_(i)));
  }
  if (c_top == 0.0 && phi_rest_at_A <= 1.0) {
    // The hard case: mu = A; the other components as above, the rest of the unit "y" along the
    // largest axes, where p has no component.
    double d2 = 0.0, y2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (a2_(i) == A) continue;
      const double y = -a_(i) * p(i) / (A - a2_(i));
      y2 += y * y;
      const double e = a_(i) * y - p(i);
      d2 += e * e;
    }
    return std::sqrt(d2 + A * std::max(0.0, 1.0 - y2));
  }
  const auto phi = [&](double mu, double* slope) {
    double f = 0.0, df = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double t = 1.0 / (mu - a2_(i));
      f += c(i) * t * t;
      df -= 2.0 * c(i) * t * t * t;
    }
    *slope = df;
    return f;
  };
  // Bracket: phi(A+) > 1 and phi(A + sqrt(sum c)) <= 1 (every mu - a_i^2 is then >= sqrt(sum c)).
  double lo = A, hi = A + std::sqrt(c.sum());
  double mu = hi;
  // Newton on F = 1/sqrt(phi) - 1, nearly linear in mu (Moré and Sorensen's trick), safeguarded.
  for (int it = 0; it < kMaxSecularIterations; ++it) {
    double dphi = 0.0;
    const double f = phi(mu, &dphi);
    if (f == 1.0) break;
    if (f > 1.0) lo = mu; else hi = mu;
    const double F = 1.0 / std::sqrt(f) - 1.0;
    const double dF = -0.5 * dphi / (f * std::sqrt(f));
    double next = mu - F / dF;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - mu) <= 4.0 * std::numeric_limits<double>::epsilon() * mu) {
      mu = next;
      break;
    }
    mu = next;
  }
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double t = mu / (mu - a2_(i));
    d2 += p(i) * p(i) * t * t;
  }
  return std::sqrt(d2);
}

}  // namespace frictionlab::dynamics::shapes
