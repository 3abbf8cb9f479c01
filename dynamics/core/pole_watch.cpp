#include "dynamics/core/pole_watch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace frictionlab::dynamics {
namespace {

// s is capped here when it is evaluated (t -> 0): s^2 = 1e200 stays finite and is the limit for
// every quadratic denominator.
constexpr double kMaxSlipRatio = 1e100;
// Bisection steps on the segment between two points: 2^-60 of the segment, below rounding.
constexpr int kBisections = 60;

int sign_of(double d) { return d > 0.0 ? 1 : (d < 0.0 ? -1 : 0); }

}  // namespace

PoleWatch::PoleWatch(const friction::FrictionLaw& law, double k) : law_(law), k_(k), active_(law.has_poles()) {}

PoleWatch::Point PoleWatch::patch_point(double U, double Omega, double a, double b, double psi) {
  Point p;
  p.sign = Omega < 0.0 ? -1.0 : 1.0;
  p.psi = psi;
  p.mu = b / a;
  const double aw = a * std::abs(Omega);
  p.t = aw > 0.0 ? aw / (aw + U) : 0.0;  // 1/(1 + U/(a|Omega|)), no overflow
  return p;
}

std::array<double, 3> PoleWatch::denominators(const Point& p) const {
  const double s = p.t > 1.0 / kMaxSlipRatio ? (1.0 - p.t) / p.t : kMaxSlipRatio;
  // a = 1 m and |Omega| = 1 1/s: U = s m/s gives the slip ratio s (only the shape matters).
  const friction::PoleDenominators d = law_.pole_denominators({s, p.sign, 1.0, p.mu, p.psi, 1.0, k_});
  return {d.F1, d.F2, d.M};
}

void PoleWatch::set_reference(const Point& p) {
  if (!active_) return;
  ref_ = p;
  ref_den_ = denominators(ref_);
}

int PoleWatch::crossing(const Point& p) const {
  if (!active_) return -1;
  const std::array<double, 3> d = denominators(p);
  for (int i = 0; i < 3; ++i) {
    const std::size_t j = static_cast<std::size_t>(i);
    if (std::isnan(ref_den_[j]) || std::isnan(d[j])) continue;  // nothing to compare
    // The last accepted state lies on the pole (the integrator closing in on it lands there at
    // rounding level): no move from it may be accepted, or the run would cross the pole unseen.
    if (ref_den_[j] == 0.0) return i;
    if (sign_of(d[j]) == sign_of(ref_den_[j])) continue;
    if (d[j] == 0.0 || passes_through_zero(ref_, p, i)) return i;
  }
  return -1;
}

bool PoleWatch::passes_through_zero(const Point& from, const Point& to, int which) const {
  const std::size_t j = static_cast<std::size_t>(which);
  const double dpsi = std::remainder(to.psi - from.psi, std::numbers::pi);  // shorter arc, mod pi
  const auto at = [&](double lambda) {
    Point q;
    q.t = from.t + lambda * (to.t - from.t);
    q.mu = from.mu + lambda * (to.mu - from.mu);
    q.psi = from.psi + lambda * dpsi;
    q.sign = to.sign;
    return denominators(q)[j];
  };
  const double d0 = at(0.0), d1 = at(1.0);
  if (std::isnan(d0) || std::isnan(d1)) return false;
  if (d1 == 0.0) return true;
  if (sign_of(d0) == sign_of(d1)) return false;
  double lo = 0.0, hi = 1.0, dlo = d0, dhi = d1;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double dm = at(mid);
    if (std::isnan(dm)) return false;  // no denominator on the way: passes through infinity
    if (dm == 0.0) return true;
    if (sign_of(dm) == sign_of(dlo)) {
      lo = mid;
      dlo = dm;
    } else {
      hi = mid;
      dhi = dm;
    }
  }
  // Through infinity |D| rises inside the segment above its values at both ends; anything else is
  // a pole, including a sign change at rounding level, where the bracket's |D| is noise as large
  // as the ends' (the integrator closing in on a pole ends there).
  return !(std::min(std::abs(dlo), std::abs(dhi)) > std::max(std::abs(d0), std::abs(d1)));
}

const char* PoleWatch::output_name(int which) {
  switch (which) {
    case 0: return "F1";
    case 1: return "F2";
    case 2: return "M";
    default: return "?";
  }
}

}  // namespace frictionlab::dynamics
