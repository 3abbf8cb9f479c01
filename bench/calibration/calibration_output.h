#pragma once
// The files of the calibration study (calibration.h), under the output folder DIR:
//   DIR/calibration.csv         one row per engine law, pressure and scope (columns below)
//   DIR/scan.csv                law,pressure,scope,c,max_err_M: the objective E(c) on the scan
//   DIR/curves.csv              pressure,law,s,F1,M: the circle's forces against s (psi = 0, Omega > 0)
//   DIR/calibration_tables.md   the results in markdown, with the command, machine and date
//   DIR/plots/calibration_scan.{gp,dat,png}    E(c), one panel per engine law
//   DIR/plots/calibration_forces.{gp,dat,png}  F1 and M against s, one column per pressure
// calibration.csv columns: law, pressure, scope, exact_spin (M/(kNa) of exact at U = 0 on the
// circle, computed), closed_form_spin (the same in closed form), then for c = exact_spin (suffix
// _spin) and for the best c (suffix _best): c, max_F1, max_F2, max_M, rms_M (per kN, kNa), and the
// grid point of the largest torque error at the best c (worst_s, worst_mu, worst_psi, worst_sign).
// Numbers have 10 significant digits. Every file is written whole or not at all.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/accuracy/report.h"
#include "bench/calibration/calibration.h"

namespace frictionlab::calibration {

/// The three CSV tables, in that order's format (see above).
void write_calibration_csv(std::ostream& out, const CalibrationResult& result);
void write_scan_csv(std::ostream& out, const CalibrationResult& result);
void write_curves_csv(std::ostream& out, const CalibrationResult& result);
/// The markdown tables, headed by the run's command, machine and date.
void write_calibration_markdown(std::ostream& out, const CalibrationResult& result, const accuracy::RunInfo& run);

/// Writes the files above (created folders; existing files replaced). std::runtime_error naming
/// the file on a failed write.
void write_calibration_files(const CalibrationResult& result, const std::filesystem::path& dir,
                             const accuracy::RunInfo& run);

/// Writes the figures' data and scripts under DIR/plots and, if `draw` and gnuplot is found, runs
/// it. Returns the figures drawn; a warning on `progress` for each one not drawn.
std::vector<std::filesystem::path> write_calibration_plots(const CalibrationResult& result,
                                                           const std::filesystem::path& dir, bool draw,
                                                           std::ostream* progress);

}  // namespace frictionlab::calibration
