#pragma once
// When does a law "change the motion"? Only where its outcomes stand clearly above the chaos
// floor: the same distance between the two halves of the reference law's own replicas (even and
// odd replica indices), which differ only by perturbations of 1e-6 and yet spread as widely as the
// chaos of the motion makes them. The rule (docs/ensembles.md), for a feature and a law:
//
//   changes       p < kSignificance (the law's and the reference's distributions differ beyond
//                 sampling: Kolmogorov-Smirnov for a number, chi-square for the outcome class)
//                 AND distance > kFloorFactor x floor distance (Wasserstein-1 for a number, total
//                 variation for the class): the difference is clearly larger than what chaos alone
//                 produces between two equally exact halves;
//   within chaos  p >= kSignificance AND distance <= kFloorFactor x floor;
//   unclear       one of the two holds and not the other;
//   negligible    (before the others) the distance is at most the feature's resolution: the
//                 smallest difference that means anything for it (dynamics/ensemble/feature_comparison.h:
//                 1e-3 in gamma3, 0.1 deg of tilt, 0.01 s, ...). A law that moves the final gamma3 of
//                 an egg at rest on its pole by 3e-8 differs from exact beyond a floor of 1e-11, and
//                 this says so without calling it a change of the motion;
//   n/a           a sample or the floor is empty (no replicas, or no run ended normally).
//
// The floor compares halves of n/2 runs, the law all n of its runs against all n of the
// reference: the floor's distances carry more sampling noise (~sqrt(2) times for W1), which makes
// the rule conservative; the factor 2 is a choice, fixed before the studies were run.

#include <string_view>

namespace frictionlab::dynamics::ensemble {

/// The significance level of the two-sample tests.
inline constexpr double kSignificance = 0.01;
/// How many times the floor's distance a law's distance must exceed to count.
inline constexpr double kFloorFactor = 2.0;

enum class Verdict { changes, within_chaos, unclear, negligible, not_available };

/// "changes", "within chaos", "unclear", "negligible", "n/a".
[[nodiscard]] std::string_view to_string(Verdict v);

/// The rule of the header comment for a p-value, a distance, the floor's distance and the
/// feature's resolution (>= 0, in the distance's unit).
[[nodiscard]] Verdict judge(double p_value, double distance, double floor_distance, double resolution = 0.0);

}  // namespace frictionlab::dynamics::ensemble
