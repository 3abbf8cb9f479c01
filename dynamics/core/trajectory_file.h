#pragma once
// The file a model's trajectory writer fills (trajectory.csv): a header line, then one whole row
// per sample. Every model's writer (dynamics/body/trajectory_csv.h, dynamics/puck/
// puck_trajectory_csv.h) formats its own columns and hands the rows here, so that what a failure
// or the size limit does to the file and to the run is written once:
//
//   * rows go through support::RecordFile (buffered, every write checked; a failed write is cut
//     back to the last whole row and the file stays failed);
//   * a write or close that fails throws OutputFailure (the run stops, reason output-error);
//   * the size limit run.max_output_bytes (dynamics/core/output_limit.h) refuses the row that
//     would pass it with OutputLimitReached (the run stops, reason output-limit); the file keeps
//     every row before it, at most the limit, and still closes cleanly.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "dynamics/core/observer.h"
#include "friction/support/checked_output.h"

namespace frictionlab::dynamics {

/// The header line of a trajectory file: the column names joined by ',', ended by '\n'.
[[nodiscard]] std::string trajectory_file_header(std::span<const std::string_view> columns);

class TrajectoryFile {
 public:
  /// Creates (or truncates) `file` and writes `header` (a whole line); `max_bytes` (0: no limit)
  /// is the most the file may hold, the header included. Throws support::OutputError if the file
  /// cannot be created, std::invalid_argument naming run.max_output_bytes if the header alone
  /// passes `max_bytes`.
  TrajectoryFile(const std::filesystem::path& file, std::string_view header, std::uint64_t max_bytes = 0);

  /// Appends one whole row (its '\n' included). Throws OutputFailure if the file cannot be
  /// written, OutputLimitReached if the row would take it past its size limit (the row is not
  /// written).
  void append(std::string_view row);
  /// Writes what is buffered and closes the file; throws OutputFailure if that fails.
  void close();

  [[nodiscard]] std::uint64_t size() const { return file_.size(); }  ///< header and rows taken, bytes
  [[nodiscard]] const std::filesystem::path& path() const { return file_.path(); }

 private:
  support::RecordFile file_;
};

}  // namespace frictionlab::dynamics
