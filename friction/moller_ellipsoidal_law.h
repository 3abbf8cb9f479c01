#pragma once
// The "ellipsoidal" coupled friction law of Möller, Leine and Glocker, on the geometric-mean
// radius.
//
// Provenance: M. Möller, R.I. Leine and Ch. Glocker approximate the Coulomb-Contensou friction set
// of a Hertz patch (R.I. Leine, Ch. Glocker, "A set-valued force law for spatial Coulomb-Contensou
// friction", Eur. J. Mech. A/Solids 22 (2003) 193-216) by an ellipsoid with semi-axes
// (kN, kN, kN Rb); the sliding law is then the smooth "normal to the ellipsoid" law below. Their
// paper is "An efficient approximation of set-valued force laws of normal cone type" (Proc. 7th
// EUROMECH Solid Mechanics Conference, Lisbon, 2009) — bibliographic details as recalled, not
// checked against the paper here. It is the law used for the tippe top in several open codes.
// docs/model.md states it as
//
//   F = -kN v / sqrt(|v|^2 + Rb^2 Omega^2),
//   torque -kN Rb^2 Omega / sqrt(|v|^2 + Rb^2 Omega^2) gamma,
//
// with v = U e1 the slip velocity of the patch centre. In the frictionlab convention
// (F = -F1 e1 - F2 e2, torque -M gamma), with den = sqrt(U^2 + Rb^2 Omega^2):
//
//   F1 = kN U / den,   F2 = 0,   M = kN Rb^2 Omega / den.
//
// Rb = (3 pi/16) sqrt(a b). For a circular Hertz patch of radius a, Rb = (3 pi/16) a makes both
// pure limits exact (pure sliding F1 = kN; pure spin M = (3 pi/16) kN a, docs/model.md). For an
// ellipse there is no single right radius: we take the circle value on the geometric-mean radius
// sqrt(a b) (the circle of the same area) — a choice of ours, not of the cited papers.
//
// Limits: U = Omega = 0 (0/0): all zero, as the exact law at rest. Omega = 0: F1 = kN exactly.
// U = 0: M = kN Rb sign(Omega). The law is dissipative (F1 U + M Omega = kN den >= 0), F1 is even
// and M odd in Omega, and nothing depends on psi (the law cannot see the orientation of the patch).
// Evaluated in r = U/(Rb|Omega|) or 1/r (F1 = kN r/sqrt(1 + r^2), M = kN Rb sign(Omega)/
// sqrt(1 + r^2)), so nothing overflows. Valid range: all inputs accepted by validate().
// Largest errors against `exact` found on the study grid (s in [1e-3, 1e3], mu in [0.05, 1], all
// psi; docs/pade-reconstruction.md §6-7): F1 0.54 kN, F2 0.21 kN (the law has none), M 0.28 kNa,
// all at mu = 0.05 with the slip along the minor axis; for a circle 0.11 kN / 0 / 0.083 kNa.

#include "friction/law.h"

namespace frictionlab::friction {

/// The ellipsoidal (Möller-Leine-Glocker) law with Rb = (3 pi/16) sqrt(a b).
class MollerEllipsoidalLaw final : public FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] std::string_view summary() const override;
  [[nodiscard]] LawPromises promises() const override;

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
};

}  // namespace frictionlab::friction
