#pragma once
// A run's trajectory, decimated: the samples at least `dt` apart (the first, then the first sample
// at or after each multiple of dt, and the last), for the optional trajectories file of an
// ensemble (--hdf5). Point samples, not averages: the nutation of gamma3 (up to ~20 Hz in the
// egg's runs) is aliased at the default 0.1 s; the file is for overviews, not for features.

#include <cstddef>
#include <string_view>
#include <vector>

namespace frictionlab::dynamics::ensemble {

struct DecimatedTrajectory {
  std::vector<double> t;          ///< s
  std::vector<double> gamma3;     ///< cosine of the tilt of the axis
  std::vector<double> spin;       ///< Omega = omega.gamma, 1/s
  std::vector<double> slip;       ///< U, m/s
  std::vector<double> n_over_mg;  ///< N/(m g)
  std::vector<double> kinetic;    ///< J

  /// The column names, in the order of columns().
  static constexpr std::string_view kColumns[] = {"t", "gamma3", "spin", "slip", "n_over_mg", "kinetic"};
  static constexpr std::size_t kColumnCount = 6;
  [[nodiscard]] std::size_t size() const { return t.size(); }
  [[nodiscard]] bool empty() const { return t.empty(); }
  /// The columns as pointers, in kColumns order.
  [[nodiscard]] std::vector<const std::vector<double>*> columns() const {
    return {&t, &gamma3, &spin, &slip, &n_over_mg, &kinetic};
  }
  [[nodiscard]] std::vector<std::vector<double>*> columns() {
    return {&t, &gamma3, &spin, &slip, &n_over_mg, &kinetic};
  }
};

}  // namespace frictionlab::dynamics::ensemble
