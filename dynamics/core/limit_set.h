#pragma once
// The limit set of a friction law at one contact: the friction wrenches (tangential force and
// moment about the normal) the contact can transmit without slipping or spinning (docs/dynamics.md
// §5, "stick"). Model-agnostic: it needs only FrictionLaw::evaluate.
//
// Maximum dissipation. A slip/spin direction is d = (U e1, a Omega) on the unit sphere of the
// plane's slip velocity and the spin scaled by the patch's major semi-axis a (so that both parts
// are speeds). The law's resistance at d, rho(d) = (F1 e1 + F2 e2, M / a) (the friction force on
// the body is -(F1 e1 + F2 e2), its torque -M gamma), dissipates D(d) = rho(d).d = F1 U + M Omega.
// The limit set is the convex set whose support function is D:
//     C = { rho : rho.d <= D(d) for every unit d }.
// For the exact law it is the set of the net wrenches of all Coulomb tractions |t| <= k p over the
// patch (D is their support function: the traction opposite the local slip maximises the power);
// for the decoupled law the cylinder |F| <= kN, |M| <= M0; for every law kN bounds the force part
// (D = kN at pure slip, a promise of every law: friction/law.h).
//
// Membership: rho is inside iff the margin m(d) = (D(d) - rho.d)/(kN) is >= 0 for every d; the
// test returns min_d m(d) and its direction. Directions: d = (cos beta cos alpha, cos beta sin
// alpha, sin beta), alpha the angle of e1 from the major axis (CCW about gamma), beta in
// [-pi/2, pi/2] (beta > 0: Omega > 0). The minimum is found:
//   * on the pure-slip circle beta = 0 in closed form, D = kN there for every law: 1 - |rho_F|/kN
//     at alpha along rho_F (the kink of the decoupled law's cylinder lies there);
//   * at the pure spins beta = ±pi/2 (one law evaluation each);
//   * elsewhere by a coarse grid (kGridAlpha x 2 kGridBeta directions) and a Nelder-Mead search
//     started from the best grid direction and from a warm start (the previous test's direction),
//     stopped when the simplex is below kDirectionTolerance rad.
// Accuracy: every margin returned is the margin at a real direction, so it is an upper bound of
// the true minimum; at a smooth minimum the search places the direction to ~kDirectionTolerance
// and the margin to ~kDirectionTolerance^2 (~1e-18 of kN); a minimum missed by the grid needs a
// basin narrower than the grid's cell (pi/8 by pi/12), which no registered law has (their D is
// smooth off the two lines handled in closed form). Cost: 3 + 160 + ~2 x 60-120 law evaluations
// per test (docs/dynamics.md §5 gives the times).
//
// Creep at the boundary. Where the wrench rho* that rolling without slip and spin needs lies
// outside the set, the contact slips at the boundary. With c = (u_t, a Omega) the slip and the
// scaled spin and c' = c_free - G rho for the friction rho (G symmetric positive definite, the
// slip response of the body, scaled like c and rho), a slip that grows along its own direction d,
// c' = lambda d with lambda > 0, needs rho = rho(d) with rho* - rho(d) = lambda G^-1 d: rho(d) is
// the projection of rho* on the set in the metric of G, and d maximises
//     (rho*.d - D(d))^2 / (d^T G^-1 d)     (Fenchel's dual of that projection).
// So the direction of creep minimises the weighted margin m(d)/sqrt(d^T Q d), Q = G^-1 (the
// `metric` of test() and follow()); with Q = I (no metric) it is the margin's own minimum, the
// direction for an isotropic body. The sign of the weighted margin is the margin's: membership
// does not depend on the metric.
//
// Degenerate sets: with kN = 0 (no load, or k = 0) or a law without spin moment (D = 0 at pure
// spin, e.g. decoupled:r_spin=0) the set has no interior: degenerate() is true and a caller must
// not rely on it to hold a contact (the body's stick mode is then never entered).

#include <Eigen/Core>

#include "friction/law.h"

namespace frictionlab::dynamics {

/// A slip/spin direction (see the header comment), rad.
struct SlipDirection {
  double alpha = 0.0;  ///< angle of the slip direction e1 from the major axis, CCW about gamma
  double beta = 0.0;   ///< elevation: tan beta = a Omega / U, in [-pi/2, pi/2]
};

/// A friction wrench in the patch frame (x along the major axis, y = gamma x x) as resistance:
/// the friction force on the body is -(Fx x + Fy y), N; the torque is -M gamma, N m.
struct PatchWrench {
  double Fx = 0.0;
  double Fy = 0.0;
  double M = 0.0;
};

/// The outcome of a membership test.
struct LimitSetTest {
  double margin = 0.0;          ///< min over directions of (D(d) - rho.d)/(kN) (weighted by
                                ///< 1/sqrt(d^T Q d) with a metric Q); < 0 outside
  SlipDirection direction;      ///< where the minimum is (the maximum-dissipation direction when
                                ///< the wrench is on the boundary)
  long evaluations = 0;         ///< law evaluations spent
  [[nodiscard]] bool inside() const { return margin >= 0.0; }
};

class LimitSet {
 public:
  static constexpr int kGridAlpha = 16;              ///< grid directions in alpha over [0, 2 pi)
  static constexpr int kGridBeta = 5;                ///< grid elevations per sign of beta, in (0, pi/2)
  static constexpr double kDirectionTolerance = 1e-9;  ///< rad: the simplex size that stops the search
  static constexpr int kMaxSearchEvaluations = 400;  ///< per Nelder-Mead search
  /// The support at pure spin per kN a below which the set counts as degenerate (no spin moment).
  static constexpr double kDegenerateSpin = 1e-12;

  /// The set of `law` at a contact with friction coefficient k, normal force N (N), patch semi-axes
  /// a >= b > 0 (m). Throws what the law throws for invalid values. The law must outlive this.
  LimitSet(const friction::FrictionLaw& law, double k, double N, double a, double b);

  /// D(d)/(kN) at the direction d: the law's dissipation per kN at unit (U, a Omega). Requires kN > 0.
  [[nodiscard]] double support(const SlipDirection& d) const;
  /// The law's resistance rho(d) per kN at d (patch frame, M per kN a), as the law gives it.
  [[nodiscard]] PatchWrench resistance(const SlipDirection& d) const;
  /// No interior (see the header comment): kN = 0 or no moment at pure spin.
  [[nodiscard]] bool degenerate() const { return degenerate_; }
  /// Whether `rho` lies in the set: the minimum margin over directions and its direction,
  /// searched also from `warm` if given. A degenerate set gives margin -inf for any rho.
  [[nodiscard]] LimitSetTest test(const PatchWrench& rho, const SlipDirection* warm = nullptr) const;
  /// The same with the margin weighted by 1/sqrt(d^T Q d) for the metric Q (symmetric positive
  /// definite, in the coordinates (x, y, a Omega) of d): the minimising direction is then the
  /// direction of creep for the slip response G = Q^-1 (see the header comment).
  [[nodiscard]] LimitSetTest test(const PatchWrench& rho, const SlipDirection* warm, const Eigen::Matrix3d& metric) const;
  /// Only the local search from `warm` (~60-120 law evaluations): the minimising direction follows
  /// a wrench that moved little since the test that gave `warm`.
  [[nodiscard]] LimitSetTest follow(const PatchWrench& rho, const SlipDirection& warm, const Eigen::Matrix3d& metric) const;
  /// The direction of creep as the slow manifold of the slip defines it, for any law: the d at
  /// which the slip's rate G (rho* - rho(d)) is along d itself (lambda > 0), for the slip response
  /// `response` = G (symmetric positive definite, in the coordinates (x, y, a Omega) of d: the
  /// inverse of test()'s metric). For a law of maximum dissipation it is the direction test() and
  /// follow() find; a law whose resistance is not the gradient of its dissipation (D not a support
  /// function where it is evaluated) has its own. Newton's method on (alpha, beta) from `start`
  /// with a finite-difference Jacobian, to kDirectionTolerance; `found` false where it does not
  /// converge or lambda <= 0 there. `evaluations` counts the law evaluations.
  [[nodiscard]] SlipDirection creep_direction(const PatchWrench& rho, const SlipDirection& start,
                                              const Eigen::Matrix3d& response, bool& found, long& evaluations) const;
  /// The margin (D(d) - rho.d)/(kN) at one direction (one law evaluation): negative proves rho
  /// outside. -inf for a degenerate set.
  [[nodiscard]] double margin_at(const PatchWrench& rho, const SlipDirection& d) const;

 private:
  [[nodiscard]] friction::FrictionForces evaluate(const SlipDirection& d) const;
  [[nodiscard]] double margin(const PatchWrench& rho_per_kN, const SlipDirection& d) const;
  [[nodiscard]] double objective(const PatchWrench& rho_per_kN, const SlipDirection& d, const Eigen::Matrix3d* metric) const;
  [[nodiscard]] LimitSetTest search(const PatchWrench& rho_SI, const SlipDirection* warm, const Eigen::Matrix3d* metric) const;
  SlipDirection nelder_mead(const PatchWrench& rho_per_kN, const Eigen::Matrix3d* metric, SlipDirection start,
                            double size, double& best, long& evaluations) const;

  const friction::FrictionLaw& law_;
  double k_, N_, a_, b_, kN_;
  bool degenerate_ = false;
};

}  // namespace frictionlab::dynamics
