#pragma once
// What the side by side measures in a run of a problem (bench/engines/problems.h), the same way
// for every engine and for frictionlab: from the samples alone.
//
//   spin-down      the first time |omega_z| falls to 1 % of its start, by linear interpolation
//                  between samples (exact for a linear decay); also whether it falls to 1e-3.
//   puck           v/(a |omega_z|) where the kinetic energy (1/2) m v^2 + (1/2) C omega_z^2 first
//                  falls to 1e-3 of its start (interpolated); also when v and |omega_z| fall to 1e-3
//                  of their starts (do they stop together?).
//   tippe-top      the first time gamma3 (the body's z axis . e_z) falls below -0.9 after an upright
//                  start (dynamics/tippe_top/tippe_top_observables.h); also when it crosses 0.
//   slide-to-roll  |v|/v0 at the last sample; also the first time the slip of the lowest point,
//                  |v + omega x (-R e_z)|, falls to 1 % of v0 (against 2 v0/(7 k g)).

#include <string>
#include <vector>

#include "bench/engines/engine.h"
#include "bench/engines/problems.h"

namespace frictionlab::engines {

struct Measure {
  double value = 0.0;  ///< the problem's quantity (NaN: not reached within the run)
  double time = 0.0;   ///< s: the secondary time (spin 1e-3, puck's stops, horizontal axis, end of slip)
  std::string detail;  ///< one line: the secondary facts
};

/// The measure of `problem` in `samples` (t ascending from 0). std::invalid_argument if the
/// samples are empty or the problem's id is unknown.
[[nodiscard]] Measure measure(const Problem& problem, const std::vector<Sample>& samples);

/// gamma3 of an orientation: the body z axis's vertical component, 1 - 2 (x^2 + y^2) / |q|^2.
[[nodiscard]] double axis_vertical(const std::array<double, 4>& q);

}  // namespace frictionlab::engines
