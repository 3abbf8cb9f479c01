#pragma once
// The paper's figures as gnuplot scripts (PNG, pngcairo), written beside their data
// (dynamics/paper/figure_data.h) so that `cd DIR/plots && gnuplot fig3-egg-printed-a.gp` redraws one:
//
//   fig2-<egg>.png              gamma3 against |omega|^2, one panel per case, laws overlaid
//   fig3-<egg>-<case>.png       against time, 3x2: gamma3, |F|, |M|, major semi-axis a, b/a, N/(m g)
//   fig3-<egg>-<case>-early.png the same over the first kEarlyWindow seconds
//
// Each law is the mean of each time bin (a line) over a translucent band of the bin's min-max (the
// zooms draw the means only: their bands are the bounces' noise and triple the PNG); a run that stopped early (e.g. the printed Padé law at its pole)
// is marked with a cross where it stopped, and its key entry says why and when. The axes of |F|,
// |M|, a and N/(m g) end 15 % above the largest bin mean of the runs that ended normally (the
// bounces' spikes and a pole's blow-up are cut).

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/paper/figure_data.h"

namespace frictionlab::dynamics::paper {

struct FigureRun {
  std::string label;   ///< law name (legend)
  std::string stem;    ///< data files data/<stem>.{full,early,end}.dat
  bool stopped_early = false;
  std::string note;    ///< e.g. "stopped: integrator-failure at t = 0.45 s"
  FigureRanges ranges; ///< its axis caps (figure_data.h)
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

/// Runs gnuplot on each script in plots_dir. Returns one message per failure (empty: all drawn);
/// a missing gnuplot is one message.
[[nodiscard]] std::vector<std::string> render_figures(const std::filesystem::path& plots_dir,
                                                      const std::vector<std::string>& scripts);

/// The line colour of a law in every figure ("#000000" for exact, ...).
[[nodiscard]] std::string law_colour(const std::string& law, std::size_t index);

}  // namespace frictionlab::dynamics::paper
