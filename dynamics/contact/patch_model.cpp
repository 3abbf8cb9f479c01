#include "dynamics/contact/patch_model.h"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "dynamics/shapes/contact_geometry.h"
#include "dynamics/contact/hertz_ellipse.h"
#include "dynamics/contact/hertz_patch.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics {
namespace {

[[noreturn]] void required(const std::string& key, const std::string& why) {
  throw support::InvalidValue(key, key + " is required" + why);
}

}  // namespace

void apply_patch_model(const PatchModelSpec& spec, const Body& body, PlaneContact& contact) {
  const bool hertz = spec.patch == "hertz";
  if (!hertz && spec.patch != "section")
    throw support::invalid_value("contact.patch", std::string_view(spec.patch),
                                 "it is not a known contact model; known: section, hertz");
  const std::pair<const char*, const std::optional<double>*> elastic[] = {
      {"contact.E1", &spec.E1}, {"contact.nu1", &spec.nu1}, {"contact.E2", &spec.E2}, {"contact.nu2", &spec.nu2}};
  bool any_elastic = false;
  for (const auto& [key, value] : elastic) any_elastic = any_elastic || value->has_value();
  if (!hertz) {
    for (const auto& [key, value] : elastic)
      if (value->has_value()) throw support::InvalidValue(key, std::string(key) + " is only used with contact.patch = \"hertz\"");
    if (spec.lambda_gamma3)
      throw support::InvalidValue("contact.lambda_gamma3", "contact.lambda_gamma3 is only used with contact.patch = \"hertz\"");
    if (!spec.lambda) required("contact.lambda", "");
    contact.patch = PatchModel::section;
    contact.lambda = *spec.lambda;
    contact.E_star = 0.0;
    return;
  }
  contact.patch = PatchModel::hertz;
  const double g3 = spec.lambda_gamma3.value_or(1.0);
  if (!(g3 >= -1.0 && g3 <= 1.0))
    throw support::invalid_value("contact.lambda_gamma3", g3,
                                 "it is the third component of the upward vertical: it must lie in [-1, 1]");
  // Hertz's stiffness per unit modulus where the upward vertical has third component g3: today's
  // arithmetic for a body of revolution; for another shape with gamma in the shape's xi1-xi3 plane.
  std::optional<ContactGeometry> geometry;
  if (body.axisymmetric) geometry.emplace(body.axisymmetric->profile, body.axisymmetric->com);
  const auto stiffness_at = [&](double E_star) {
    if (geometry) return HertzNormalContact(E_star).stiffness(*geometry, g3);
    try {
      const shapes::SurfaceContact c = body.shape->contact({std::sqrt((1.0 - g3) * (1.0 + g3)), 0.0, g3});
      return E_star * hertz_ellipse(c.R_major, c.R_minor).stiffness_per_modulus;
    } catch (const std::domain_error& e) {
      throw support::invalid_value("contact.lambda_gamma3", g3,
                                   std::string("the shape has no point contact there (") + e.what() +
                                       "): give a tilted reference orientation");
    }
  };
  if (any_elastic) {
    if (spec.lambda)
      throw support::InvalidValue("contact.lambda",
                                  "contact.lambda and the elastic constants contact.E1, nu1, E2, nu2 both fix the "
                                  "stiffness of the Hertz patch (contact.patch = \"hertz\"); give one of them");
    for (const auto& [key, value] : elastic)
      if (!value->has_value()) required(key, " when any of contact.E1, nu1, E2, nu2 is given");
    contact.E_star = effective_modulus(*spec.E1, *spec.nu1, *spec.E2, *spec.nu2);
    contact.lambda = stiffness_at(contact.E_star);
    return;
  }
  if (!spec.lambda) required("contact.lambda", " (or the elastic constants contact.E1, nu1, E2, nu2)");
  contact.lambda = *spec.lambda;
  contact.E_star = std::isfinite(contact.lambda) && contact.lambda > 0.0
                       ? (geometry ? modulus_matching_stiffness(*geometry, contact.lambda, g3)
                                   : contact.lambda / stiffness_at(1.0))
                       : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace frictionlab::dynamics
