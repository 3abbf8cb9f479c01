#pragma once
// The figures of an ensemble's report, as data files and gnuplot scripts in DIR/figures/ and PNGs
// drawn from them (support::run_gnuplot; `cd DIR/figures && gnuplot NAME.gp` redraws one):
//
//   divergence.png            the distribution of divergence times: per law against the
//                             reference on the same replica, and the floor's (the reference on
//                             two replicas); empirical distribution functions over the compared
//                             runs, so a curve ends at the share of runs that parted;
//   axis_divergence.png       the angle between the runs' symmetry axes against time: per law
//                             against the reference on the same replica, and the floor's; the
//                             median over the compared runs and its quartiles (lines), log-log;
//   shadow_errors.png         (a study with shadow laws) per shadow law, the distribution over the
//                             reference law's runs of each run's median |ΔF|/(kN) along its
//                             motion (thick) and of its largest (thin);
//   map-final_class.png       (two varied keys on a grid) the outcome class most replicas of a
//                             cell end in, one panel per law;
//   map-t_vertical.png        the median time to the vertical (grey: never reached);
//   map-final_gamma3.png      the median final gamma3;
//   map-log10_terminal_ratio.png, map-path_lateral.png   (a puck study, instead of the two above
//                             and of divergence.png) the median ratio U/(a|Omega|) at the first
//                             stop, in log10, and the path's end across the initial velocity;
//   map-changes.png           per law but the reference: where its outcome class differs from
//                             the reference's beyond the reference's own replicas
//                             (dynamics/ensemble/outcome_map.h).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/ensemble/outcome_map.h"
#include "dynamics/ensemble/run_record.h"

namespace frictionlab::dynamics::ensemble {

struct FiguresOutcome {
  std::vector<std::filesystem::path> drawn;  ///< PNGs written
  std::vector<std::string> errors;           ///< figures not drawn, and why (one line each)
};

/// Writes the figures' data and scripts under `dir`/figures and, with `draw`, runs gnuplot.
/// `title` heads every figure. Throws support::OutputError if a data file cannot be written.
[[nodiscard]] FiguresOutcome write_figures(const std::filesystem::path& dir, const std::string& title,
                                           const std::vector<std::string>& laws, const std::vector<RunRecord>& rows,
                                           const std::optional<OutcomeMap>& map, bool draw,
                                           RunModel model = RunModel::body,
                                           const std::vector<std::string>& shadow_laws = {});

}  // namespace frictionlab::dynamics::ensemble
