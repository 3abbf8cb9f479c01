#include "dynamics/rigid_rolling/rigid_body.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "dynamics/rigid_rolling/ellipsoid_surface.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace rigid_body_test {

RigidRollingBody valid_body() {
  RigidRollingBody b;
  b.mass = 1.0;
  b.inertia = Eigen::Vector3d(2e-4, 16e-4, 17e-4).asDiagonal();
  b.surface = std::make_shared<EllipsoidSurface>(Eigen::Vector3d(0.2, 0.03, 0.02), Eigen::Vector3d(0.0, 0.0, 0.01));
  return b;
}

void expect_invalid(const RigidRollingBody& b, const std::string& key) {
  try {
    b.validate();
    ADD_FAILURE() << "no exception for " << key;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(DynRigidRollingBody, ValidBodyPasses) { EXPECT_NO_THROW(valid_body().validate()); }

TEST(DynRigidRollingBody, InvalidValuesNameTheirKey) {
  RigidRollingBody b = valid_body();
  b.mass = 0.0;
  expect_invalid(b, "body.mass");
  b = valid_body();
  b.gravity = -9.81;
  expect_invalid(b, "body.gravity");
  b = valid_body();
  b.spin_damping = -1.0;
  expect_invalid(b, "body.spin_damping");
  b = valid_body();
  b.surface.reset();
  expect_invalid(b, "body.surface");
  b = valid_body();
  b.inertia(0, 1) = 1e-5;  // not symmetric
  expect_invalid(b, "body.inertia");
  b = valid_body();
  b.inertia(0, 0) = -1e-4;
  expect_invalid(b, "body.inertia");
  b = valid_body();
  b.inertia(2, 2) = 19e-4;  // 19 > 2 + 16: no real body
  expect_invalid(b, "body.inertia");
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
