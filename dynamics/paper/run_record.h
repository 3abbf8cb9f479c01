#pragma once
// What `frictionlab paper` keeps of a run on disk besides `frictionlab simulate`'s files, and how
// it reads a finished run back (--resume):
//
//   trajectory.csv  every kTrajectoryEvery-th sample of the run (0.5 s at the paper's 0.01 s) and
//                   the last one: the rows of the full trajectory at those times, bit for bit
//                   (rerunning scenario.toml writes every sample). The features and figures are
//                   measured on every sample, in memory, before the file is thinned.
//   gamma3.csv      the series the laws are compared on (dynamics/paper/trajectory_compare.h,
//                   dynamics/paper/divergence.h): t, gamma3 and its 1-s moving average (computed
//                   from every sample), and the symmetry axis in world axes, at every
//                   kComparisonEvery-th sample and the last, in the shortest round-trip form.
//
// A finished run is read back from summary.json (dynamics/body/summary_json.h), features.json
// (dynamics/paper/feature_json.h) and gamma3.csv; every number reads back to the same double, so a
// resumed job reports what the first job measured.

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "dynamics/body/simulation.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics::paper {

/// trajectory.csv keeps every this-many-th sample (and the last): 0.5 s at the paper's 0.01 s, an
/// overview (the features and figures are measured on every sample, in memory). The default job's
/// trajectories take 6.4 MB so, 32 MB at 0.1 s and 320 MB in full (docs/experiments.md §4);
/// --full-trajectories keeps every sample.
inline constexpr int kTrajectoryEvery = 50;
/// gamma3.csv keeps every this-many-th sample (and the last): the laws are compared every 0.1 s.
inline constexpr int kComparisonEvery = 10;

/// Rows kept of `rows` when row 0, every `every`-th row and the last are kept (every >= 1).
[[nodiscard]] long thinned_rows(long rows, int every);

/// Rewrites the CSV file at `path` (one header line, then one line per sample) keeping the header,
/// every `every`-th data line from the first, and the last; through a temporary file renamed over
/// it (support::write_file_atomically). Returns the data lines kept. every == 1: left as it is.
/// support::OutputError / std::runtime_error if it cannot be read or written.
long thin_csv(const std::filesystem::path& path, int every);

/// The data lines of a CSV file (lines after the header); -1 if it cannot be read.
[[nodiscard]] long csv_data_rows(const std::filesystem::path& path);

/// The series two runs are compared on (every vector as long as t).
struct ComparisonSeries {
  std::vector<double> t;              ///< s
  std::vector<double> gamma3;
  std::vector<double> gamma3_smooth;  ///< its moving average over the features' smoothing window
  std::vector<double> axis_x, axis_y, axis_z;  ///< the symmetry axis in world axes (run_series.h)
};

/// Every `every`-th point from the first, and the last.
[[nodiscard]] ComparisonSeries thin_series(const ComparisonSeries& full, int every);
/// gamma3.csv: "t,gamma3,gamma3_mean_1s,axis_x,axis_y,axis_z", shortest round-trip numbers.
/// support::OutputError.
void write_comparison_series(const std::filesystem::path& path, const ComparisonSeries& s);
/// std::runtime_error if the file is missing or malformed.
[[nodiscard]] ComparisonSeries read_comparison_series(const std::filesystem::path& path);

/// The termination reason named `name` ("rest", "law-pole", ...), if any.
[[nodiscard]] std::optional<Termination> termination_named(std::string_view name);

/// The summary of a summary.json: reason, message, rule, counts, times, energies, the final state
/// and the work done (the fields the report uses; the thresholds are not read back).
/// `weight` = m g (N) turns min_N_over_mg back into a force. std::runtime_error naming the key if
/// one is missing or of the wrong type.
[[nodiscard]] RunSummary summary_from_json(const support::Json& j, double weight);

/// The JSON document of a file; std::runtime_error if it cannot be read or parsed.
[[nodiscard]] support::Json read_json_file(const std::filesystem::path& path);

}  // namespace frictionlab::dynamics::paper
