#include "dynamics/shapes/profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

// A root is simple when |P'| L / max P exceeds this (dimensionless; O(1) for a smooth pole, 0 for
// a double root). Below it the pole is conical or cusped to working precision.
constexpr double kSimpleRootTolerance = 1e-6;
// Samples (Chebyshev-Lobatto) for the positivity and convexity checks. G is a polynomial whose
// sign changes are also located exactly by its roots; the samples catch near-double roots.
constexpr int kCheckSamples = 2048;
// Imaginary part (relative) below which a root of G counts as real (a touching zero of G).
constexpr double kConvexityRootImagTolerance = 1e-6;
// Real roots closer than this (relative to the largest |root|) are one multiple root: rounding
// splits a double root by ~sqrt(machine epsilon) ~ 1e-8.
constexpr double kRootClusterTolerance = 1e-6;

using support::message_number;

// The coefficients as given and the rule they break, keyed by `what` (body.chi2, ...).
[[noreturn]] void fail(const std::string& what, const std::vector<double>& c, const std::string& rule) {
  throw support::InvalidValue(what, what + " = " + support::message_list(c) + " is not a valid body profile: " + rule);
}

double chebyshev_node(double lo, double hi, int i, int n) {
  const double c = std::cos(std::numbers::pi * static_cast<double>(i) / static_cast<double>(n));
  return 0.5 * (lo + hi) - 0.5 * (hi - lo) * c;
}

}  // namespace

Profile::Profile(std::vector<double> chi2_ascending, std::string what) {
  const std::vector<double> given = chi2_ascending;
  for (double c : given)
    if (!std::isfinite(c)) fail(what, given, "every coefficient must be a finite number");
  p_ = Polynomial(std::move(chi2_ascending));
  if (p_.degree() < 2)
    fail(what, given, "chi^2 must be a polynomial of degree >= 2 to be positive between two roots");

  // Real roots, with near-coincident ones merged into one multiple root (value, multiplicity).
  const std::vector<double> raw = real_roots(p_);
  double root_scale = 0.0;
  for (double r : raw) root_scale = std::max(root_scale, std::abs(r));
  std::vector<std::pair<double, int>> roots;
  for (double r : raw) {
    if (!roots.empty() && r - roots.back().first <= kRootClusterTolerance * root_scale) {
      ++roots.back().second;
    } else {
      roots.emplace_back(r, 1);
    }
  }
  // Candidate bodies: consecutive real roots with P > 0 between them.
  std::vector<std::pair<double, double>> spans;
  std::vector<int> span_multiplicity;
  for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
    if (p_(0.5 * (roots[i].first + roots[i + 1].first)) > 0.0) {
      spans.emplace_back(roots[i].first, roots[i + 1].first);
      span_multiplicity.push_back(std::max(roots[i].second, roots[i + 1].second));
    }
  }
  if (spans.empty())
    fail(what, given, "chi^2 must be positive on a bounded interval between two real roots (it is not)");
  if (spans.size() > 1) {
    std::string s;
    for (const auto& [lo, hi] : spans) {
      if (!s.empty()) s += ", ";
      s.append("(").append(message_number(lo)).append(", ").append(message_number(hi)).append(")");
    }
    fail(what, given, "chi^2 is positive on several bounded intervals " + s + "; the body must be one");
  }
  z_lo_ = spans.front().first;
  z_hi_ = spans.front().second;
  if (span_multiplicity.front() > 1)
    fail(what, given, "a pole (" + message_number(z_lo_) + " or " + message_number(z_hi_) +
                          " m) is a multiple root of chi^2 (a cone or cusp); the poles must be simple roots");
  const double L = z_hi_ - z_lo_;

  double pmax = 0.0;
  for (int i = 1; i < kCheckSamples; ++i) {
    const double z = chebyshev_node(z_lo_, z_hi_, i, kCheckSamples);
    const double pz = p_(z);
    if (!(pz > 0.0))
      fail(what, given, "chi^2 must be positive between its roots " + message_number(z_lo_) + " and " +
                            message_number(z_hi_) + " m; it is " + message_number(pz) + " at z = " + message_number(z));
    pmax = std::max(pmax, pz);
  }
  max_radius_ = std::sqrt(pmax);

  const Polynomial dp = p_.derivative();
  for (double z : {z_lo_, z_hi_}) {
    if (std::abs(dp(z)) * L / pmax < kSimpleRootTolerance)
      fail(what, given, "the pole at z = " + message_number(z) + " m is a multiple root of chi^2 (a cone or cusp); "
                        "the poles must be simple roots");
  }

  // Strict convexity: G = 2 P P'' - P'^2 < 0 on [z_lo, z_hi].
  const Polynomial G = 2.0 * (p_ * dp.derivative()) + (-1.0) * (dp * dp);
  for (int i = 0; i <= kCheckSamples; ++i) {
    const double z = chebyshev_node(z_lo_, z_hi_, i, kCheckSamples);
    if (!(G(z) < 0.0))
      fail(what, given, "the body is not strictly convex: 2 P P'' - P'^2 = " + message_number(G(z)) +
                            " >= 0 at z = " + message_number(z) + " m (a convex body of revolution needs chi'' < 0)");
  }
  if (G.degree() >= 1) {
    for (double z : real_roots(G, kConvexityRootImagTolerance)) {
      if (z > z_lo_ && z < z_hi_)
        fail(what, given, "the body is not strictly convex: chi'' vanishes at z = " + message_number(z) +
                              " m (a convex body of revolution needs chi'' < 0)");
    }
  }
}

Profile Profile::sphere(double radius) {
  if (!(std::isfinite(radius) && radius > 0.0))
    throw support::invalid_value("sphere radius", radius, "it must be finite and > 0 m");
  return Profile({radius * radius, 0.0, -1.0}, "sphere profile");
}

Profile Profile::spheroid(double equatorial, double polar) {
  if (!(std::isfinite(equatorial) && equatorial > 0.0))
    throw support::invalid_value("spheroid equatorial semi-axis", equatorial, "it must be finite and > 0 m");
  if (!(std::isfinite(polar) && polar > 0.0))
    throw support::invalid_value("spheroid polar semi-axis", polar, "it must be finite and > 0 m");
  const double e2 = equatorial * equatorial;
  return Profile({e2, 0.0, -e2 / (polar * polar)}, "spheroid profile");
}

Profile Profile::paper_egg() {
  // 2 (z + 0.1)(z - 1.2)(z - 0.252), expanded.
  const Polynomial p = 2.0 * (Polynomial({0.1, 1.0}) * Polynomial({-1.2, 1.0}) * Polynomial({-0.252, 1.0}));
  return Profile(p.coefficients(), "egg profile");
}

}  // namespace frictionlab::dynamics
