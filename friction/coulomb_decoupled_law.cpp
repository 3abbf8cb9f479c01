#include "friction/coulomb_decoupled_law.h"

#include <boost/math/special_functions/ellint_2.hpp>
#include <cmath>

namespace frictionlab::friction {

std::string_view CoulombDecoupledLaw::name() const { return "coulomb-decoupled"; }

std::string_view CoulombDecoupledLaw::summary() const {
  return "decoupled Coulomb: F1 = kN along the slip, M = (3/8) kN a E(e) sign(Omega) (exact "
         "pure-spin torque)";
}

LawPromises CoulombDecoupledLaw::promises() const {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::even;  // F2 = 0
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;  // psi plays no part
  p.psi_mirror = true;
  p.dissipative = true;
  p.bounded = true;
  p.whole_domain = true;
  p.exact_pure_spin = true;
  p.tolerance = 1e-14;  // rounding of a closed form
  return p;
}

FrictionForces CoulombDecoupledLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  if (F0 == 0.0) return {};
  FrictionForces out;
  out.F1 = in.U > 0.0 ? F0 : 0.0;
  out.F2 = 0.0;
  if (in.Omega != 0.0) {
    const double mu = in.b / in.a;
    // e = sqrt(1 - mu^2) written as sqrt((1 - mu)(1 + mu)): no cancellation near the circle.
    const double e = std::sqrt((1.0 - mu) * (1.0 + mu));
    const double M0 = 3.0 / 8.0 * F0 * in.a * boost::math::ellint_2(e);
    out.M = std::copysign(M0, in.Omega);
  }
  return out;
}

}  // namespace frictionlab::friction
