#include "friction/moller_ellipsoidal_law.h"

#include <cmath>
#include <numbers>

namespace frictionlab::friction {

std::string_view MollerEllipsoidalLaw::name() const { return "moller-ellipsoidal"; }

std::string_view MollerEllipsoidalLaw::summary() const {
  return "ellipsoidal law of Moller, Leine & Glocker, Rb = (3 pi/16) sqrt(a b) (circle value on "
         "the geometric-mean radius)";
}

FrictionForces MollerEllipsoidalLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  if (F0 == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  const double Rb = 3.0 * std::numbers::pi / 16.0 * std::sqrt(in.a * in.b);
  const double w = Rb * in.Omega;               // Rb Omega, m/s
  const double den = std::hypot(in.U, w);       // no overflow for large U or Rb Omega
  FrictionForces out;
  out.F1 = F0 * (in.U / den);
  out.F2 = 0.0;
  out.M = F0 * Rb * (w / den);
  return out;
}

}  // namespace frictionlab::friction
