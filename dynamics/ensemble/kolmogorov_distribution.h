#pragma once
// The Kolmogorov distribution: the limit law of sqrt(n) sup|F_n - F| (Kolmogorov 1933).
// Its complementary distribution function (Press et al., Numerical Recipes 3rd ed. (2007), §6.14.12
// and eqs. (6.14.56)-(6.14.57)):
//
//   Q_KS(z) = 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 z^2)                        (fast for large z)
//   P_KS(z) = 1 - Q_KS(z) = sqrt(2 pi)/z sum_{j>=1} exp(-(2j-1)^2 pi^2 / (8 z^2))   (for small z)
//
// Each series is summed until its terms fall below 1e-17 of the sum; NR3 switches at z = 1.18,
// where both need only a few terms. Boost.Math 1.74 has no Kolmogorov distribution (it came in
// 1.75), hence this.

namespace frictionlab::dynamics::ensemble {

/// Q_KS(z) = P(K > z) for z >= 0 (Q_KS(0) = 1); accurate to ~1e-15.
[[nodiscard]] double kolmogorov_q(double z);
/// P_KS(z) = P(K <= z) = 1 - Q_KS(z), accurate to ~1e-15 also where it is tiny.
[[nodiscard]] double kolmogorov_p(double z);

/// The two series themselves (each converges for every z > 0, slowly at one end: the Q series
/// below ~0.3, the P series above ~3).
[[nodiscard]] double kolmogorov_q_series(double z);
[[nodiscard]] double kolmogorov_p_series(double z);

/// z below which P_KS's series is used, above which Q_KS's.
inline constexpr double kKolmogorovSwitch = 1.18;

}  // namespace frictionlab::dynamics::ensemble
