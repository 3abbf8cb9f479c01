#include "friction/decoupled_law.h"

#include <boost/math/special_functions/ellint_2.hpp>
#include <cmath>
#include <limits>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

std::string summary_of(const std::optional<double>& r_spin) {
  if (!r_spin) {
    return "decoupled Coulomb: F1 = kN along the slip, M = (3/8) kN a E(e) sign(Omega) (exact Hertz "
           "pure-spin torque)";
  }
  return "decoupled Coulomb with a torsional length (Bullet, Chrono, Gazebo): F1 = kN along the slip, "
         "M = N r_spin sign(Omega), r_spin = " +
         support::message_number(*r_spin) + " m";
}

}  // namespace

DecoupledLaw::DecoupledLaw(std::optional<double> r_spin) : r_spin_(r_spin), summary_(summary_of(r_spin)) {
  if (r_spin && !(std::isfinite(*r_spin) && *r_spin >= 0.0)) {
    throw support::invalid_value("r_spin", *r_spin, "the torsional length must be a finite number >= 0 m");
  }
}

std::vector<LawParameter> DecoupledLaw::parameters() {
  return {LawParameter::number("r_spin", 0.0, /*min_open=*/false, std::numeric_limits<double>::infinity(), true, "m",
                               std::nullopt, "M0 = (3/8) kN a E(e), the exact pure-spin torque of the Hertz patch",
                               "the torsional length of Bullet, Chrono, Gazebo: torque limit N r_spin")};
}

LawPromises DecoupledLaw::promises() const {
  LawPromises p = LawPromises::closed_form_without_F2();
  p.bounded = !r_spin_;           // M0 <= (3 pi/16) kN a for the Hertz default only
  p.exact_pure_spin = !r_spin_;
  p.whole_domain = !r_spin_ || *r_spin_ <= 1.0;  // N r_spin overflows only above 1 m
  return p;
}

FrictionForces DecoupledLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  FrictionForces out;
  out.F1 = in.U > 0.0 ? F0 : 0.0;
  out.F2 = 0.0;
  if (in.Omega == 0.0) return out;
  double M0 = 0.0;
  if (r_spin_) {
    M0 = in.N * *r_spin_;
    if (!std::isfinite(M0)) {
      throw support::invalid_value("N", in.N,
                                   "with r_spin = " + support::message_number(*r_spin_) +
                                       " m, the torque limit N r_spin overflows: it must be a finite double (N m)");
    }
  } else if (F0 != 0.0) {
    const double mu = in.b / in.a;
    // e = sqrt(1 - mu^2) written as sqrt((1 - mu)(1 + mu)): no cancellation near the circle.
    const double e = std::sqrt((1.0 - mu) * (1.0 + mu));
    M0 = 3.0 / 8.0 * F0 * in.a * boost::math::ellint_2(e);
  }
  out.M = M0 == 0.0 ? 0.0 : std::copysign(M0, in.Omega);  // no -0 without a moment
  return out;
}

}  // namespace frictionlab::friction
