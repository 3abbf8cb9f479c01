#pragma once
// The files of the tippe-top study (dynamics/tippe_top/tippe_top_study.h) in an output folder:
//   tippe-top.md    the report: per law, how the run ended, the inversion time, the energy and
//                   Jellett checks, with the command that made it;
//   runs.csv        the same numbers, one row per law, every digit, with the overrides;
//   figures/        gamma3.png (gamma3 against time, every law), jellett.png (L.r / L.r(0)), their
//                   gnuplot scripts and data (gnuplot NAME.gp in figures/ redraws one).
// Every write is checked (support::write_file_atomically).

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/tippe_top/tippe_top_study.h"

namespace frictionlab::dynamics::tippe_top {

/// Writes the report and the table; with `plots`, the figures' data and scripts and runs gnuplot.
/// Returns the problems with the figures, one line each (the rest is written regardless).
[[nodiscard]] std::vector<std::string> write_tippe_top_study(const TippeTopStudyResults& results,
                                                             const std::filesystem::path& out,
                                                             const std::string& command, bool plots);

}  // namespace frictionlab::dynamics::tippe_top
