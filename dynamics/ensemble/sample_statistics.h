#pragma once
// Summaries of samples for the ensemble's report:
//
//   quantile     the sample quantile of type 7 of Hyndman & Fan (The American Statistician 50
//                (1996) 361; R's default): linear interpolation between order statistics at
//                h = (n - 1) p;
//   total variation distance of two distributions over categories: (1/2) sum |p_i - q_i|, in [0, 1];
//   chi-square test of homogeneity of two samples over categories (Pearson): X^2 = sum over the
//                2 x k table of (observed - expected)^2 / expected, with k' - 1 degrees of freedom
//                (k' the categories seen), p = P(chi2_{k'-1} >= X^2) (Boost.Math's chi_squared
//                distribution); asymptotic, reliable when expected counts are >= ~5.

#include <map>
#include <string>
#include <vector>

namespace frictionlab::dynamics::ensemble {

/// The type-7 quantile at p in [0, 1] of the finite values of `x` (NaN if there are none).
[[nodiscard]] double quantile(std::vector<double> x, double p);

/// Counts of each category.
using CategoryCounts = std::map<std::string, long>;

/// (1/2) sum |a_i/n_a - b_i/n_b| over the categories of either; NaN if either is empty.
[[nodiscard]] double total_variation(const CategoryCounts& a, const CategoryCounts& b);

/// The chi-square test of homogeneity of the two samples' categories: its p-value (1 if they
/// show only one category between them; NaN if either is empty).
[[nodiscard]] double chi_square_homogeneity_p(const CategoryCounts& a, const CategoryCounts& b);

}  // namespace frictionlab::dynamics::ensemble
