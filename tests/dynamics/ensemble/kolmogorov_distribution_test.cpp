// The Kolmogorov distribution (dynamics/ensemble/kolmogorov_distribution.h) against tabulated
// values and its own limits.

#include "dynamics/ensemble/kolmogorov_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace frictionlab::dynamics::ensemble {
namespace kolmogorov_distribution_test {

TEST(EnsembleKolmogorovDistribution, CriticalValuesMatchTheTables) {
  // The asymptotic critical values z_alpha with Q_KS(z_alpha) = alpha, as tabulated to three
  // decimals (Smirnov, Ann. Math. Statist. 19 (1948) 279, Table 1; Massey, JASA 46 (1951) 68):
  // alpha = 0.20, 0.10, 0.05, 0.025, 0.01, 0.005, 0.001.
  const double z[] = {1.073, 1.224, 1.358, 1.480, 1.628, 1.731, 1.949};
  const double alpha[] = {0.20, 0.10, 0.05, 0.025, 0.01, 0.005, 0.001};
  for (int i = 0; i < 7; ++i) {
    // Three decimals of z: Q may differ by |dQ/dz| * 5e-4 = 4 z Q-ish; a 1 % relative band holds it.
    EXPECT_NEAR(kolmogorov_q(z[i]), alpha[i], 0.012 * alpha[i]) << "z = " << z[i];
  }
}

TEST(EnsembleKolmogorovDistribution, KnownValuesToFifteenDigits) {
  // P_KS(1) = 0.7300 to the four decimals of the classical tables (Smirnov 1948, above); and the
  // single leading terms of each series where the others are below 1e-17.
  EXPECT_NEAR(kolmogorov_p(1.0), 0.7300, 5e-5);
  const double z = 4.0;  // Q = 2 exp(-32) (1 - exp(-96) + ...)
  EXPECT_NEAR(kolmogorov_q(z) / (2.0 * std::exp(-2.0 * z * z)), 1.0, 1e-15);
  const double small = 0.3;  // P = sqrt(2 pi)/z exp(-pi^2/(8 z^2)) (1 + exp(-pi^2/z^2) + ...)
  EXPECT_NEAR(kolmogorov_p(small) /
                  (std::sqrt(2.0 * std::numbers::pi) / small * std::exp(-std::numbers::pi * std::numbers::pi / (8 * small * small))),
              1.0, 1e-15);
}

TEST(EnsembleKolmogorovDistribution, BothSeriesAgreeWhereTheyMeetAndTheLimitsHold) {
  // The two series are independent computations of the same function: they agree where both
  // converge quickly, around the switch.
  for (double z = 0.8; z <= 1.6; z += 0.05) EXPECT_NEAR(kolmogorov_q_series(z), 1.0 - kolmogorov_p_series(z), 2e-15) << z;
  for (const double d : {-1e-9, 1e-9}) {
    const double z = kKolmogorovSwitch + d;
    EXPECT_NEAR(kolmogorov_q(z) + kolmogorov_p(z), 1.0, 1e-15) << z;
  }
  EXPECT_EQ(kolmogorov_q(0.0), 1.0);
  EXPECT_EQ(kolmogorov_p(0.0), 0.0);
  EXPECT_LT(kolmogorov_q(10.0), 1e-80);
  double previous = 1.0;
  for (double z = 0.05; z < 3.0; z += 0.05) {
    const double q = kolmogorov_q(z);
    EXPECT_LE(q, previous) << "Q_KS decreases: z = " << z;
    EXPECT_GE(q, 0.0);
    previous = q;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
