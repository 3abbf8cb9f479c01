#pragma once
// shadow.csv beside a run with shadow laws (dynamics/core/shadow_laws.h): one row per output sample
// of the run (the trajectory's times), so that it lines up with trajectory.csv row by row:
//
//   t          s
//   phase      0 airborne, 1 bouncing, 2 sliding, 3 rolling-spin, 4 near-rest (motion_phase.h)
//   s          U/(a |Omega|), the slip ratio; NaN where Omega = 0 or out of contact
//   b_over_a   the patch's axis ratio; NaN out of contact
//   a          m, the patch's major semi-axis; 0 out of contact
//   psi        rad, the angle from the slip to the major axis; NaN out of contact
//   N          N, the normal force
//   then per shadow law LAW (its spec): dF1[LAW], dF2[LAW] (per k N), dM[LAW] (per k N a) and
//   dP[LAW] (W), the law's friction minus the run's own at the sample's contact (0 out of contact,
//   NaN where the law failed).
//
// The file never stops or changes the run: a write that fails, or a row that would take the file
// past run.max_output_bytes, ends the file there (whole rows kept) and is reported in the summary.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/core/shadow_laws.h"
#include "dynamics/core/trajectory_file.h"

namespace frictionlab::dynamics {

class ShadowCsv {
 public:
  /// Creates `file` with its header for `laws`; support::OutputError if it cannot be created.
  ShadowCsv(const std::filesystem::path& file, const ShadowLaws& laws, std::uint64_t max_bytes);

  /// Appends the row of the sample at t; never throws (see the header comment).
  void write(double t, const ShadowPoint& p);
  /// Closes the file; never throws (a failure is error()).
  void close();

  [[nodiscard]] long rows() const { return rows_; }
  [[nodiscard]] std::uint64_t bytes() const { return file_.size(); }
  [[nodiscard]] const std::filesystem::path& path() const { return file_.path(); }
  /// Why the file ended early (a failed write, the size limit), or empty.
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  const ShadowLaws& laws_;
  TrajectoryFile file_;
  std::vector<ShadowError> errors_;
  std::string line_;
  long rows_ = 0;
  bool ended_ = false;
  std::string error_;
};

/// The header line of shadow.csv for these law specs (a name with ',' or '"' is quoted, RFC 4180).
[[nodiscard]] std::string shadow_csv_header(const std::vector<std::string>& specs);

}  // namespace frictionlab::dynamics
