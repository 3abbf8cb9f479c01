#include "dynamics/rigid_rolling/steady_spin.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include "dynamics/rigid_rolling/ellipsoid_body.h"
#include "dynamics/rigid_rolling/inertia_misalignment.h"
#include "dynamics/rigid_rolling/numerical_jacobian.h"
#include "dynamics/rigid_rolling/rattleback_presets.h"
#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace steady_spin_test {

// The central-difference Jacobian (step 1e-5 * max(1, |x|)) is good to ~1e-9 of the largest entry
// (O(h^2) truncation of terms up to n^2 ~ 1e3, O(eps/h) rounding); 1e-7 of max|L| leaves room and
// fails for any wrong term of the closed form (those are O(1) of an entry).
constexpr double kFiniteDifference = 1e-7;

// The distance from each element of a to the nearest element of b.
double worst_nearest(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < b.size(); ++j) nearest = std::min(nearest, std::abs(a(i) - b(j)));
    worst = std::max(worst, nearest);
  }
  return worst;
}

EllipsoidBody aligned_rattleback() {
  EllipsoidBody b = kane_levinson_rattleback();
  b.inertia(0, 1) = b.inertia(1, 0) = 0.0;
  return b;
}

TEST(DynRigidSteadySpin, ClosedFormIsTheFiniteDifferenceJacobianOfTheNonlinearModel) {
  const EllipsoidBody rb = kane_levinson_rattleback();
  const SteadySpinBody lin = steady_spin_body(rb);
  const RigidRollingModel model(rigid_body(rb));
  const int idx[4] = {0, 1, 3, 4};  // (w1, w2, g1, g2) in the packed (omega, gamma)
  for (double n : {0.0, 0.5, -3.0, 12.0, 40.0}) {
    const RollingJacobian jac = numerical_jacobian(model, RollingState{Eigen::Vector3d(0.0, 0.0, n), Eigen::Vector3d::UnitZ()});
    const SteadySpinMatrix l = steady_spin_matrix(lin, n);
    Eigen::Matrix4d block;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) block(i, j) = jac(idx[i], idx[j]);
    const double scale = l.cwiseAbs().maxCoeff();
    EXPECT_EIGEN_NEAR(block, l, kFiniteDifference * scale) << "n = " << n;
    // omega3 and the length of gamma decouple: their rows and columns vanish.
    for (int k : {2, 5}) {
      EXPECT_LE(jac.row(k).cwiseAbs().maxCoeff(), kFiniteDifference * scale) << "row " << k << ", n = " << n;
      EXPECT_LE(jac.col(k).cwiseAbs().maxCoeff(), kFiniteDifference * scale) << "column " << k << ", n = " << n;
    }
  }
}

TEST(DynRigidSteadySpin, EigenvaluesMatchTheFiniteDifferenceJacobian) {
  const EllipsoidBody rb = kane_levinson_rattleback();
  const SteadySpinBody lin = steady_spin_body(rb);
  const RigidRollingModel model(rigid_body(rb));
  for (double n : {0.5, 5.0, -5.0, 20.0}) {
    const RollingJacobian jac = numerical_jacobian(model, RollingState{Eigen::Vector3d(0.0, 0.0, n), Eigen::Vector3d::UnitZ()});
    const Eigen::VectorXcd fd = Eigen::EigenSolver<RollingJacobian>(jac, false).eigenvalues();
    const Eigen::VectorXcd closed = steady_spin_eigenvalues(lin, n);
    Eigen::VectorXcd expected(6);
    expected << closed, 0.0, 0.0;  // plus the two decoupled zeros
    const double scale = closed.cwiseAbs().maxCoeff();
    EXPECT_LE(worst_nearest(closed, fd), 1e-6 * scale) << "n = " << n;
    EXPECT_LE(worst_nearest(fd, expected), 1e-6 * scale) << "n = " << n;
    EXPECT_NEAR(steady_spin_growth_rate(lin, n), closed.real().maxCoeff(), 0.0);
  }
}

TEST(DynRigidSteadySpin, ReversingTheSpinNegatesTheSpectrum) {
  const SteadySpinBody lin = steady_spin_body(kane_levinson_rattleback());
  for (double n : {0.3, 4.0, 25.0}) {
    const Eigen::VectorXcd up = steady_spin_eigenvalues(lin, n);
    const Eigen::VectorXcd down = steady_spin_eigenvalues(lin, -n);
    EXPECT_LE(worst_nearest(down, -up), 1e-12 * up.cwiseAbs().maxCoeff()) << "n = " << n;
  }
}

TEST(DynRigidSteadySpin, AlignedRattlebackIsNeutralAndSenseSymmetric) {
  // J12 = 0: the body is symmetric under y -> -y, which maps spin n to -n, so growth(n) =
  // growth(-n); with time reversal the spectrum is symmetric under lambda -> -lambda. Below its
  // first spin-induced instability (none up to 200 1/s for this body) Re lambda = 0 up to rounding.
  const SteadySpinBody lin = steady_spin_body(aligned_rattleback());
  for (double n : {0.1, 1.0, 5.0, 20.0, 50.0, 100.0, 200.0}) {
    const Eigen::VectorXcd up = steady_spin_eigenvalues(lin, n);
    const double rounding = 1e-12 * up.cwiseAbs().maxCoeff();
    EXPECT_LE(up.real().cwiseAbs().maxCoeff(), rounding) << "n = " << n;
    EXPECT_NEAR(steady_spin_growth_rate(lin, n), steady_spin_growth_rate(lin, -n), 2.0 * rounding) << "n = " << n;
  }
}

TEST(DynRigidSteadySpin, SlowSpinCoefficientsAreTheSlopesOfTheGrowthRates) {
  // Re lambda is odd in n per mode (lambda(-n) = -lambda(n)), so Re lambda/n = alpha + O(n^2):
  // at n = 1e-3 1/s the relative difference is ~(n/omega_roll)^2 ~ 1e-9; 1e-6 leaves room.
  const SteadySpinBody lin = steady_spin_body(kane_levinson_rattleback());
  const SlowSpinCoefficients a = slow_spin_coefficients(lin);
  constexpr double n = 1e-3;
  const Eigen::VectorXcd ev = steady_spin_eigenvalues(lin, n);
  for (Eigen::Index i = 0; i < ev.size(); ++i) {
    const double f = std::abs(ev(i).imag());
    const bool pitch = std::abs(f - a.pitch_frequency) < std::abs(f - a.roll_frequency);
    const double alpha = pitch ? a.pitch : a.roll;
    EXPECT_NEAR(ev(i).real() / n, alpha, 1e-6 * std::abs(alpha)) << "eigenvalue " << ev(i);
    EXPECT_NEAR(f, pitch ? a.pitch_frequency : a.roll_frequency, 1e-6 * f);
  }
}

TEST(DynRigidSteadySpin, SmallMisalignmentFormulaIsFirstOrderInTheAngle) {
  // The product form drops O(delta^2) relative terms: its relative error must fall four-fold when
  // delta halves, and its signs follow J12 (pitch grows for n J12 > 0, roll for n J12 < 0).
  const EllipsoidBody base = kane_levinson_rattleback();
  double previous = 0.0;
  for (double delta : {-0.04, -0.02, -0.01}) {
    EllipsoidBody b = base;
    b.inertia = inertia_rotated_about_vertical(2e-4, 16e-4, 17e-4, delta);
    const SteadySpinBody lin = steady_spin_body(b);
    const SlowSpinCoefficients exact = slow_spin_coefficients(lin);
    const SlowSpinCoefficients small = small_misalignment_coefficients(lin);
    EXPECT_GT(lin.inertia(0, 1), 0.0);
    EXPECT_GT(small.pitch, 0.0);
    EXPECT_LT(small.roll, 0.0);
    const double error = std::max(std::abs(small.pitch / exact.pitch - 1.0), std::abs(small.roll / exact.roll - 1.0));
    EXPECT_LT(error, 4.0 * delta * delta) << "delta = " << delta;
    if (previous > 0.0) {
      EXPECT_GT(previous / error, 3.5) << "delta = " << delta;
      EXPECT_LT(previous / error, 4.5) << "delta = " << delta;
    }
    previous = error;
  }
}

TEST(DynRigidSteadySpin, InvalidBodiesThrow) {
  SteadySpinBody lin = steady_spin_body(kane_levinson_rattleback());
  SteadySpinBody bad = lin;
  bad.inertia(0, 2) = bad.inertia(2, 0) = 1e-6;
  EXPECT_THROW((void)steady_spin_matrix(bad, 1.0), std::invalid_argument);
  bad = lin;
  bad.radius_2 = bad.height;
  EXPECT_THROW((void)steady_spin_matrix(bad, 1.0), std::invalid_argument);
  bad = lin;
  bad.height = 0.0;
  EXPECT_THROW((void)slow_spin_coefficients(bad), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
