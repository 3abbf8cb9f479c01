#include "dynamics/contact_geometry.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace frictionlab::dynamics {
namespace {

// Starting points for Newton: z(gamma3) is analytic on [-1, 1] (g' != 0 up to the poles), so
// linear interpolation in this table is accurate to ~1e-5 L and Newton needs 2-3 steps.
constexpr int kGuessTableSize = 257;
// Newton stops when its step is below this fraction of the body length (the next step would be
// ~1e-28 L: the result is exact to rounding).
constexpr double kNewtonStepTolerance = 1e-14;
constexpr int kMaxNewtonIterations = 100;

}  // namespace

ContactGeometry::ContactGeometry(const Profile& profile, double com) : profile_(profile), com_(com) {
  guess_.resize(kGuessTableSize);
  const double mid = 0.5 * (profile_.z_lo() + profile_.z_hi());
  for (int i = 0; i < kGuessTableSize; ++i) {
    const double g3 = -1.0 + 2.0 * i / (kGuessTableSize - 1);
    guess_[static_cast<std::size_t>(i)] = solve(g3, mid);
  }
}

double ContactGeometry::solve_contact_z(double gamma3) const {
  const double x = (std::clamp(gamma3, -1.0, 1.0) + 1.0) * 0.5 * (kGuessTableSize - 1);
  const int i = std::clamp(static_cast<int>(x), 0, kGuessTableSize - 2);
  const double w = x - i;
  const double z0 = (1.0 - w) * guess_[static_cast<std::size_t>(i)] + w * guess_[static_cast<std::size_t>(i) + 1];
  return solve(gamma3, z0);
}

double ContactGeometry::solve(double gamma3, double z) const {
  const double lo0 = profile_.z_lo();
  const double hi0 = profile_.z_hi();
  // The poles, exactly (the pole z is a root of P: g = ±1 there).
  if (gamma3 >= 1.0) return lo0;
  if (gamma3 <= -1.0) return hi0;
  const Polynomial& P = profile_.chi2();
  double lo = lo0, hi = hi0;
  if (!(z > lo && z < hi)) z = 0.5 * (lo + hi);
  const double tol = kNewtonStepTolerance * (hi0 - lo0);
  // Safeguarded Newton (rtsafe): f = g - gamma3 decreases in z; keep a bracket, bisect on escape.
  for (int it = 0; it < kMaxNewtonIterations; ++it) {
    const PolynomialJet j = P.jet(z);
    const double s2 = 4.0 * j.value + j.d1 * j.d1;
    const double s = std::sqrt(s2);
    const double f = j.d1 / s - gamma3;
    if (f == 0.0) return z;
    if (f > 0.0) lo = z; else hi = z;
    const double fp = 2.0 * (2.0 * j.value * j.d2 - j.d1 * j.d1) / (s2 * s);
    double next = z - f / fp;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = std::abs(next - z);
    z = next;
    if (step <= tol) break;
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
