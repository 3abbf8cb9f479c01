#include "dynamics/shapes/mass_properties.h"

#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "friction/support/errors.h"

namespace frictionlab::dynamics {

MassProperties homogeneous_mass_properties(const Profile& profile, double mass) {
  if (!(std::isfinite(mass) && mass > 0.0))
    throw support::invalid_value("body mass", mass, "it must be finite and > 0 kg");
  const Polynomial& P = profile.chi2();
  const double lo = profile.z_lo();
  const double hi = profile.z_hi();
  // The highest degree integrated is that of P^2 (2d) or z^2 P (d + 2); n nodes are exact to 2n - 1.
  const int d = P.degree();
  const std::size_t nodes = static_cast<std::size_t>(d + 3);
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> table(
      gsl_integration_glfixed_table_alloc(nodes), &gsl_integration_glfixed_table_free);

  const auto integrate = [&](auto&& f) {
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes; ++i) {
      double z = 0.0, w = 0.0;
      gsl_integration_glfixed_point(lo, hi, i, &z, &w, table.get());
      sum += w * f(z, P(z));
    }
    return sum;
  };
  const double v = integrate([](double, double p) { return p; });
  MassProperties m;
  m.mass = mass;
  m.volume = std::numbers::pi * v;
  m.centroid = integrate([](double z, double p) { return z * p; }) / v;
  const double rho = mass / m.volume;
  const double pp = integrate([](double, double p) { return p * p; });
  // Second moment about the centroid directly (no cancellation for a body far from z = 0).
  const double zc = m.centroid;
  const double p_dz2 = integrate([zc](double z, double p) { return p * (z - zc) * (z - zc); });
  m.C = rho * std::numbers::pi * 0.5 * pp;
  m.A = rho * std::numbers::pi * (0.25 * pp + p_dz2);
  return m;
}

}  // namespace frictionlab::dynamics
