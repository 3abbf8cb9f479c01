#pragma once
// The terminal ratio of a sliding-spinning puck on a circular patch, from the friction law itself
// (docs/puck.md §3). For a circle F2 = 0 (docs/model.md §2), so the path is straight and the
// motion is two equations,
//     m v' = -F1,     I omega' = -M,     F1 = k m g f(r),   M = k m g a mu(r),
// where f = F1/(kN) and mu = M/(kNa) depend only on the slip ratio r = v/(a |omega|) (the scaling
// of docs/model.md). With kappa = I/(m a^2):
//     d ln r/dt = v'/v - omega'/omega = (k g / v) G(r),     G(r) = r mu(r)/kappa - f(r).
// As v -> 0 the factor k g/v grows without bound, so near the end r is driven onto a zero r* of G
// with G'(r*) < 0 (an attracting fixed point: slip and spin stop together, v/(a omega) -> r*), or to
// 0 if G < 0 on (0, r_1) (the slip stops first), or to infinity if G > 0 beyond the last zero (the
// spin stops first). A zero with G' > 0 repels. The limits
//     G(r)/r -> mu(0)/kappa - f'(0)   (r -> 0),      G(r) -> m2/kappa - 1   (r -> infinity)
// (mu(0) the pure-spin moment, f'(0) the slow-slip slope, m2 the pressure's second moment along
// one axis over a^2, e.g. Hertz 1/5, uniform 1/4) decide the ends: the three regimes in the
// inertia ratio of Weidman & Malhotra (2005) and Goyal, Ruina & Papadopoulos (1991), which for
// uniform pressure are kappa > 2/3 (r -> 0), 1/4 < kappa < 2/3 (a finite r*; the uniform disk,
// kappa = 1/2: r* = 0.653), kappa < 1/4 (r -> infinity).
//
// The law is evaluated on a unit circle (a = b = 1 m, psi = 0, N = 1 N, k = 1, Omega = 1 1/s, U = r
// m/s); any law and any pressure model of the registry works.

#include <string>
#include <vector>

#include "friction/law.h"

namespace frictionlab::dynamics::puck {

/// G(r) of the header comment for `law` on a circle and the inertia ratio kappa = I/(m a^2).
[[nodiscard]] double terminal_ratio_drift(const friction::FrictionLaw& law, double kappa, double r);

struct TerminalRatioAnalysis {
  double kappa = 0.0;
  std::vector<double> attracting;  ///< zeros of G with G' < 0, ascending
  /// For each attracting zero, lambda = r* |G'(r*)|/f(r*): near it r - r* ~ v^lambda
  /// (d ln|r - r*|/d ln v = lambda, from d ln r/d ln v = -G/f).
  std::vector<double> exponents;
  std::vector<double> repelling;   ///< zeros of G with G' > 0, ascending
  double small_slope = 0.0;        ///< G(r)/r at the smallest r of the scan (-> mu(0)/kappa - f'(0))
  double large_limit = 0.0;        ///< G at the largest r of the scan (-> m2/kappa - 1)
  /// "together" (one attracting zero and r -> r* from everywhere below and above), "slip-first"
  /// (r -> 0), "spin-first" (r -> infinity), or "depends" (repelling zeros: the end depends on the
  /// start).
  std::string regime;
};

/// Scans G on a logarithmic grid of r in [r_min, r_max] (points per decade), refines every sign
/// change to 1e-12 relative with TOMS 748 (Boost.Math) and classifies the ends.
[[nodiscard]] TerminalRatioAnalysis analyse_terminal_ratio(const friction::FrictionLaw& law, double kappa,
                                                           double r_min = 1e-4, double r_max = 1e4,
                                                           int points_per_decade = 40);

}  // namespace frictionlab::dynamics::puck
