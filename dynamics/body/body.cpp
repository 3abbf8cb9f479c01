#include "dynamics/body/body.h"

#include <cmath>
#include <stdexcept>
#include <string>

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

Body make_body(const BodySpec& spec) {
  Profile profile = profile_of(spec);
  require_positive("body.mass", spec.mass, "kg");
  const MassProperties homo = homogeneous_mass_properties(profile, spec.mass);

  double com = spec.preset == "egg-printed" ? 0.0 : homo.centroid;
  if (spec.com) com = *spec.com;
  if (!std::isfinite(com) || !(com > profile.z_lo() && com < profile.z_hi()))
    throw invalid_value("body.com", com,
                        "the centre of mass must lie on the axis inside the body, between the poles z = " +
                            message_number(profile.z_lo()) + " and " + message_number(profile.z_hi()) + " m");
  const double A = spec.A ? *spec.A : homo.transverse_about(com);
  const double C = spec.C ? *spec.C : homo.C;
  require_positive("body.A", A, "kg m^2");
  require_positive("body.C", C, "kg m^2");
  if (C > 2.0 * A * (1.0 + kInertiaTriangleSlack))
    throw invalid_value("body.C", C, "a body of revolution has C <= 2A (here A = " + message_number(A) + " kg m^2)");
  return Body{std::move(profile), spec.mass, com, A, C, homo};
}

}  // namespace frictionlab::dynamics
