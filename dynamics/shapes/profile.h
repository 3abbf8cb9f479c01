#pragma once
// The meridian of a convex body of revolution: xi1^2 + xi2^2 = chi(z)^2, eq. (10) of the paper,
// with P(z) = chi(z)^2 a polynomial of any degree in the profile coordinate z (along the symmetry
// axis, metres; the body frame puts its origin at the centre of mass, xi3 = z - z_com).
//
// Rules (checked at construction, std::invalid_argument naming the value and the rule):
//  * P > 0 on exactly one bounded interval (z_lo, z_hi) between two consecutive real roots: the
//    poles of the body;
//  * both roots are simple (P'(z_lo) > 0 > P'(z_hi)), so the poles are smooth and not conical;
//  * the body is strictly convex: chi'' < 0, i.e. G(z) = 2 P P'' - P'^2 < 0 on [z_lo, z_hi]
//    (chi'' = G / (4 P^(3/2)); at the poles G = -P'^2 < 0 automatically).
// Presets: a sphere, a spheroid, and the egg of the paper's section 2 (docs/model.md §6).

#include <string>
#include <vector>

#include "dynamics/shapes/polynomial.h"

namespace frictionlab::dynamics {

class Profile {
 public:
  /// chi^2 as ascending coefficients in metres: P(z) = c0 + c1 z + c2 z^2 + ... (units m^(2-i)).
  /// `what` names the input in error messages (e.g. "body.chi2").
  explicit Profile(std::vector<double> chi2_ascending, std::string what = "chi2");

  /// Sphere of radius `radius` (m, > 0) centred at z = 0: P = R^2 - z^2.
  [[nodiscard]] static Profile sphere(double radius);
  /// Spheroid with equatorial semi-axis `equatorial` and polar semi-axis `polar` (m, > 0),
  /// centred at z = 0: P = e^2 (1 - z^2/p^2).
  [[nodiscard]] static Profile spheroid(double equatorial, double polar);
  /// The paper's egg, section 2: chi^2 = 2 (z + 0.1)(z - 1.2)(z - 0.252), z in (-0.1, 0.252) m.
  [[nodiscard]] static Profile paper_egg();

  [[nodiscard]] const Polynomial& chi2() const { return p_; }
  /// Lower pole (P' > 0 there), m.
  [[nodiscard]] double z_lo() const { return z_lo_; }
  /// Upper pole (P' < 0 there), m.
  [[nodiscard]] double z_hi() const { return z_hi_; }
  /// Length along the axis, m.
  [[nodiscard]] double length() const { return z_hi_ - z_lo_; }
  /// Largest radius max chi over the profile (sampled), m.
  [[nodiscard]] double max_radius() const { return max_radius_; }

 private:
  Polynomial p_;
  double z_lo_ = 0.0;
  double z_hi_ = 0.0;
  double max_radius_ = 0.0;
};

}  // namespace frictionlab::dynamics
