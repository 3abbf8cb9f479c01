#pragma once
// The paper's figures as gnuplot scripts (PNG, pngcairo), written beside their data
// (dynamics/paper/figure_data.h) so that `cd DIR/plots && gnuplot fig3-egg-printed-a.gp` redraws one:
//
//   fig2-<egg>.png              gamma3 against |omega|^2, one panel per case, laws overlaid
//   fig3-<egg>-<case>.png       against time, 3x2: gamma3, |F|, |M|, major semi-axis a, b/a, N/(m g)
//   fig3-<egg>-<case>-early.png the same over the first kEarlyWindow seconds
//
// What each panel draws:
//   * every run of the group, the baseline (the reference law with tightened tolerances: the
//     chaos floor) included, as its mean line, with its 5-95 % quantiles beneath every mean line:
//     a translucent band in fig. 2 (gamma3's nutation, a narrow band), two thin lines in the run's
//     own colour and dash in fig. 3 (whose impacts spread them over decades: a band would cover
//     the means);
//   * each run in its own colour AND its own dash pattern (the figures survive grayscale);
//   * |F|, |M| and N/(m g), dominated by the impacts of the bouncing phases, on log axes (four
//     decades below 1.5x the highest band top of the runs that ended normally; values below are
//     drawn at the bottom); a on a linear axis up to 1.05x that top; gamma3 and b/a on fixed axes;
//   * a run that stopped early (the printed Padé law at its pole) as a cross where it stopped in
//     every panel, and no band (its bins near a pole are meaningless); why and when it stopped is
//     said once per figure, off the curves: in fig. 3 in its key entry, in fig. 2 (one panel per
//     case, each with its own stop) beside the cross of that panel, on the side away from the
//     nearer edge (to its left, as time runs right to left).

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/paper/figure_data.h"

namespace frictionlab::dynamics::paper {

struct FigureRun {
  std::string label;     ///< law name, or the baseline's label (legend)
  std::string stem;      ///< data files data/<stem>.{full,early,end}.dat
  bool baseline = false; ///< the reference law rerun with tolerances x kBaselineToleranceFactor
  bool stopped_early = false;
  std::string stop;      ///< how and when it stopped, e.g. "law-pole at t = 0.3163 s"
  double t_final = 0.0;  ///< s, its last sample
  FigureRanges ranges;   ///< its axis caps (figure_data.h)
};

struct FigureGroup {
  std::string egg;
  std::string case_id;
  std::string description;  ///< initial condition, for the title
  std::vector<FigureRun> runs;
};

/// Writes the scripts for `groups` into `plots_dir` (data in plots_dir/data); returns the script
/// file names, relative to plots_dir, each producing the PNG of the same stem.
[[nodiscard]] std::vector<std::string> write_figure_scripts(const std::filesystem::path& plots_dir,
                                                            const std::vector<FigureGroup>& groups);

/// How a run is drawn: its colour (by law, the same in every figure; grey for the baseline) and
/// its dash pattern (by its place in the group: no two runs of a figure share one).
struct LineStyle {
  std::string colour;  ///< "#rrggbb"
  std::string dash;    ///< gnuplot dashtype: "1" (solid), "2", ..., "(20,6)"
};
[[nodiscard]] LineStyle line_style(const FigureRun& run, std::size_t index);

}  // namespace frictionlab::dynamics::paper
