// `exact`, and `exact-reference` in its domain, against the 30-digit table
// tests/friction/reference/exact_table.csv (Boost.Math style: bulk values generated at high
// precision by a script kept beside them, tolerances named and explained).
//
// The table comes from tests/friction/reference/generate_exact_table.py: the definition of the
// law integrated in two dimensions by tanh-sinh quadrature in mpmath at 50 digits, split at the
// instantaneous centre of rotation; it shares no method with either law. Its points run from
// mu = 1 down to mu = 1e-12, over the ICR inside, 1e-9 on either side of the rim, at rho = sqrt 2,
// outside and far, psi on and near the axes, both signs of Omega, s up to 1e4.
//
// Tolerances, per kN for F1 and F2 and per kNa for M:
//   * the table's own error is below 1e-30 (see the script): negligible against all below;
//   * kExactLawAccuracy (friction/exact_law.h): what `exact` promises for every valid input;
//   * kExactReferenceAccuracy (friction/exact_reference_law.h): what `exact-reference` promises
//     for b/a >= kExactReferenceMinAxisRatio.

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
#include "tests/friction/dimensionless_contact.h"

namespace frictionlab::friction {
namespace exact_law_table_test {

struct TableRow {
  std::string kind;
  double s, mu, psi, sign;
  FrictionForces value;  // F1/(kN), F2/(kN), M/(kNa)
};

std::vector<TableRow> read_table() {
  std::ifstream in(FRICTIONLAB_EXACT_TABLE);
  std::vector<TableRow> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      EXPECT_EQ(line, "case,s,mu,psi,sign,F1,F2,M");
      continue;
    }
    std::istringstream fields(line);
    std::string kind, field;
    std::getline(fields, kind, ',');
    std::vector<double> v;
    while (std::getline(fields, field, ',')) v.push_back(std::strtod(field.c_str(), nullptr));
    EXPECT_EQ(v.size(), 7u) << line;
    if (v.size() != 7u) continue;
    rows.push_back({kind, v[0], v[1], v[2], v[3], {v[4], v[5], v[6]}});
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
  out << r.kind << ": s = " << r.s << ", mu = " << r.mu << ", psi = " << r.psi << ", sign = " << r.sign;
  return out.str();
}

TEST(ExactLawTable, CoversSlenderPatchesBothSpinsAndEveryIcrPosition) {
  const auto& rows = table();
  ASSERT_GE(rows.size(), 100u);
  double smallest_mu = 1.0;
  int negative = 0;
  int rim = 0;
  for (const auto& r : rows) {
    smallest_mu = std::min(smallest_mu, r.mu);
    negative += r.sign < 0;
    rim += r.kind == "rim-" || r.kind == "rim+";
  }
  EXPECT_EQ(smallest_mu, 1e-12);
  EXPECT_GT(negative, 30);
  EXPECT_GT(rim, 20);
}

TEST(ExactLawTable, ExactLawAgreesToItsStatedAccuracy) {
  const ExactLaw law;
  double worst = 0.0;
  for (const auto& r : table()) {
    const double e = error(law.evaluate(contact(r)), r.value);
    EXPECT_LE(e, kExactLawAccuracy) << where(r);
    worst = std::max(worst, e);
  }
  RecordProperty("largest_error", std::to_string(worst));
}

TEST(ExactLawTable, ExactReferenceAgreesToItsStatedAccuracyInItsDomain) {
  // Milliseconds per call: every second point of its domain (b/a >= 0.01).
  const ExactReferenceLaw law;
  int checked = 0;
  int index = 0;
  for (const auto& r : table()) {
    if (r.mu < kExactReferenceMinAxisRatio || index++ % 2 != 0) continue;
    EXPECT_LE(error(law.evaluate(contact(r)), r.value), kExactReferenceAccuracy) << where(r);
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

// Regression pin: the largest error of `exact` against the table, observed on 2026-11-22 on the
// development machine (2-core AMD EPYC KVM guest, Debian 12, g++ 12.2, Release), was
// kObservedLargestError (M at mu = 1e-12, psi = 0.4, the ICR at rho = sqrt 2: the whole - gap
// subtraction). The pin sits at twice that: a change that loses accuracy anywhere in the table
// fails here long before it breaks the promise (kExactLawAccuracy = 1e-13).
constexpr double kObservedLargestError = 2.94e-14;
constexpr double kPin = 2.0 * kObservedLargestError;

TEST(ExactLawRegressionPin, LargestErrorAgainstTheTable) {
  const ExactLaw law;
  double worst = 0.0;
  std::string at;
  for (const auto& r : table()) {
    const double e = error(law.evaluate(contact(r)), r.value);
    if (e > worst) {
      worst = e;
      at = where(r);
    }
  }
  EXPECT_LE(worst, kPin) << "largest error " << worst << " at " << at;
}

}  // namespace
}  // namespace frictionlab::friction
