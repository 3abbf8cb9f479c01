// `exact:pressure=uniform` and `exact:pressure=punch`, and `exact-reference` in its domain,
// against the 30-digit table tests/friction/reference/pressure_table.csv.
//
// The table comes from tests/friction/reference/generate_pressure_table.py: the definition of the
// law in polar coordinates about the instantaneous centre of rotation, the chord integrals in
// closed form and the integral over directions by tanh-sinh quadrature in mpmath at 50 digits
// (the method of the Hertz table, exact_law_table_test.cpp); it shares no quadrature with either
// law. Its points run from b/a = 0.01 down to 1e-12 (uniform) and 1e-3 to 1e-12 (punch), over the
// ICR inside, 1e-9 on either side of the rim, just outside, at rho = sqrt 2, 4, 1e3, s = 1e4 and
// s = 1e-8, psi on and near the axes, both signs of Omega, and the two fuzzed inputs of docs/pressure-models.md §3
// (the uniform law once gave F1 = 1.00008 kN and F1 < 0 there).
//
// Tolerances, per kN for F1 and F2 and per kNa for M: the table's own error is below 1e-30;
// kExactLawPressureAccuracy (friction/exact_law.h) is what `exact` promises for these pressures at
// every b/a >= 1e-12, kExactReferenceAccuracy what `exact-reference` promises for b/a >= 0.01.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "friction/exact_law.h"
#include "friction/exact_reference_law.h"
#include "friction/pressure.h"
#include "tests/friction/dimensionless_contact.h"

namespace frictionlab::friction {
namespace exact_law_pressure_table_test {

struct TableRow {
  Pressure pressure;
  std::string kind;
  double s, mu, psi, sign;
  FrictionForces value;  // F1/(kN), F2/(kN), M/(kNa)
};

std::vector<TableRow> read_table() {
  std::ifstream in(FRICTIONLAB_PRESSURE_TABLE);
  std::vector<TableRow> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      EXPECT_EQ(line, "pressure,case,s,mu,psi,sign,F1,F2,M");
      continue;
    }
    std::istringstream fields(line);
    std::string pressure, kind, field;
    std::getline(fields, pressure, ',');
    std::getline(fields, kind, ',');
    std::vector<double> v;
    while (std::getline(fields, field, ',')) v.push_back(std::strtod(field.c_str(), nullptr));
    EXPECT_EQ(v.size(), 7u) << line;
    if (v.size() != 7u) continue;
    rows.push_back({parse_pressure(pressure), kind, v[0], v[1], v[2], v[3], {v[4], v[5], v[6]}});
  }
  return rows;
}

const std::vector<TableRow>& table() {
  static const std::vector<TableRow> rows = read_table();
  return rows;
}

ContactInput contact(const TableRow& r) { return dimensionless_contact(r.s, r.mu, r.psi, r.sign); }

// The largest of |F1 - F1*|, |F2 - F2*|, |M - M*| (a = N = k = 1: per kN and kNa).
double error(const FrictionForces& f, const FrictionForces& want) {
  return std::max({std::abs(f.F1 - want.F1), std::abs(f.F2 - want.F2), std::abs(f.M - want.M)});
}

std::string where(const TableRow& r) {
  std::ostringstream out;
  out.precision(17);
  out << pressure_name(r.pressure) << " " << r.kind << ": s = " << r.s << ", mu = " << r.mu << ", psi = " << r.psi
      << ", sign = " << r.sign;
  return out.str();
}

TEST(ExactPressureTable, CoversSlitsBothSpinsAndEveryIcrPosition) {
  const auto& rows = table();
  ASSERT_GE(rows.size(), 100u);
  double smallest_mu[2] = {1.0, 1.0};
  int negative = 0;
  int rim = 0;
  for (const auto& r : rows) {
    double& m = smallest_mu[r.pressure == Pressure::uniform ? 0 : 1];
    m = std::min(m, r.mu);
    negative += r.sign < 0;
    rim += r.kind == "rim-" || r.kind == "rim+";
  }
  EXPECT_EQ(smallest_mu[0], 1e-12);
  EXPECT_EQ(smallest_mu[1], 1e-12);
  EXPECT_GT(negative, 40);
  EXPECT_GT(rim, 20);
}

TEST(ExactPressureTable, ExactLawAgreesToItsStatedAccuracy) {
  for (const auto& r : table()) {
    const ExactLaw law(r.pressure);
    EXPECT_LE(error(law.evaluate(contact(r)), r.value), kExactLawPressureAccuracy) << where(r);
  }
}

TEST(ExactPressureTable, ExactReferenceAgreesToItsStatedAccuracyInItsDomain) {
  int checked = 0;
  for (const auto& r : table()) {
    if (r.mu < kExactReferenceMinAxisRatio) continue;
    const ExactReferenceLaw law(r.pressure);
    EXPECT_LE(error(law.evaluate(contact(r)), r.value), kExactReferenceAccuracy) << where(r);
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

// Regression pin: the largest error of `exact` against the table for each pressure, observed on
// 2026-11-28 on the development machine (2-core AMD EPYC KVM guest, Debian 12, g++ 12.2, Release):
// uniform 1.01e-12 (F1 at b/a = 1e-4, s = 1e4: the unfolded rim integrals, whose rounding grows like
// 1e-16/mu; below b/a = 1e-4 the folded ones stay below 1e-15), punch 1.42e-14 (b/a = 1e-12,
// rho = sqrt 2). The pin sits at twice that: a change that loses accuracy fails here long before it
// breaks the promise (kExactLawPressureAccuracy = 1e-10).
constexpr double kObservedLargestUniformError = 1.01e-12;
constexpr double kObservedLargestPunchError = 1.42e-14;

TEST(ExactPressureRegressionPin, LargestErrorAgainstTheTable) {
  for (const Pressure p : {Pressure::uniform, Pressure::punch}) {
    const ExactLaw law(p);
    double worst = 0.0;
    std::string at;
    for (const auto& r : table()) {
      if (r.pressure != p) continue;
      const double e = error(law.evaluate(contact(r)), r.value);
      if (e > worst) {
        worst = e;
        at = where(r);
      }
    }
    const double pin = 2.0 * (p == Pressure::uniform ? kObservedLargestUniformError : kObservedLargestPunchError);
    EXPECT_LE(worst, pin) << "largest error " << worst << " at " << at;
  }
}

}  // namespace
}  // namespace frictionlab::friction
