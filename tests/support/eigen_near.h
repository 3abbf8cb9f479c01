#pragma once
// EXPECT_EIGEN_NEAR(a, b, tol) / ASSERT_EIGEN_NEAR: two Eigen objects of any type (vectors,
// matrices, expressions) have the same shape and |a - b| <= tol, |.| the Frobenius norm (the
// Euclidean norm for vectors). On failure both sides, their difference and the norm are printed
// with 17 digits (after manif's gtest_eigen_utils.h).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <sstream>

namespace frictionlab::testing {

template <class A, class B>
::testing::AssertionResult eigen_near(const char* ea, const char* eb, const char* etol, const Eigen::MatrixBase<A>& a,
                                      const Eigen::MatrixBase<B>& b, double tol) {
  std::ostringstream m;
  m.precision(17);
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    m << ea << " is " << a.rows() << "x" << a.cols() << " but " << eb << " is " << b.rows() << "x" << b.cols();
    return ::testing::AssertionFailure() << m.str();
  }
  const auto diff = (a.template cast<double>() - b.template cast<double>()).eval();
  const double d = diff.norm();
  if (d <= tol) return ::testing::AssertionSuccess();  // a NaN difference fails here
  const Eigen::IOFormat fmt(Eigen::FullPrecision, 0, ", ", "\n      ", "[", "]");
  m << "|" << ea << " - " << eb << "| = " << d << " > " << etol << " = " << tol << "\n  " << ea << " =\n      "
    << a.format(fmt) << "\n  " << eb << " =\n      " << b.format(fmt) << "\n  difference =\n      "
    << diff.format(fmt);
  return ::testing::AssertionFailure() << m.str();
}

}  // namespace frictionlab::testing

#define EXPECT_EIGEN_NEAR(a, b, tol) EXPECT_PRED_FORMAT3(::frictionlab::testing::eigen_near, a, b, tol)
#define ASSERT_EIGEN_NEAR(a, b, tol) ASSERT_PRED_FORMAT3(::frictionlab::testing::eigen_near, a, b, tol)
