#pragma once
// Where a law is singular on the accuracy grid: its poles, and values no contact can produce.
//
// Two detectors, both reported per point and per (mu, psi):
// * generic, for every law: a point is singular if an output is NaN or +-inf, or larger in size
//   than kSingularMagnitude (in kN or kNa), far beyond anything the exact law gives;
// * structural, for laws that declare poles (FrictionLaw::has_poles() and pole_denominators(); the
//   printed Padé law, both readings of alpha, declares the denominators of eq. (8)): the sign of
//   each denominator at every node, and the grid intervals of s where it changes sign, which
//   bracket a real pole. The magnitude test alone misses a pole at large s: there the printed
//   F2 ~ 1/(2 (s - s_pole)) stays below 10 at every node of a 200-point grid once s_pole exceeds ~3.
// The denominators are taken at Omega > 0 (those of the printed law depend on |Omega| only).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bench/accuracy/evaluation.h"
#include "bench/accuracy/grid.h"

namespace frictionlab::accuracy {

/// |F1|, |F2| (per kN) or |M| (per kNa) above this marks a point as singular: the exact law has
/// |F| <= 1 and |M| <= (3/8) E(e) <= 3 pi/16 ~ 0.59, so 10 is unreachable by any sound law.
inline constexpr double kSingularMagnitude = 10.0;

/// True if an output is non-finite or larger in size than kSingularMagnitude.
[[nodiscard]] bool is_singular(double F1, double F2, double M);

/// The outputs of a law, for naming them in reports.
enum class Component : int { F1 = 0, F2 = 1, M = 2 };
[[nodiscard]] std::string_view component_name(Component c);

/// Denominators of the three outputs at (s, mu, psi), scaled by 1/(a^2 Omega^2); NaN where the
/// law has no denominator for that output there (e.g. the printed F2 at sin 2psi = 0, a4 infinite).
struct Denominators {
  double F1, F2, M;
  [[nodiscard]] double operator[](Component c) const {
    return c == Component::F1 ? F1 : c == Component::F2 ? F2 : M;
  }
};
using DenominatorFunction = std::function<Denominators(double s, double mu, double psi)>;

/// The denominators the law called `law` declares (FrictionLaw::pole_denominators(), at a = 1,
/// b = mu, U = s, Omega = 1), if it has poles; std::nullopt if it has none. Throws
/// std::invalid_argument for an unknown name.
[[nodiscard]] std::optional<DenominatorFunction> known_denominators(std::string_view law);

/// One grid interval of s, at fixed (mu, psi), across which a denominator changes sign.
struct PoleBracket {
  Component component;
  std::size_t imu, ipsi;
  double s_low, s_high;  ///< the two neighbouring nodes of s that bracket the pole
};

/// Every sign change of every denominator between neighbouring s nodes of `grid`.
[[nodiscard]] std::vector<PoleBracket> pole_brackets(const Grid& grid, const DenominatorFunction& den);

/// Bits of the singularity map, one value per (mu, psi, s).
enum SingularityBit : std::uint8_t {
  kF2DenominatorNegative = 1,  ///< the F2 denominator is < 0 (the printed F2's branch past its pole)
  kMDenominatorNegative = 2,   ///< the M denominator is < 0
  kF1DenominatorNegative = 4,  ///< the F1 denominator is < 0
  kSingularValue = 8,          ///< is_singular() at either sign of Omega
};

/// The map over (mu, psi, s), indexed (imu * psi_points + ipsi) * s_points + is: the OR of the
/// bits above (denominator bits only if `den` is given).
[[nodiscard]] std::vector<std::uint8_t> singularity_map(const Grid& grid, const LawValues& law,
                                                        const std::optional<DenominatorFunction>& den);

}  // namespace frictionlab::accuracy
