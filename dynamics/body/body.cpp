#include "dynamics/body/body.h"

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "dynamics/shapes/body_of_revolution.h"
#include "dynamics/shapes/shape_registry.h"
#include "dynamics/shapes/solid_mass_properties.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

using support::invalid_value;
using support::message_number;

// C <= 2A holds for every body of revolution (2A - C = 2 ∫ xi3^2 dm >= 0); equality is a flat
// disc. The slack only absorbs rounding in user-supplied values.
constexpr double kInertiaTriangleSlack = 1e-12;

void require_positive(const std::string& key, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0))
    throw invalid_value(key, value, std::string("it must be finite and > 0 ") + unit);
}

Profile profile_of(const BodySpec& s) {
  const bool has_chi2 = !s.chi2.empty();
  if (has_chi2 && !s.preset.empty())
    throw std::invalid_argument("body.profile = '" + s.preset +
                                "' and body.chi2 are both given: give a preset name or coefficients, not both");
  if (!has_chi2 && s.preset.empty())
    throw std::invalid_argument("body: give body.profile (a preset name) or body.chi2 (coefficients)");
  const auto only_for = [&](bool present, const char* key, const char* preset) {
    if (present && s.preset != preset)
      throw std::invalid_argument(std::string(key) + " is only used by the '" + preset + "' preset" +
                                  (s.preset.empty() ? std::string(" (chi2 is given)")
                                                    : " (profile is '" + s.preset + "')"));
  };
  if (!has_chi2) {
    bool known = false;
    for (const auto& p : body_presets()) known = known || p == s.preset;
    if (!known) {
      std::string list;
      for (const auto& p : body_presets()) list += (list.empty() ? "" : ", ") + p;
      throw std::invalid_argument("body.profile = '" + s.preset + "' is not a known preset; known: " + list);
    }
  }
  only_for(s.radius.has_value(), "body.radius", "sphere");
  only_for(s.semi_axes.has_value(), "body.semi_axes", "spheroid");
  if (has_chi2) return Profile(s.chi2, "body.chi2");
  if (s.preset == "sphere") {
    if (!s.radius) throw std::invalid_argument("body.radius is required for the 'sphere' preset");
    require_positive("body.radius", *s.radius, "m");
    return Profile::sphere(*s.radius);
  }
  if (s.preset == "spheroid") {
    if (!s.semi_axes)
      throw std::invalid_argument("body.semi_axes = [equatorial, polar] is required for the 'spheroid' preset");
    require_positive("body.semi_axes[0] (equatorial)", (*s.semi_axes)[0], "m");
    require_positive("body.semi_axes[1] (polar)", (*s.semi_axes)[1], "m");
    return Profile::spheroid((*s.semi_axes)[0], (*s.semi_axes)[1]);
  }
  return Profile::paper_egg();  // egg-printed, egg-homogeneous
}

}  // namespace

std::vector<std::string> body_presets() { return {"sphere", "spheroid", "egg-printed", "egg-homogeneous"}; }

bool is_axisymmetric_inertia(const Eigen::Matrix3d& J) {
  return J(0, 1) == 0.0 && J(0, 2) == 0.0 && J(1, 2) == 0.0 && J(1, 0) == 0.0 && J(2, 0) == 0.0 && J(2, 1) == 0.0 &&
         J(0, 0) == J(1, 1);
}

namespace {

void require_inside(const shapes::Shape& shape, const Eigen::Vector3d& com) {
  if (!(com.allFinite() && shape.contains(com)))
    throw invalid_value("body.com", std::span<const double>(com.data(), 3),
                        "the centre of mass must lie inside the body (shape frame, m)");
}

// A shape of a registered kind other than a body of revolution.
Body make_shaped_body(const BodySpec& spec) {
  if (!spec.preset.empty() || !spec.chi2.empty() || spec.radius || spec.semi_axes)
    throw std::invalid_argument("body.shape = '" + spec.shape +
                                "': body.profile and body.chi2 describe a body of revolution only");
  for (const auto& [given, key] : {std::pair{spec.A.has_value(), "body.A"}, std::pair{spec.C.has_value(), "body.C"}})
    if (given)
      throw std::invalid_argument(std::string(key) + " is only used by a body of revolution (body.shape = '" + spec.shape +
                                  "'): give the full tensor body.inertia");
  if (spec.com)
    throw invalid_value("body.com", *spec.com,
                        "for body.shape = '" + spec.shape + "' the centre of mass is a point [x, y, z] of the shape frame (m)");
  shapes::ShapeSpec shape_spec;
  shape_spec.kind = spec.shape;
  shape_spec.parameters = spec.shape_parameters;
  shape_spec.section = "body";
  Body b;
  b.shape = shapes::make_shape(shape_spec);
  require_positive("body.mass", spec.mass, "kg");
  b.mass = spec.mass;
  b.homogeneous = b.shape->homogeneous(spec.mass);
  b.centre_of_mass = spec.com_vector ? *spec.com_vector : b.homogeneous.centroid;
  require_inside(*b.shape, b.centre_of_mass);
  b.inertia = spec.inertia ? *spec.inertia : b.homogeneous.inertia_about(b.centre_of_mass);
  shapes::validate_inertia(b.inertia, "body.inertia");
  return b;
}

}  // namespace

Body make_body(const BodySpec& spec) {
  if (!spec.shape.empty() && spec.shape != "revolution") return make_shaped_body(spec);
  if (spec.com && spec.com_vector)
    throw std::invalid_argument("body.com: give the centre of mass once, as a number (on the axis) or as [x, y, z]");
  if (spec.inertia && (spec.A || spec.C))
    throw std::invalid_argument(std::string(spec.A ? "body.A" : "body.C") +
                                " and body.inertia both give the inertia: give A and C, or the full tensor");
  Profile profile = profile_of(spec);
  require_positive("body.mass", spec.mass, "kg");
  const MassProperties homo = homogeneous_mass_properties(profile, spec.mass);
  auto shape = std::make_shared<const shapes::BodyOfRevolution>(profile);

  Body b;
  b.mass = spec.mass;
  b.homogeneous = shape->homogeneous(spec.mass);
  const bool on_axis = !spec.com_vector || (spec.com_vector->x() == 0.0 && spec.com_vector->y() == 0.0);
  if (on_axis) {
    double com = spec.preset == "egg-printed" ? 0.0 : homo.centroid;
    if (spec.com) com = *spec.com;
    if (spec.com_vector) com = spec.com_vector->z();
    if (!std::isfinite(com) || !(com > profile.z_lo() && com < profile.z_hi()))
      throw invalid_value("body.com", com,
                          "the centre of mass must lie on the axis inside the body, between the poles z = " +
                              message_number(profile.z_lo()) + " and " + message_number(profile.z_hi()) + " m");
    b.centre_of_mass = Eigen::Vector3d(0.0, 0.0, com);
  } else {
    b.centre_of_mass = *spec.com_vector;
    require_inside(*shape, b.centre_of_mass);
  }
  if (spec.inertia) {
    b.inertia = *spec.inertia;
    shapes::validate_inertia(b.inertia, "body.inertia");
  } else if (on_axis) {
    const double com = b.centre_of_mass.z();
    const double A = spec.A ? *spec.A : homo.transverse_about(com);
    const double C = spec.C ? *spec.C : homo.C;
    require_positive("body.A", A, "kg m^2");
    require_positive("body.C", C, "kg m^2");
    if (C > 2.0 * A * (1.0 + kInertiaTriangleSlack))
      throw invalid_value("body.C", C, "a body of revolution has C <= 2A (here A = " + message_number(A) + " kg m^2)");
    b.inertia = Eigen::Vector3d(A, A, C).asDiagonal();
  } else {
    if (spec.A || spec.C)
      throw std::invalid_argument(std::string(spec.A ? "body.A" : "body.C") +
                                  " needs the centre of mass on the axis; off the axis give the full tensor body.inertia");
    b.inertia = b.homogeneous.inertia_about(b.centre_of_mass);
  }
  if (on_axis && is_axisymmetric_inertia(b.inertia)) {
    const double A = b.inertia(0, 0);
    const double C = b.inertia(2, 2);
    if (spec.inertia && C > 2.0 * A * (1.0 + kInertiaTriangleSlack))
      throw invalid_value("body.C", C, "a body of revolution has C <= 2A (here A = " + message_number(A) + " kg m^2)");
    b.axisymmetric = AxisymmetricBody{profile, b.centre_of_mass.z(), A, C, homo};
  }
  b.shape = std::move(shape);
  return b;
}

}  // namespace frictionlab::dynamics
