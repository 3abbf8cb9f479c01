#pragma once
// The state of the puck and named access to its parts (docs/puck.md):
//
//   x = ( x, y, heading, vx, vy, omega, W_slide, W_spin )
//
// position of the centre (m) and velocity (m/s) in the fixed horizontal frame, heading (rad) the
// angle from the frame's x axis to the patch's major axis (body x), counter-clockwise seen from
// above, omega = heading' (1/s) the spin; W_slide = ∫ F1 U dt and W_spin = ∫ M Omega dt (J), the
// work done against sliding and spinning friction, so that E + W_slide + W_spin = E(0) can be
// checked.

#include <Eigen/Core>

namespace frictionlab::dynamics::puck {

struct PuckLayout {
  static constexpr int kPosition = 0;
  static constexpr int kHeading = 2;
  static constexpr int kVelocity = 3;
  static constexpr int kSpin = 5;
  static constexpr int kSlideWork = 6;
  static constexpr int kSpinWork = 7;
  static constexpr int kSize = 8;
};

using PuckState = Eigen::Matrix<double, PuckLayout::kSize, 1>;

inline auto position(PuckState& x) { return x.segment<2>(PuckLayout::kPosition); }
inline auto position(const PuckState& x) { return x.segment<2>(PuckLayout::kPosition); }
inline double& heading(PuckState& x) { return x[PuckLayout::kHeading]; }
inline double heading(const PuckState& x) { return x[PuckLayout::kHeading]; }
inline auto velocity(PuckState& x) { return x.segment<2>(PuckLayout::kVelocity); }
inline auto velocity(const PuckState& x) { return x.segment<2>(PuckLayout::kVelocity); }
inline double& spin(PuckState& x) { return x[PuckLayout::kSpin]; }
inline double spin(const PuckState& x) { return x[PuckLayout::kSpin]; }
inline double& slide_work(PuckState& x) { return x[PuckLayout::kSlideWork]; }
inline double slide_work(const PuckState& x) { return x[PuckLayout::kSlideWork]; }
inline double& spin_work(PuckState& x) { return x[PuckLayout::kSpinWork]; }
inline double spin_work(const PuckState& x) { return x[PuckLayout::kSpinWork]; }

/// A state with zero accumulated work.
inline PuckState make_puck_state(const Eigen::Vector2d& position_m, double heading_rad, const Eigen::Vector2d& v,
                                 double omega) {
  PuckState x = PuckState::Zero();
  position(x) = position_m;
  heading(x) = heading_rad;
  velocity(x) = v;
  spin(x) = omega;
  return x;
}

}  // namespace frictionlab::dynamics::puck
