#include "dynamics/contact/hertz_ellipse.h"

#include <boost/math/special_functions/ellint_rd.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "friction/support/errors.h"

namespace frictionlab::dynamics {
namespace {

// The eccentricity equation is solved in x = ln mu against t = ln(B/A) (docs/contact-models.md §2):
// a starting point interpolated in a table of the solution over t in [0, kTableEnd], then one
// Newton step, which is exact to rounding from there. Beyond the table (B/A > e^16 ~ 9e6), a
// safeguarded Newton iteration.
constexpr double kTableEnd = 16.0;
constexpr int kTableSize = 1025;  // spacing 1/64: cubic Hermite error ~ h^4 |mu''''|/384 < 1e-10
// A Newton step from a starting point this close (relative) leaves an error of its square: the
// step is then the last one. From the table the step is ~1e-11 or less.
constexpr double kLastStep = 1e-8;
constexpr int kMaxIterations = 200;  // Newton in x converges in < 10 from any start tested

// Below this k^2 = 1 - mu^2 the numerator of dD/dmu comes from its series (the closed form
// cancels: its error ~1e-16/k^2 is < 1e-14 above; the series' first neglected term is
// < 0.007 k^14 < 1e-16 below).
constexpr double kSeriesBelowK2 = 1e-2;
// (D (1 + mu^2) - K) / (k^2 pi/2) = sum c_n k^(2n), from the Maclaurin series of K and E in k^2
// (DLMF 19.5.1).
constexpr std::array<double, 7> kSlopeSeries = {-3.0 / 8,           -3.0 / 32,          -45.0 / 1024,
                                                -105.0 / 4096,      -2205.0 / 131072,   -6237.0 / 524288,
                                                -297297.0 / 33554432};

struct Integrals {
  double K;
  double D;  ///< (K - E)/e^2
  double B;  ///< (E - mu^2 K)/e^2 = K - D
};

// K(e), D(e) and B(e) in Carlson's forms with the complementary modulus mu = sqrt(1 - e^2)
// (DLMF 19.25.1): K - E = (e^2/3) R_D(0, mu^2, 1) and E - mu^2 K = (e^2 mu^2/3) R_D(0, 1, mu^2), so
// D = R_D(0, mu^2, 1)/3, B = mu^2 R_D(0, 1, mu^2)/3 and K = B + D. Each is a sum of positive terms:
// exact to rounding for mu near 1 and near 0 alike (no e = sqrt(1 - mu^2) is formed).
Integrals integrals(double mu) {
  const double m2 = mu * mu;
  const double D = boost::math::ellint_rd(0.0, m2, 1.0) / 3.0;
  const double B = m2 * boost::math::ellint_rd(0.0, 1.0, m2) / 3.0;
  return {B + D, D, B};
}

// d/dmu of K, D and B. With dK/de = (E - mu^2 K)/(e mu^2), dE/de = (E - K)/e (DLMF 19.4.1) and
// de/dmu = -mu/e:  K' = -B/mu,  D' = (D mu^2 - B)/(mu e^2),  B' = K' - D'.
struct Slopes {
  double dK;
  double dD;
  double dB;
};

Slopes slopes(double mu, const Integrals& I) {
  const double k2 = (1.0 - mu) * (1.0 + mu);
  double n_over_k2 = 0.0;  // (D mu^2 - B)/k^2 = (D (1 + mu^2) - K)/k^2
  if (k2 < kSeriesBelowK2) {
    for (auto c = kSlopeSeries.rbegin(); c != kSlopeSeries.rend(); ++c) n_over_k2 = n_over_k2 * k2 + *c;
    n_over_k2 *= std::numbers::pi / 2.0;
  } else {
    n_over_k2 = (I.D * mu * mu - I.B) / k2;
  }
  const double dK = -I.B / mu, dD = n_over_k2 / mu;
  return {dK, dD, dK - dD};
}

// The curvature ratio B/A = (K - D)/(mu^2 D) that the ellipse mu needs (B here is Legendre's B
// above, not the curvature): R_D(0, 1, mu^2)/R_D(0, mu^2, 1).
double ratio_of(double mu, const Integrals& I) { return I.B / (mu * mu * I.D); }

// d ln(B/A) / d ln mu: -3/2 at the circle, -> -2 as mu -> 0; never 0.
double log_slope(double mu, const Integrals& I, const Slopes& S) { return mu * (S.dB / I.B - S.dD / I.D) - 2.0; }

// The solution of ratio(mu) = rho (= e^t), with K, D and their slopes there.
struct Root {
  double mu;
  Integrals I;
  Slopes S;
  double log_slope;
};

// One Newton step in ln mu from mu0 within kLastStep of the root: ln(r/rho) = r/rho - 1 and
// e^dx - 1 = dx, and K, D move along their slopes, each to a relative error below 1e-16.
Root last_step(double mu0, double rho) {
  const Integrals I0 = integrals(mu0);
  const Slopes S = slopes(mu0, I0);
  const double L = log_slope(mu0, I0, S);
  const double dmu = -mu0 * (ratio_of(mu0, I0) / rho - 1.0) / L;
  return {mu0 + dmu, {I0.K + S.dK * dmu, I0.D + S.dD * dmu, I0.B + S.dB * dmu}, S, L};
}

// Safeguarded Newton in x = ln mu on [-t, 0] (the ratio exceeds 1/mu, so the root lies above
// 1/rho), from x, until a step below kLastStep; then last_step.
Root solve_by_newton(double rho, double t, double x) {
  double lo = -t, hi = 0.0;
  for (int it = 0; it < kMaxIterations; ++it) {
    const double mu = std::exp(x);
    const Integrals I = integrals(mu);
    const double F = std::log(ratio_of(mu, I)) - t;
    if (F > 0.0) lo = x; else hi = x;  // the ratio falls as mu grows
    double next = x - F / log_slope(mu, I, slopes(mu, I));
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = std::abs(next - x);
    x = next;
    if (step < kLastStep) break;
  }
  return last_step(std::exp(x), rho);
}

// mu and dmu/dt at t_i = i h, interleaved: the starting points (cubic Hermite).
const std::vector<double>& guess_table() {
  static const std::vector<double> table = [] {
    std::vector<double> g(2 * kTableSize);
    const double h = kTableEnd / (kTableSize - 1);
    g[0] = 1.0;
    g[1] = -2.0 / 3.0;  // dmu/dt = mu / (d ln ratio/d ln mu) = 1/(-3/2) at the circle
    double x = 0.0;
    for (int i = 1; i < kTableSize; ++i) {
      const double t = i * h;
      const Root r = solve_by_newton(std::exp(t), t, x - 0.7 * h);  // from the previous node
      x = std::log(r.mu);
      g[2 * static_cast<std::size_t>(i)] = r.mu;
      g[2 * static_cast<std::size_t>(i) + 1] = r.mu / r.log_slope;
    }
    return g;
  }();
  return table;
}

// Equal radii: the circle, mu = 1 exactly.
Root circle() {
  const Integrals I = integrals(1.0);
  const Slopes S = slopes(1.0, I);
  return {1.0, I, S, log_slope(1.0, I, S)};
}

Root solve(double rho) {
  const double t = std::log(rho);
  if (t < kTableEnd) {
    constexpr double h = kTableEnd / (kTableSize - 1);
    const double u = t / h;
    const int i = std::min(static_cast<int>(u), kTableSize - 2);
    const double s = u - i, s2 = s * s, s3 = s2 * s;
    const double* g = guess_table().data() + 2 * static_cast<std::size_t>(i);  // mu0, mu0', mu1, mu1'
    const double mu0 = (2 * s3 - 3 * s2 + 1) * g[0] + (s3 - 2 * s2 + s) * h * g[1] + (-2 * s3 + 3 * s2) * g[2] +
                       (s3 - s2) * h * g[3];
    const Root r = last_step(mu0, rho);
    if (std::abs(r.mu - mu0) < kLastStep * mu0) return r;  // always, for the table's accuracy
    return solve_by_newton(rho, t, std::log(mu0));
  }
  return solve_by_newton(rho, t, -0.5 * t);  // mu ~ sqrt(ln(4/mu)/rho) for large rho
}

}  // namespace

double hertz_curvature_ratio(double mu) {
  if (!(mu > 0.0 && mu <= 1.0)) throw std::invalid_argument("hertz_curvature_ratio: mu must lie in (0, 1]");
  return ratio_of(mu, integrals(mu));
}

HertzEllipse hertz_ellipse(double R1, double R2) {
  if (!(std::isfinite(R1) && R1 > 0.0 && std::isfinite(R2) && R2 > 0.0))
    throw std::invalid_argument("hertz_ellipse: the principal radii must be finite and > 0 m");
  const double R_major = std::max(R1, R2);
  const double rho = R_major / std::min(R1, R2);  // B/A >= 1
  const Root r = rho - 1.0 > kHertzCircleRelTol ? solve(rho) : circle();
  HertzEllipse h;
  h.mu = r.mu;
  h.K = r.I.K;
  h.D = r.I.D;
  h.a2_per_depth = 2.0 * R_major * r.I.D / r.I.K;
  h.stiffness_per_modulus = 2.0 * std::numbers::pi / 3.0 * std::sqrt(h.a2_per_depth) / r.I.K;
  // ln S = const + ln(R_major)/2 + ln(D)/2 - 3 ln(K)/2 with mu = mu(ln rho), ln rho = ln R_major - ln R_minor.
  const double dlnS_dmu = 0.5 * r.S.dD / r.I.D - 1.5 * r.S.dK / r.I.K;
  const double minor = -dlnS_dmu * r.mu / r.log_slope;
  const double major = 0.5 - minor;
  h.dlnS_dlnR1 = R1 >= R2 ? major : minor;
  h.dlnS_dlnR2 = R1 >= R2 ? minor : major;
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
