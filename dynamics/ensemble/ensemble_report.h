#pragma once
// DIR/report.md of a finished study (docs/ensembles.md shows one): what ran, how the runs ended,
// per feature and law the quantiles and the distances to the reference law next to the chaos
// floor with the verdict of dynamics/ensemble/chaos_floor_rule.h, the outcome classes, the
// divergence times, the maps (two varied keys on a grid) and the cost. Everything is computed
// from DIR/runs.csv, so `frictionlab ensemble STUDY --out DIR --resume` on a finished folder
// rewrites the report without running anything.

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/ensemble/ensemble_figures.h"
#include "dynamics/ensemble/ensemble_plan.h"
#include "dynamics/ensemble/run_record.h"

namespace frictionlab::dynamics::ensemble {

/// The rows of DIR/runs.csv (std::invalid_argument naming the file and line for a bad row).
[[nodiscard]] std::vector<RunRecord> read_runs(const std::filesystem::path& runs_csv, std::size_t key_count,
                                               RunModel model = RunModel::body, std::size_t shadow_count = 0);

/// "AMD EPYC 7B13 (2 cores), Linux 6.1.0": the machine a report was made on.
[[nodiscard]] std::string machine_description();

struct ReportOutcome {
  std::filesystem::path report;
  FiguresOutcome figures;
};

/// Writes DIR/report.md and DIR/figures/ (gnuplot run when `draw`) for the finished study of
/// `plan`. `command` is how the ensemble was run.
ReportOutcome write_report(const EnsemblePlan& plan, const std::filesystem::path& dir, const std::string& command,
                           bool draw);

/// The report's text (for tests): `figures` lists the PNGs to link, relative to DIR.
[[nodiscard]] std::string report_markdown(const EnsemblePlan& plan, const std::vector<RunRecord>& rows,
                                          const std::string& command, const std::string& machine,
                                          const std::vector<std::string>& figures);

}  // namespace frictionlab::dynamics::ensemble
