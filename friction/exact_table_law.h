#pragma once
// `exact-table`: the exact law (friction/exact_law.h) tabulated, for each pressure model, as
// tensor-product B-splines over the ICR and the axis ratio (the table design of
// docs/exact-table.md; the table is friction/exact_table.h). Within kExactTableAccuracy = 1e-6 of
// `exact` (per kN for F1, F2, per kNa for M; kN = k·N) for every b/a in [0.01, 1], every slip ratio
// and orientation. Largest errors found on 200,000 seeded random points per pressure, a third near
// the rim on either side (tests/friction/exact_table_law_test.cpp, the check set of
// docs/exact-table.md): F1, F2, M 3.5e-7, 3.6e-7, 2.9e-7 (Hertz), 3.4e-7, 3.0e-7, 2.1e-7 (uniform),
// 4.0e-7, 2.2e-7, 2.2e-7 (punch), all at b/a ~ 0.011. Cost: about what `exact` costs on the
// benchmark's random inputs (138 ns, exact 131 ns, pade-printed 37.2 ns: one run of friction_bench,
// docs/exact-table.md §7): 288 multiply-adds over 24 rows of a 5.8 MB table per call, a constant
// cost, where exact's grows for slender patches with the ICR near the rim. Its batch (FrictionLaw::
// evaluate of spans) locates blocks of contacts before summing them, the same values, ~0.76 of a
// call (friction/exact_table_batch.h).
//
// With s = U/(a|Omega|), mu = b/a, (Xt, Yt) = s (sin psi, cos psi) the ICR in the patch axes and
// (Gx, Gy, m) the table at (Xt, Yt, mu) (friction/exact_table.h):
//
//   F1 = -kN (Gx sin psi + Gy cos psi),   F2 = kN (Gx cos psi - Gy sin psi),
//   M  = kNa c_p E(e) m sign(Omega),      e^2 = 1 - mu^2,
//
// c_p the pressure's pure-spin factor (3/8 Hertz, 4/(3 pi) uniform, 1/2 punch) and E by the fit of
// friction/elliptic_e_fit.h. F1, F2 are even in Omega and M odd exactly; pi-periodicity and the
// mirror psi -> -psi hold to rounding (the table is even in Xt and in Yt).
//
// The table is generated from `exact` in this process, at the first evaluation for a pressure
// (once per pressure per process, thread-safe: ExactTable::of), not read from a data file or
// compiled in: 5.8 MB of coefficients per pressure as a C++ literal would slow every build of the
// library, and a table generated from `exact` in the same process cannot drift from it. The
// generation (218,250 evaluations of `exact`, three banded solves per block) measured, CPU time:
// Hertz 90 ms, uniform 258 ms, punch 109 ms (`friction_bench --benchmark_filter=
// BM_exact_table_build --benchmark_repetitions=3`, medians; 2026-11-29, 2-core AMD EPYC KVM
// guest). The first call for a pressure pays it; every later call allocates nothing.
//
// Limits, each an explicit branch:
//   * N = 0 or k = 0: all zero. U = Omega = 0: all zero, as `exact` (the law is indeterminate).
//   * Omega = 0, U > 0 (pure sliding), or s = +inf: F1 = kN, F2 = M = 0 exactly.
//   * U = 0, Omega != 0 (pure spin): F1 = F2 = 0 exactly, M = c_p k N a E(e) sign(Omega) to the
//     fit's 1.3e-14.
//   * s > 1e8: the fast-slip expansion F1 = kN (1 - m2 d3/(2 s^2)), F2 = kN m2 d4/(2 s^2),
//     M = kNa m2 d3/s sign(Omega) (m2 the pressure's second moment; d3, d4 of docs/model.md), as
//     `exact` returns there (its truncation error is below 1e-24); it also keeps s^2 in range.
//   * A circle (b = a): psi plays no part and F2 = 0 exactly.
//   * b/a < 0.01 throws std::invalid_argument naming the value: the table ends there.
// Input validation (finite values, b <= a, ...) is FrictionLaw::evaluate's (friction/law.h).

#include <span>
#include <string_view>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"
#include "friction/pressure.h"

namespace frictionlab::friction {

/// The accuracy ExactTableLaw promises against ExactLaw, per kN (forces) and per kNa (moment),
/// for every valid input with b/a >= kExactTableMinAxisRatio (friction/exact_table.h).
inline constexpr double kExactTableAccuracy = 1e-6;

/// The exact law, tabulated (the table design of docs/exact-table.md), for a pressure model.
class ExactTableLaw final : public FrictionLaw {
 public:
  explicit ExactTableLaw(Pressure pressure = Pressure::hertz) : pressure_(pressure) {}

  /// What a spec may set: pressure = hertz|uniform|punch, as for `exact`.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] Pressure pressure() const { return pressure_; }

  [[nodiscard]] std::string_view name() const override { return "exact-table"; }
  [[nodiscard]] std::string_view summary() const override {
    return "the exact law tabulated: tensor-product B-splines built from exact at first use "
           "(docs/exact-table.md), within 1e-6 kN and kNa of exact for b/a >= 0.01";
  }
  /// Every property of `exact` (docs/model.md), to kExactTableAccuracy, for b/a >= 0.01.
  [[nodiscard]] LawPromises promises() const override;

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
  void do_evaluate_batch(std::span<const ContactInput> in, std::span<FrictionForces> out) const override;
  Pressure pressure_;
};

}  // namespace frictionlab::friction
