#include "dynamics/shapes/shape_registry.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/shapes/body_of_revolution.h"
#include "dynamics/shapes/ellipsoid.h"
#include "dynamics/shapes/toroidal_disk.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::shapes {
namespace shape_registry_test {

std::string error_of(const ShapeSpec& spec) {
  try {
    (void)make_shape(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DynShapesRegistry, ListsTheBuiltInKindsFirst) {
  const std::vector<std::string> kinds = shape_kinds();
  ASSERT_GE(kinds.size(), 3u);
  EXPECT_EQ(kinds[0], "ellipsoid");
  EXPECT_EQ(kinds[1], "revolution");
  EXPECT_EQ(kinds[2], "toroidal-disk");
  const auto info = list_shapes();
  ASSERT_EQ(info.size(), kinds.size());
  EXPECT_EQ(info[0].parameters.at(0).name, "semi_axes");
  EXPECT_EQ(info[0].parameters.at(0).count, 3u);
  EXPECT_FALSE(info[2].summary.empty());
}

TEST(DynShapesRegistry, MakesEachBuiltInKind) {
  const auto e = make_shape({"ellipsoid", {{"semi_axes", {0.2, 0.03, 0.02}}}});
  EXPECT_EQ(e->kind(), "ellipsoid");
  EXPECT_EQ(dynamic_cast<const Ellipsoid&>(*e).semi_axes(), Eigen::Vector3d(0.2, 0.03, 0.02));
  const auto r = make_shape({"revolution", {{"chi2", {0.01, 0.0, -1.0}}}});  // a sphere of radius 0.1
  EXPECT_EQ(r->kind(), "revolution");
  EXPECT_NEAR(r->contact(Eigen::Vector3d::UnitZ()).R_major, 0.1, 1e-15);
  const auto d = make_shape({"toroidal-disk", {{"radius", {0.05}}, {"rim_radius", {0.002}}}});
  EXPECT_EQ(d->kind(), "toroidal-disk");
  EXPECT_EQ(dynamic_cast<const ToroidalDisk&>(*d).rim_radius(), 0.002);
}

TEST(DynShapesRegistry, ErrorsNameTheScenarioKeyAndTheRule) {
  const std::string unknown = error_of({"cube", {}});
  EXPECT_EQ(unknown.rfind("body.shape = 'cube' is invalid: it is not a known shape; known shapes: ellipsoid, "
                          "revolution, toroidal-disk", 0), 0u) << unknown;
  EXPECT_EQ(error_of({"ellipsoid", {}}),
            "body.semi_axes is required by the 'ellipsoid' shape: semi-axes a1, a2, a3 along e1, e2, e3, each > 0 "
            "(3 values, m)");
  EXPECT_EQ(error_of({"ellipsoid", {{"semi_axes", {0.2, 0.1}}}}),
            "body.semi_axes = [0.2, 0.1] is invalid: the 'ellipsoid' shape needs semi-axes a1, a2, a3 along e1, e2, "
            "e3, each > 0 (3 values, m)");
  EXPECT_EQ(error_of({"ellipsoid", {{"semi_axes", {0.2, -0.1, 0.1}}}}),
            "body.semi_axes = [0.2, -0.1, 0.1] is invalid: the semi-axes a1, a2, a3 must be finite and > 0 m");
  EXPECT_EQ(error_of({"ellipsoid", {{"semi_axes", {0.2, 0.1, 0.1}}, {"radius", {1.0}}}}),
            "body.radius is not a parameter of the 'ellipsoid' shape; its parameters: semi_axes");
  EXPECT_EQ(error_of({"toroidal-disk", {{"radius", {0.05}}, {"rim_radius", {0.0}}}}),
            "body.rim_radius = 0 is invalid: it must be finite and > 0 m");
  EXPECT_NE(error_of({"toroidal-disk", {{"radius", {0.05}}, {"rim_radius", {NAN}}}}).find("must be finite"),
            std::string::npos);
  EXPECT_NE(error_of({"revolution", {{"chi2", {1.0, 0.0, 1.0}}}}).find("body.chi2"), std::string::npos);
  // Another section, and the key kept on the exception for the caller to say who set it.
  ShapeSpec spec{"ellipsoid", {{"semi_axes", {0.2, 0.1}}}, "bodies.celt"};
  try {
    (void)make_shape(spec);
    ADD_FAILURE();
  } catch (const support::InvalidValue& e) {
    EXPECT_EQ(e.key(), "bodies.celt.semi_axes");
  }
}

class Unit final : public Shape {
 public:
  explicit Unit(std::string_view kind) : kind_(kind) {}
  [[nodiscard]] std::string_view kind() const override { return kind_; }
  [[nodiscard]] SurfaceContact contact(const Eigen::Vector3d& g) const override { return {-g, 1.0, 1.0, Eigen::Vector3d::UnitX()}; }
  [[nodiscard]] RadiiGradient radii_gradient(const Eigen::Vector3d&, const SurfaceContact&) const override { return {}; }
  [[nodiscard]] SolidMassProperties homogeneous(double) const override { return {}; }
  [[nodiscard]] double size() const override { return 1.0; }
  [[nodiscard]] double radius_about(const Eigen::Vector3d& p) const override { return 1.0 + p.norm(); }
  [[nodiscard]] bool contains(const Eigen::Vector3d& p) const override { return p.norm() < 1.0; }

 private:
  std::string kind_;
};

TEST(DynShapesRegistry, RegistersAndUnregistersUserKinds) {
  register_shape({"test-unit", "unit sphere (test)", {}, [](const ShapeArguments&) {
                    return std::make_shared<const Unit>("test-unit");
                  }});
  EXPECT_EQ(shape_kinds().back(), "test-unit");
  EXPECT_EQ(make_shape({"test-unit", {}})->size(), 1.0);
  EXPECT_NE(error_of({"test-unit", {{"radius", {1.0}}}}).find("it takes none"), std::string::npos);
  EXPECT_THROW(register_shape({"test-unit", "again", {}, [](const ShapeArguments&) {
                                 return std::make_shared<const Unit>("test-unit");
                               }}),
               std::invalid_argument);
  EXPECT_TRUE(unregister_shape("test-unit"));
  EXPECT_FALSE(unregister_shape("test-unit"));
  EXPECT_THROW((void)unregister_shape("ellipsoid"), std::invalid_argument);
  EXPECT_NE(error_of({"test-unit", {}}).find("not a known shape"), std::string::npos);
  // Malformed registrations.
  const ShapeFactory f = [](const ShapeArguments&) { return std::make_shared<const Unit>("x"); };
  EXPECT_THROW(register_shape({"Bad Name", "s", {}, f}), std::invalid_argument);
  EXPECT_THROW(register_shape({"test-x", "", {}, f}), std::invalid_argument);
  EXPECT_THROW(register_shape({"test-x", "s", {}, nullptr}), std::invalid_argument);
  EXPECT_THROW(register_shape({"test-x", "s", {{"a", 1, "m", ""}, {"a", 1, "m", ""}}, f}), std::invalid_argument);
  EXPECT_THROW(register_shape({"test-x", "s", {{"shape", 1, "m", ""}}, f}), std::invalid_argument);
  // A factory that makes another kind is a programming error.
  register_shape({"test-liar", "makes another kind (test)", {}, f});
  EXPECT_THROW((void)make_shape({"test-liar", {}}), std::logic_error);
  EXPECT_TRUE(unregister_shape("test-liar"));
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
