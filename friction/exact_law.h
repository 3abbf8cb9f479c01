#pragma once
// The exact law of coupled sliding and spinning friction over an elliptic Hertz patch
// (docs/model.md): the integrals of the local Coulomb traction over the contact ellipse,
// accurate to 1e-13 k N (forces) and 1e-13 k N a (moment) for every valid input with
// b/a >= 1e-12 (kExactLawAccuracy, kExactMinAxisRatio). Largest error found: 5e-14 (the whole -
// gap subtraction near rho = 2, against the window quadrature); 2.9e-14 against the 30-digit
// table tests/friction/reference/exact_table.csv (mu = 1 .. 1e-12; docs/exact-law.md §2).
// About 120 ns per call (median).
//
//   F1 = k ∫∫ p (v/|v|).e1 dA,   F2 = k ∫∫ p (v/|v|).e2 dA,   M = k ∫∫ p (rho x v/|v|).gamma dA,
//   p = 3N/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2),   v(rho) = U e1 + Omega gamma x rho.
//
// F1/(kN), F2/(kN) and M/(kNa) depend only on s = U/(a |Omega|), mu = b/a, psi and sign(Omega).
// Method (docs/exact-law.md): polar coordinates about the instantaneous centre of rotation
// (ICR), folded onto whole lines, make every radial integral elementary; the remaining integral
// over the line direction is done
//   * in closed form (complete elliptic integrals of modulus sqrt(1 - mu^2), by the AGM) when
//     the ICR is inside the patch or on its rim;
//   * ICR outside: by composite Gauss-Legendre quadrature, graded towards the complex branch
//     points of the integrand, over the directions that hit the patch, or (for an ICR within
//     twice the rim, 1.5 times for mu < 0.01, when cheaper) as the closed form minus the
//     directions that miss it;
//   * by the fast-slip expansion F1 = kN (1 - d3/(10 s^2)), F2 = kN d4/(10 s^2),
//     M = kNa d3/(5 s) sign(Omega) for s > 1e8, where its truncation error is below 1e-24.
// No heap allocation per call; Gauss rules are built once. Safe to call concurrently.
//
// Limits, each handled by an explicit branch:
//   * N = 0 or k = 0: all zero.
//   * Omega = 0, U > 0 (pure sliding): F1 = kN, F2 = M = 0 exactly.
//   * U = 0, Omega != 0 (pure spin): F1 = F2 = 0 exactly, M = (3/8) k N a E(e) sign(Omega).
//   * U = Omega = 0: the law is indeterminate there (every direction of v/|v| is a limit);
//     returns F1 = F2 = M = 0. A caller that needs rest friction must model it separately.
//   * b/a < 1e-12 throws std::invalid_argument: the panel grading is built for b/a >= 1e-12, and
//     a thinner patch evaluated as a slit of 1e-12 would be off by O(1) within ~b/a of 90 deg.
// k N and k N a beyond the double range are rejected by validate(); s = U/(a|Omega|) comes from
// slip_ratio() (law.h), with no overflow or underflow of a|Omega| (s = +inf is pure sliding).

#include <string_view>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"
#include "friction/pressure.h"

namespace frictionlab::friction {

/// The accuracy ExactLaw promises, per kN (forces) and per kNa (moment), for every valid input
/// with b/a >= kExactMinAxisRatio.
inline constexpr double kExactLawAccuracy = 1e-13;
/// The smallest axis ratio b/a ExactLaw accepts (std::invalid_argument below).
inline constexpr double kExactMinAxisRatio = 1e-12;

/// The accuracy ExactLaw promises for the uniform and flat-punch pressures (per kN and kNa,
/// b/a >= kExactMinAxisRatio); docs/pressure-models.md gives the largest error found.
inline constexpr double kExactLawPressureAccuracy = 1e-10;

/// Exact coupled dry friction over an elliptic patch, by quadrature (docs/model.md), for a
/// pressure model (friction/pressure.h; docs/pressure-models.md): Hertz (the default, as above),
/// uniform or the flat punch. Punch: the same reduction, with the chord factor D^0 (the whole
/// period is again a polynomial in the ICR, the window integrand is smooth to its ends). Uniform:
/// the ICR reduction in the Jacobi amplitude (ICR inside) or in the window (outside); near the rim
/// and for b/a < 0.01 the divergence theorem turns the patch integrals into integrals over its rim
/// of |rho - c| (times polynomials), done by Gauss-Legendre panels graded towards the complex zeros
/// of |rho(t) - c|^2, and for b/a < 1e-4 folded by the patch's mirror symmetries, so that no
/// O(b/a) sum is divided by b/a (docs/pressure-models.md §3).
class ExactLaw final : public FrictionLaw {
 public:
  explicit ExactLaw(Pressure pressure = Pressure::hertz) : pressure_(pressure) {}

  /// What a spec may set (friction/law_spec.h): pressure = hertz|uniform|punch.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] Pressure pressure() const { return pressure_; }

  [[nodiscard]] std::string_view name() const override { return "exact"; }
  [[nodiscard]] LawPromises promises() const override;
  [[nodiscard]] std::string_view summary() const override {
    return "exact integral of Coulomb traction over the elliptic Hertz patch (docs/model.md), "
           "semi-analytic quadrature: accurate to 1e-13 kN and kNa for b/a >= 1e-12 (largest error "
           "found 5e-14)";
  }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
  Pressure pressure_;
};

}  // namespace frictionlab::friction
