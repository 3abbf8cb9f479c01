#pragma once
// The figures of the accuracy study, drawn by gnuplot from data and scripts left beside them.
//
// Under DIR/plots (each figure has NAME.gp, its data NAME.dat and the picture NAME.png):
// * heat_<law>:     |law - exact| over (log10 s, psi) for F1, F2, M (columns) at three mu (rows:
//                   the grid nodes nearest 0.05, 0.5, 1), the max over both signs of Omega, on one
//                   log colour scale from kHeatFloor to kHeatCeiling; non-finite points are white;
// * singular_<law>: for laws with known denominators or with singular points, a map over
//                   (log10 s, psi) at six mu of where each denominator is negative and where an
//                   output is non-finite or larger than kSingularMagnitude;
// * curves_<case>:  F1, F2, M against s (log axis) of every law beside exact, at (mu, psi) =
//                   (0.5, pi/4) and (0.1, pi/3), one row of panels per sign of Omega.
// The scripts use only relative paths: `cd DIR/plots && gnuplot NAME.gp` redraws a figure.

#include <filesystem>
#include <iosfwd>
#include <numbers>
#include <string>
#include <vector>

#include "bench/accuracy/study.h"

namespace frictionlab::accuracy {

/// The colour scale of the heat maps: |error| below the floor is drawn as the floor (it is below
/// anything the figures need to tell apart; `exact` against itself is all floor), above the
/// ceiling as the ceiling (an error of 10 kN is already a broken law).
inline constexpr double kHeatFloor = 1e-6;
inline constexpr double kHeatCeiling = 10.0;

/// A (mu, psi) where the curves are drawn, both signs of Omega.
struct CurveCase {
  double mu;
  double psi;  ///< rad
  std::string tag;  ///< file-name part, e.g. "mu0.5_psi45"
};
[[nodiscard]] std::vector<CurveCase> curve_cases();

struct PlotOptions {
  bool draw = true;  ///< run gnuplot (otherwise only write the data and scripts)
};

struct PlotReport {
  std::vector<std::filesystem::path> scripts;  ///< every script written
  std::vector<std::filesystem::path> figures;  ///< every PNG gnuplot produced
  std::string terminal;                        ///< "pngcairo", "png", or "" if no gnuplot
  std::vector<std::string> failures;           ///< scripts gnuplot failed on
};

/// The best PNG terminal of the installed gnuplot ("pngcairo", else "png"), or "" if gnuplot
/// cannot be run.
[[nodiscard]] std::string detect_gnuplot_terminal();

/// Writes the data and scripts under dir/plots and, if options.draw and gnuplot is found, draws
/// them (warning on one line of `progress` if gnuplot is missing or fails).
PlotReport write_plots(const StudyResult& study, const std::filesystem::path& dir,
                       const PlotOptions& options = {}, std::ostream* progress = nullptr);

}  // namespace frictionlab::accuracy
