#pragma once
// The "ellipsoidal" coupled friction law of Möller, Leine and Glocker, with a given radius Rb or
// with the Hertz-calibrated default; and the maximum-dissipation rule on an ellipsoidal friction
// set that it shares with the MuJoCo law (friction/mujoco_elliptic_law.h).
//
// Provenance: M. Möller, R.I. Leine and Ch. Glocker approximate the Coulomb-Contensou friction set
// of a contact patch (R.I. Leine, Ch. Glocker, "A set-valued force law for spatial
// Coulomb-Contensou friction", Eur. J. Mech. A/Solids 22 (2003) 193-216) by an ellipsoid with
// semi-axes (kN, kN, kN Rb) in (force, force, moment) space; the sliding law is the force on that
// ellipsoid that dissipates most (its normal cone). Their paper is "An efficient approximation of
// set-valued force laws of normal cone type" (Proc. 7th EUROMECH Solid Mechanics Conference,
// Lisbon, 2009) — bibliographic details as recalled, not checked against the paper here.
//
// Maximum dissipation on an ellipsoid (the derivation, docs/engines.md §1): for the set
// (|F|/F0)^2 + (M/M0)^2 <= 1 and a contact that slips at U along e1 and spins at Omega, the
// element that maximises the power F.v + M Omega is, by a Lagrange multiplier,
//
//   F = F0^2 U / D,   M = M0^2 Omega / D,   D = sqrt(F0^2 U^2 + M0^2 Omega^2),
//
// i.e. with r = F0 U / (M0 |Omega|):  F1 = F0 r / sqrt(1 + r^2),  M = M0 sign(Omega) / sqrt(1 + r^2),
// F2 = 0 (the force lies along the slip). The point is on the boundary: (F1/F0)^2 + (M/M0)^2 = 1
// whenever the contact moves.
//
// The ellipsoidal law takes F0 = kN and M0 = kN Rb (Rb a length, m), so r = U / (Rb |Omega|):
//
//   F1 = kN U / sqrt(U^2 + Rb^2 Omega^2),  F2 = 0,  M = kN Rb^2 Omega / sqrt(U^2 + Rb^2 Omega^2).
//
// The radius: `ellipsoidal:Rb=...` fixes Rb in metres, whatever the patch (as an engine does);
// without Rb the law is Hertz-calibrated: Rb = (3 pi/16) sqrt(a b), which makes the pure-spin
// torque exact for a circular Hertz patch, (3 pi/16) kN a (docs/model.md). For an ellipse there is
// no single right radius: the circle value on the geometric-mean radius sqrt(a b) (the circle of
// the same area) is a choice of ours, not of the cited papers. This default is the law known before
// as `moller-ellipsoidal` (an alias of `ellipsoidal` in the registry). Which fixed Rb best matches the exact law
// for each pressure: docs/engines.md (`frictionlab calibrate`).
//
// Limits: U = Omega = 0 (0/0): all zero, as the exact law at rest. Omega = 0: F1 = kN exactly.
// U = 0: M = kN Rb sign(Omega). Dissipative (F1 U + M Omega = kN sqrt(U^2 + Rb^2 Omega^2) >= 0), F1
// even and M odd in Omega, nothing depends on psi (the law cannot see the patch's orientation).
// Evaluated in r or 1/r, so nothing overflows. With a fixed Rb the torque limit kN Rb exceeds
// kN a on a patch smaller than Rb (no `bounded` promise), and overflows only if Rb > 1 m and kN
// is near the largest double: such input is rejected (std::invalid_argument).
// Largest errors of the Hertz-calibrated default against `exact` on the study grid (s in
// [1e-3, 1e3], mu in [0.05, 1], all psi; docs/accuracy.md): F1 0.54 kN, F2 0.21 kN (the law has
// none), M 0.28 kNa, all at mu = 0.05 with the slip along the minor axis; for a circle 0.11 kN /
// 0 / 0.083 kNa. For a fixed Rb the errors depend on Rb/a: docs/engines.md.

#include <optional>
#include <string>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"

namespace frictionlab::friction {

/// The element of the friction set (|F|/F0)^2 + (M/M0)^2 <= 1 that dissipates most, for a slip
/// ratio r = F0 U / (M0 |Omega|) in [0, +inf] and `sign` = sign(Omega) (+1 or -1): F1 = F0 r /
/// sqrt(1 + r^2), F2 = 0, M = M0 sign / sqrt(1 + r^2), evaluated without overflow (F0, M0 finite,
/// >= 0). r = +inf is pure sliding (F1 = F0, M = 0).
[[nodiscard]] FrictionForces ellipsoidal_max_dissipation(double F0, double M0, double r, double sign);

/// The ellipsoidal (Möller-Leine-Glocker) law, with a fixed Rb (m) or Hertz-calibrated.
class EllipsoidalLaw final : public FrictionLaw {
 public:
  /// Rb: the radius in metres (finite, > 0), or none for the Hertz-calibrated
  /// Rb = (3 pi/16) sqrt(a b). std::invalid_argument naming Rb otherwise.
  explicit EllipsoidalLaw(std::optional<double> Rb = std::nullopt);

  /// What `ellipsoidal:Rb=...` may set (friction/law_spec.h): Rb, m, > 0; none: Hertz-calibrated.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] std::string_view name() const override { return "ellipsoidal"; }
  [[nodiscard]] std::string_view summary() const override { return summary_; }
  [[nodiscard]] LawPromises promises() const override;
  /// The fixed radius, m, or none (Hertz-calibrated).
  [[nodiscard]] std::optional<double> radius() const { return Rb_; }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;

  std::optional<double> Rb_;
  std::string summary_;
};

}  // namespace frictionlab::friction
