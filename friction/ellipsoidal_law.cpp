#include "friction/ellipsoidal_law.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

// The Hertz calibration: Rb/a = (3 pi/16) sqrt(b/a), exact at pure spin for a circle.
constexpr double kHertzCircleSpin = 3.0 * std::numbers::pi / 16.0;

std::string summary_of(const std::optional<double>& Rb) {
  if (!Rb) {
    return "ellipsoidal law of Moller, Leine & Glocker, Rb = (3 pi/16) sqrt(a b) (Hertz-calibrated: "
           "the circle's pure-spin torque on the geometric-mean radius)";
  }
  return "ellipsoidal law of Moller, Leine & Glocker with a fixed Rb = " + support::message_number(*Rb) +
         " m: F = kN v/sqrt(U^2 + Rb^2 Omega^2), M = kN Rb^2 Omega/sqrt(U^2 + Rb^2 Omega^2)";
}

}  // namespace

FrictionForces ellipsoidal_max_dissipation(double F0, double M0, double r, double sign) {
  FrictionForces out;
  out.F2 = 0.0;
  if (r <= 1.0) {
    const double root = std::sqrt(1.0 + r * r);
    out.F1 = F0 * (r / root);
    out.M = M0 * (sign / root);
  } else {
    const double t = 1.0 / r;  // 0 for r = inf: pure sliding
    const double root = std::sqrt(1.0 + t * t);
    out.F1 = F0 / root;
    out.M = M0 * (sign * t / root);
  }
  return out;
}

EllipsoidalLaw::EllipsoidalLaw(std::optional<double> Rb) : Rb_(Rb), summary_(summary_of(Rb)) {
  if (Rb && !(std::isfinite(*Rb) && *Rb > 0.0)) {
    throw support::invalid_value("Rb", *Rb, "the radius of the ellipsoidal law must be a finite number > 0 m");
  }
}

std::vector<LawParameter> EllipsoidalLaw::parameters() {
  return {LawParameter::number("Rb", 0.0, /*min_open=*/true, std::numeric_limits<double>::infinity(), true, "m",
                               std::nullopt, "Rb = (3 pi/16) sqrt(a b), exact at pure spin on a circular Hertz patch",
                               "the radius of the friction ellipsoid: pure-spin torque kN Rb")};
}

LawPromises EllipsoidalLaw::promises() const {
  LawPromises p = LawPromises::closed_form_without_F2();
  // |M| <= kN Rb: within kN a for the Hertz default (Rb <= (3 pi/16) a), not for a fixed Rb.
  p.bounded = !Rb_;
  // kN Rb overflows only for Rb > 1 m (kN is a finite double): below, every input is evaluated.
  p.whole_domain = !Rb_ || *Rb_ <= 1.0;
  return p;
}

FrictionForces EllipsoidalLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  if (F0 == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  if (in.Omega == 0.0) return {F0, 0.0, 0.0};  // pure sliding
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  if (Rb_) {
    const double M0 = F0 * *Rb_;
    if (!std::isfinite(M0)) {
      throw support::invalid_value("N", in.N,
                                   "with k = " + support::message_number(in.k) + " and Rb = " +
                                       support::message_number(*Rb_) +
                                       " m, the torque limit k N Rb overflows: it must be a finite double (N m)");
    }
    // r = U/(Rb |Omega|), +inf when above the double range (pure sliding to rounding).
    return ellipsoidal_max_dissipation(F0, M0, slip_ratio(in.U, *Rb_, in.Omega), sign);
  }
  // Rb/a = (3 pi/16) sqrt(mu) >= 2.8e-154 for the validated mu; r = s/(Rb/a), and M0 = kN a (Rb/a)
  // is formed as (kN a) (Rb/a) so that neither Rb Omega nor U^2 appears.
  const double rb = kHertzCircleSpin * std::sqrt(in.b / in.a);
  return ellipsoidal_max_dissipation(F0, F0 * in.a * rb, slip_ratio(in.U, in.a, in.Omega) / rb, sign);
}

}  // namespace frictionlab::friction
