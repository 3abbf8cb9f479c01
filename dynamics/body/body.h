#pragma once
// The rigid body: a convex profile of revolution (dynamics/shapes/profile.h), its mass, the position of
// its centre of mass on the axis, and its central inertia J = diag(A, A, C) (docs/model.md §5).
// Mass properties default to the homogeneous solid (dynamics/shapes/mass_properties.h); each can be
// overridden, which the paper's egg needs (docs/model.md §6: its printed centre of mass is not the
// centroid of the homogeneous solid).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/shapes/mass_properties.h"
#include "dynamics/shapes/profile.h"

namespace frictionlab::dynamics {

struct Body {
  Profile profile;
  double mass = 0.0;  ///< kg, > 0
  double com = 0.0;   ///< profile coordinate z of the centre of mass (xi3 = z - com), m
  double A = 0.0;     ///< transverse central moment of inertia, kg m^2, > 0
  double C = 0.0;     ///< axial moment of inertia, kg m^2, 0 < C <= 2A
  MassProperties homogeneous;  ///< of the homogeneous solid, for reference
};

/// What a scenario's [body] section says (docs/dynamics.md). Exactly one of `preset` or `chi2`.
struct BodySpec {
  /// "sphere" (needs radius), "spheroid" (needs semi_axes), "egg-printed", "egg-homogeneous";
  /// empty when `chi2` is given.
  std::string preset;
  std::vector<double> chi2;  ///< ascending coefficients of chi^2 in the profile coordinate, m
  std::optional<double> radius;                    ///< sphere radius, m
  std::optional<std::array<double, 2>> semi_axes;  ///< spheroid {equatorial, polar}, m
  double mass = 0.0;                               ///< kg
  std::optional<double> com;  ///< centre of mass (profile coordinate, m); default: see make_body
  std::optional<double> A;    ///< kg m^2; default: homogeneous solid about `com`
  std::optional<double> C;    ///< kg m^2; default: homogeneous solid
};

/// The preset names, in a stable order.
[[nodiscard]] std::vector<std::string> body_presets();

/// Builds and validates a body. Defaults: `com` = the homogeneous centroid, except `egg-printed`
/// (com = 0, the paper's printed origin); `A` = the homogeneous solid's transverse moment about
/// `com` (parallel axes); `C` = the homogeneous solid's. Errors (std::invalid_argument) name the
/// scenario key: body.mass, body.com (inside the body), body.A, body.C (> 0, C <= 2A), ...
[[nodiscard]] Body make_body(const BodySpec& spec);

}  // namespace frictionlab::dynamics
