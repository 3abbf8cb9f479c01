#pragma once
// Distances between two samples of a scalar outcome (a law's runs against the reference law's),
// computed from their empirical distribution functions F_a, F_b:
//
//   Wasserstein-1    W1 = integral |F_a(x) - F_b(x)| dx (Vallender, Theory Probab. Appl. 18 (1974)
//                    784: the L1 distance of the distribution functions), in the unit of x: how far,
//                    on average, mass must move to turn one sample into the other. Two samples that
//                    differ by a shift s have W1 = s.
//   Kolmogorov-Smirnov  D = sup_x |F_a(x) - F_b(x)|, in [0, 1], with its p-value: the probability
//                    that two samples of the same continuous distribution, of sizes n and m, give a
//                    statistic at least D. Asymptotic form with the effective size
//                    N_e = n m / (n + m) and Stephens' correction (Stephens, J. R. Statist. Soc. B 32
//                    (1970) 115; Press et al., Numerical Recipes 3rd ed. (2007) §14.3.3):
//                    p = Q_KS([sqrt(N_e) + 0.12 + 0.11/sqrt(N_e)] D) (kolmogorov_distribution.h).
//                    Accurate to about 1e-2 in p for N_e >= 4 (NR3 §14.3.3), which suffices to judge
//                    p against a 1 % level; ties (discrete features such as lift-off counts) make it
//                    conservative.
//
// Non-finite values are the caller's to remove (an empty sample gives NaN).

#include <vector>

namespace frictionlab::dynamics::ensemble {

/// W1 of the two samples' empirical distributions; NaN if either is empty.
[[nodiscard]] double wasserstein1(std::vector<double> a, std::vector<double> b);

/// The Kolmogorov-Smirnov statistic D; NaN if either sample is empty.
[[nodiscard]] double ks_statistic(std::vector<double> a, std::vector<double> b);

/// The asymptotic p-value of D for samples of sizes n and m (see the header comment).
[[nodiscard]] double ks_p_value(double d, long n, long m);

}  // namespace frictionlab::dynamics::ensemble
