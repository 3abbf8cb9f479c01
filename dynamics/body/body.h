#pragma once
// The rigid body: a convex shape (dynamics/shapes/shape.h, shared and immutable), its mass, its
// centre of mass anywhere (a point in the shape frame) and its full central inertia tensor J
// (docs/model.md §5, docs/convex-bodies.md §9). The body frame of the equations of motion is the
// shape frame translated to the centre of mass (the same axes): J is a symmetric 3x3 tensor in those
// axes, J_ij = -∫ xi_i xi_j dm for i != j (dynamics/shapes/solid_mass_properties.h), whose principal
// axes may be turned against the shape's (a rattleback's are).
//
// Mass properties default to the homogeneous solid (Shape::homogeneous); each can be overridden,
// which the paper's egg needs (docs/model.md §6: its printed centre of mass is not the centroid of
// the homogeneous solid).
//
// Today's bodies of revolution (a profile chi^2, the centre of mass on the axis, J = diag(A, A, C))
// also keep their own description, `axisymmetric`: the equations of motion then run the arithmetic
// they always ran (bit for bit), and the outputs that name A, C and the profile read it.

#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/shapes/mass_properties.h"
#include "dynamics/shapes/profile.h"
#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics {

/// A body of revolution with its centre of mass on the axis and J = diag(A, A, C).
struct AxisymmetricBody {
  Profile profile;
  double com = 0.0;  ///< profile coordinate z of the centre of mass (xi3 = z - com), m
  double A = 0.0;    ///< transverse central moment of inertia, kg m^2, > 0
  double C = 0.0;    ///< axial moment of inertia, kg m^2, 0 < C <= 2A
  MassProperties homogeneous;  ///< of the homogeneous solid, for reference
};

struct Body {
  std::shared_ptr<const shapes::Shape> shape;  ///< never null
  double mass = 0.0;                           ///< kg, > 0
  /// The centre of mass in the shape frame, m (strictly inside the body).
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();
  /// The central inertia tensor J in the body axes (= the shape axes), kg m^2: symmetric, positive
  /// definite, principal moments obeying the triangle inequalities.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
  shapes::SolidMassProperties homogeneous;  ///< of the homogeneous solid (shape frame), for reference
  /// Set iff the shape is a body of revolution, the centre of mass lies on its axis and J is
  /// diag(A, A, C) exactly: today's description (the equations' fast path).
  std::optional<AxisymmetricBody> axisymmetric;
};

/// What a scenario's [body] section says (docs/dynamics.md §7, docs/convex-bodies.md §10).
/// Without `shape` (or with shape = "revolution"): a body of revolution from exactly one of
/// `preset` or `chi2`. With another shape kind: the kind's parameters (shapes/shape_registry.h).
struct BodySpec {
  /// A registered shape kind other than "revolution" (shapes::shape_kinds()), or empty: a body of
  /// revolution described by today's keys (profile, chi2, radius, semi_axes).
  std::string shape;
  /// The kind's parameters (name -> values) when `shape` is set.
  std::map<std::string, std::vector<double>> shape_parameters;
  /// "sphere" (needs radius), "spheroid" (needs semi_axes), "egg-printed", "egg-homogeneous";
  /// empty when `chi2` is given.
  std::string preset;
  std::vector<double> chi2;  ///< ascending coefficients of chi^2 in the profile coordinate, m
  std::optional<double> radius;                    ///< sphere radius, m
  std::optional<std::array<double, 2>> semi_axes;  ///< spheroid {equatorial, polar}, m
  double mass = 0.0;                               ///< kg
  /// Centre of mass on the axis of a body of revolution (profile coordinate, m); default: see make_body.
  std::optional<double> com;
  /// Centre of mass as a point of the shape frame (m); any shape. Not with `com`.
  std::optional<Eigen::Vector3d> com_vector;
  std::optional<double> A;    ///< kg m^2 (revolution only); default: homogeneous solid about `com`
  std::optional<double> C;    ///< kg m^2 (revolution only); default: homogeneous solid
  /// body.inertia: the full central tensor (kg m^2, shape axes, J_ij = -∫ xi_i xi_j dm); not with A, C.
  std::optional<Eigen::Matrix3d> inertia;
};

/// The preset names, in a stable order.
[[nodiscard]] std::vector<std::string> body_presets();

/// Builds and validates a body. Defaults: the centre of mass = the homogeneous centroid, except
/// `egg-printed` (com = 0, the paper's printed origin); the inertia = the homogeneous solid's about
/// the centre of mass (parallel axes). Errors (std::invalid_argument) name the scenario key:
/// body.mass, body.com (inside the body), body.A, body.C (> 0, C <= 2A), body.inertia (symmetric,
/// positive definite, triangle inequalities), body.shape and the shape's parameters, ...
[[nodiscard]] Body make_body(const BodySpec& spec);

/// J = diag(A, A, C) exactly, the centre of mass on the axis: the body as today's axisymmetric one.
[[nodiscard]] bool is_axisymmetric_inertia(const Eigen::Matrix3d& J);

}  // namespace frictionlab::dynamics
