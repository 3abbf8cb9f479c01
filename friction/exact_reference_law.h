#pragma once
// The exact law again, by brute force: the traction integrals of docs/model.md by a plain nested
// adaptive 2-D quadrature (GSL QAGP/QAGS inside QAG), in polar coordinates about the patch centre.
// It shares no formula with ExactLaw beyond the definition of the law, so it is the cross-check
// of ExactLaw's semi-analytic scheme. Slow on purpose (10-100 ms per call; the registry marks it
// slow): for tests and small accuracy studies, never inside a simulation.
//
// Coordinates: polar about the patch centre in the ellipse frame (x along the major axis),
// rho = r (cos t, sin t), with r = r_max(t) sin chi, r_max(t) = (cos^2 t / a^2 + sin^2 t / b^2)^-1/2,
// so that the pressure factor (1 - r^2 / r_max^2)^n = cos^(2n) chi is harmless:
//   p dA = ((n + 1) N / (pi a b)) r_max^2 cos^(2n+1) chi sin chi dchi dt,   chi in [0, pi/2],
// smooth for every pressure model (friction/pressure.h): cos^2 chi sin chi (Hertz, n = 1/2),
// cos chi sin chi (uniform), sin chi (flat punch, n = -1/2: the substitution absorbs the edge
// singularity (1 - r^2/r_max^2)^(-1/2) = 1/cos chi into dr = r_max cos chi dchi).
// The traction direction v/|v| jumps at the instantaneous centre of rotation (ICR), so the inner
// integral (21-point Gauss-Kronrod, QAG, per piece) breaks at the ray's closest approach to the
// ICR and is graded about it (ratio 4, from the ICR's distance to the chord), and the outer one
// (QAG on [t_c, t_c + 2 pi]) breaks at the ICR's direction t_c, at t_c + pi, at the major axis
// (t = 0, pi, where r_max^2 peaks over a width ~b/a) and at the rim points where the rays' closest
// approach to the ICR crosses the rim, graded about them where that is sharp (docs/exact-law.md §4).
// Requested errors: 1e-12 (outer) per kN and per kNa; a GSL error estimate above 1e-10 (outer) or
// 1e-10/(2 pi) (a ray) throws std::domain_error.
//
// Domain and accuracy: b/a >= kExactReferenceMinAxisRatio = 0.01, where it is accurate to
// kExactReferenceAccuracy = 1e-10 kN and kNa. Largest error against the 30-digit tables
// (tests/friction/reference/exact_table.csv, pressure_table.csv; the 64 points in its domain):
// 9.3e-15. On 6,000 inputs fuzzed towards the rim and the axes (b/a = 0.01 to 0.5, every pressure)
// no GSL failure, and within 6.1e-13 of `exact` except where `exact:pressure=uniform` itself is off
// (the ICR within ~1e-5 of the tip of a slender patch). Until 2026-11-28, without the graded breaks,
// GSL failed on 95 of 8,400 such inputs. Below b/a = 0.01
// GSL stops on round-off near the major axis (b/a ~ 1e-3 gave errors of 2e-10, b/a ~ 1e-6 wrong
// values of 0.4 with GSL reporting success, b/a ~ 1e-9 GSL failures), so smaller ratios are
// rejected with std::invalid_argument naming the value and the rule.
//
// Limits as in ExactLaw: N = 0 or k = 0, and U = Omega = 0 (indeterminate), give zero forces;
// Omega = 0, or s = U/(a|Omega|) above the double range, gives F1 = kN exactly. Thread-safe: GSL
// workspaces are allocated per call; the GSL error handler is switched off once (process-wide) so
// that GSL never aborts.

#include <string_view>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"
#include "friction/pressure.h"

namespace frictionlab::friction {

/// The accuracy ExactReferenceLaw promises, per kN (forces) and per kNa (moment), in its domain.
inline constexpr double kExactReferenceAccuracy = 1e-10;
/// The smallest axis ratio b/a ExactReferenceLaw accepts (std::invalid_argument below).
inline constexpr double kExactReferenceMinAxisRatio = 0.01;

/// The exact law by nested adaptive GSL quadrature over the ellipse (reference, slow), for a
/// pressure model (default Hertz).
class ExactReferenceLaw final : public FrictionLaw {
 public:
  explicit ExactReferenceLaw(Pressure pressure = Pressure::hertz) : pressure_(pressure) {}

  /// What a spec may set (friction/law_spec.h): pressure = hertz|uniform|punch.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] Pressure pressure() const { return pressure_; }

  [[nodiscard]] std::string_view name() const override { return "exact-reference"; }
  [[nodiscard]] LawPromises promises() const override;
  [[nodiscard]] std::string_view summary() const override {
    return "exact law by nested adaptive 2-D GSL quadrature over the patch (slow cross-check of "
           "'exact'): b/a >= 0.01 only, accurate to 1e-10 kN and kNa there (largest error found 1e-14)";
  }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
  Pressure pressure_;
};

}  // namespace frictionlab::friction
