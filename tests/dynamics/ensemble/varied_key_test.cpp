// Varied keys and replicas (dynamics/ensemble/varied_key.h, dynamics/ensemble/replica.h).

#include "dynamics/ensemble/varied_key.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "dynamics/ensemble/replica.h"
#include "dynamics/rigid_rolling/inertia_misalignment.h"

namespace frictionlab::dynamics::ensemble {
namespace varied_key_test {

InitialState base() {
  InitialState s;
  s.gamma = Eigen::Vector3d(0.6, 0.0, 0.8);
  s.omega = Eigen::Vector3d(1.0, 2.0, 3.0);
  s.v = Eigen::Vector3d(0.5, 0.0, 0.0);
  s.eps = -1e-5;
  return s;
}

// The Kane & Levinson rattleback's central tensor (data/scenarios/rattleback-reversal.toml), kg m^2.
Eigen::Matrix3d kane_levinson() {
  Eigen::Matrix3d j;
  j << 2.0e-4, 0.2e-4, 0.0, 0.2e-4, 16.0e-4, 0.0, 0.0, 0.0, 17.0e-4;
  return j;
}

StartState misaligned(const Eigen::Matrix3d& base_inertia, double delta) {
  return apply_start(base(), base_inertia, {VariedKey::parse("body.misalignment", "k")}, {delta});
}

// Relative to the tensor's largest element: what "J to 1e-15" means for a tensor whose elements
// differ by two orders (J12 = 0.2e-4, J33 = 17e-4 kg m^2).
double tensor_difference(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(EnsembleVariedKey, DerivedKeysSetTheVectorsTheScenarioHolds) {
  const std::vector<VariedKey> keys{VariedKey::parse("initial.gamma3", "k0"), VariedKey::parse("initial.omega3", "k1"),
                                    VariedKey::parse("initial.v2", "k2"), VariedKey::parse("contact.k", "k3")};
  EXPECT_EQ(keys[0].kind(), VariedKey::Kind::gamma3);
  EXPECT_EQ(keys[1].kind(), VariedKey::Kind::omega);
  EXPECT_EQ(keys[1].component(), 2);
  EXPECT_EQ(keys[2].kind(), VariedKey::Kind::velocity);
  EXPECT_EQ(keys[2].component(), 1);
  EXPECT_EQ(keys[3].kind(), VariedKey::Kind::plain);

  const StartState s = apply_start(base(), kane_levinson(), keys, {0.28, 50.0, -0.25, 0.3});
  // gamma = (sqrt(1 - 0.28^2), 0, 0.28) = (0.96, 0, 0.28).
  EXPECT_NEAR(s.initial.gamma[0], 0.96, 1e-15);
  EXPECT_EQ(s.initial.gamma[1], 0.0);
  EXPECT_EQ(s.initial.gamma[2], 0.28);
  EXPECT_EQ(s.initial.omega, Eigen::Vector3d(1.0, 2.0, 50.0)) << "the other components as in the base";
  EXPECT_EQ(s.initial.v, Eigen::Vector3d(0.5, -0.25, 0.0));
  EXPECT_EQ(s.initial.eps, -1e-5);
  const auto o = start_overrides(s);
  ASSERT_EQ(o.size(), 4u);
  EXPECT_EQ(o[0], "contact.k=0.3");
  EXPECT_EQ(o[1].rfind("initial.gamma=[0.96", 0), 0u) << o[1];
  EXPECT_EQ(o[2], "initial.omega=[1, 2, 50]");
  EXPECT_EQ(o[3], "initial.v=[0.5, -0.25, 0]");
}

TEST(EnsembleVariedKey, OnlyTheVectorsAStartChangesAreWritten) {
  const std::vector<VariedKey> keys{VariedKey::parse("initial.eps", "k")};
  const auto o = start_overrides(apply_start(base(), kane_levinson(), keys, {-2e-5}));
  EXPECT_EQ(o, std::vector<std::string>{"initial.eps=-2e-05"});
}

TEST(EnsembleVariedKey, VectorKeysAndOutOfRangeValuesAreRejectedNamingTheKey) {
  for (const std::string key : {"initial.gamma", "initial.omega", "initial.v", "contact.law"}) {
    try {
      (void)VariedKey::parse(key, "vary[2].key");
      ADD_FAILURE() << key;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("vary[2].key = '" + key + "'"), std::string::npos) << e.what();
    }
  }
  const std::vector<VariedKey> keys{VariedKey::parse("initial.gamma3", "k")};
  EXPECT_THROW((void)apply_start(base(), kane_levinson(), keys, {1.0000001}), std::invalid_argument);
  EXPECT_THROW((void)apply_start(base(), kane_levinson(), keys, {std::nan("")}), std::invalid_argument);
  EXPECT_NO_THROW((void)apply_start(base(), kane_levinson(), keys, {-1.0}));
}

// The horizontal 2x2 block's principal moments in closed form (m -+ r), independent of the
// eigen-solver the key uses: A (axis nearest e1) < B for the rattleback.
TEST(EnsembleVariedKey, MisalignmentZeroIsTheDiagonalTensorOfTheBasesMoments) {
  const Eigen::Matrix3d j = kane_levinson();
  const double m = 0.5 * (j(0, 0) + j(1, 1));
  const double r = std::hypot(0.5 * (j(0, 0) - j(1, 1)), j(0, 1));
  const StartState s = misaligned(j, 0.0);
  EXPECT_TRUE(s.inertia_set);
  EXPECT_FALSE(s.gamma_set || s.omega_set || s.velocity_set);
  EXPECT_EQ(s.inertia(0, 1), 0.0);
  EXPECT_EQ(s.inertia(1, 0), 0.0);
  EXPECT_EQ(s.inertia.col(2), Eigen::Vector3d(0.0, 0.0, 17.0e-4)) << "e3 and its moment J33 untouched";
  EXPECT_EQ(s.inertia.row(2), Eigen::RowVector3d(0.0, 0.0, 17.0e-4));
  EXPECT_NEAR(s.inertia(0, 0), m - r, 1e-15 * m) << "the smaller moment: the axis nearest e1";
  EXPECT_NEAR(s.inertia(1, 1), m + r, 1e-15 * m);
}

// delta is the angle rigid_rolling::misalignment_angle measures (its own convention, written
// independently: 2 delta = atan2(-2 J12, J22 - J11)), the principal moments stay, and the tensor
// is inertia_rotated_about_vertical(A, B, C, delta) of the same module.
TEST(EnsembleVariedKey, MisalignmentTurnsThePrincipalAxesByDeltaKeepingTheMoments) {
  const Eigen::Matrix3d j = kane_levinson();
  const double m = 0.5 * (j(0, 0) + j(1, 1));
  const double r = std::hypot(0.5 * (j(0, 0) - j(1, 1)), j(0, 1));
  for (const double delta : {-0.7, -0.06, -0.0143, -1e-8, 1e-8, 0.005, 0.03, 0.7}) {
    const Eigen::Matrix3d t = misaligned(j, delta).inertia;
    EXPECT_NEAR(rigid_rolling::misalignment_angle(t), delta, 1e-14) << delta;
    EXPECT_LT(tensor_difference(t, rigid_rolling::inertia_rotated_about_vertical(m - r, m + r, 17.0e-4, delta)), 1e-15)
        << delta;
    EXPECT_EQ(t, t.transpose()) << delta;
    EXPECT_EQ(t(0, 2), 0.0);
    EXPECT_EQ(t(1, 2), 0.0);
    // Invariants of the horizontal block: trace and determinant are the moments' sum and product.
    EXPECT_NEAR(t(0, 0) + t(1, 1), 2.0 * m, 1e-15 * m) << delta;
    EXPECT_NEAR(t(0, 0) * t(1, 1) - t(0, 1) * t(0, 1), (m - r) * (m + r), 1e-14 * (m - r) * (m + r)) << delta;
  }
  // The sign: the KL tensor's J12 > 0 is a negative angle; the opposite angle flips J12 alone.
  const Eigen::Matrix3d plus = misaligned(j, 0.0143).inertia, minus = misaligned(j, -0.0143).inertia;
  EXPECT_NEAR(minus(0, 1), 0.2e-4, 0.01 * 0.2e-4) << "J12 = +0.2e-4 kg m^2 at delta = -0.0143 rad";
  EXPECT_EQ(plus(0, 1), -minus(0, 1));
  EXPECT_EQ(plus(0, 0), minus(0, 0));
}

TEST(EnsembleVariedKey, MisalignmentAtTheBasesOwnAngleReproducesTheBase) {
  const Eigen::Matrix3d j = kane_levinson();
  const double own = rigid_rolling::misalignment_angle(j);
  EXPECT_NEAR(own, -0.0143, 5e-5) << "the Kane & Levinson misalignment";
  EXPECT_LT(tensor_difference(misaligned(j, own).inertia, j), 1e-15);
  // The axis nearest e1 keeps its moment also when it is the larger (J11 > J22: then
  // misalignment_angle, the smaller moment's axis, is a quarter turn away), and when C equals B.
  for (const Eigen::Matrix3d& other : {rigid_rolling::inertia_rotated_about_vertical(16e-4, 2e-4, 17e-4, 0.2),
                                       rigid_rolling::inertia_rotated_about_vertical(2e-4, 16e-4, 16e-4, -0.3)}) {
    const double angle = 0.5 * std::atan(2.0 * other(0, 1) / (other(0, 0) - other(1, 1)));  // |angle| < pi/4
    EXPECT_LT(tensor_difference(misaligned(other, angle).inertia, other), 1e-15) << other;
    EXPECT_NEAR(std::abs(angle), std::abs(other(0, 0) > other(1, 1) ? 0.2 : 0.3), 1e-14);
  }
}

// The tensor is written whole with round-trip numbers: read back, it is the same to the last bit.
TEST(EnsembleVariedKey, MisalignmentIsWrittenAsTheWholeTensorWithRoundTripNumbers) {
  const StartState s = misaligned(kane_levinson(), 0.03);
  const auto o = start_overrides(s);
  ASSERT_EQ(o.size(), 1u);
  ASSERT_EQ(o[0].rfind("body.inertia=[[", 0), 0u) << o[0];
  Eigen::Matrix3d back;
  const char* c = o[0].c_str() + std::string("body.inertia=").size();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      while (*c == '[' || *c == ',' || *c == ' ' || *c == ']') ++c;
      char* end = nullptr;
      back(i, k) = std::strtod(c, &end);
      ASSERT_NE(end, c) << o[0];
      c = end;
    }
  EXPECT_EQ(back, s.inertia) << o[0];
  EXPECT_EQ(std::string(c), "]]");
}

TEST(EnsembleVariedKey, MisalignmentOutOfRangeOrOfABaseItCannotTurnIsRejectedNamingTheKey) {
  const auto message = [](const Eigen::Matrix3d& j, double delta) {
    try {
      (void)misaligned(j, delta);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const auto expect_rejected = [&](const Eigen::Matrix3d& j, double delta, const std::string& rule) {
    const std::string m = message(j, delta);
    EXPECT_EQ(m.rfind("body.misalignment = ", 0), 0u) << m;
    EXPECT_NE(m.find(rule), std::string::npos) << m;
  };
  expect_rejected(kane_levinson(), std::nan(""), "finite");
  expect_rejected(kane_levinson(), std::numeric_limits<double>::infinity(), "finite");
  expect_rejected(kane_levinson(), std::numbers::pi / 4, "|delta| < pi/4");
  expect_rejected(kane_levinson(), -0.8, "|delta| < pi/4");
  EXPECT_NO_THROW((void)misaligned(kane_levinson(), std::nextafter(-std::numbers::pi / 4, 0.0)));
  Eigen::Matrix3d tilted = kane_levinson();
  tilted(0, 2) = tilted(2, 0) = 1e-7;  // e3 no principal axis
  expect_rejected(tilted, 0.01, "J13 = J23 = 0");
  tilted = kane_levinson();
  tilted(1, 2) = tilted(2, 1) = -1e-9;
  expect_rejected(tilted, 0.01, "J13 = J23 = 0");
  expect_rejected(Eigen::Vector3d(5e-4, 5e-4, 8e-4).asDiagonal().toDenseMatrix(), 0.01, "J11 = J22");
  Eigen::Matrix3d at45 = Eigen::Vector3d(5e-4, 5e-4, 8e-4).asDiagonal();
  at45(0, 1) = at45(1, 0) = 1e-4;
  expect_rejected(at45, 0.01, "45 degrees");
  // The puck has no inertia tensor.
  try {
    (void)puck_start_overrides(Eigen::Vector2d::Zero(), {VariedKey::parse("body.misalignment", "k", true)}, {0.01});
    ADD_FAILURE() << "a puck accepted body.misalignment";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("body.misalignment = ", 0), 0u) << e.what();
  }
}

TEST(EnsembleReplica, ReplicaZeroIsTheStartItself) {
  StartState s;
  s.initial = base();
  const StartState r = perturb_replica(s, 1e-6, 5.0, 1, 3, 0);
  EXPECT_EQ(r.initial.gamma, s.initial.gamma);
  EXPECT_EQ(r.initial.omega, s.initial.omega);
  EXPECT_FALSE(r.gamma_set);
}

TEST(EnsembleReplica, PerturbationHasTheGivenSizeAndIsSeeded) {
  StartState s;
  s.initial = base();
  const double size = 1e-6;
  const double omega_norm = s.initial.omega.norm();
  for (long replica = 1; replica < 20; ++replica) {
    const StartState r = perturb_replica(s, size, 5.0, 1, 3, replica);
    EXPECT_NEAR(r.initial.gamma.norm(), 1.0, 1e-15);
    const double tilt = (r.initial.gamma - s.initial.gamma).norm();
    EXPECT_GT(tilt, 0.0);
    EXPECT_LE(tilt, std::sqrt(3.0) * size * 1.000001);  // |u| <= sqrt(3) before normalisation
    const double dw = (r.initial.omega - s.initial.omega).norm();
    EXPECT_GT(dw, 0.0);
    EXPECT_LE(dw, std::sqrt(3.0) * size * omega_norm * 1.000001) << "scaled by |omega| (> the rate scale 5)";
    EXPECT_EQ(r.initial.v, s.initial.v) << "v is not perturbed";
    EXPECT_TRUE(r.gamma_set && r.omega_set);
    const StartState again = perturb_replica(s, size, 5.0, 1, 3, replica);
    EXPECT_EQ(again.initial.gamma, r.initial.gamma) << "seeded by (seed, start, replica) alone";
  }
  EXPECT_NE(perturb_replica(s, size, 5.0, 1, 3, 1).initial.gamma, perturb_replica(s, size, 5.0, 1, 4, 1).initial.gamma);
  EXPECT_NE(perturb_replica(s, size, 5.0, 1, 3, 1).initial.gamma, perturb_replica(s, size, 5.0, 2, 3, 1).initial.gamma);
  // A start at rest is perturbed on the body's rate scale.
  s.initial.omega.setZero();
  const double dw = perturb_replica(s, size, 5.0, 1, 3, 1).initial.omega.norm();
  EXPECT_GT(dw, 0.0);
  EXPECT_LE(dw, std::sqrt(3.0) * size * 5.0);
}

TEST(EnsembleVariedKey, APuckStartSetsItsVelocityAndPassesPlainKeysOn) {
  const std::vector<VariedKey> keys = {VariedKey::parse("initial.v2", "k"), VariedKey::parse("puck.b", "k"),
                                       VariedKey::parse("initial.v1", "k")};
  const auto o = puck_start_overrides(Eigen::Vector2d(1.0, 0.5), keys, {0.25, 0.02, 3.0});
  EXPECT_EQ(o, (std::vector<std::string>{"puck.b=0.02", "initial.v=[3, 0.25]"}));
  EXPECT_THROW((void)VariedKey::parse("initial.omega", "k"), std::invalid_argument) << "the body's is a vector";
  EXPECT_EQ(puck_start_overrides(Eigen::Vector2d(1.0, 0.5), {VariedKey::parse("initial.omega", "k", true)}, {7.0}),
            (std::vector<std::string>{"initial.omega=7"}))
      << "the puck's spin is a plain scalar key";
  for (const char* body_key : {"initial.gamma3", "initial.omega3", "initial.v3"})
    EXPECT_THROW((void)puck_start_overrides(Eigen::Vector2d::Zero(), {VariedKey::parse(body_key, "k")}, {0.5}),
                 std::invalid_argument)
        << body_key;
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
