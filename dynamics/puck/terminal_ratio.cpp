#include "dynamics/puck/terminal_ratio.h"

#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace frictionlab::dynamics::puck {

double terminal_ratio_drift(const friction::FrictionLaw& law, double kappa, double r) {
  const friction::FrictionForces f = law.evaluate({r, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0});
  return r * f.M / kappa - f.F1;
}

TerminalRatioAnalysis analyse_terminal_ratio(const friction::FrictionLaw& law, double kappa, double r_min,
                                             double r_max, int points_per_decade) {
  if (!(kappa > 0.0 && std::isfinite(kappa))) throw std::invalid_argument("the inertia ratio kappa must be finite and > 0");
  if (!(r_min > 0.0 && r_max > r_min) || points_per_decade < 1)
    throw std::invalid_argument("the scan needs 0 < r_min < r_max and points_per_decade >= 1");
  TerminalRatioAnalysis out;
  out.kappa = kappa;
  const auto G = [&](double r) { return terminal_ratio_drift(law, kappa, r); };
  const int n = static_cast<int>(std::ceil(std::log10(r_max / r_min) * points_per_decade));
  const auto r_at = [&](int i) { return r_min * std::pow(r_max / r_min, static_cast<double>(i) / n); };
  double r0 = r_at(0), g0 = G(r0);
  out.small_slope = g0 / r0;
  for (int i = 1; i <= n; ++i) {
    const double r1 = r_at(i), g1 = G(r1);
    if (g0 == 0.0 || (g0 < 0.0) != (g1 < 0.0)) {
      double root = r0;
      if (g0 != 0.0 && g1 != 0.0) {
        std::uintmax_t iterations = 200;
        const auto bracket = boost::math::tools::toms748_solve(
            G, r0, r1, g0, g1, boost::math::tools::eps_tolerance<double>(40), iterations);
        root = 0.5 * (bracket.first + bracket.second);
      } else if (g1 == 0.0) {
        root = r1;
      }
      if (root != r0 || g0 == 0.0) (g0 > g1 ? out.attracting : out.repelling).push_back(root);
    }
    r0 = r1;
    g0 = g1;
  }
  out.large_limit = g0;
  for (const double r : out.attracting) {
    const double h = 1e-5 * r;
    const double slope = (G(r + h) - G(r - h)) / (2.0 * h);
    const double f = law.evaluate({r, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0}).F1;
    out.exponents.push_back(r * std::abs(slope) / f);
  }
  if (!out.repelling.empty()) {
    out.regime = "depends";
  } else if (out.attracting.size() == 1) {
    out.regime = "together";
  } else if (out.attracting.empty()) {
    out.regime = out.small_slope < 0.0 ? "slip-first" : "spin-first";
  } else {
    out.regime = "depends";
  }
  return out;
}

}  // namespace frictionlab::dynamics::puck
