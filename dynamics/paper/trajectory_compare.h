#pragma once
// Two runs of the same case compared along the trajectory: when their gamma3 first differ by more
// than a threshold (on a common time grid, by linear interpolation), and how their ends differ.

#include <vector>

#include "dynamics/paper/run_features.h"

namespace frictionlab::dynamics::paper {

/// Linear interpolation of y(t) at x (t ascending, at least one sample); NaN outside [t0, tn].
[[nodiscard]] double interpolate(const std::vector<double>& t, const std::vector<double>& y, double x);

struct Divergence {
  bool found = false;
  double t = kNaN;        ///< s: first grid time with |ya - yb| > threshold
  double horizon = 0.0;   ///< s: the runs were compared on [0, horizon] (the shorter run)
};

/// First time |ya - yb| > threshold on the grid 0, dt, 2 dt, ... up to the end of the shorter run
/// (that end included). dt > 0 and threshold >= 0, else std::invalid_argument.
[[nodiscard]] Divergence first_divergence(const std::vector<double>& ta, const std::vector<double>& ya,
                                          const std::vector<double>& tb, const std::vector<double>& yb,
                                          double threshold, double dt);

/// |acos(g_a) - acos(g_b)| in degrees: the difference in the tilt of the axis from the vertical
/// (the azimuth of a body of revolution on a plane carries no information).
[[nodiscard]] double tilt_difference_deg(double gamma3_a, double gamma3_b);

}  // namespace frictionlab::dynamics::paper
