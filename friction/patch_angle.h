#pragma once
// The orientation of the contact patch in the slip frame, as a friction law reads it: the angle psi
// from e1 to the major axis, CCW about gamma (docs/model.md), or the major axis's unit direction
// (cos psi, sin psi) in that frame.
//
// Laws need cos psi and sin psi, never psi itself, and read them once per evaluation with
// cos_sin(). A caller that has the angle (the command line, Python, the benchmarks) passes it as a
// double; cos_sin() then takes std::cos and std::sin of it where the law asks, as every law did
// before this type existed (results through an angle are bit for bit those of before, and cost
// what they cost: the two fuse into one sincos inside the law). A caller that has the major axis as
// a unit vector in the slip frame (the dynamics: the dot products of the axis with e1 and e2)
// passes that direction, and no trigonometric function runs at all: the angle is computed
// (std::atan2) only when asked for, e.g. for an output.

#include <cmath>

namespace frictionlab::friction {

/// The patch's orientation psi (rad), as an angle or as the unit direction (cos psi, sin psi).
/// Cheap to copy; no allocation.
class PatchAngle {
 public:
  /// validate() (friction/law.h) refuses a direction with |c^2 + s^2 - 1| above this: one from
  /// the dot products of unit vectors is unit to a few roundings (~1e-16).
  static constexpr double kUnitTolerance = 1e-12;

  struct CosSin {
    double c, s;
  };

  /// psi = 0: the major axis along e1.
  constexpr PatchAngle() = default;
  /// psi = `radians` (any double; validate() requires it finite). Implicit, so that a double
  /// stands where an angle is meant ({U, Omega, a, b, 0.3, N, k}, in.psi = 0.3).
  constexpr PatchAngle(double radians) : radians_(radians) {}  // NOLINT(google-explicit-constructor)
  /// The orientation of the unit direction (cos psi, sin psi) = (c, s) of the major axis in the
  /// slip frame, stored as given (validate() requires it finite and unit to kUnitTolerance).
  [[nodiscard]] static constexpr PatchAngle from_direction(double c, double s) {
    PatchAngle p;
    p.cos_ = c;
    p.sin_ = s;
    p.direction_ = true;
    return p;
  }

  /// (cos psi, sin psi): the direction as given, or std::cos and std::sin of the angle (computed
  /// here, at each call: a law calls this once).
  [[nodiscard]] CosSin cos_sin() const {
    if (direction_) return {cos_, sin_};
    return {std::cos(radians_), std::sin(radians_)};
  }
  /// The angle, rad: as given when made from an angle; for a direction, std::atan2(s, c) folded to
  /// [0, pi) (the major axis is a line: psi and psi + pi are the same patch).
  [[nodiscard]] double radians() const { return direction_ ? direction_radians() : radians_; }
  /// True when made by from_direction().
  [[nodiscard]] constexpr bool is_direction() const { return direction_; }

 private:
  [[nodiscard]] double direction_radians() const;

  double radians_ = 0.0;  ///< the angle, when made from one
  double cos_ = 1.0;      ///< the direction, when made from one
  double sin_ = 0.0;
  bool direction_ = false;
};

}  // namespace frictionlab::friction
