#include "dynamics/body/body.h"

#include <gtest/gtest.h>

#include <string>

namespace frictionlab::dynamics {
namespace body_test {

// docs/model.md §6 prints 3 significant digits.
constexpr double kPrintedTol = 5e-5;

std::string error_of(const BodySpec& spec) {
  try {
    (void)make_body(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

BodySpec egg(const std::string& preset) {
  BodySpec s;
  s.preset = preset;
  s.mass = 2.0;
  return s;
}

TEST(DynBody, EggPrintedPutsTheCentreOfMassAtTheOrigin) {
  const Body b = make_body(egg("egg-printed"));
  EXPECT_EQ(b.axisymmetric->com, 0.0);
  EXPECT_NEAR(b.axisymmetric->A, 0.0502, kPrintedTol);
  EXPECT_NEAR(b.axisymmetric->C, 0.0559, kPrintedTol);
}

TEST(DynBody, EggHomogeneousPutsTheCentreOfMassAtTheCentroid) {
  const Body b = make_body(egg("egg-homogeneous"));
  EXPECT_NEAR(b.axisymmetric->com, 0.0705, kPrintedTol);
  EXPECT_NEAR(b.axisymmetric->A, 0.0403, kPrintedTol);
  EXPECT_NEAR(b.axisymmetric->C, 0.0559, kPrintedTol);
}

TEST(DynBody, OverridesReplaceEachMassProperty) {
  BodySpec s = egg("egg-homogeneous");
  s.com = 0.01;
  const Body b1 = make_body(s);
  EXPECT_NEAR(b1.axisymmetric->A, b1.axisymmetric->homogeneous.transverse_about(0.01), 1e-15);  // A follows com by parallel axes
  s.A = 0.05;
  s.C = 0.06;
  const Body b2 = make_body(s);
  EXPECT_EQ(b2.axisymmetric->A, 0.05);
  EXPECT_EQ(b2.axisymmetric->C, 0.06);
  EXPECT_EQ(b2.axisymmetric->com, 0.01);
}

TEST(DynBody, ChiTwoCoefficientsMakeABody) {
  BodySpec s;
  s.chi2 = {0.01, 0.0, -1.0};  // sphere R = 0.1
  s.mass = 1.0;
  const Body b = make_body(s);
  EXPECT_NEAR(b.axisymmetric->C, 0.4 * 0.01, 1e-15);
  EXPECT_NEAR(b.axisymmetric->com, 0.0, 1e-15);
}

TEST(DynBody, ErrorsNameTheKeyAndTheRule) {
  BodySpec s = egg("egg-printed");
  s.mass = -1.0;
  EXPECT_NE(error_of(s).find("body.mass = -1"), std::string::npos) << error_of(s);

  s = egg("egg-printed");
  s.com = 0.3;
  EXPECT_NE(error_of(s).find("body.com = 0.3"), std::string::npos) << error_of(s);

  s = egg("egg-printed");
  s.A = 0.01;  // C = 0.0559 > 2A
  EXPECT_NE(error_of(s).find("C <= 2A"), std::string::npos) << error_of(s);

  s = egg("egg-printed");
  s.radius = 0.1;
  EXPECT_NE(error_of(s).find("body.radius is only used by the 'sphere' preset"), std::string::npos) << error_of(s);

  s = egg("cube");
  EXPECT_NE(error_of(s).find("body.profile = 'cube' is not a known preset"), std::string::npos) << error_of(s);

  s = egg("sphere");
  EXPECT_NE(error_of(s).find("body.radius is required"), std::string::npos) << error_of(s);

  s = egg("sphere");
  s.chi2 = {1.0, 0.0, -1.0};
  EXPECT_NE(error_of(s).find("both given"), std::string::npos) << error_of(s);
}

// ---------------------------------------------------------------------------------------------
// Shapes other than today's bodies of revolution (docs/convex-bodies.md §10).

BodySpec ellipsoid(double a1, double a2, double a3, double mass) {
  BodySpec s;
  s.shape = "ellipsoid";
  s.shape_parameters["semi_axes"] = {a1, a2, a3};
  s.mass = mass;
  return s;
}

TEST(DynBody, EllipsoidDefaultsToTheHomogeneousSolid) {
  // Closed form: J = (m/5) diag(a2^2 + a3^2, a1^2 + a3^2, a1^2 + a2^2) about the centre.
  const Body b = make_body(ellipsoid(0.3, 0.2, 0.1, 5.0));
  EXPECT_FALSE(b.axisymmetric.has_value());
  EXPECT_EQ(b.shape->kind(), "ellipsoid");
  EXPECT_LT(b.centre_of_mass.norm(), 1e-15);
  const Eigen::Vector3d expected(0.05, 0.1, 0.13);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(b.inertia(i, i), expected[i], 1e-15) << i;
  EXPECT_EQ(b.inertia(0, 1), 0.0);
}

TEST(DynBody, GivenCentreOfMassMovesTheDefaultInertiaByParallelAxes) {
  BodySpec s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.com_vector = Eigen::Vector3d(0.01, 0.02, 0.0);
  const Body b = make_body(s);
  // J_p = J_c + m (|d|^2 I - d d^T): J12 = -m d1 d2.
  EXPECT_NEAR(b.inertia(0, 1), -5.0 * 0.01 * 0.02, 1e-16);
  EXPECT_NEAR(b.inertia(2, 2), 0.13 + 5.0 * (0.01 * 0.01 + 0.02 * 0.02), 1e-15);
}

TEST(DynBody, RevolutionBodyOffItsAxisIsNoLongerAxisymmetric) {
  BodySpec s;
  s.preset = "sphere";
  s.radius = 0.05;
  s.mass = 1.0;
  s.com_vector = Eigen::Vector3d(0.0, 0.0, 0.01);
  EXPECT_TRUE(make_body(s).axisymmetric.has_value());  // on the axis: today's body
  s.com_vector = Eigen::Vector3d(0.005, 0.0, 0.0);
  const Body b = make_body(s);
  EXPECT_FALSE(b.axisymmetric.has_value());
  EXPECT_EQ(b.shape->kind(), "revolution");
}

TEST(DynBody, ShapeErrorsNameTheKeyAndTheRule) {
  BodySpec s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.inertia = Eigen::Matrix3d::Identity();
  s.inertia->operator()(0, 1) = 0.5;  // not symmetric
  EXPECT_NE(error_of(s).find("body.inertia"), std::string::npos) << error_of(s);
  EXPECT_NE(error_of(s).find("symmetric"), std::string::npos) << error_of(s);

  s.inertia = Eigen::Vector3d(1.0, 1.0, 3.0).asDiagonal();  // 3 > 1 + 1
  EXPECT_NE(error_of(s).find("body.inertia"), std::string::npos) << error_of(s);
  EXPECT_NE(error_of(s).find("must not exceed the sum of the other two"), std::string::npos) << error_of(s);

  s.inertia = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();  // not positive definite
  EXPECT_NE(error_of(s).find("positive"), std::string::npos) << error_of(s);

  s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.com_vector = Eigen::Vector3d(0.0, 0.0, 0.2);  // outside: a3 = 0.1
  EXPECT_NE(error_of(s).find("body.com"), std::string::npos) << error_of(s);
  EXPECT_NE(error_of(s).find("inside"), std::string::npos) << error_of(s);

  s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.A = 0.1;
  EXPECT_NE(error_of(s).find("body.A is only used by a body of revolution"), std::string::npos) << error_of(s);

  s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.com = 0.01;
  EXPECT_NE(error_of(s).find("body.com = 0.01 is invalid"), std::string::npos) << error_of(s);

  s = ellipsoid(0.3, -0.2, 0.1, 5.0);
  EXPECT_NE(error_of(s).find("body.semi_axes"), std::string::npos) << error_of(s);

  s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.shape_parameters["radius"] = {0.1};
  EXPECT_NE(error_of(s).find("body.radius"), std::string::npos) << error_of(s);

  s = ellipsoid(0.3, 0.2, 0.1, 5.0);
  s.shape = "cube";
  EXPECT_NE(error_of(s).find("body.shape"), std::string::npos) << error_of(s);

  BodySpec r = egg("egg-printed");
  r.inertia = Eigen::Matrix3d::Identity() * 0.05;
  r.A = 0.05;
  EXPECT_NE(error_of(r).find("both give the inertia"), std::string::npos) << error_of(r);
}

}  // namespace
}  // namespace frictionlab::dynamics
