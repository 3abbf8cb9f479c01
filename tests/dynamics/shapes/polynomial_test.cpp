#include "dynamics/shapes/polynomial.h"

#include <gtest/gtest.h>

namespace frictionlab::dynamics {
namespace polynomial_test {

// Root polishing leaves a few ulps; roots here are O(1).
constexpr double kRootTol = 1e-13;

TEST(DynPolynomial, EvaluatesValueAndDerivativesByHorner) {
  const Polynomial p({1.0, -2.0, 0.5, 3.0});  // 1 - 2x + x^2/2 + 3x^3
  const double x = 0.7;
  const PolynomialJet j = p.jet(x);
  EXPECT_DOUBLE_EQ(j.value, 1 - 2 * x + 0.5 * x * x + 3 * x * x * x);
  EXPECT_DOUBLE_EQ(j.d1, -2 + x + 9 * x * x);
  EXPECT_DOUBLE_EQ(j.d2, 1 + 18 * x);
  EXPECT_DOUBLE_EQ(p(x), j.value);
  EXPECT_DOUBLE_EQ(p.derivative()(x), j.d1);
  EXPECT_DOUBLE_EQ(p.antiderivative().derivative()(x), p(x));
}

TEST(DynPolynomial, DropsTrailingZerosAndMultiplies) {
  EXPECT_EQ(Polynomial({1.0, 2.0, 0.0, 0.0}).degree(), 1);
  EXPECT_EQ(Polynomial({0.0}).degree(), -1);
  const Polynomial q = Polynomial({-1.0, 1.0}) * Polynomial({1.0, 1.0});  // x^2 - 1
  EXPECT_EQ(q.coefficients(), (std::vector<double>{-1.0, 0.0, 1.0}));
  EXPECT_EQ((q + Polynomial({1.0})).coefficients(), (std::vector<double>{0.0, 0.0, 1.0}));
  EXPECT_EQ((2.0 * q).coefficients(), (std::vector<double>{-2.0, 0.0, 2.0}));
}

TEST(DynPolynomial, FindsRealRootsOnly) {
  // (x - 1)(x - 2)(x + 3)(x^2 + 1)
  const Polynomial p =
      Polynomial({-1.0, 1.0}) * Polynomial({-2.0, 1.0}) * Polynomial({3.0, 1.0}) * Polynomial({1.0, 0.0, 1.0});
  const std::vector<double> r = real_roots(p);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], -3.0, kRootTol);
  EXPECT_NEAR(r[1], 1.0, kRootTol);
  EXPECT_NEAR(r[2], 2.0, kRootTol);
  EXPECT_THROW((void)real_roots(Polynomial({1.0})), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics
