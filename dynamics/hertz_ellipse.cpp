#include "dynamics/hertz_ellipse.h"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_d.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "friction/support/errors.h"

namespace frictionlab::dynamics {
namespace {

// toms748 stops when the bracket is this many bits wide: 2 ulps of mu.
constexpr int kSolverBits = 51;
// The bracket closes in ~10 iterations for every ratio tested (1 + 1e-12 ... 1e12); a limit far
// above that only guards against a non-terminating loop.
constexpr std::uintmax_t kMaxSolverIterations = 200;

struct Integrals {
  double K;
  double D;
};

// K(e) and D(e) with e^2 = 1 - mu^2 formed as (1 - mu)(1 + mu): exact to rounding for mu -> 1.
Integrals integrals(double mu) {
  const double e = std::sqrt((1.0 - mu) * (1.0 + mu));
  return {boost::math::ellint_1(e), boost::math::ellint_d(e)};
}

double ratio_of(double mu, const Integrals& I) { return (I.K - I.D) / (mu * mu * I.D); }

}  // namespace

double hertz_curvature_ratio(double mu) {
  if (!(mu > 0.0 && mu <= 1.0)) throw std::invalid_argument("hertz_curvature_ratio: mu must lie in (0, 1]");
  return ratio_of(mu, integrals(mu));
}

HertzEllipse hertz_ellipse(double R_major, double R_minor) {
  if (!(std::isfinite(R_major) && R_major > 0.0 && std::isfinite(R_minor) && R_minor > 0.0))
    throw std::invalid_argument("hertz_ellipse: the principal radii must be finite and > 0 m");
  if (R_major < R_minor) std::swap(R_major, R_minor);
  const double rho = R_major / R_minor;  // B/A >= 1
  double mu = 1.0;
  if (rho - 1.0 > kHertzCircleRelTol) {
    // f(mu) = ratio(mu) - rho falls from > 0 at mu = 1/rho (the ratio exceeds 1/mu everywhere:
    // it grows like mu^(-3/2) near 1 and like ln(4/mu)/mu^2 near 0) to 1 - rho < 0 at mu = 1.
    const auto f = [rho](double m) { return ratio_of(m, integrals(m)) - rho; };
    double lo = 1.0 / rho;
    double f_lo = f(lo);
    while (f_lo <= 0.0 && lo > 1e-300) {  // never taken for the reason above; kept for safety
      lo *= 0.5;
      f_lo = f(lo);
    }
    std::uintmax_t iterations = kMaxSolverIterations;
    const auto [left, right] = boost::math::tools::toms748_solve(
        f, lo, 1.0, f_lo, 1.0 - rho, boost::math::tools::eps_tolerance<double>(kSolverBits), iterations);
    mu = 0.5 * (left + right);
  }
  const Integrals I = integrals(mu);
  HertzEllipse h;
  h.mu = mu;
  h.K = I.K;
  h.D = I.D;
  h.a2_per_depth = 2.0 * R_major * I.D / I.K;
  h.stiffness_per_modulus = 2.0 * std::numbers::pi / 3.0 * std::sqrt(h.a2_per_depth) / I.K;
  return h;
}

double effective_modulus(double E1, double nu1, double E2, double nu2) {
  const auto modulus = [](const char* key, double E) {
    if (!(E > 0.0))  // also NaN
      throw support::invalid_value(key, E, "Young's modulus must be > 0 Pa (inf: rigid)");
  };
  const auto poisson = [](const char* key, double nu) {
    if (!(nu > -1.0 && nu <= 0.5)) throw support::invalid_value(key, nu, "Poisson's ratio must lie in (-1, 0.5]");
  };
  modulus("contact.E1", E1);
  poisson("contact.nu1", nu1);
  modulus("contact.E2", E2);
  poisson("contact.nu2", nu2);
  const double compliance = (1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2;
  // Both rigid (and nu = ±1 excluded above): no finite stiffness.
  if (!(compliance > 0.0))
    throw support::invalid_value("contact.E1", E1, "the plane and the body cannot both be rigid (E1 = E2 = inf)");
  return 1.0 / compliance;
}

}  // namespace frictionlab::dynamics
