#include "dynamics/shapes/solid_mass_properties.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::shapes {
namespace {

using support::invalid_value;
using support::message_number;

// Given values are rounded: a symmetric tensor typed with 17 digits, or a flat disc exactly on
// the triangle inequality's edge, must pass.
constexpr double kSymmetryRelTol = 1e-12;
constexpr double kTriangleRelSlack = 1e-12;

std::array<double, 9> row_major(const Eigen::Matrix3d& J) {
  std::array<double, 9> v{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v[static_cast<std::size_t>(3 * i + j)] = J(i, j);
  return v;
}

std::string element(int i, int j) { return "J" + std::to_string(i + 1) + std::to_string(j + 1); }

}  // namespace

Eigen::Matrix3d SolidMassProperties::inertia_about(const Eigen::Vector3d& point) const {
  const Eigen::Vector3d d = centroid - point;
  return inertia + mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

PrincipalInertia principal_inertia(const Eigen::Matrix3d& J) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(J);
  PrincipalInertia p;
  p.moments = solver.eigenvalues();
  p.axes = solver.eigenvectors();
  if (p.axes.determinant() < 0.0) p.axes.col(2) = -p.axes.col(2);  // a proper rotation
  return p;
}

Eigen::Matrix3d rotate_inertia(const Eigen::Matrix3d& J, const Eigen::Matrix3d& Q) { return Q * J * Q.transpose(); }

Eigen::Matrix3d inertia_from_principal(const Eigen::Vector3d& moments, const Eigen::Vector3d& axis, double angle) {
  const double n = axis.norm();
  if (!(std::isfinite(n) && n > 0.0))
    throw invalid_value("inertia rotation axis", std::array{axis.x(), axis.y(), axis.z()},
                        "it must be a finite, non-zero vector");
  if (!std::isfinite(angle)) throw invalid_value("inertia rotation angle", angle, "it must be finite (rad)");
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(angle, axis / n).toRotationMatrix();
  // The product may sum J_ij and J_ji in different orders (an ulp apart): a tensor written out as a
  // scenario's body.inertia should be symmetric exactly, so the lower triangle mirrors the upper.
  Eigen::Matrix3d J = rotate_inertia(moments.asDiagonal().toDenseMatrix(), Q);
  J.triangularView<Eigen::StrictlyLower>() = J.transpose().triangularView<Eigen::StrictlyLower>();
  return J;
}

void validate_mass(double mass, std::string_view key) {
  if (!(std::isfinite(mass) && mass > 0.0)) throw invalid_value(key, mass, "it must be finite and > 0 kg");
}

void validate_inertia(const Eigen::Matrix3d& J, std::string_view key) {
  const auto values = row_major(J);
  if (!J.allFinite()) throw invalid_value(key, values, "every element must be finite (kg m^2)");
  const double scale = J.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(J(i, j) - J(j, i)) > kSymmetryRelTol * scale)
        throw invalid_value(key, values,
                            "the tensor must be symmetric, but " + element(i, j) + " = " + message_number(J(i, j)) +
                                " and " + element(j, i) + " = " + message_number(J(j, i)));
  const Eigen::Matrix3d S = 0.5 * (J + J.transpose());
  const Eigen::Vector3d I = principal_inertia(S).moments;  // ascending
  const std::string moments = "its principal moments are " + message_number(I(0)) + ", " + message_number(I(1)) +
                              ", " + message_number(I(2)) + " kg m^2";
  if (!(I(0) > 0.0)) throw invalid_value(key, values, "the tensor must be positive definite; " + moments);
  if (I(2) > (I(0) + I(1)) * (1.0 + kTriangleRelSlack))
    throw invalid_value(key, values,
                        moments + ", and the largest must not exceed the sum of the other two (I3 <= I1 + I2, "
                                  "true of every body: I1 + I2 - I3 = 2 ∫ x3^2 dm in principal axes)");
}

}  // namespace frictionlab::dynamics::shapes
