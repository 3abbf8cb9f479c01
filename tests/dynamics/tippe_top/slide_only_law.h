#pragma once
// A test law without a spin moment: the exact law's sliding force (F1, F2) and M = 0. Not a
// physical law; it makes Jellett's quantity of a sphere an exact integral of the motion
// (dynamics/tippe_top/tippe_top_observables.h), whatever the sliding force.

#include "friction/exact_law.h"
#include "friction/law.h"

namespace frictionlab::testing {

class SlideOnlyTestLaw final : public friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-slide-only"; }
  [[nodiscard]] std::string_view summary() const override { return "exact sliding force, no spin moment (tests)"; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    friction::FrictionForces f = exact_.evaluate(in);
    f.M = 0.0;
    return f;
  }
  friction::ExactLaw exact_;
};

}  // namespace frictionlab::testing
