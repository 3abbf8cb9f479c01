#pragma once
// The files of the accuracy study: summaries, ready-to-paste markdown and, on request, per-point
// CSV tables.
//
// Layout under the output folder DIR (README.md written there documents every column):
//   DIR/points/<law>.csv        one row per grid point (the reference too, as points/exact.csv);
//                               only with StudyFiles::point_tables (18-26 MB per law on the
//                               default grid, 165 MB for the default laws and the reference; the
//                               rest of the study, figures included, is 4.8 MB)
//   DIR/summary.csv             one row per law, over the whole grid
//   DIR/summary_by_mu.csv       one row per law and mu
//   DIR/summary_by_region.csv   one row per law and region (s bands, sign of Omega)
//   DIR/singular/<law>.csv      pole brackets of laws whose denominators are known
//   DIR/accuracy_tables.md      the tables, in markdown
//   DIR/README.md               what each file and column means
// Numbers are written with 10 significant digits (enough for errors down to 1e-10 relative);
// non-finite values as nan, inf or -inf.

#include <filesystem>
#include <iosfwd>
#include <string>

#include "bench/accuracy/study.h"

namespace frictionlab::accuracy {

/// Where and when a study ran, for the tables' header.
struct RunInfo {
  std::string date;     ///< UTC, ISO 8601
  std::string machine;  ///< CPU model and thread count, from /proc/cpuinfo
  std::string command;  ///< the command line that produced the files
  double seconds = 0.0; ///< wall time of the study's evaluation and statistics (not the writing)
};

/// The date and machine of this run (command and seconds left empty).
[[nodiscard]] RunInfo describe_this_run();

/// 10 significant digits, or nan / inf / -inf.
[[nodiscard]] std::string format_number(double x);

/// Header: s,mu,psi,sign,F1,F2,M,err_F1,err_F2,err_M,dissipation; then one row per grid point.
void write_points_csv(std::ostream& out, const Grid& grid, const LawValues& law,
                      const LawValues& reference);

/// One row per law over the whole grid (summary.csv).
void write_summary_csv(std::ostream& out, const StudyResult& study);
/// One row per law and grid mu (summary_by_mu.csv).
void write_summary_by_mu_csv(std::ostream& out, const StudyResult& study);
/// One row per law and region (summary_by_region.csv).
void write_summary_by_region_csv(std::ostream& out, const StudyResult& study);
/// component,mu,psi,s_low,s_high: one row per pole bracket of `law`.
void write_poles_csv(std::ostream& out, const Grid& grid, const LawSummary& law);
/// The markdown tables (accuracy_tables.md).
void write_tables_markdown(std::ostream& out, const StudyResult& study, const RunInfo& run);
/// Which of the optional files to write.
struct StudyFiles {
  bool point_tables = false;  ///< points/<law>.csv (the bulk of the output: 18-26 MB per law by default)
};

/// The description of the files and columns (README.md).
void write_readme(std::ostream& out, const StudyResult& study, const RunInfo& run, const StudyFiles& files = {});

/// Writes every file above under `dir` (created if missing; existing files are replaced), the
/// per-point tables only if `files` asks for them. Throws std::runtime_error naming the file if
/// one cannot be written.
void write_study_files(const StudyResult& study, const std::filesystem::path& dir,
                       const RunInfo& run, std::ostream* progress = nullptr, const StudyFiles& files = {});

}  // namespace frictionlab::accuracy
