#include "friction/exact_table_law.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "friction/exact_law.h"
#include "friction/exact_table.h"
#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

// Above this slip ratio the law returns the fast-slip expansion, as `exact` does above the same
// ratio (friction/exact_law.cpp): the table would be as good there, but its outside block squares
// the ICR's coordinates, which leave the double range beyond s ~ 1e154.
constexpr double kFastSlipRatio = 1e8;

}  // namespace

std::vector<LawParameter> ExactTableLaw::parameters() { return ExactLaw::parameters(); }

// Every property of the exact law (it is the exact law, tabulated), to the table's accuracy and on
// its range of axis ratios.
LawPromises ExactTableLaw::promises() const {
  LawPromises p = ExactLaw(pressure_).promises();
  p.min_axis_ratio = kExactTableMinAxisRatio;
  p.tolerance = kExactTableAccuracy;
  return p;
}

FrictionForces ExactTableLaw::do_evaluate(const ContactInput& in) const {
  const double mu = in.b / in.a;
  if (mu < kExactTableMinAxisRatio) {
    throw std::invalid_argument("friction input b = " + support::shortest(in.b) +
                                " is invalid for exact-table: the axis ratio b/a = " + support::shortest(mu) +
                                " is below " + support::significant(kExactTableMinAxisRatio, 3) +
                                ", where its table ends (use exact)");
  }
  const double kN = in.k * in.N;
  if (kN == 0.0) return {};
  if (in.Omega == 0.0) {
    if (in.U == 0.0) return {};  // indeterminate at U = Omega = 0: zero, as exact
    return {kN, 0.0, 0.0};       // pure sliding
  }
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  const double s = slip_ratio(in.U, in.a, in.Omega);
  if (std::isinf(s)) return {kN, 0.0, 0.0};  // pure sliding: U/(a|Omega|) beyond the doubles
  const double kNa = kN * in.a;
  // A circle is symmetric under rotation: psi = 0 makes F2 = 0 exact.
  const PatchAngle::CosSin axis = (mu == 1.0) ? PatchAngle::CosSin{1.0, 0.0} : in.psi.cos_sin();
  const double c = axis.c;
  const double sn = axis.s;

  if (s > kFastSlipRatio) {
    // Fast-slip expansion (docs/model.md, docs/pressure-models.md), m2 the second moment per axis.
    const double m2 = pressure_second_moment(pressure_);
    const double d3 = (1.0 - mu) * (1.0 + mu) * c * c + mu * mu;
    const double d4 = 2.0 * (1.0 - mu) * (1.0 + mu) * sn * c;
    const double is = 1.0 / s;
    return {kN * (1.0 - 0.5 * m2 * d3 * is * is), kN * 0.5 * m2 * d4 * is * is, sign * kNa * m2 * d3 * is};
  }

  // The table design of docs/exact-table.md, "Evaluation, in order".
  const ExactTable& table = ExactTable::of(pressure_);
  const double ln_mu = std::log(mu);
  const double M0 = table.pure_spin_moment(mu, ln_mu);  // step 4
  if (s == 0.0) return {0.0, 0.0, sign * kNa * M0};     // pure spin: the table's centre, m = 1
  const ExactTableValue g = table.at(s * sn, s * c, mu, ln_mu);  // steps 5-8
  // Step 9: G back to the slip frame.
  const double F1 = -(g.gx * sn + g.gy * c);
  const double F2 = g.gx * c - g.gy * sn;
  return {kN * F1, kN * F2, sign * kNa * M0 * g.m};
}

}  // namespace frictionlab::friction
