#include "dynamics/body/scenario_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "dynamics/shapes/solid_mass_properties.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

using Limits = ScenarioLimits;

std::string range_rule(double lo, double hi, const std::string& unit) {
  return "it must be within [" + support::message_number(lo) + ", " + support::message_number(hi) + "]" +
         (unit.empty() ? "" : " " + unit);
}

bool within(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

// The key under which the body's size was given, and its value as written.
support::InvalidValue invalid_size(const BodySpec& spec, const std::string& rule) {
  if (spec.preset == "sphere" && spec.radius) return support::invalid_value("body.radius", *spec.radius, rule);
  if (spec.preset == "spheroid" && spec.semi_axes)
    return support::invalid_value("body.semi_axes", std::span<const double>(*spec.semi_axes), rule);
  if (!spec.chi2.empty()) return support::invalid_value("body.chi2", std::span<const double>(spec.chi2), rule);
  return support::invalid_value("body.profile", std::string_view(spec.preset), rule);
}

}  // namespace

double BodyExtent::smallest() const { return std::min(length, 2.0 * rho_max); }

namespace {

// The smallest width of a convex shape, min over directions n of h(n) + h(-n) (h the support
// function: h(-gamma) = -r(gamma).gamma), over a Fibonacci set of directions and the shape's axes
// turned by a small angle (a flat face, where contact() has no point, lies across an axis).
// An upper bound that is close enough for the limits (a few per cent).
double smallest_width(const shapes::Shape& shape) {
  constexpr int kDirections = 2000;
  constexpr double kAxisTilt = 1e-4;
  double best = std::numeric_limits<double>::infinity();
  const auto width = [&](const Eigen::Vector3d& n) {
    try {
      const Eigen::Vector3d u = n.normalized();
      best = std::min(best, -shape.contact(u).r.dot(u) - shape.contact(-u).r.dot(-u));
    } catch (const std::domain_error&) {
      // no point contact in this direction (a flat face): the tilted axes cover it
    }
  };
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d n = Eigen::Vector3d::Unit(i);
    n[(i + 1) % 3] = kAxisTilt;
    width(n);
  }
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kDirections; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / kDirections;
    const double rho = std::sqrt((1.0 - z) * (1.0 + z));
    width(Eigen::Vector3d(rho * std::cos(golden * i), rho * std::sin(golden * i), z));
  }
  return best;
}

}  // namespace

BodyExtent extent_of(const Body& body) {
  if (!body.axisymmetric) {
    const double width = smallest_width(*body.shape);
    return BodyExtent{width, body.shape->size(), body.shape->radius_about(body.centre_of_mass)};
  }
  // r^2 = (z - com)^2 + P(z) is smooth on [z_lo, z_hi]; 1024 intervals resolve its maximum far
  // below the precision the limits need.
  constexpr int kSamples = 1024;
  const AxisymmetricBody& a = *body.axisymmetric;
  BodyExtent e{a.profile.length(), a.profile.max_radius(), 0.0};
  for (int i = 0; i <= kSamples; ++i) {
    const double z = a.profile.z_lo() + a.profile.length() * i / kSamples;
    const double r2 = (z - a.com) * (z - a.com) + std::max(0.0, a.profile.chi2()(z));
    e.r_max = std::max(e.r_max, std::sqrt(r2));
  }
  return e;
}

void check_body_spec(const BodySpec& spec) {
  if (!within(spec.mass, Limits::kMinMass, Limits::kMaxMass))
    throw support::invalid_value("body.mass", spec.mass, range_rule(Limits::kMinMass, Limits::kMaxMass, "kg"));
  const std::string size_rule = "the body's size must be within [" + support::message_number(Limits::kMinSize) + ", " +
                                support::message_number(Limits::kMaxSize) + "] m";
  if (spec.preset == "sphere" && spec.radius && !within(2.0 * *spec.radius, Limits::kMinSize, Limits::kMaxSize))
    throw invalid_size(spec, size_rule + " (here its diameter is " + support::message_number(2.0 * *spec.radius) + " m)");
  if (spec.preset == "spheroid" && spec.semi_axes)
    for (const double axis : *spec.semi_axes)
      if (!within(2.0 * axis, Limits::kMinSize, Limits::kMaxSize))
        throw invalid_size(spec, size_rule + " (here an axis is " + support::message_number(2.0 * axis) + " m)");
}

void check_body(const BodySpec& spec, const Body& body, const BodyExtent& e) {
  if (!body.axisymmetric) {
    if (!within(e.length, Limits::kMinSize, Limits::kMaxSize) || !within(2.0 * e.rho_max, Limits::kMinSize, Limits::kMaxSize))
      throw support::invalid_value(
          spec.shape.empty() ? "body.profile" : "body.shape", std::string_view(spec.shape.empty() ? spec.preset : spec.shape),
          "the body's smallest width (" + support::message_number(e.length) + " m) and its largest diameter (" +
              support::message_number(2.0 * e.rho_max) + " m) must be within [" +
              support::message_number(Limits::kMinSize) + ", " + support::message_number(Limits::kMaxSize) + "] m");
    const double top = body.mass * e.r_max * e.r_max;
    const Eigen::Vector3d moments = shapes::principal_inertia(body.inertia).moments;
    for (const double I : moments)
      if (!within(I, Limits::kMinInertiaFraction * top, top))
        throw support::invalid_value("body.inertia", I,
                                     "each principal moment must be within [" +
                                         support::message_number(Limits::kMinInertiaFraction * top) + ", " +
                                         support::message_number(top) +
                                         "] kg m^2 (up to m r_max^2: the mass lies inside the body, r_max = " +
                                         support::message_number(e.r_max) + " m)");
    return;
  }
  for (const double size : {e.length, 2.0 * e.rho_max})
    if (!within(size, Limits::kMinSize, Limits::kMaxSize))
      throw invalid_size(spec, "the body's length along its axis (" + support::message_number(e.length) +
                                   " m) and its largest diameter (" + support::message_number(2.0 * e.rho_max) +
                                   " m) must be within [" + support::message_number(Limits::kMinSize) + ", " +
                                   support::message_number(Limits::kMaxSize) + "] m");
  const auto check_inertia = [&](const char* key, double value, double r, const char* r_name) {
    const double top = body.mass * r * r;
    if (!within(value, Limits::kMinInertiaFraction * top, top))
      throw support::invalid_value(key, value,
                                   range_rule(Limits::kMinInertiaFraction * top, top, "kg m^2") + " (up to m " + r_name +
                                       "^2: the mass lies inside the body, " + r_name + " = " +
                                       support::message_number(r) + " m)");
  };
  check_inertia("body.A", body.axisymmetric->A, e.r_max, "r_max");
  check_inertia("body.C", body.axisymmetric->C, e.rho_max, "rho_max");
}

void check_contact(const PlaneContact& c, const Body& body, const BodyExtent& e) {
  if (!within(c.k, 0.0, Limits::kMaxFriction))
    throw support::invalid_value("contact.k", c.k, range_rule(0.0, Limits::kMaxFriction, ""));
  if (!within(c.lambda, Limits::kMinStiffness, Limits::kMaxStiffness))
    throw support::invalid_value("contact.lambda", c.lambda,
                                 range_rule(Limits::kMinStiffness, Limits::kMaxStiffness, "N/m^1.5"));
  if (!within(c.g, 0.0, Limits::kMaxGravity))
    throw support::invalid_value("contact.g", c.g, range_rule(0.0, Limits::kMaxGravity, "m/s^2"));
  const double compression = -c.static_height(body.mass * c.g);
  const double deepest = Limits::kMaxCompressionFraction * e.smallest();
  if (compression > deepest)
    throw support::invalid_value(
        "contact.lambda", c.lambda,
        "the static compression (m g / lambda)^(2/3) = " + support::message_number(compression) + " m is more than " +
            support::message_number(Limits::kMaxCompressionFraction) + " of the body's smallest size (" +
            support::message_number(e.smallest()) + " m): too soft for the weight, Hertz's law needs small compressions");
}

void check_initial(const Eigen::Vector3d& v, const Eigen::Vector3d& omega, double eps, const BodyExtent& e) {
  if (!(std::isfinite(v.norm()) && v.norm() <= Limits::kMaxSpeed))
    throw support::invalid_value("initial.v", std::span<const double>(v.data(), 3),
                                 "its length must be at most " + support::message_number(Limits::kMaxSpeed) + " m/s");
  const double surface_speed = omega.norm() * e.r_max;
  if (!(std::isfinite(surface_speed) && surface_speed <= Limits::kMaxSpeed))
    throw support::invalid_value("initial.omega", std::span<const double>(omega.data(), 3),
                                 "the surface would move at up to |omega| r_max = " +
                                     support::message_number(surface_speed) + " m/s about the centre of mass (r_max = " +
                                     support::message_number(e.r_max) + " m); it must be at most " +
                                     support::message_number(Limits::kMaxSpeed) + " m/s");
  const double deepest = Limits::kMaxCompressionFraction * e.smallest();
  if (!within(eps, -deepest, Limits::kMaxHeight))
    throw support::invalid_value("initial.eps", eps,
                                 range_rule(-deepest, Limits::kMaxHeight, "m") + " (a penetration of at most " +
                                     support::message_number(Limits::kMaxCompressionFraction) +
                                     " of the body's smallest size; a start at most " +
                                     support::message_number(Limits::kMaxHeight) + " m above the plane)");
}

}  // namespace frictionlab::dynamics
