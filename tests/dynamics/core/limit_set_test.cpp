// The law's limit set (dynamics/core/limit_set.h) against closed forms: the decoupled law's
// cylinder |F| <= kN, |M| <= M0 (its margin is the distance to the cylinder's surface), the exact
// law's support at pure slip (kN) and pure spin ((3 pi/16) kNa on a circle, (3/8) E(e) kNa on an
// ellipse), and points on the exact circle's boundary from the closed forms of F1 and M.
#include "dynamics/core/limit_set.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <boost/math/special_functions/ellint_2.hpp>
#include <cmath>
#include <memory>
#include <numbers>

#include "friction/registry.h"

namespace frictionlab::dynamics {
namespace limit_set_test {

constexpr double kPi = std::numbers::pi;
constexpr double k = 0.3;
constexpr double N = 20.0;   // N
constexpr double a = 2e-3;   // m
constexpr double kN = k * N;
// The margin of a closed-form law is found to rounding at a direction the search hits exactly
// (the kink lines) and to ~1e-16 elsewhere; 1e-12 of kN leaves room for the grid's rounding.
constexpr double kMarginTolerance = 1e-12;
// Where a margin comes from a smooth minimum found by the search: the direction to ~1e-9 rad.
constexpr double kSearchTolerance = 1e-10;

std::unique_ptr<friction::FrictionLaw> law(const char* spec) { return friction::make_law(spec); }

TEST(DynLimitSet, DecoupledIsTheCylinderAndItsMarginTheDistanceToItsSurface) {
  const auto decoupled = law("decoupled");
  const double M0 = 3.0 * kPi / 16.0 * kN * a;  // circle
  const LimitSet set(*decoupled, k, N, a, a);
  ASSERT_FALSE(set.degenerate());
  // Inside: margin = min(1 - |F|/kN, (M0 - |M|)/(kN a)) (normalised distance to the surface).
  const double f = 0.6, m = 0.8;
  const LimitSetTest in = set.test({f * kN * std::cos(0.4), f * kN * std::sin(0.4), -m * M0});
  EXPECT_NEAR(in.margin, std::min(1.0 - f, (1.0 - m) * M0 / (kN * a)), kMarginTolerance);
  EXPECT_TRUE(in.inside());
  // Just outside the mantle and just outside the lids.
  EXPECT_FALSE(set.test({1.001 * kN, 0.0, 0.0}).inside());
  EXPECT_NEAR(set.test({1.001 * kN, 0.0, 0.0}).margin, -0.001, kMarginTolerance);
  EXPECT_FALSE(set.test({0.0, 0.0, 1.001 * M0}).inside());
  EXPECT_FALSE(set.test({0.0, 0.0, -1.001 * M0}).inside());
  EXPECT_TRUE(set.test({0.0, 0.999 * kN, 0.999 * M0}).inside());  // near the corner, inside
  // Outside at a corner: the distance to the rim circle, in normalised units.
  const double df = 0.003, dm = 0.004;
  const LimitSetTest corner = set.test({(1.0 + df) * kN, 0.0, M0 + dm * kN * a});
  EXPECT_NEAR(corner.margin, -std::hypot(df, dm), kSearchTolerance);
}

TEST(DynLimitSet, ExactSupportIsKNAtPureSlipAndThePureSpinMomentAtPureSpin) {
  const auto exact = law("exact");
  const double mu = 0.5;
  const LimitSet circle(*exact, k, N, a, a);
  const LimitSet ellipse(*exact, k, N, a, mu * a);
  for (const double alpha : {0.0, 0.7, 2.0, 4.0}) {
    EXPECT_NEAR(circle.support({alpha, 0.0}), 1.0, 1e-12);
    EXPECT_NEAR(ellipse.support({alpha, 0.0}), 1.0, 1e-12);
  }
  const double circle_spin = 3.0 * kPi / 16.0;
  const double ellipse_spin = 3.0 / 8.0 * boost::math::ellint_2(std::sqrt(1.0 - mu * mu));
  for (const double beta : {0.5 * kPi, -0.5 * kPi}) {
    EXPECT_NEAR(circle.support({0.0, beta}), circle_spin, 1e-9);
    EXPECT_NEAR(ellipse.support({1.0, beta}), ellipse_spin, 1e-9);
  }
  // Membership along the axes of the wrench space.
  EXPECT_TRUE(circle.test({0.999 * kN, 0.0, 0.0}).inside());
  EXPECT_FALSE(circle.test({1.001 * kN, 0.0, 0.0}).inside());
  EXPECT_TRUE(circle.test({0.0, 0.0, 0.999 * circle_spin * kN * a}).inside());
  EXPECT_FALSE(circle.test({0.0, 0.0, -1.001 * circle_spin * kN * a}).inside());
  EXPECT_TRUE(ellipse.test({0.0, 0.0, 0.999 * ellipse_spin * kN * a}).inside());
  EXPECT_FALSE(ellipse.test({0.0, 0.0, 1.001 * ellipse_spin * kN * a}).inside());
}

TEST(DynLimitSet, ExactCircleBoundaryIsTheClosedFormWrenchOfEachSlipRatio) {
  // Circle, Hertz pressure, u = U/(a |Omega|) <= 1 (docs/model.md): per kN and kNa,
  // F1 = (3 pi/32) u (4 - u^2), |M| = (3 pi/128)(8 - 8 u^2 + 3 u^4). Those wrenches lie on the
  // boundary: scaled by 1 - 1e-6 they are inside (margin > 0), by 1 + 1e-6 outside; a point on the
  // cylinder's corner (|F| = 0.9 kN, |M| = 0.9 of the pure-spin moment) lies outside the exact set.
  const auto exact = law("exact");
  const LimitSet set(*exact, k, N, a, a);
  for (const double u : {0.25, 0.5, 0.9}) {
    const double F1 = 3.0 * kPi / 32.0 * u * (4.0 - u * u) * kN;
    const double M = 3.0 * kPi / 128.0 * (8.0 - 8.0 * u * u + 3.0 * std::pow(u, 4)) * kN * a;
    EXPECT_TRUE(set.test({(1.0 - 1e-6) * F1, 0.0, (1.0 - 1e-6) * M}).inside()) << "u = " << u;
    EXPECT_FALSE(set.test({(1.0 + 1e-6) * F1, 0.0, (1.0 + 1e-6) * M}).inside()) << "u = " << u;
    // The minimising direction of a boundary point is its own direction: tan beta = 1/u.
    const LimitSetTest on = set.test({F1, 0.0, M});
    EXPECT_NEAR(on.margin, 0.0, 1e-9) << "u = " << u;
    EXPECT_NEAR(on.direction.beta, std::atan(1.0 / u), 1e-4) << "u = " << u;
  }
  EXPECT_FALSE(set.test({0.9 * kN, 0.0, 0.9 * 3.0 * kPi / 16.0 * kN * a}).inside());
}

// The direction of creep (the header comment): outside the decoupled law's cylinder at its rim
// (|F| > kN and |M| > M0) the projection in the metric of G = diag(g, g, h) is the rim point
// (kN F/|F|, M0) whatever G, and d is along G (rho* - rim) (per kN, M per kN a):
// tan beta = h (M* - M0) / (g (|F*| - kN)), alpha along F*. Without a metric, h = g.
TEST(DynLimitSet, TheDirectionOfCreepAtTheCylindersRimFollowsTheMetric) {
  const auto decoupled = law("decoupled");
  const double M0 = 3.0 * kPi / 16.0 * kN * a;
  const LimitSet set(*decoupled, k, N, a, a);
  const double df = 0.02, dm = 0.03, alpha = 0.8;
  const PatchWrench rho{(1.0 + df) * kN * std::cos(alpha), (1.0 + df) * kN * std::sin(alpha), M0 + dm * kN * a};
  for (const double h_over_g : {1.0, 4.0, 0.1}) {
    const Eigen::Matrix3d Q = Eigen::Vector3d(1.0, 1.0, 1.0 / h_over_g).asDiagonal();  // G^-1, g = 1
    const LimitSetTest t = set.test(rho, nullptr, Q);
    EXPECT_FALSE(t.inside());
    EXPECT_NEAR(t.direction.beta, std::atan2(h_over_g * dm, df), 1e-7) << "h/g = " << h_over_g;
    EXPECT_NEAR(std::remainder(t.direction.alpha - alpha, 2.0 * kPi), 0.0, 1e-7) << "h/g = " << h_over_g;
  }
}

// The defining property of the direction of creep for a smooth law and a full metric: the wrench
// less the law's resistance in that direction is along Q d (rho* - rho(d) = lambda Q d, lambda > 0),
// checked on the exact law of an elliptic patch (its boundary known only through the law).
TEST(DynLimitSet, TheWrenchLessTheCreepResistanceIsAlongTheMetricTimesTheDirection) {
  const auto exact = law("exact");
  const LimitSet set(*exact, k, N, a, 0.4 * a);
  Eigen::Matrix3d G;
  G << 3.0, 0.4, -0.2,  //
      0.4, 1.5, 0.3,    //
      -0.2, 0.3, 0.2;
  const Eigen::Matrix3d Q = G.inverse();
  const PatchWrench rho{0.7 * kN, -0.5 * kN, 0.35 * kN * a};
  const LimitSetTest t = set.test(rho, nullptr, Q);
  ASSERT_FALSE(t.inside());
  const PatchWrench r = set.resistance(t.direction);  // per kN, M per kN a
  const Eigen::Vector3d gap(rho.Fx / kN - r.Fx, rho.Fy / kN - r.Fy, rho.M / (kN * a) - r.M);
  const double cb = std::cos(t.direction.beta);
  const Eigen::Vector3d d(cb * std::cos(t.direction.alpha), cb * std::sin(t.direction.alpha), std::sin(t.direction.beta));
  const Eigen::Vector3d Qd = Q * d;
  EXPECT_GT(gap.dot(Qd), 0.0);
  EXPECT_LT(gap.cross(Qd).norm(), 1e-6 * gap.norm() * Qd.norm()) << gap.transpose() << " vs " << Qd.transpose();
  // Without the metric the direction differs here (the metric is far from isotropic).
  const LimitSetTest plain = set.test(rho);
  EXPECT_GT(std::hypot(plain.direction.alpha - t.direction.alpha, plain.direction.beta - t.direction.beta), 1e-2);
  // Following from a nearby direction finds the same one.
  const LimitSetTest followed = set.follow(rho, {t.direction.alpha + 0.01, t.direction.beta - 0.01}, Q);
  EXPECT_NEAR(followed.direction.alpha, t.direction.alpha, 1e-6);
  EXPECT_NEAR(followed.direction.beta, t.direction.beta, 1e-6);
}

// The slow manifold's condition (creep_direction): the slip's rate G (rho* - rho(d)) along d with a
// positive factor. For the exact law (maximum dissipation) the metric projection's direction that
// test() finds satisfies it to the search's tolerance, and the solve from there refines it to
// rounding without leaving it (the condition need not have a single root: the solve starts from the
// search's direction).
TEST(DynLimitSet, TheDirectionOfCreepOfTheSlowManifoldHasTheSlipsRateAlongIt) {
  Eigen::Matrix3d G;
  G << 3.0, 0.4, -0.2,  //
      0.4, 1.5, 0.3,    //
      -0.2, 0.3, 0.2;
  const PatchWrench rho{0.7 * kN, -0.5 * kN, 0.35 * kN * a};
  const auto rate_along = [&](const LimitSet& set, const SlipDirection& dir, double& lambda) {
    const PatchWrench r = set.resistance(dir);
    const Eigen::Vector3d w = G * Eigen::Vector3d(rho.Fx / kN - r.Fx, rho.Fy / kN - r.Fy, rho.M / (kN * a) - r.M);
    const double cb = std::cos(dir.beta);
    const Eigen::Vector3d d(cb * std::cos(dir.alpha), cb * std::sin(dir.alpha), std::sin(dir.beta));
    lambda = w.dot(d);
    return w.cross(d).norm() / w.norm();
  };
  const auto exact = law("exact");
  const LimitSet set(*exact, k, N, a, 0.4 * a);
  const LimitSetTest t = set.test(rho, nullptr, G.inverse());
  ASSERT_FALSE(t.inside());
  bool found = false;
  long evaluations = 0;
  const SlipDirection d = set.creep_direction(rho, t.direction, G, found, evaluations);
  ASSERT_TRUE(found);
  EXPECT_NEAR(d.alpha, t.direction.alpha, 1e-6);
  EXPECT_NEAR(d.beta, t.direction.beta, 1e-6);
  double lambda = 0.0;
  EXPECT_LT(rate_along(set, d, lambda), 1e-10);
  EXPECT_GT(lambda, 0.0);
  EXPECT_GT(evaluations, 0);
  EXPECT_LT(rate_along(set, t.direction, lambda), 1e-5);  // the search's own direction, to its tolerance

}

TEST(DynLimitSet, ASetWithoutInteriorIsDegenerateAndHoldsNothing) {
  const auto no_spin = law("decoupled:r_spin=0");
  const LimitSet flat(*no_spin, k, N, a, a);
  EXPECT_TRUE(flat.degenerate());
  EXPECT_FALSE(flat.test({0.0, 0.0, 0.0}).inside());
  const auto exact = law("exact");
  EXPECT_TRUE(LimitSet(*exact, 0.0, N, a, a).degenerate());  // k = 0
  EXPECT_TRUE(LimitSet(*exact, k, 0.0, a, a).degenerate());  // N = 0
  EXPECT_FALSE(LimitSet(*exact, k, N, a, a).degenerate());
}

}  // namespace
}  // namespace frictionlab::dynamics
