#pragma once
// The data behind the paper's figures, one set of files per run (whitespace-separated, '#'
// header), read by the gnuplot scripts of dynamics/paper/figure_scripts.h:
//
//   <stem>.full.dat   kFigureBins time bins over the whole run
//   <stem>.early.dat  kEarlyBins time bins over the first kEarlyWindow seconds
//   <stem>.end.dat    the last sample (where a run that stopped early stopped)
//
// Each bin gives, for each quantity, a line value (a mean) and a band (the 5 % and 95 % quantiles
// of the samples), so that the figures draw what a quantity sweeps without letting its extremes
// hide the mean:
//
//   gamma3, b/a        over the bin's own samples: the band is the nutation of the axis;
//   |F|, |M|, a, N     over kImpactWindow (2 s) centred on the bin: these are dominated by the
//                      Hertz impacts of the bouncing phases (milliseconds long, tens of m g, the
//                      body in the air in between), which a 100-Hz sample catches or misses at
//                      random. The mean over 2 s (~200 samples) is the time average (the mean of N
//                      is m g while the body hops), a smooth line; the band is the spread of the
//                      impacts. Out of contact |F| = |M| = a = N = 0, and these zeros count.
//
// Empty bins are left out; b/a is undefined (skipped) out of contact.

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/paper/run_series.h"

namespace frictionlab::dynamics::paper {

/// Bins of the whole run (0.15-0.6 s each for the paper's 120-450 s runs sampled at 100 Hz).
inline constexpr int kFigureBins = 800;
/// s: the zoomed figures show the first this many seconds (vertical spin and first tilt).
inline constexpr double kEarlyWindow = 40.0;
/// Bins of the zoom: 0.5 s each.
inline constexpr int kEarlyBins = 80;
/// s: the window (centred on each bin) over which the impact-dominated quantities are summarised.
inline constexpr double kImpactWindow = 2.0;
/// The band: these quantiles of the samples.
inline constexpr double kBandLow = 0.05;
inline constexpr double kBandHigh = 0.95;

/// Column numbers (1-based, gnuplot's `using`) of the .full.dat and .early.dat files: for each
/// quantity the band (5 % and 95 % quantiles) and the mean.
struct FigureColumns {
  static constexpr int t = 1;                                            // s, bin centre
  static constexpr int gamma3_lo = 2, gamma3_hi = 3, gamma3_mean = 4;    // -
  static constexpr int omega_sq = 5;                                     // 1/s^2, mean
  static constexpr int force_lo = 6, force_hi = 7, force_mean = 8;       // N (2-s window)
  static constexpr int moment_lo = 9, moment_hi = 10, moment_mean = 11;  // N mm (2-s window)
  static constexpr int major_lo = 12, major_hi = 13, major_mean = 14;    // mm (2-s window)
  static constexpr int ratio_lo = 15, ratio_hi = 16, ratio_mean = 17;    // -
  static constexpr int n_lo = 18, n_hi = 19, n_mean = 20;                // N/(m g) (2-s window)
};
/// Columns of the .end.dat file: t gamma3 omega_sq force moment(N mm) major(mm) ratio n_over_mg.
struct EndColumns {
  static constexpr int t = 1, gamma3 = 2, omega_sq = 3, force = 4, moment = 5, major = 6, ratio = 7, n = 8;
};

/// A quantity over a bin: its mean and its band. NaN when no sample is finite.
struct Band {
  double lo;    ///< kBandLow quantile
  double hi;    ///< kBandHigh quantile
  double mean;  ///< arithmetic mean
};

/// One bin of a figure, in the units plotted (|M| in N mm, a in mm).
struct FigureBin {
  double t;  ///< s, bin centre
  Band gamma3;
  double omega_sq;  ///< 1/s^2, mean over the bin
  Band force, moment, major, axis_ratio, n_over_mg;
};

/// The p-quantile (0 <= p <= 1) of `values` by linear interpolation between order statistics
/// (Hyndman & Fan's definition 7, numpy's default); non-finite values are skipped; NaN if none.
[[nodiscard]] double quantile(std::vector<double> values, double p);

/// `bins` bins of equal width over [t0, t1] (the last bin closed; one bin if t1 <= t0); empty bins
/// are left out.
[[nodiscard]] std::vector<FigureBin> figure_bins(const RunSeries& s, double t0, double t1, int bins);

/// Where the capped axes of the figures end: the largest band top (95 % quantile) of |F| (N),
/// |M| (N mm), a (mm), N/(m g) of a run (0 if none).
struct AxisCaps {
  double force = 0.0, moment = 0.0, major = 0.0, n_over_mg = 0.0;
};
struct FigureRanges {
  AxisCaps full;   ///< bins over the whole run
  AxisCaps early;  ///< bins over the first kEarlyWindow seconds
};

/// Writes the three files for `s` under `dir` (created if needed); support::OutputError if it
/// cannot. Returns the axis caps, as read_figure_ranges reads them from the files written.
FigureRanges write_figure_data(const std::filesystem::path& dir, const std::string& stem, const RunSeries& s);

/// The axis caps of the files `<stem>.full.dat` and `<stem>.early.dat` under `dir` (the numbers as
/// written, so that a figure drawn from the files alone gets the same axes). std::runtime_error if
/// a file is missing or malformed.
[[nodiscard]] FigureRanges read_figure_ranges(const std::filesystem::path& dir, const std::string& stem);

}  // namespace frictionlab::dynamics::paper
