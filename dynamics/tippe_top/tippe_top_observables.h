#pragma once
// What the tippe-top study measures along a run (docs/tippe-top.md): the inversion, and Jellett's
// quantity.
//
// Inversion. gamma3 = gamma . xi3 (gamma the upward vertical, xi3 the symmetry axis pointing from
// the pole nearest the centre of mass to the far pole): +1 when the top stands on its near pole,
// -1 when it is inverted. The inversion time is when gamma3, having started near +1 (above
// kUprightGamma3), first falls below kInvertedGamma3; the study also reports when it first
// crosses 0 (the axis horizontal).
//
// Jellett's quantity. For a body whose surface near the contact is a sphere of radius R centred on
// the axis at d (from the centre of mass, body frame), the contact point is r = d - R gamma, and
// with L = J omega the angular momentum about the centre of mass,
//     d(L . r)/dt = (r x (N gamma + F) - M gamma) . r + L . (omega x d) = -M gamma . r,
// since the torque of any force applied at r is normal to r, L . (omega x d) = 0 for d on the
// symmetry axis of J = diag(A, A, C), and gamma is fixed in space. So L . r is conserved exactly
// by every law without a spin moment (M = 0), whatever the sliding force, the normal force (lift-
// offs included) or the compression of the plane; a spin moment changes it at the rate -M gamma . r
// (Jellett 1872; for the tippe top e.g. Cohen, Am. J. Phys. 45 (1977) 12, and Ueda, Sasaki &
// Watanabe, SIAM J. Appl. Dyn. Syst. 4 (2005) 1159). It holds for the sphere profile only (another
// profile's r is not d - R gamma).

#include <limits>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/body/state.h"

namespace frictionlab::dynamics::tippe_top {

/// gamma3 above this at the start: the top starts "near +1" (a tilt below ~25 degrees).
inline constexpr double kUprightGamma3 = 0.9;
/// gamma3 below this: the top is inverted (a tilt within ~25 degrees of the inverted vertical).
inline constexpr double kInvertedGamma3 = -0.9;

/// gamma3 of the state (gamma normalised).
[[nodiscard]] double gamma3(const StateVector& x);

/// L . r (kg m^3/s): L = diag(A, A, C) omega about the centre of mass, r = c.point.r the contact
/// point, both in the body frame. `c` must be sys.contact_state(x).
[[nodiscard]] double jellett_quantity(const Body& body, const StateVector& x, const ContactState& c);

/// d(L . r)/dt = -M gamma . r for a sphere (header comment); 0 out of contact.
[[nodiscard]] double jellett_rate(const ContactState& c);

/// Follows gamma3 through samples (t ascending) and locates its crossings by linear interpolation
/// between samples.
class InversionWatch {
 public:
  void add(double t, double gamma3);
  /// gamma3 at the first sample was above kUprightGamma3.
  [[nodiscard]] bool started_upright() const { return started_upright_; }
  /// First time gamma3 fell below 0 (NaN: never).
  [[nodiscard]] double horizontal_time() const { return horizontal_; }
  /// First time gamma3 fell below kInvertedGamma3 after an upright start (NaN: never).
  [[nodiscard]] double inversion_time() const { return inverted_; }
  /// The smallest gamma3 seen, and when.
  [[nodiscard]] double min_gamma3() const { return min_; }
  [[nodiscard]] double min_gamma3_time() const { return min_t_; }

 private:
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  bool first_ = true;
  bool started_upright_ = false;
  double t_prev_ = 0.0, g_prev_ = 0.0;
  double horizontal_ = kNaN, inverted_ = kNaN;
  double min_ = std::numeric_limits<double>::infinity(), min_t_ = kNaN;
};

}  // namespace frictionlab::dynamics::tippe_top
