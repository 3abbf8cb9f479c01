#pragma once
// The data behind the paper's figures, one set of files per run (whitespace-separated, '#'
// header), read by the gnuplot scripts of dynamics/paper/figure_scripts.h:
//
//   <stem>.full.dat   kFigureBins time bins over the whole run
//   <stem>.early.dat  kFigureBins time bins over the first kEarlyWindow seconds
//   <stem>.end.dat    the last sample (where a run that stopped early stopped)
//
// Each bin holds the minimum and maximum of each quantity over its samples: where a quantity
// oscillates faster than the bins (nutation of gamma3, the Hertz bounce of N) the figures draw
// the band it sweeps, not an aliased line. Empty bins are left out.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>

#include "dynamics/paper/run_series.h"

namespace frictionlab::dynamics::paper {

inline constexpr int kFigureBins = 1500;
/// s: the zoomed figures show the first this many seconds (vertical spin and first tilt).
inline constexpr double kEarlyWindow = 40.0;

/// Column numbers (1-based, gnuplot's `using`) of the .full.dat and .early.dat files.
struct FigureColumns {
  static constexpr int t = 1;                                   // s, bin centre
  static constexpr int gamma3_min = 2, gamma3_max = 3;          // -
  static constexpr int omega_sq = 4;                            // 1/s^2, bin mean
  static constexpr int force_min = 5, force_max = 6;            // N
  static constexpr int moment_min = 7, moment_max = 8;          // N mm
  static constexpr int major_min = 9, major_max = 10;           // mm
  static constexpr int ratio_min = 11, ratio_max = 12;          // -
  static constexpr int n_min = 13, n_max = 14;                  // N/(m g)
};
/// Columns of the .end.dat file: t gamma3 omega_sq force moment(N mm) major(mm) ratio n_over_mg.
struct EndColumns {
  static constexpr int t = 1, gamma3 = 2, omega_sq = 3, force = 4, moment = 5, major = 6, ratio = 7, n = 8;
};

/// Writes the three files for `s` under `dir` (created if needed); std::runtime_error if it cannot.
void write_figure_data(const std::filesystem::path& dir, const std::string& stem, const RunSeries& s);

}  // namespace frictionlab::dynamics::paper
