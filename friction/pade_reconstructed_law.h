#pragma once
// The Padé law of the source paper with its coefficients re-derived from the limits of the exact
// law: the printed forms (8), coefficients matched at slow and at fast slip, one form changed.
//
// Provenance: the forms are those of M.A. Munitsyna (2013), eq. (8) (see pade_printed_law.h); the
// coefficients are ours, matched to the exact law over the elliptic Hertz patch (docs/model.md).
// Derivation, and which printed coefficients survive: docs/pade-reconstruction.md.
//
// With F0 = kN, alpha = a (the major semi-axis), mu = b/a, s = U/(a|Omega|), k^2 = 1 - mu^2,
// K = K(k), E = E(k) (complete elliptic integrals, modulus k), B = ((1 + mu^2) K - 2E)/k^2,
// C = B/k^2 (-> pi/16 at the circle), L = K + B cos 2psi, d3, d4 of eq. (9):
//
//   F1 = F0 (U^2 + a1 U alpha|Omega|) / (U^2 + a1 U alpha|Omega| + a2 alpha^2 Omega^2)    Eq. (8)
//   F2 = F0 a3 U alpha^2 Omega^2 / (U^3 + a4 alpha^3 |Omega|^3)          (changed form, see below)
//   M  = M0 (b1 U alpha Omega + alpha^2 Omega|Omega|)
//           / (b2 U^2 + b1 U alpha|Omega| + alpha^2 Omega^2)                                Eq. (8)
//
//   M0 = (3/8) E alpha F0,   a1 = (3/40) d3 L,   a2 = d3/10,
//   a3 = d4/10 = (1 - mu^2) sin 2psi / 10,   a4 = 2/(15 C) = 2 k^2/(15 B),
//   b1 = 8 d3 L / (15 E^2),   b2 = L/E.
//
// Matched (per kN and kNa): slow slip s -> 0: F1 = (3/4) L s, F2 = (3/4) B sin 2psi s,
// M = M0 sign(Omega) (1 - (L/E) s^2); fast slip s -> inf: F1 = 1 - d3/(10 s^2),
// F2 = d4/(10 s^2), |M| = d3/(5 s). The printed F2 form -F0 U alpha Omega/(U^2 + ...) decays like
// 1/s and is odd in Omega; the exact F2 decays like 1/s^2 and is even in Omega, and matching its
// slope with that form forces a negative constant term (the printed a4 < 0, hence a real pole). The
// changed form is the lowest-degree rational function that is even in Omega, ~ s at slow slip,
// ~ 1/s^2 at fast slip, with no s^2 term at slow slip and no 1/s^3 term at fast slip (the exact
// expansions have neither) and a positive denominator: its two coefficients are fixed by the two
// limits. Printed coefficients kept:
// a2 exactly; a3 in magnitude (now the fast-slip numerator); the structures of a1, b1, b2, M0 with
// the printed power-of-mu approximations replaced by the elliptic integrals they stand for
// (K + B cos 2psi ~ (pi/2) d5 mu^(-3/4), E ~ (pi/2) mu^(1/2)); b1 with its sign corrected.
//
// Properties (tested in tests/friction/pade_reconstructed_law_test.cpp): every coefficient is
// positive (a3 has the sign of sin 2psi), so no denominator vanishes for U >= 0, any mu in (0, 1],
// any psi; F1, F2 even and M odd in Omega; pi-periodic in psi; F2 = 0 for a circle and for
// sin 2psi = 0; 0 <= F1 < F0, |M| <= M0; dissipative (F1 U + M Omega >= 0). Not bounded by kN
// in |F|: sqrt(F1^2 + F2^2) <= F0 holds for mu >= 1.2e-3 (on s = 1e-3..1e3, psi = 0..90 deg),
// and exceeds it below (1.006 F0 at mu = 1e-3, s = 0.28, psi = 46 deg).
// Limits: U = Omega = 0: all zero (rest). Omega = 0: F1 = F0, F2 = M = 0.
// U = 0: F1 = F2 = 0, M = M0 sign(Omega).
// Evaluated in s when s < 1 and in 1/s otherwise (s from slip_ratio(), law.h), so no power of U or
// Omega can overflow.
// K, E and C come from one arithmetic-geometric mean (Gauss; DLMF 19.8.1, 19.8.2), with the sums
// arranged so that B and C carry no cancellation near the circle: relative error ~1e-15 for every
// mu in (0, 1] (checked against Boost's Carlson and Legendre integrals in the tests). Cost: ~43 ns
// per evaluation on the development machine (printed law: ~36 ns).
// Valid range: all inputs accepted by validate().
// Largest errors against `exact` found on the study grid (s in [1e-3, 1e3], mu in [0.05, 1], all
// psi, both signs of Omega; docs/pade-reconstruction.md §6): F1 0.85 kN (mu = 0.05, psi = pi/2,
// s = 0.067), F2 0.19 kN (mu = 0.05, psi = 0.65, s = 0.32), M 0.13 kNa (mu = 0.15, psi = pi/2,
// s = 0.94); rms 0.084, 0.0098, 0.023. These are limits of the forms (8), not of the matching:
// even for a circle, where the matched F1 coefficients are the printed ones, F1 is off by 0.22 kN
// near s = 0.35. The law is smooth and safe along trajectories, not accurate to a few per cent.

#include "friction/law.h"

namespace frictionlab::friction {

/// Complete elliptic integrals of modulus k = sqrt(1 - mu^2), for the patch axis ratio mu.
struct PatchEllipticIntegrals {
  double K;  ///< K(k), first kind
  double E;  ///< E(k), second kind
  double B;  ///< ((1 + mu^2) K - 2E)/k^2 = int_0^(pi/2) -cos 2t / sqrt(1 - k^2 sin^2 t) dt, >= 0
  double C;  ///< B/k^2 = int_0^(pi/2) sin^2 t cos^2 t / (1 - k^2 sin^2 t)^(3/2) dt, > 0
};

/// K, E, B, C for mu in (0, 1] by the arithmetic-geometric mean; mu = 1 gives pi/2, pi/2, 0, pi/16.
[[nodiscard]] PatchEllipticIntegrals patch_elliptic_integrals(double mu);

/// The matched coefficients of the reconstructed law (dimensionless).
struct PadeReconstructedCoefficients {
  double a1, a2;            ///< F1, as in eq. (8)
  double a3, a4;            ///< F2 = F0 a3 s / (s^3 + a4) (changed form)
  double b1, b2;            ///< M, as in eq. (8)
  double m0_over_alpha_f0;  ///< M0 / (alpha F0) = (3/8) E(k)
};

/// The coefficients for axis ratio mu in (0, 1] and orientation psi (an angle in rad converts; only
/// its cosine and sine are read).
[[nodiscard]] PadeReconstructedCoefficients pade_reconstructed_coefficients(double mu, const PatchAngle& psi);

/// The forms (8) with coefficients matched to the exact law at slow and fast slip.
class PadeReconstructedLaw final : public FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] std::string_view summary() const override;
  [[nodiscard]] LawPromises promises() const override;

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
};

}  // namespace frictionlab::friction
