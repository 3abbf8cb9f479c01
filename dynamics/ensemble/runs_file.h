#pragma once
// DIR/runs.csv of an ensemble: one row per finished run, appended and flushed as each run ends
// (support::RecordFile), so that a job killed at any moment keeps every run it finished, in whole
// rows. The rows come in the order runs finish; once every run is done the file is rewritten
// sorted by run index (atomically), so the finished table does not depend on the number of
// threads or ranks.

#include <filesystem>
#include <memory>
#include <set>
#include <string>

#include "dynamics/ensemble/run_record.h"
#include "friction/support/checked_output.h"

namespace frictionlab::dynamics::ensemble {

/// What an earlier session left in runs.csv.
struct ExistingRuns {
  std::set<long> done;         ///< run indices with a whole row
  long rows = 0;               ///< whole rows (a run recorded twice counts once in `done`)
  bool cut_partial_row = false;  ///< the file ended in part of a row (a kill mid-write): cut off
};

/// Reads `file` of an earlier session: its header must be `header`, every line but a last one
/// without its line ending must be a row with a run index below `runs` (else std::invalid_argument
/// naming the file and line). A partial last row is cut off the file.
[[nodiscard]] ExistingRuns read_existing_runs(const std::filesystem::path& file, const std::string& header, long runs);

/// Appends rows to runs.csv, each flushed at once.
class RunsWriter {
 public:
  /// A new file with `header` (truncate), or the end of an existing one (resume).
  RunsWriter(const std::filesystem::path& file, const std::string& header, bool resume);
  void write(const RunRecord& r);  ///< throws support::OutputError
  void close();

 private:
  support::RecordFile file_;
};

/// Rewrites `file` with its rows sorted by run index, one per run (the first of duplicates), through
/// a temporary file renamed over it.
void sort_runs_file(const std::filesystem::path& file);

}  // namespace frictionlab::dynamics::ensemble
