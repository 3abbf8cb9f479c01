#pragma once
// The size limit of a run's trajectory file, run.max_output_bytes (docs/dynamics.md §4). It is
// checked twice: on the plan, before anything runs (a file of t_end/output_dt rows that would pass
// the limit even if every value took one character is refused, naming the key), and by the writer
// on every row, on the bytes it actually writes (support::RecordFile's size limit): the row that
// would pass the limit is not written and the run stops at once with reason output-limit
// (dynamics/core/observer.h OutputLimitReached), its file whole and at most the limit.

#include <cstddef>
#include <string_view>

namespace frictionlab::dynamics {

/// Default run.max_output_bytes: 100 MB. The largest trajectory.csv of a shipped scenario is
/// 10.6 MB at its own output_dt (egg-homogeneous-c at 0.02 s; 21 MB at the paper job's 0.01 s):
/// room for a finer interval, not for the gigabytes a mistyped one (3.3e-7 s) would write.
inline constexpr long kDefaultMaxOutputBytes = 100'000'000;

/// The smallest file a run to t_end writes: a header of `header_bytes`, then a row at t = 0 and
/// at every multiple of output_dt up to t_end, each at least `min_row_bytes` long. (A run that
/// ends earlier writes fewer rows; a row at the final time may add one.)
[[nodiscard]] double planned_output_bytes(double t_end, double output_dt, std::size_t header_bytes,
                                          std::size_t min_row_bytes);

/// std::invalid_argument naming run.output_dt, the planned rows, `file` and run.max_output_bytes
/// if planned_output_bytes(...) > max_output_bytes.
void check_planned_output(double t_end, double output_dt, long max_output_bytes, std::size_t header_bytes,
                          std::size_t min_row_bytes, std::string_view file);

}  // namespace frictionlab::dynamics
