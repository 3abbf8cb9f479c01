#include "friction/mujoco_elliptic_law.h"

#include <cmath>
#include <limits>

#include "friction/ellipsoidal_law.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

bool normal(double x) { return x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max(); }

// k U / (T w) for finite k, U, T, w >= 0 with T, w > 0, without spurious overflow or underflow: the
// products are formed only when both are normal doubles, otherwise significands and exponents are
// combined apart (the result is then +inf or 0 only if it is beyond the double range).
double ratio(double k, double U, double T, double w) {
  if (k == 0.0 || U == 0.0) return 0.0;
  const double num = k * U;
  const double den = T * w;
  if (normal(num) && normal(den)) return num / den;
  int ek = 0, eu = 0, et = 0, ew = 0;
  const double mk = std::frexp(k, &ek);
  const double mu = std::frexp(U, &eu);
  const double mt = std::frexp(T, &et);
  const double mw = std::frexp(w, &ew);
  return std::ldexp((mk * mu) / (mt * mw), ek + eu - et - ew);
}

}  // namespace

MujocoEllipticLaw::MujocoEllipticLaw(double torsional)
    : torsional_(torsional),
      summary_("MuJoCo condim 4, elliptic cone (f1/k)^2 + (f2/k)^2 + (tau/torsional)^2 <= N^2, maximally "
               "dissipative: the ellipsoidal law with Rb = torsional/k, torsional = " +
               support::message_number(torsional) + " m") {
  if (!(std::isfinite(torsional) && torsional > 0.0)) {
    throw support::invalid_value("torsional", torsional,
                                 "MuJoCo's torsional friction coefficient must be a finite number > 0 m");
  }
}

std::vector<LawParameter> MujocoEllipticLaw::parameters() {
  return {LawParameter::number("torsional", 0.0, /*min_open=*/true, std::numeric_limits<double>::infinity(), true,
                               "m", kDefaultTorsional, "",
                               "MuJoCo's torsional friction mu3 (MJCF friction=\"k mu3 ...\"): pure-spin torque N mu3")};
}

LawPromises MujocoEllipticLaw::promises() const {
  LawPromises p = LawPromises::closed_form_without_F2();
  p.bounded = false;                     // N torsional knows nothing of the patch
  p.whole_domain = torsional_ <= 1.0;    // N torsional overflows only above 1 m
  return p;
}

FrictionForces MujocoEllipticLaw::do_evaluate(const ContactInput& in) const {
  if (in.N == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  const double F0 = in.k * in.N;
  if (in.Omega == 0.0) return {F0, 0.0, 0.0};  // pure sliding
  const double M0 = in.N * torsional_;
  if (!std::isfinite(M0)) {
    throw support::invalid_value("N", in.N,
                                 "with torsional = " + support::message_number(torsional_) +
                                     " m, the torque limit N torsional overflows: it must be a finite double (N m)");
  }
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  return ellipsoidal_max_dissipation(F0, M0, ratio(in.k, in.U, torsional_, std::abs(in.Omega)), sign);
}

}  // namespace frictionlab::friction
