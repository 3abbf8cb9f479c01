// The engines' laws made from specs by the registry: each parameter reaches its law, the defaults
// are the documented ones, the old names still denote the Hertz-calibrated defaults, bad values
// are refused naming the key.

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>
#include <string>

#include "friction/decoupled_law.h"
#include "friction/ellipsoidal_law.h"
#include "friction/mujoco_elliptic_law.h"
#include "friction/registry.h"

namespace frictionlab::friction {
namespace engine_law_specs_test {

// A contact that slips and spins, with its pure-spin twin (const, not constexpr: an angle's cosine and
// sine are computed at run time, friction/patch_angle.h).
const ContactInput kMoving{0.03, -7.0, 0.004, 0.002, 0.4, 12.0, 0.3};
const ContactInput kSpin{0.0, 5.0, 0.004, 0.002, 0.4, 12.0, 0.3};

void expect_same(const FrictionLaw& a, const FrictionLaw& b, const ContactInput& in) {
  const auto f = a.evaluate(in);
  const auto g = b.evaluate(in);
  EXPECT_EQ(f.F1, g.F1) << a.spec() << " vs " << b.spec();
  EXPECT_EQ(f.F2, g.F2) << a.spec() << " vs " << b.spec();
  EXPECT_EQ(f.M, g.M) << a.spec() << " vs " << b.spec();
}

TEST(EngineLawSpecs, ParametersReachTheLaws) {
  expect_same(*make_law("ellipsoidal:Rb=0.0021"), EllipsoidalLaw(0.0021), kMoving);
  expect_same(*make_law("mujoco-elliptic:torsional=3.7e-4"), MujocoEllipticLaw(3.7e-4), kMoving);
  expect_same(*make_law("decoupled:r_spin=1e-3"), DecoupledLaw(1e-3), kMoving);
  // Pure-spin torques from the closed forms: kN Rb, N torsional, N r_spin.
  EXPECT_NEAR(make_law("ellipsoidal:Rb=0.0021")->evaluate(kSpin).M, 0.3 * 12.0 * 0.0021, 1e-15);
  EXPECT_NEAR(make_law("mujoco-elliptic:torsional=3.7e-4")->evaluate(kSpin).M, 12.0 * 3.7e-4, 1e-15);
  EXPECT_NEAR(make_law("decoupled:r_spin=1e-3")->evaluate(kSpin).M, 12.0 * 1e-3, 1e-15);
  EXPECT_EQ(make_law("decoupled:r_spin=0")->evaluate(kSpin).M, 0.0);
}

TEST(EngineLawSpecs, DefaultsAndOldNames) {
  // mujoco-elliptic defaults to MuJoCo's own 0.005 m.
  expect_same(*make_law("mujoco-elliptic"), MujocoEllipticLaw(0.005), kMoving);
  // ellipsoidal and decoupled default to the Hertz calibration, which the old names denote.
  for (const ContactInput& in : {kMoving, kSpin}) {
    expect_same(*make_law("ellipsoidal"), *make_law("moller-ellipsoidal"), in);
    expect_same(*make_law("decoupled"), *make_law("coulomb-decoupled"), in);
  }
  // On a circle both are exact at pure spin: (3 pi/16) kN a.
  const ContactInput circle{0.0, 2.0, 0.01, 0.01, 0.0, 5.0, 0.2};
  for (const char* spec : {"ellipsoidal", "decoupled"}) {
    EXPECT_NEAR(make_law(spec)->evaluate(circle).M, 3.0 * std::numbers::pi / 16.0 * 0.2 * 5.0 * 0.01, 1e-15) << spec;
  }
}

TEST(EngineLawSpecs, BadValuesAreRefusedNamingTheKey) {
  for (const char* spec : {"ellipsoidal:Rb=0", "ellipsoidal:Rb=-1", "mujoco-elliptic:torsional=0",
                           "decoupled:r_spin=-0.001", "decoupled:r_spin=inf", "ellipsoidal:torsional=1"}) {
    try {
      (void)make_law(spec);
      ADD_FAILURE() << spec << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
