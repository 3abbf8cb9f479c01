// Varied keys and replicas (dynamics/ensemble/varied_key.h, dynamics/ensemble/replica.h).

#include "dynamics/ensemble/varied_key.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dynamics/ensemble/replica.h"

namespace frictionlab::dynamics::ensemble {
namespace {

InitialState base() {
  InitialState s;
  s.gamma = Eigen::Vector3d(0.6, 0.0, 0.8);
  s.omega = Eigen::Vector3d(1.0, 2.0, 3.0);
  s.v = Eigen::Vector3d(0.5, 0.0, 0.0);
  s.eps = -1e-5;
  return s;
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

  const StartState s = apply_start(base(), keys, {0.28, 50.0, -0.25, 0.3});
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
  const auto o = start_overrides(apply_start(base(), keys, {-2e-5}));
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
  EXPECT_THROW((void)apply_start(base(), keys, {1.0000001}), std::invalid_argument);
  EXPECT_THROW((void)apply_start(base(), keys, {std::nan("")}), std::invalid_argument);
  EXPECT_NO_THROW((void)apply_start(base(), keys, {-1.0}));
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
