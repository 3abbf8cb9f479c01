#pragma once
// Designs of experiments over the unit box [0, 1)^d: where in the space of varied scenario keys a
// study starts its runs. A study maps each coordinate onto its key's range (linearly or
// logarithmically: dynamics/ensemble/study.h).
//
//   grid     the product of each axis's own points (the first axis varies slowest);
//   random   independent uniform points (RandomStream: the same on every machine);
//   sobol    the Sobol low-discrepancy sequence of GSL (gsl_qrng_sobol, dimensions 1 to 40; Bratley &
//            Fox, ACM TOMS 14 (1988) 88, Algorithm 659), from its first point on (GSL omits the
//            origin: the first points in 2-D are (0.5, 0.5), (0.75, 0.25), (0.25, 0.75), ...);
//            deterministic, so the seed plays no part;
//   lhs      a Latin hypercube (McKay, Beckman & Conover, Technometrics 21 (1979) 239): along each
//            axis every one of the n strata [k/n, (k+1)/n) holds exactly one point, at a uniform
//            position inside it; the strata are matched across axes by independent permutations.

#include <cstdint>
#include <string_view>
#include <vector>

namespace frictionlab::dynamics::ensemble {

enum class DesignKind { grid, random, sobol, lhs };

/// "grid", "random", "sobol", "lhs".
[[nodiscard]] std::string_view to_string(DesignKind kind);

/// A point of the unit box, one coordinate per axis.
using UnitPoint = std::vector<double>;

/// The product of the axes' values (each in any range), first axis slowest. No axes: one empty point.
[[nodiscard]] std::vector<UnitPoint> grid_product(const std::vector<std::vector<double>>& axes);

/// `n` uniform points in [0, 1)^dims from RandomStream(seed), point by point, axis by axis.
[[nodiscard]] std::vector<UnitPoint> random_points(int dims, long n, std::uint64_t seed);

/// The first `n` points of GSL's Sobol sequence in `dims` dimensions (1 <= dims <= 40, else
/// std::invalid_argument).
[[nodiscard]] std::vector<UnitPoint> sobol_points(int dims, long n);

/// The largest dimension gsl_qrng_sobol supports.
inline constexpr int kSobolMaxDimension = 40;

/// A Latin hypercube of `n` points in [0, 1)^dims from RandomStream(seed): for each axis in turn,
/// a permutation of the strata, then one uniform offset per point.
[[nodiscard]] std::vector<UnitPoint> latin_hypercube(int dims, long n, std::uint64_t seed);

}  // namespace frictionlab::dynamics::ensemble
