#pragma once
// The exact law again, by brute force: the traction integrals of model notes §1 by a plain nested
// adaptive 2-D quadrature (GSL QAGP/QAGS inside QAG), in polar coordinates about the patch centre.
// It shares no formula with ExactLaw beyond the definition of the law, so it is the cross-check
// of ExactLaw's semi-analytic scheme. Slow on purpose (milliseconds per call): for tests and
// accuracy studies, never inside a simulation.
//
// Coordinates: polar about the patch centre in the ellipse frame (x along the major axis),
// rho = r (cos t, sin t), with r = r_max(t) sin chi, r_max(t) = (cos^2 t / a^2 + sin^2 t / b^2)^-1/2,
// so that the Hertz factor sqrt(1 - r^2 / r_max^2) = cos chi is smooth:
//   p dA = (3N / (2 pi a b)) r_max^2 cos^2 chi sin chi dchi dt,   chi in [0, pi/2].
// The traction direction v/|v| jumps at the instantaneous centre of rotation (ICR), so the inner
// integral (QAGP/QAGS) breaks at the ray's closest approach to the ICR, and the outer one (QAG,
// 21-point Gauss-Kronrod, on [t_c, t_c + 2 pi]) breaks at the ICR's direction t_c, at t_c + pi
// and at the major axis (t = 0, pi, where r_max^2 peaks over a width ~b/a). Requested errors:
// 1e-12 (outer) per kN and per kNa; measured against the semi-analytic law and a 30-digit
// evaluation, the reference is good to ~5e-12 kN (worst seen 5e-12, ICR very near the centre
// of a slender patch). A GSL error estimate above 1e-10 throws.
//
// Limits as in ExactLaw: N = 0 or k = 0, and U = Omega = 0 (indeterminate), give zero forces;
// Omega = 0 gives F1 = kN exactly. Thread-safe: GSL workspaces are allocated per call; the GSL
// error handler is switched off once (process-wide) so that GSL never aborts, and a failed
// integration throws std::runtime_error.

#include <string_view>

#include "friction/law.h"

namespace frictionlab::friction {

/// The exact law by nested adaptive GSL quadrature over the ellipse (reference, slow).
class ExactReferenceLaw final : public FrictionLaw {
 public:
  ExactReferenceLaw() = default;

  [[nodiscard]] std::string_view name() const override { return "exact-reference"; }
  [[nodiscard]] std::string_view summary() const override {
    return "exact law by nested adaptive 2-D GSL quadrature over the patch (slow cross-check of "
           "'exact', ~1e-11 kN)";
  }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
};

}  // namespace frictionlab::friction
