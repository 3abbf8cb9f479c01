#pragma once
// Steady spin of a rolling body about the vertical through its centre of mass and its lowest point,
// and its linearisation (docs/rigid-rolling.md §2). At rest the body stands on the point of its
// surface straight below G, at height l; body z is up there and is a principal axis of J; the
// surface's principal radii of curvature at that point are R1 along body x and R2 along body y.
// Steady spin omega = n e3, gamma = e3 is then an equilibrium for every n. With the perturbation
// z = (w1, w2, g1, g2) (omega = n e3 + w, gamma = e3 + g, to first order; w3 and the length of gamma
// decouple with eigenvalue 0), the closed form (derived in the docs, not by differentiating the
// nonlinear right-hand side) is
//
//   M2 (w1', w2')^T = n P (w1, w2)^T + Q (g1, g2)^T,   g1' = -w2 + n g2,   g2' = w1 - n g1,
//   M2 = [[J11 + m l^2, J12], [J12, J22 + m l^2]],
//   P  = [[J12, J22 - J33 - m l R1 + m l^2], [J33 - J11 + m l R2 - m l^2, -J12]],
//   Q  = [[0, m l n^2 (R1 - R2) - m g (R2 - l)], [m l n^2 (R1 - R2) + m g (R1 - l), 0]].
//
// Its eigenvalues lambda(n) satisfy lambda(-n) = -lambda(n) (time reversal). The growth rate of a
// spin sense is max Re lambda. For slow spin, Re lambda = alpha n + O(n^2) per mode ("pitch": the
// rocking about body y, mostly g1; "roll": about body x, mostly g2), with
//
//   alpha = m l (R1 - R2) v1 v2 / (2 v^T Mt v)
//
// from the n = 0 mode shape v of Mt q'' + K0 q = 0, q = (g1, g2), Mt = [[J22 + m l^2, -J12],
// [-J12, J11 + m l^2]], K0 = m g diag(R1 - l, R2 - l); to first order also in J12 (small
// misalignment), with the uncoupled frequencies wp^2 = m g (R1 - l)/(J22 + m l^2) (pitch) and
// wr^2 = m g (R2 - l)/(J11 + m l^2) (roll),
//
//   alpha_pitch = J12 m l (R1 - R2) wp^2 / (2 A' B' (wp^2 - wr^2)),
//   alpha_roll  = -J12 m l (R1 - R2) wr^2 / (2 A' B' (wp^2 - wr^2)),   A' = J11 + m l^2, B' = J22 + m l^2.
//
// With J12 = -(B0 - A0) delta (dynamics/rigid_rolling/inertia_misalignment.h) this is the product of
// the misalignment, the difference of the inverse moments 1/A' - 1/B', the difference of the radii
// R1 - R2 and a squared frequency that Kondo & Nakanishi (Phys. Rev. E 95 (2017) 062207, abstract)
// name as the factors of the reversal time.

#include <Eigen/Core>
#include <complex>

namespace frictionlab::dynamics::rigid_rolling {

struct SteadySpinBody {
  double mass = 0.0;                                  ///< m, kg, > 0
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< J about G, body frame, kg m^2; J13 = J23 = 0
  double height = 0.0;    ///< l, height of G above the contact point at rest, m, > 0
  double radius_1 = 0.0;  ///< R1, principal radius of curvature along body x at the rest point, m, > l
  double radius_2 = 0.0;  ///< R2, along body y, m, > l
  double gravity = 9.81;  ///< g, m/s^2, > 0

  /// Throws std::invalid_argument naming the value and the rule (rest must be stable: R1, R2 > l;
  /// body z principal: |J13|, |J23| <= 1e-12 max|J|).
  void validate() const;
};

using SteadySpinMatrix = Eigen::Matrix4d;
using SteadySpinSpectrum = Eigen::Vector4cd;

/// The closed-form matrix L(n) of z' = L z, z = (w1, w2, g1, g2); n the spin, 1/s.
[[nodiscard]] SteadySpinMatrix steady_spin_matrix(const SteadySpinBody& body, double spin);
/// Eigen's EigenSolver of L(n), in one place (it takes ~15 s to compile): the eigenvalues (1/s, in
/// the solver's order) and, when `vectors`, the eigenvectors as columns.
struct SteadySpinModes {
  SteadySpinSpectrum values;
  Eigen::Matrix4cd vectors;  ///< empty (all zero) unless asked for
};
[[nodiscard]] SteadySpinModes steady_spin_modes(const SteadySpinBody& body, double spin, bool vectors);
/// Its eigenvalues, 1/s, sorted by imaginary part then real part (ascending).
[[nodiscard]] SteadySpinSpectrum steady_spin_eigenvalues(const SteadySpinBody& body, double spin);
/// max Re lambda(n), 1/s: the growth rate of small oscillations about steady spin n.
[[nodiscard]] double steady_spin_growth_rate(const SteadySpinBody& body, double spin);

/// First-order coefficients: Re lambda = coefficient * n + O(n^2) for each mode, and its frequency.
struct SlowSpinCoefficients {
  double pitch = 0.0;            ///< alpha of the pitch mode (rocking about body y), dimensionless
  double roll = 0.0;             ///< alpha of the roll mode (rocking about body x)
  double pitch_frequency = 0.0;  ///< its angular frequency at n = 0, rad/s
  double roll_frequency = 0.0;
};

/// alpha from the exact n = 0 mode shapes (any J12).
[[nodiscard]] SlowSpinCoefficients slow_spin_coefficients(const SteadySpinBody& body);
/// alpha to first order in J12 as well (the product form above; frequencies of the uncoupled
/// modes). Throws std::invalid_argument if the uncoupled frequencies coincide (no first order).
[[nodiscard]] SlowSpinCoefficients small_misalignment_coefficients(const SteadySpinBody& body);

}  // namespace frictionlab::dynamics::rigid_rolling
