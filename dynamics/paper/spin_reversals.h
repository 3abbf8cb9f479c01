#pragma once
// Spin reversals of a run: how often the spin about the vertical, Omega = omega . gamma, changes
// its sense, when it first does, and the sense it ends with. The rattleback's signature (docs/
// rigid-rolling.md: spun in its unstable sense it rocks, stops spinning and spins the other way),
// measured on a sampled series (dynamics/paper/run_series.h) of any body.
//
// A reversal counts when Omega passes from >= +theta to <= -theta or back (a Schmitt trigger), with
// theta = kReversalFraction times the largest |Omega| of the run: the spin's own scale, so that the
// count means the same for a 3 1/s rattleback and a 100 1/s egg, and the rounding of a spin that
// decays to rest about 0 (or a slow rocking that never spins) counts nothing. A reversal's time is
// the sample at which Omega reached the far threshold.
//
// The final sense is sign(Omega) at the last sample if |Omega| >= theta there, else 0 (the spin
// died out: no sense).

#include <vector>

#include "dynamics/paper/run_features.h"  // kNaN

namespace frictionlab::dynamics::paper {

/// theta / max |Omega|: 2 % (a reversal that regains 2 % of the largest spin; the rigid
/// rattleback of Kane & Levinson reverses to ~40 % of its initial spin, docs/rigid-rolling.md).
inline constexpr double kReversalFraction = 0.02;

struct SpinReversals {
  long count = 0;             ///< reversals over the run
  double t_first = kNaN;      ///< s, the first (NaN: none)
  int final_sense = 0;        ///< +1, -1, or 0 (the spin died out)
  double threshold = kNaN;    ///< theta, 1/s (NaN for an empty series)
};

/// The reversals of `spin` (1/s) sampled at `t` (s, ascending, the same length; otherwise
/// std::invalid_argument). An empty series gives the defaults.
[[nodiscard]] SpinReversals spin_reversals(const std::vector<double>& t, const std::vector<double>& spin,
                                           double fraction = kReversalFraction);

}  // namespace frictionlab::dynamics::paper
