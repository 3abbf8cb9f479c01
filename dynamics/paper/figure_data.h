#pragma once
// The data behind the paper's figures, one set of files per run (whitespace-separated, '#'
// header), read by the gnuplot scripts of dynamics/paper/figure_scripts.h:
//
//   <stem>.full.dat   kFigureBins time bins over the whole run
//   <stem>.early.dat  kFigureBins time bins over the first kEarlyWindow seconds
//   <stem>.end.dat    the last sample (where a run that stopped early stopped)
//
// Each bin holds the minimum, maximum and mean of each quantity over its samples: where a quantity
// oscillates faster than the bins (nutation of gamma3, the Hertz bounce of N) the figures draw the
// band it sweeps and its mean, not an aliased line. Empty bins are left out.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/paper/run_series.h"

namespace frictionlab::dynamics::paper {

/// Bins of the whole run (0.15-0.6 s each for the paper's 120-450 s runs sampled at 100 Hz).
inline constexpr int kFigureBins = 800;
/// s: the zoomed figures show the first this many seconds (vertical spin and first tilt).
inline constexpr double kEarlyWindow = 40.0;
/// Bins of the zoom: 0.5 s, fifty samples each, so that a bin's mean averages over the irregular
/// bounces (~49 Hz Hertz oscillation) instead of catching one phase of them.
inline constexpr int kEarlyBins = 80;


/// Column numbers (1-based, gnuplot's `using`) of the .full.dat and .early.dat files: for each
/// quantity the minimum, maximum and mean over the bin's samples.
struct FigureColumns {
  static constexpr int t = 1;  // s, bin centre
  static constexpr int gamma3_min = 2, gamma3_max = 3, gamma3_mean = 4;  // -
  static constexpr int omega_sq = 5;                                    // 1/s^2, mean
  static constexpr int force_min = 6, force_max = 7, force_mean = 8;    // N
  static constexpr int moment_min = 9, moment_max = 10, moment_mean = 11;  // N mm
  static constexpr int major_min = 12, major_max = 13, major_mean = 14;    // mm
  static constexpr int ratio_min = 15, ratio_max = 16, ratio_mean = 17;    // -
  static constexpr int n_min = 18, n_max = 19, n_mean = 20;                // N/(m g)
};
/// Columns of the .end.dat file: t gamma3 omega_sq force moment(N mm) major(mm) ratio n_over_mg.
struct EndColumns {
  static constexpr int t = 1, gamma3 = 2, omega_sq = 3, force = 4, moment = 5, major = 6, ratio = 7, n = 8;
};

/// The largest bin mean of |F| (N), |M| (N mm), a (mm), N/(m g) of a run (0 if none): where the
/// figures' axes end. The bands (min-max) of the bouncing phases go far higher (Hertz impacts of
/// 30-80 m g lasting milliseconds) and are cut there.
struct AxisCaps {
  double force = 0.0, moment = 0.0, major = 0.0, n_over_mg = 0.0;
};
struct FigureRanges {
  AxisCaps full;   ///< bins over the whole run
  AxisCaps early;  ///< bins over the first kEarlyWindow seconds
};

/// Writes the three files for `s` under `dir` (created if needed); std::runtime_error if it
/// cannot. Returns the axis caps of the run.
FigureRanges write_figure_data(const std::filesystem::path& dir, const std::string& stem, const RunSeries& s);

}  // namespace frictionlab::dynamics::paper
