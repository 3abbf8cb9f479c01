#include "dynamics/rigid_rolling/steady_spin.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <span>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace {

// |J13|, |J23| up to this fraction of max|J| count as zero (body z principal).
constexpr double kPrincipalTolerance = 1e-12;

struct Reduced {
  double m, l, r1, r2, g, j11, j22, j12, c;
  double a_prime() const { return j11 + m * l * l; }
  double b_prime() const { return j22 + m * l * l; }
};

Reduced reduced(const SteadySpinBody& b) {
  b.validate();
  return {b.mass, b.height, b.radius_1, b.radius_2, b.gravity, b.inertia(0, 0), b.inertia(1, 1), b.inertia(0, 1), b.inertia(2, 2)};
}

}  // namespace

void SteadySpinBody::validate() const {
  if (!(std::isfinite(mass) && mass > 0.0)) throw support::invalid_value("steady_spin.mass", mass, "it must be finite and > 0 kg");
  if (!(std::isfinite(gravity) && gravity > 0.0))
    throw support::invalid_value("steady_spin.gravity", gravity, "it must be finite and > 0 m/s^2");
  if (!(std::isfinite(height) && height > 0.0))
    throw support::invalid_value("steady_spin.height", height, "it must be finite and > 0 m (G above the contact point)");
  if (!(std::isfinite(radius_1) && radius_1 > height))
    throw support::invalid_value("steady_spin.radius_1", radius_1,
                                 "it must be finite and > steady_spin.height (a stable rest point)");
  if (!(std::isfinite(radius_2) && radius_2 > height))
    throw support::invalid_value("steady_spin.radius_2", radius_2,
                                 "it must be finite and > steady_spin.height (a stable rest point)");
  const std::span<const double> j(inertia.data(), 9);
  if (!inertia.allFinite()) throw support::invalid_value("steady_spin.inertia", j, "it must be finite (kg m^2)");
  const double scale = inertia.cwiseAbs().maxCoeff();
  if (!(std::max({std::abs(inertia(0, 2)), std::abs(inertia(1, 2)), std::abs(inertia(2, 0)), std::abs(inertia(2, 1))}) <=
        kPrincipalTolerance * scale))
    throw support::invalid_value("steady_spin.inertia", j,
                                 "body z must be a principal axis (J13 = J23 = 0) for steady spin about it");
  if (!(inertia(0, 0) > 0.0 && inertia(1, 1) > 0.0 && inertia(2, 2) > 0.0 &&
        inertia(0, 0) * inertia(1, 1) > inertia(0, 1) * inertia(1, 0) &&
        std::abs(inertia(0, 1) - inertia(1, 0)) <= kPrincipalTolerance * scale))
    throw support::invalid_value("steady_spin.inertia", j, "it must be symmetric positive definite");
}

SteadySpinMatrix steady_spin_matrix(const SteadySpinBody& body, double n) {
  const Reduced b = reduced(body);
  const double ml = b.m * b.l;
  Eigen::Matrix2d m2;
  m2 << b.a_prime(), b.j12, b.j12, b.b_prime();
  Eigen::Matrix2d p;
  p << b.j12, b.j22 - b.c - ml * b.r1 + ml * b.l, b.c - b.j11 + ml * b.r2 - ml * b.l, -b.j12;
  Eigen::Matrix2d q;
  q << 0.0, ml * n * n * (b.r1 - b.r2) - b.m * b.g * (b.r2 - b.l), ml * n * n * (b.r1 - b.r2) + b.m * b.g * (b.r1 - b.l), 0.0;
  const Eigen::Matrix2d m2_inverse = m2.inverse();
  SteadySpinMatrix l = SteadySpinMatrix::Zero();
  l.topLeftCorner<2, 2>() = n * m2_inverse * p;
  l.topRightCorner<2, 2>() = m2_inverse * q;
  l.bottomLeftCorner<2, 2>() << 0.0, -1.0, 1.0, 0.0;
  l.bottomRightCorner<2, 2>() << 0.0, n, -n, 0.0;
  return l;
}

SteadySpinModes steady_spin_modes(const SteadySpinBody& body, double spin, bool vectors) {
  const Eigen::EigenSolver<SteadySpinMatrix> solver(steady_spin_matrix(body, spin), vectors);
  SteadySpinModes out;
  out.values = solver.eigenvalues();
  out.vectors = vectors ? Eigen::Matrix4cd(solver.eigenvectors()) : Eigen::Matrix4cd::Zero();
  return out;
}

SteadySpinSpectrum steady_spin_eigenvalues(const SteadySpinBody& body, double spin) {
  SteadySpinSpectrum ev = steady_spin_modes(body, spin, false).values;
  std::sort(ev.begin(), ev.end(), [](const std::complex<double>& x, const std::complex<double>& y) {
    return x.imag() != y.imag() ? x.imag() < y.imag() : x.real() < y.real();
  });
  return ev;
}

double steady_spin_growth_rate(const SteadySpinBody& body, double spin) {
  return steady_spin_eigenvalues(body, spin).real().maxCoeff();
}

SlowSpinCoefficients slow_spin_coefficients(const SteadySpinBody& body) {
  const Reduced b = reduced(body);
  Eigen::Matrix2d mt;
  mt << b.b_prime(), -b.j12, -b.j12, b.a_prime();
  const Eigen::Matrix2d k0 = Eigen::Vector2d(b.m * b.g * (b.r1 - b.l), b.m * b.g * (b.r2 - b.l)).asDiagonal();
  // K0 v = w^2 Mt v with v^T Mt v = 1 (Eigen normalises so).
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> modes(k0, mt);
  double alpha[2], frequency[2], share[2];
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d v = modes.eigenvectors().col(k);
    alpha[k] = b.m * b.l * (b.r1 - b.r2) * v(0) * v(1) / (2.0 * v.dot(mt * v));
    frequency[k] = std::sqrt(modes.eigenvalues()(k));
    share[k] = std::abs(v(0)) / (std::abs(v(0)) + std::abs(v(1)));  // g1: tilt along x, rocking about y
  }
  const int p = share[0] >= share[1] ? 0 : 1;  // the pitch mode is the one with more g1
  SlowSpinCoefficients out;
  out.pitch = alpha[p];
  out.pitch_frequency = frequency[p];
  out.roll = alpha[1 - p];
  out.roll_frequency = frequency[1 - p];
  return out;
}

SlowSpinCoefficients small_misalignment_coefficients(const SteadySpinBody& body) {
  const Reduced b = reduced(body);
  const double wp2 = b.m * b.g * (b.r1 - b.l) / b.b_prime();
  const double wr2 = b.m * b.g * (b.r2 - b.l) / b.a_prime();
  if (!(wp2 != wr2))
    throw support::invalid_value("steady_spin.radius_1", body.radius_1,
                                 "the uncoupled pitch and roll frequencies coincide: no first-order misalignment theory");
  const double common = b.j12 * b.m * b.l * (b.r1 - b.r2) / (2.0 * b.a_prime() * b.b_prime() * (wp2 - wr2));
  return {common * wp2, -common * wr2, std::sqrt(wp2), std::sqrt(wr2)};
}

}  // namespace frictionlab::dynamics::rigid_rolling
