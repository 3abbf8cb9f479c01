#pragma once
// The files of the puck study (dynamics/puck/puck_study.h) in an output folder:
//   puck-study.md          the report: the terminal regimes predicted from each law, the disk runs,
//                          the elliptic puck, with the command that made it;
//   theory.csv, disk.csv, ellipse.csv   the same numbers, one row each, every digit;
//   figures/               drift.png (G(r) at kappa = 1/2), regimes.png (r* against kappa),
//                          ratio.png (the disk's ratio against its kinetic energy), paths.png (the
//                          elliptic puck's paths), their gnuplot scripts and data (gnuplot NAME.gp
//                          in figures/ redraws one).
// Every write is checked (support::write_file_atomically).

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/puck/puck_study.h"

namespace frictionlab::dynamics::puck {

/// Writes the report and the tables; with `plots`, the figures' data and scripts and runs gnuplot.
/// Returns the problems with the figures (gnuplot missing or failing), one line each; the rest
/// is written regardless. `command`: the command line, for the provenance line.
[[nodiscard]] std::vector<std::string> write_puck_study(const PuckStudyResults& results, const std::filesystem::path& out,
                                                        const std::string& command, bool plots);

}  // namespace frictionlab::dynamics::puck
