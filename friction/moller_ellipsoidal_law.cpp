#include "friction/moller_ellipsoidal_law.h"

#include <cmath>
#include <numbers>

namespace frictionlab::friction {

std::string_view MollerEllipsoidalLaw::name() const { return "moller-ellipsoidal"; }

std::string_view MollerEllipsoidalLaw::summary() const {
  return "ellipsoidal law of Moller, Leine & Glocker, Rb = (3 pi/16) sqrt(a b) (circle value on "
         "the geometric-mean radius)";
}

LawPromises MollerEllipsoidalLaw::promises() const {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::even;  // F2 = 0
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;  // psi plays no part
  p.psi_mirror = true;
  p.dissipative = true;
  p.bounded = true;
  p.whole_domain = true;
  p.tolerance = 1e-14;  // rounding of a closed form
  return p;
}

FrictionForces MollerEllipsoidalLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  if (F0 == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  if (in.Omega == 0.0) return {F0, 0.0, 0.0};  // pure sliding
  // Rb/a = (3 pi/16) sqrt(mu) (>= 2.8e-154 for the validated mu), and the ratio
  // r = U/(Rb|Omega|): F1 = F0 r/sqrt(1 + r^2), M = F0 Rb sign(Omega)/sqrt(1 + r^2), evaluated in
  // r or 1/r so that no square can overflow and neither Rb Omega nor U^2 is formed.
  const double rb = 3.0 * std::numbers::pi / 16.0 * std::sqrt(in.b / in.a);
  const double r = slip_ratio(in.U, in.a, in.Omega) / rb;  // may be +inf: pure sliding
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  const double F0a = F0 * in.a;
  FrictionForces out;
  out.F2 = 0.0;
  if (r <= 1.0) {
    const double root = std::sqrt(1.0 + r * r);
    out.F1 = F0 * (r / root);
    out.M = F0a * rb * (sign / root);
  } else {
    const double t = 1.0 / r;
    const double root = std::sqrt(1.0 + t * t);
    out.F1 = F0 / root;
    out.M = F0a * rb * (sign * t / root);
  }
  return out;
}

}  // namespace frictionlab::friction
