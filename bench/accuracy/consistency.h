#pragma once
// Physical consistency checks of a law on the grid: dissipation and the signs of its outputs.
//
// Dissipation (docs/model.md §2): the power of friction F1 U + M Omega is >= 0 for the exact law
// (it is the integral of k p |v| over the patch), so a law with F1 U + M Omega < 0 at some contact
// feeds energy into the motion there. On the grid (a = 1, |Omega| = 1, kN = 1) the power per
// kN a|Omega| is F1 s + M sign(Omega).
//
// Signs: the exact F2 has the sign of sin 2psi for both signs of Omega (it is even in Omega); the
// printed Padé F2 is odd in Omega, so it has the wrong sign for one of the two spins. A sign check
// only looks at points where the reference is clearly non-zero, |reference| > threshold.

#include <cstddef>
#include <span>

#include "bench/accuracy/error_stats.h"

namespace frictionlab::accuracy {

/// |reference| above which the sign of a law's F2 (or M) is checked: 1e-9 kN is ten thousand times
/// the exact law's accuracy (1e-13), so the reference's sign is certain there.
inline constexpr double kSignThreshold = 1e-9;

/// Power of friction per (kN a|Omega|): F1 s + M sign, for F1 per kN, M per kNa, s = U/(a|Omega|).
[[nodiscard]] inline double dissipation(double F1, double M, double s, int sign) {
  return F1 * s + M * static_cast<double>(sign);
}

struct DissipationStats {
  std::size_t checked = 0;     ///< points with a finite power
  std::size_t nonfinite = 0;   ///< points whose power is NaN or +-inf (not checked)
  std::size_t violations = 0;  ///< points where the power is < 0
  double worst = 0.0;          ///< the most negative power found (0 if there is no violation)
  std::size_t worst_index = kNoIndex;  ///< where `worst` occurs
};

/// Counts the points of `power` (one value of F1 s + M sign per point) below 0.
[[nodiscard]] DissipationStats dissipation_stats(std::span<const double> power);

struct SignStats {
  std::size_t considered = 0;  ///< points with finite value and |reference| > threshold
  std::size_t opposite = 0;    ///< ... where value * reference < 0
  std::size_t zero = 0;        ///< ... where value == 0 (the law has no such component there)

  /// Counts one point (skipped if value is not finite or |reference| <= threshold).
  void add(double value, double reference, double threshold = kSignThreshold);

  /// Fraction of the considered points with sign(value) != sign(reference): opposite + zero.
  [[nodiscard]] double mismatch_fraction() const { return fraction(opposite + zero); }
  [[nodiscard]] double opposite_fraction() const { return fraction(opposite); }
  [[nodiscard]] double zero_fraction() const { return fraction(zero); }

 private:
  [[nodiscard]] double fraction(std::size_t n) const {
    return considered == 0 ? 0.0 : static_cast<double>(n) / static_cast<double>(considered);
  }
};

/// Compares sign(value[i]) with sign(reference[i]) where |reference[i]| > threshold and value[i]
/// is finite (non-finite values are reported by error_stats).
[[nodiscard]] SignStats sign_stats(std::span<const double> value, std::span<const double> reference,
                                   double threshold = kSignThreshold);

}  // namespace frictionlab::accuracy
