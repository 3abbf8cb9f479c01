#include "dynamics/shapes/contact_geometry.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace frictionlab::dynamics {
namespace {

// Starting points for Newton: z(gamma3) is analytic on [-1, 1] (g' != 0 up to the poles), so
// cubic Hermite interpolation in this table (values and slopes dz/dgamma3 = s^3/(2G)) is accurate
// to ~h^4 |z^(4)|/384 ~ 1e-13 L, and one Newton step reaches rounding.
constexpr int kGuessTableSize = 1025;
// Building the table: Newton from the middle, stopped when its step is below this fraction of
// the body length (the result is then exact to rounding).
constexpr double kTableStepTolerance = 1e-14;
// At run time: a Newton step below this fraction of the length is the last one. Newton's error
// after a step of size e is ~ (g''/2g') e^2 ~ e^2/L, i.e. <= 1e-20 L here: exact to rounding.
constexpr double kAcceptStepTolerance = 1e-10;
constexpr int kMaxNewtonIterations = 100;

}  // namespace

ContactGeometry::ContactGeometry(const Profile& profile, double com)
    : profile_(profile), third_derivative_(profile.chi2().derivative().derivative().derivative()), com_(com) {
  guess_.resize(2 * kGuessTableSize);
  const double mid = 0.5 * (profile_.z_lo() + profile_.z_hi());
  for (int i = 0; i < kGuessTableSize; ++i) {
    const double g3 = -1.0 + 2.0 * i / (kGuessTableSize - 1);
    const double z = solve(g3, mid, kTableStepTolerance);
    const PolynomialJet j = profile_.chi2().jet(z);
    const double s2 = 4.0 * j.value + j.d1 * j.d1;
    // dz/dgamma3 = 1/g'(z) = s^3 / (2 G): finite up to the poles (G = -P'^2 there).
    guess_[2 * static_cast<std::size_t>(i)] = z;
    guess_[2 * static_cast<std::size_t>(i) + 1] = s2 * std::sqrt(s2) / (2.0 * (2.0 * j.value * j.d2 - j.d1 * j.d1));
  }
}

double ContactGeometry::solve_contact_z(double gamma3) const {
  constexpr double h = 2.0 / (kGuessTableSize - 1);
  const double x = (std::clamp(gamma3, -1.0, 1.0) + 1.0) / h;
  const int i = std::clamp(static_cast<int>(x), 0, kGuessTableSize - 2);
  const double t = x - i;
  const double* g = guess_.data() + 2 * static_cast<std::size_t>(i);  // z0, dz0, z1, dz1
  // Cubic Hermite basis.
  const double t2 = t * t, t3 = t2 * t;
  const double z0 = (2 * t3 - 3 * t2 + 1) * g[0] + (t3 - 2 * t2 + t) * h * g[1] + (-2 * t3 + 3 * t2) * g[2] +
                    (t3 - t2) * h * g[3];
  return solve(gamma3, z0, kAcceptStepTolerance);
}

double ContactGeometry::solve(double gamma3, double z, double step_tolerance) const {
  const double lo0 = profile_.z_lo();
  const double hi0 = profile_.z_hi();
  // The poles, exactly (the pole z is a root of P: g = ±1 there).
  if (gamma3 >= 1.0) return lo0;
  if (gamma3 <= -1.0) return hi0;
  const Polynomial& P = profile_.chi2();
  double lo = lo0, hi = hi0;
  z = std::clamp(z, lo0, hi0);  // a starting point outside (interpolation overshoot) goes to the pole
  const double tol = step_tolerance * (hi0 - lo0);
  const double width_tol = 4.0 * std::numeric_limits<double>::epsilon() * std::max({std::abs(lo0), std::abs(hi0)});
  // Safeguarded Newton (rtsafe): f = g - gamma3 decreases in z; keep a bracket, bisect on escape.
  // Only a small Newton step ends the loop (its error is then ~step^2/L); bisection runs until the
  // bracket is down to rounding.
  for (int it = 0; it < kMaxNewtonIterations; ++it) {
    const PolynomialJet j = P.jet(z);
    const double s2 = 4.0 * j.value + j.d1 * j.d1;
    const double s = std::sqrt(s2);
    const double f = j.d1 / s - gamma3;
    if (f == 0.0) return z;
    if (f > 0.0) lo = z; else hi = z;
    const double fp = 2.0 * (2.0 * j.value * j.d2 - j.d1 * j.d1) / (s2 * s);
    double next = z - f / fp;
    const bool newton = next > lo && next < hi;
    if (!newton) next = 0.5 * (lo + hi);
    const double step = std::abs(next - z);
    z = next;
    if (newton ? step <= tol : hi - lo <= width_tol) break;
  }
  return z;
}

ContactPoint ContactGeometry::contact_point(const Eigen::Vector3d& gamma) const {
  ContactPoint c;
  const double g3 = std::clamp(gamma.z(), -1.0, 1.0);
  const bool pole = gamma.x() == 0.0 && gamma.y() == 0.0;
  c.z = pole ? (g3 > 0.0 ? profile_.z_lo() : profile_.z_hi()) : solve_contact_z(g3);
  const PolynomialJet j = profile_.chi2().jet(c.z);
  const double s2 = 4.0 * j.value + j.d1 * j.d1;
  const double s = std::sqrt(s2);
  const double q = 0.5 * s;
  c.r = Eigen::Vector3d(-gamma.x() * q, -gamma.y() * q, c.z - com_);
  c.R_parallel = q;
  c.R_meridian = s2 * s / (2.0 * std::abs(2.0 * j.value * j.d2 - j.d1 * j.d1));
  return c;
}

RadiiSlope ContactGeometry::radii_slope(const ContactPoint& c) const {
  const PolynomialJet j = profile_.chi2().jet(c.z);
  const double s2 = 4.0 * j.value + j.d1 * j.d1;
  const double s = std::sqrt(s2);
  const double G = 2.0 * j.value * j.d2 - j.d1 * j.d1;  // < 0
  const double ds = j.d1 * (2.0 + j.d2) / s;
  const double dG = 2.0 * j.value * third_derivative_(c.z);
  const double dz = s2 * s / (2.0 * G);  // dz/dgamma3
  return {-s2 * (3.0 * ds * G - s * dG) / (2.0 * G * G) * dz, 0.5 * ds * dz};
}

PatchShape ContactGeometry::patch(const ContactPoint& c, const Eigen::Vector3d& gamma, double depth) {
  assert(depth >= 0.0);
  PatchShape p;
  const double rho2 = gamma.x() * gamma.x() + gamma.y() * gamma.y();
  const double am = std::sqrt(2.0 * depth * c.R_meridian);
  const double ap = std::sqrt(2.0 * depth * c.R_parallel);
  if (rho2 == 0.0) {
    // At a pole the patch is a circle; its "major axis" is body e1 (deterministic, in the plane).
    p.a = p.b = std::max(am, ap);
    p.major = Eigen::Vector3d::UnitX();
    p.circle = true;
    return p;
  }
  const double rho = std::sqrt(rho2);
  const double g3 = gamma.z();
  // Projection of e3 onto the contact plane, normalised: (e3 - gamma3 gamma) / rho.
  const Eigen::Vector3d meridian(-g3 * gamma.x() / rho, -g3 * gamma.y() / rho, rho);
  const double Rmax = std::max(c.R_meridian, c.R_parallel);
  if (std::abs(c.R_meridian - c.R_parallel) <= kCircleRelTol * Rmax) {
    p.a = p.b = std::max(am, ap);
    p.major = meridian;
    p.circle = true;
  } else if (c.R_meridian > c.R_parallel) {
    p.a = am;
    p.b = ap;
    p.major = meridian;
  } else {
    p.a = ap;
    p.b = am;
    p.major = gamma.cross(meridian);
  }
  return p;
}

}  // namespace frictionlab::dynamics
