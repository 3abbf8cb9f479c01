#pragma once
// Decoupled Coulomb friction: full sliding friction plus full pivoting torque, independently —
// the law a naive simulator uses.
//
//   F1 = kN if U > 0, 0 if U = 0;   F2 = 0;   M = M0 sign(Omega) (0 if Omega = 0),
//   M0 = (3/8) k N a E(e),  e^2 = 1 - mu^2,  mu = b/a,
//
// with E the complete elliptic integral of the second kind (boost::math::ellint_2, modulus e).
// M0 is the exact pure-spin torque of the Hertz patch (docs/model.md; circle: (3 pi/16) kN a), so
// the law is exact in the two pure limits (U = 0, or Omega = 0) and ignores the coupling in
// between: it overestimates both F1 and |M| whenever slip and spin coexist (the exact law
// satisfies F1 < kN and |M| < M0 for U > 0, Omega != 0).
//
// Provenance: the classical decoupled model of sliding plus pivoting friction (e.g. Contensou's
// "pivoting" torque with the Hertz pressure); this implementation follows docs/model.md.
// Limits: discontinuous at U = 0 (F1 jumps from 0 to kN) and at Omega = 0 (M jumps by 2 M0); F1
// is even and M odd in Omega, nothing depends on psi. Dissipative: F1 U + M Omega =
// kN U + M0 |Omega| >= 0. Valid range: all inputs accepted by validate().
// Against `exact` it is an upper bound (F1 >= F1_exact, |M| >= |M_exact|); its errors are the whole
// coupling effect: up to kN in F1 (slow slip) and up to M0 in M (fast slip), rms 0.60 kN and
// 0.33 kNa on the study grid (docs/pade-reconstruction.md §7).

#include "friction/law.h"

namespace frictionlab::friction {

/// Decoupled Coulomb sliding friction plus the exact pure-spin torque.
class CoulombDecoupledLaw final : public FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] std::string_view summary() const override;
  [[nodiscard]] LawPromises promises() const override;

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
};

}  // namespace frictionlab::friction
