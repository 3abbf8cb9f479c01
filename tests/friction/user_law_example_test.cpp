// The example of docs/extending.md, compiled and run: a user's own friction law, defined and
// registered in the user's code (no edit of friction/registry.cpp), then used by spec like any
// built-in law. Keep this file and the page in step.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "friction/registry.h"

namespace user {

namespace fl = frictionlab::friction;

// --- docs/extending.md: example begins ---
// Coulomb sliding friction with a torsional resistance of radius r_spin, decoupled:
// F1 = kN sign(U), F2 = 0, M = kN r_spin sign(Omega)   (kN = k·N: friction coefficient times normal force).
class TorsionalLaw final : public fl::FrictionLaw {
 public:
  explicit TorsionalLaw(double r_spin) : r_spin_(r_spin) {}
  [[nodiscard]] std::string_view name() const override { return "user-torsional"; }
  [[nodiscard]] std::string_view summary() const override {
    return "decoupled Coulomb sliding and torsional friction of radius r_spin (user example)";
  }

 private:
  [[nodiscard]] fl::FrictionForces do_evaluate(const fl::ContactInput& in) const override {
    const double kN = in.k * in.N;
    const double F1 = in.U > 0.0 ? kN : 0.0;
    const double M = in.Omega == 0.0 ? 0.0 : std::copysign(kN * r_spin_, in.Omega);
    return {F1, 0.0, M};
  }
  double r_spin_;  // m
};

// Registered before main() runs: the law is known to make_law(), list_laws() and everything built
// on them (the command line, scenario files, studies) from then on.
const fl::LawRegistrar torsional_registrar{{
    .name = "user-torsional",
    .summary = "decoupled Coulomb sliding and torsional friction of radius r_spin (user example)",
    .parameters = {fl::LawParameter::number("r_spin", 0.0, false, 1.0, false, "m", 0.001, "",
                                            "torsional friction radius")},
    .facts = {},
    .factory = [](const fl::LawArguments& args) { return std::make_unique<TorsionalLaw>(*args.number("r_spin")); },
}};
// --- docs/extending.md: example ends ---

}  // namespace user

namespace frictionlab::friction {
namespace user_law_example_test {

TEST(UserLawExample, IsMadeByItsSpecAndComputesItsFormula) {
  const auto law = make_law("user-torsional:r_spin=0.002");
  EXPECT_EQ(law->name(), "user-torsional");
  EXPECT_EQ(law->spec(), "user-torsional:r_spin=0.002");
  // U = 0.1 m/s, Omega = -3 rad/s, a = 0.01 m, b = 0.005 m, psi = 0, N = 10 N, k = 0.5.
  const FrictionForces f = law->evaluate({0.1, -3.0, 0.01, 0.005, 0.0, 10.0, 0.5});
  EXPECT_EQ(f.F1, 5.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, -5.0 * 0.002);
  EXPECT_EQ(make_law("user-torsional")->evaluate({0.0, 1.0, 0.01, 0.005, 0.0, 10.0, 0.5}).M, 5.0 * 0.001);
  EXPECT_THROW((void)make_law("user-torsional:r_spin=-1"), std::invalid_argument);
}

// A law without parameters, registered at run time by the short form.
class NoFrictionLaw final : public FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "user-no-friction"; }
  [[nodiscard]] std::string_view summary() const override { return "no friction at all (user example)"; }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput&) const override { return {}; }
};

TEST(UserLawExample, TheShortFormRegistersALawWithoutParameters) {
  register_law("user-no-friction", "no friction at all (user example)", [] { return std::make_unique<NoFrictionLaw>(); });
  const FrictionForces f = make_law("user-no-friction")->evaluate({0.1, -3.0, 0.01, 0.005, 0.0, 10.0, 0.5});
  EXPECT_EQ(f.F1, 0.0);
  EXPECT_EQ(f.M, 0.0);
  EXPECT_THROW((void)make_law("user-no-friction:x=1"), std::invalid_argument);  // it has no parameters
  EXPECT_TRUE(unregister_law("user-no-friction"));
  EXPECT_THROW((void)make_law("user-no-friction"), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::friction
