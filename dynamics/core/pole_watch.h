#pragma once
// Watches the poles of a rational friction law along a run (friction/law.h: has_poles(),
// pole_denominators()). A trajectory that reaches a pole is not a solution of the equations past
// it, so the run must stop there (reason "law-pole", dynamics/body/simulation.h) instead of stepping
// across: an adaptive step can land on the far side, where the forces are finite again, and be
// accepted (the printed Padé law's F2, eq. (8), is crossed that way at tolerances 1e-9).
//
// The denominators divided by (a Omega)^2 depend only on the shape of the contact: the slip ratio
// s = U/(a |Omega|), the axis ratio mu = b/a, the angle psi and the sign of Omega (the scaling
// fact of docs/model.md). A state is mapped to the point (t, mu, psi) with t = 1/(1 + s) in [0, 1]:
//   in contact    s from the patch (s = inf, t = 0, when Omega = 0);
//   no contact    the patch has shrunk to nothing: s = inf (t = 0), mu the limit of b/a as the
//                 depth goes to 0, so that landing with slip and lifting off with slip are watched
//                 like any other motion (each model maps its contact to a point: pole_point,
//                 dynamics/core/run_loop.h).
//
// A denominator can change sign in two ways: through 0 (a pole: the output blows up) or through
// infinity (e.g. the printed a4 = -8/(3 mu^(3/4) pi d6) when psi passes 0 or pi/2 and d6 changes
// sign: the output goes through 0 and stays smooth). A sign change between two states is
// classified by bisection on the straight segment between their points (psi along the shorter
// arc, modulo pi): it passes through infinity when |D| at the final bracket is larger than at both
// ends or when a point without denominator (NaN) lies on the way, and is a pole otherwise (|D|
// falls inside, or, at rounding level, cannot be told apart: the integrator closing in on a pole
// ends with both states within rounding of it). A reference exactly on a pole lets nothing leave.

#include <array>

#include "friction/law.h"

namespace frictionlab::dynamics {

class PoleWatch {
 public:
  /// `k`: the plane's friction coefficient (passed to the law with the shape).
  PoleWatch(const friction::FrictionLaw& law, double k);

  /// True if the law declares poles; otherwise nothing is watched and crossing() is always -1.
  [[nodiscard]] bool active() const { return active_; }

  /// The shape coordinates of a state (see the header comment).
  struct Point {
    double t = 0.0;      ///< 1/(1 + s), s = U/(a |Omega|)
    double mu = 1.0;     ///< b/a
    double psi = 0.0;    ///< rad
    double sign = 1.0;   ///< sign of Omega (+1 when Omega = 0)
  };
  /// The point of a contact over a patch a >= b > 0 (a planar model's patch, dynamics/puck/).
  [[nodiscard]] static Point patch_point(double U, double Omega, double a, double b, double psi);

  /// The denominators at a point (divided by (a Omega)^2; NaN where an output has none).
  [[nodiscard]] std::array<double, 3> denominators(const Point& p) const;

  /// The reference: the last accepted state of the run.
  void set_reference(const Point& p);

  /// Which denominator passes through 0 between the reference and `c`: 0 (F1), 1 (F2), 2 (M), or
  /// -1 for none. A reference exactly on a pole (a denominator = 0) lets nothing leave it. Cheap when no sign changes (one call of the law's pole_denominators); no
  /// allocation.
  [[nodiscard]] int crossing(const Point& p) const;

  /// "F1", "F2", "M".
  [[nodiscard]] static const char* output_name(int which);

 private:
  [[nodiscard]] bool passes_through_zero(const Point& from, const Point& to, int which) const;

  const friction::FrictionLaw& law_;
  double k_;
  bool active_;
  Point ref_{};
  std::array<double, 3> ref_den_{};
};

}  // namespace frictionlab::dynamics
