#pragma once
// The Padé law of the source paper, formulas (8)-(9), exactly as printed.
//
// Provenance: M.A. Munitsyna, "Dynamics of a body of revolution on a horizontal plane within the
// interconnected model of friction" (2013), eqs. (8)-(9) (received 20.11.2012; Russian; docs/model.md cites it), an approximation
// of the exact law over the elliptic Hertz patch by the same author (2012). With F0 = kN,
// alpha = a (the major semi-axis; the text also says min{a, b}: see pade-printed-minor),
// mu = b/a, s-terms written in U and alpha|Omega|:
//
//   Eq. (8)  F1 = F0 (U^2 + a1 U alpha|Omega|) / (U^2 + a1 U alpha|Omega| + a2 alpha^2 Omega^2)
//            F2 = -F0 U alpha Omega / (U^2 + a3 U alpha|Omega| + a4 alpha^2 Omega^2)
//            M  = M0 (b1 U alpha Omega + alpha^2 Omega|Omega|)
//                    / (b2 U^2 + b1 U alpha|Omega| + alpha^2 Omega^2)
//   Eq. (9)  M0 = (3 pi/16) mu^(1/2) alpha F0,
//            a1 = 3 pi d3 d5 / (80 mu^(3/4)),   a2 = d3/10,   a3 = -d4/10,
//            a4 = -8 / (3 mu^(3/4) pi d6),      b1 = -16 d3 d5 / (15 mu^(7/4) pi),
//            b2 = d5 / mu^(5/4),
//            d3 = (1 - mu^2) cos^2 psi + mu^2,  d4 = (1 - mu^2) sin 2psi,
//            d5 = (1 - mu^(1/4)) cos 2psi + mu^(1/4),   d6 = (1 - mu^(1/4)) sin 2psi.
//   The printed a0 = (8/(3 pi)) mu^(3/4)/d5 and b0 = (15 pi/16) mu^(1/2)/d3 are never used.
//
// Oddities kept on purpose (docs/model.md; the accuracy study measures them): b1 < 0; F2 is odd in
// Omega while the exact F2 is even; a4 < 0, so the denominator of F2 vanishes at a real slip ratio
// (a pole); d5 < 0 for mu < 1/16 near cos 2psi = -1 changes the signs of a1, b1, b2.
//
// Where the printed formula is not defined, this implementation returns its limits:
//   * U = 0 and Omega = 0 (every ratio is 0/0): F1 = F2 = M = 0, as the exact law does at rest;
//   * d6 = 0 (sin 2psi = 0 or a circle): a4 is infinite and F2 = 0, its limit for d6 -> 0;
//   * N = 0 or k = 0: everything is 0.
// Where it has no value it throws std::invalid_argument naming the input and the rule:
//   * on a real pole (a denominator of eq. (8) that vanishes, or so nearly that the quotient
//     leaves the double range); near one the values are finite and as large as the formula says;
//   * for b/a < kPadePrintedMinAxisRatio, where the coefficients leave the double range.
// Evaluated in sigma = U/(alpha|Omega|) or 1/sigma (the same rational functions), so no power of U
// or alpha Omega can overflow.
// Valid range: none is stated in the paper; see docs/accuracy.md for the measured errors.

#include "friction/law.h"

namespace frictionlab::friction {

/// The smallest axis ratio b/a the printed law is evaluated for: its coefficients grow like
/// mu^(-7/4) (1e262 here) and leave the double range near mu = 1e-176.
inline constexpr double kPadePrintedMinAxisRatio = 1e-150;

/// Which semi-axis the printed formulas call alpha.
enum class PadeAlpha {
  major,  ///< alpha = a, as in the definition of the coefficients
  minor,  ///< alpha = min{a, b} = b, as in the sentence after eq. (12)
};

/// The coefficients of eq. (9) for one patch shape and orientation (dimensionless).
struct PadePrintedCoefficients {
  double a1, a2, a3, a4, b1, b2;
  double m0_over_alpha_f0;  ///< M0 / (alpha F0) = (3 pi/16) mu^(1/2)
};

/// Eq. (9) for axis ratio mu in (0, 1] and orientation psi (an angle in rad converts; only its
/// cosine and sine are read). a4 is ±inf where d6 = 0.
[[nodiscard]] PadePrintedCoefficients pade_printed_coefficients(double mu, const PatchAngle& psi);

/// Eqs. (8)-(9) as printed, alpha = the major semi-axis.
class PadePrintedLaw final : public FrictionLaw {
 public:
  explicit PadePrintedLaw(PadeAlpha alpha = PadeAlpha::major) : alpha_(alpha) {}
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] std::string_view summary() const override;
  /// F1 even, F2 odd (the exact F2 is even), M odd in Omega; pi-periodic in psi. Not mirror
  /// symmetric (a3 and a4 change sign with psi, so F2(-psi) != -F2(psi)), not dissipative
  /// (b1 < 0 gives M the wrong sign at large slip), not bounded (poles).
  [[nodiscard]] LawPromises promises() const override;
  /// The printed signs let the F2 denominator of eq. (8) vanish (a4 < 0), and the M denominator
  /// for small mu: both are watched.
  [[nodiscard]] bool has_poles() const override { return true; }
  /// Eq. (8)'s three denominators divided by (a Omega)^2, with U = s a|Omega|, alpha = c a:
  ///   F1: s^2 + a1 c s + a2 c^2,   F2: s^2 + a3 c s + a4 c^2 (NaN where a4 is infinite),
  ///   M:  b2 s^2 + b1 c s + c^2;   c = 1 (alpha = a) or mu (alpha = b).
  [[nodiscard]] PoleDenominators pole_denominators(const ContactInput& in) const override;

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
  PadeAlpha alpha_;
};

}  // namespace frictionlab::friction
