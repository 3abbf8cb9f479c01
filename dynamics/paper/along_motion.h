#pragma once
// The error along the motion, per case of the paper job (docs/experiments.md §3):
//
//   (a) shadow-<group>.png      each compared law's friction minus the reference's, evaluated at the
//                               reference run's own contact states (its shadow laws,
//                               dynamics/core/shadow_laws.h), against time: one panel per output
//                               (|dF1|, |dF2| per kN, |dM| per kNa, |dP| in W), log axes, the
//                               median of each 0.25 %-of-the-run bin as a thick line and its 95 %
//                               quantile as a thin one in the same style, the phase of the motion
//                               shaded behind;
//   (b) divergence-<group>.png  each law's distance from the reference run (the angle between their
//                               symmetry axes, dynamics/paper/divergence.h) against time, log axis,
//                               beside the chaos floor's (the reference rerun with tolerances x0.1),
//                               and the 1-degree line where the axes have parted;
//   (c) a table per case in the report: each law's typical and worst error along the motion, the
//       energy it would have dissipated more (or less), and when it parts from the reference
//       against when the floor does.

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/paper/experiment_runner.h"

namespace frictionlab::dynamics::paper {

/// Bins of figure (a) over the reference run.
inline constexpr int kShadowBins = 400;

/// Reads the reference run's shadow.csv (every sample: call before it is thinned) and writes the
/// binned data of figure (a) to dir/<stem>.shadow.dat. std::runtime_error if the file cannot be
/// read; support::OutputError if the data cannot be written.
void write_shadow_figure_data(const std::filesystem::path& shadow_csv, const std::filesystem::path& dir,
                              const std::string& stem);

struct AlongMotion {
  std::vector<std::string> scripts;  ///< gnuplot scripts written, relative to the plots folder
  std::string report;                ///< the report's section (markdown)
};

/// For every case with a reference run: the scripts of figures (a) (if its shadow data exists) and
/// (b) in plots_dir (their data in plots_dir/data), and the report's section.
[[nodiscard]] AlongMotion write_along_motion(const std::filesystem::path& plots_dir,
                                             const std::vector<RunResult>& results);

}  // namespace frictionlab::dynamics::paper
