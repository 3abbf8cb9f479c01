#pragma once
// The trajectory as CSV, one row per sample (dynamics/core/observer.h), columns in this order
// (SI units; vectors in the body frame; docs/dynamics.md §6):
//
//   t          s      time
//   gamma1..3  -      upward unit vertical (normalised, as the forces see it)
//   omega1..3  1/s    angular velocity
//   v1..3      m/s    velocity of the centre of mass
//   eps        m      height of the contact point over the plane (< 0: penetration)
//   N          N      normal force, eq. (6)
//   U          m/s    slip speed of the contact point
//   Omega      1/s    spin omega.gamma
//   F1, F2     N      friction force components, F = -F1 e1 - F2 e2
//   M          N m    friction torque, -M gamma
//   a, b       m      patch semi-axes (0 out of contact)
//   psi        rad    angle from the slip direction e1 to the major axis, [0, pi)
//   energy     J      total mechanical energy (kinetic + gravity + Hertz spring)
//   kinetic    J      kinetic energy
//   W_slide    J      work done against sliding friction so far, ∫ F1 U dt
//   W_spin     J      work done against spinning friction so far, ∫ M Omega dt
//   in_contact 0/1    eps < 0
//   stick      0/1    the body's mode (docs/dynamics.md §5): 1 in stick (rolling without slip and
//                     spin; F1, F2, M are then the stick wrench, not the law's)
//   x, y       m      position of the centre of mass on the plane (world axes; the pose,
//                     dynamics/body/state.h: integrated beside the state, not fed back)
//   qw, qx, qy, qz -  orientation, the unit quaternion turning body vectors into world ones
//                     (x .. qz are left out of a run with run.pose = false)
//
// Numbers are written in the shortest form that reads back to the same double; a zero is written
// "0" whatever its sign (support/number_format.h: the sign of a zero here is arithmetic residue,
// F1 = -0 at pure spin, or gamma2 = -0, and "-0" reads as a negative number).
//
// The file only ever holds whole rows: rows are buffered (support::RecordFile, 64 KiB, ~140 rows;
// a process killed from outside loses at most those) and a write that fails is cut back to the
// last whole row. A failed write throws OutputFailure, which stops the simulation; the writer
// then stays failed. A size limit (run.max_output_bytes, dynamics/core/output_limit.h) refuses the row
// that would pass it with OutputLimitReached, which stops the simulation too; the file keeps every
// row before it (its size is at most the limit) and closes cleanly. (That file is every model's,
// dynamics/core/trajectory_file.h; this writer formats the body's columns.)

#include <array>
#include <cstdint>
#include <string>
#include <filesystem>
#include <string_view>

#include "dynamics/body/equations_of_motion.h"  // the body's Sample and Observer
#include "dynamics/core/observer.h"
#include "dynamics/core/trajectory_file.h"

namespace frictionlab::dynamics {

inline constexpr std::array<std::string_view, 33> kTrajectoryColumns = {
    "t",  "gamma1", "gamma2", "gamma3", "omega1", "omega2",  "omega3",  "v1",     "v2",
    "v3", "eps",    "N",      "U",      "Omega",  "F1",      "F2",      "M",      "a",
    "b",  "psi",    "energy", "kinetic", "W_slide", "W_spin", "in_contact", "stick", "x",
    "y",  "qw",     "qx",     "qy",     "qz",     "slip_held"};

/// The pose's columns, [kPoseColumnsBegin, kPoseColumnsEnd) of kTrajectoryColumns: x .. qz.
inline constexpr std::size_t kPoseColumnsBegin = 26;
inline constexpr std::size_t kPoseColumnsEnd = 32;
static_assert(kTrajectoryColumns[kPoseColumnsBegin] == "x" && kTrajectoryColumns[kPoseColumnsEnd - 1] == "qz");

/// Whether column i of kTrajectoryColumns is written: all of them, the pose's only with the pose
/// (run.pose).
[[nodiscard]] constexpr bool trajectory_column_written(std::size_t i, bool pose) {
  return pose || i < kPoseColumnsBegin || i >= kPoseColumnsEnd;
}

/// One row: the values of kTrajectoryColumns at sample `s` (in_contact as 0 or 1, the quaternion normalised), as the CSV reads
/// back (-0.0 as +0.0). The CSV writes these numbers; other sinks (the Python module's arrays) take
/// them from here too, so they hold what the file holds, bit for bit.
[[nodiscard]] std::array<double, kTrajectoryColumns.size()> trajectory_row(const Sample& s);

/// The header line, "t,gamma1,...,slip_held\n" (without the pose's columns if `pose` is false).
[[nodiscard]] std::string trajectory_header(bool pose = true);
/// The smallest row: every value one character, each followed by ',' or the line's end.
inline constexpr std::size_t kMinTrajectoryRowBytes = 2 * kTrajectoryColumns.size();

class TrajectoryCsv final : public Observer {
 public:
  /// Creates (or truncates) `file` and writes the header; `max_bytes` (0: no limit) is the most the
  /// file may hold, the header included. Throws support::OutputError if the file cannot be
  /// created, std::invalid_argument if the header alone passes `max_bytes`.
  /// `pose` false leaves the pose's columns out (run.pose).
  explicit TrajectoryCsv(const std::filesystem::path& file, std::uint64_t max_bytes = 0, bool pose = true);
  /// Appends one row. Throws OutputFailure if the file cannot be written, OutputLimitReached if
  /// the row would take it past its size limit (the row is not written).
  void sample(const Sample& s) override;
  /// Writes what is buffered and closes the file; throws OutputFailure if that fails.
  void close();

  [[nodiscard]] long rows() const { return rows_; }  ///< rows given (not all may have reached the file)
  [[nodiscard]] std::uint64_t bytes() const { return file_.size(); }  ///< header and rows taken, bytes
  [[nodiscard]] const std::filesystem::path& path() const { return file_.path(); }

 private:
  TrajectoryFile file_;
  std::string line_;
  long rows_ = 0;
  bool pose_;
};

}  // namespace frictionlab::dynamics
