#pragma once
// The puck's trajectory as CSV, one row per sample (dynamics/puck/puck_run.h), columns in this
// order (SI units, the fixed horizontal frame; docs/puck.md §2):
//
//   t          s      time
//   x, y       m      position of the centre
//   heading    rad    angle from x to the patch's major axis
//   vx, vy     m/s    velocity of the centre
//   omega      1/s    spin
//   U          m/s    slip speed |v| (0 once held)
//   Omega      1/s    spin as the law sees it (0 once held)
//   psi        rad    angle from the slip direction to the major axis, [0, pi)
//   F1, F2     N      friction force, F = -F1 e1 - F2 e2
//   M          N m    friction torque, -M z
//   ratio      -      U/(a |Omega|); nan when Omega = 0 (no spin, or the spin held: the slip ratio
//                     is not defined; docs/puck.md §2)
//   energy     J      kinetic energy m v^2/2 + I omega^2/2
//   W_slide    J      work done against sliding friction so far
//   W_spin     J      work done against spinning friction so far
//   held       -      0 none, 1 slip held at 0, 2 spin held, 3 both (dynamics/puck/puck_equations.h)
//
// Whole rows only, every write checked, and the size limit run.max_output_bytes: the trajectory
// file every model writes (dynamics/core/trajectory_file.h); this writer formats the columns.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "dynamics/core/trajectory_file.h"
#include "dynamics/puck/puck_run.h"

namespace frictionlab::dynamics::puck {

inline constexpr std::array<std::string_view, 18> kPuckTrajectoryColumns = {
    "t", "x", "y", "heading", "vx", "vy", "omega", "U", "Omega", "psi", "F1", "F2", "M", "ratio",
    "energy", "W_slide", "W_spin", "held"};

/// The header line, "t,x,...,held\n".
[[nodiscard]] std::string puck_trajectory_header();
/// The smallest row: every value one character, each followed by ',' or the line's end.
inline constexpr std::size_t kMinPuckTrajectoryRowBytes = 2 * kPuckTrajectoryColumns.size();

class PuckTrajectoryCsv final : public PuckObserver {
 public:
  /// `a`: the patch's major semi-axis (for the ratio column); `max_bytes` (0: no limit) the most
  /// the file may hold, the header included (a row past it throws OutputLimitReached). Throws
  /// support::OutputError if the file cannot be created, std::invalid_argument if the header
  /// alone passes `max_bytes`.
  PuckTrajectoryCsv(const std::filesystem::path& file, double a, std::uint64_t max_bytes = 0);
  void sample(const PuckSample& s) override;
  void close();
  [[nodiscard]] long rows() const { return rows_; }
  [[nodiscard]] std::uint64_t bytes() const { return file_.size(); }  ///< header and rows taken, bytes

 private:
  TrajectoryFile file_;
  double a_;
  std::string line_;
  long rows_ = 0;
};

}  // namespace frictionlab::dynamics::puck
