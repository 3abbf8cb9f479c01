#pragma once
// MuJoCo's contact friction with condim = 4 and an elliptic cone, in steady sliding: the
// maximum-dissipation point of its friction cone, which is the ellipsoidal law with
// Rb = torsional / k.
//
// Provenance: MuJoCo 2.2.2 (the version Debian ships), documentation "Computation > Contact"
// (doc/computation.rst) and src/engine/engine_core_constraint.c. With condim = 4 a contact has a
// normal force fn, two tangential forces f1, f2 and a torsional torque tau about the normal, and
// the elliptic cone is
//
//   (f1/mu1)^2 + (f2/mu2)^2 + (tau/mu3)^2 <= fn^2,
//
// where MJCF `friction="k torsional rolling"` on a geom gives mu1 = mu2 = k (dimensionless) and
// mu3 = torsional (a length, m; the mixing of two geoms takes the larger value, and MuJoCo raises
// any coefficient below mjMINMU = 1e-5 to 1e-5). In the cone ("middle") zone of its solver the
// force lies on this boundary, along the direction diag(mu)^2 times the constraint residual (the
// function mj_constraintUpdate); read with the residual along the relative velocity (slip U along
// e1, spin Omega), that is the maximum-dissipation point of the ellipsoid with F0 = k fn and
// M0 = mu3 fn (friction/ellipsoidal_law.h):
//
//   F1 = kN r/sqrt(1 + r^2),  F2 = 0,  M = N torsional sign(Omega)/sqrt(1 + r^2),
//   r = k U/(torsional |Omega|),
//
// which is the ellipsoidal law with Rb = mu3/mu1 = torsional/k (docs/engines.md §1 derives it).
//
// What this law is not (docs/engines.md §4 compares it with MuJoCo itself): MuJoCo's contact is
// soft — its forces come from a regularised convex problem (solref, solimp, impratio), the
// direction in the cone zone follows the constraint-space acceleration residual, not the velocity
// alone, and below a slip or spin speed set by the impedance the friction acts as a damper inside
// the cone rather than on its boundary. This law is MuJoCo's cone taken at its word: the limit of
// a hard, maximally dissipative contact.
//
// The parameter `torsional` (m, finite, > 0; default 0.005, MuJoCo's) is the MJCF value; k is the contact's Coulomb
// coefficient (ContactInput::k). With k = 0 the tangential force vanishes and the torque is
// N torsional sign(Omega). Limits: U = Omega = 0: all zero; Omega = 0: F1 = kN; U = 0:
// M = N torsional sign(Omega). Dissipative, F1 even and M odd in Omega, independent of psi. The
// torque limit N torsional does not know the patch (no `bounded` promise) and overflows only for
// torsional > 1 m and N near the largest double (rejected with std::invalid_argument).

#include <string>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"

namespace frictionlab::friction {

/// MuJoCo's condim-4 elliptic cone, maximally dissipative: the ellipsoidal law with
/// Rb = torsional / k.
class MujocoEllipticLaw final : public FrictionLaw {
 public:
  /// torsional: MJCF's torsional friction coefficient (m), finite and > 0; std::invalid_argument
  /// naming it otherwise.
  explicit MujocoEllipticLaw(double torsional = kDefaultTorsional);

  /// MuJoCo's default torsional coefficient (MJCF friction="1 0.005 0.0001"), m.
  static constexpr double kDefaultTorsional = 0.005;
  /// What `mujoco-elliptic:torsional=...` may set (friction/law_spec.h): torsional, m, > 0,
  /// default kDefaultTorsional.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] std::string_view name() const override { return "mujoco-elliptic"; }
  [[nodiscard]] std::string_view summary() const override { return summary_; }
  [[nodiscard]] LawPromises promises() const override;
  [[nodiscard]] double torsional() const { return torsional_; }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;

  double torsional_;
  std::string summary_;
};

}  // namespace frictionlab::friction
