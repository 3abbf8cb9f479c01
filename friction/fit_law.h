#pragma once
// `fit`: the closed-form law of friction/standalone/fit_law.h behind frictionlab's interface, for
// each pressure model (`fit:pressure=hertz|uniform|punch`). The header, which an engine may copy,
// holds the formula, the fitted coefficients and what holds by construction; docs/fit.md derives
// it and reports how it was fitted and how far it is from `exact`.
//
// Provenance: the form is ours — the gradient of a dissipation function D = P^(1/8), P a
// polynomial of degree 4 in the squared generalized velocities with nonnegative coefficients, in
// the manner of the polynomial limit surfaces of robotic pushing (Zhou, Bowers, Mason, Bagnell,
// "A convex polynomial force-motion model for planar sliding", 2016, cited as recalled), with the
// exact pure-spin moment and the exact fast-slip expansion (docs/model.md) built in, and 20
// coefficients per pressure fitted to `exact` by friction/tools/fit_dissipation.py.
// Validity: b/a in [0.05, 1] (fitted); below, the polynomials extrapolate, every promise below
// still holds, the accuracy is not measured. Largest errors found against `exact` on 120,000
// seeded points per pressure (tests/friction/fit_law_test.cpp): frictionlab_fit::kMaxError,
// per kN (kN = k·N) and per kNa.
//
// Limits, each exact: N = 0 or k = 0: zero. U = Omega = 0: zero (the law is indeterminate there,
// as `exact`). Omega = 0: F1 = kN, F2 = M = 0. U = 0: F = 0, M = c_p kNa E(e) sign(Omega).

#include <span>
#include <string_view>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"
#include "friction/pressure.h"

namespace frictionlab::friction {

/// The tolerance of the promises of `fit` that hold by construction (dissipation, parities,
/// symmetries, pure spin, bounds), per kN and kNa: rounding of a closed form.
inline constexpr double kFitLawPromiseTolerance = 1e-12;

/// The `fit` law for a pressure model.
class FitLaw final : public FrictionLaw {
 public:
  explicit FitLaw(Pressure pressure = Pressure::hertz) : pressure_(pressure) {}

  /// What a spec may set: pressure = hertz|uniform|punch, as for `exact`.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] Pressure pressure() const { return pressure_; }
  /// The largest error found against `exact` for this pressure, per kN and kNa, b/a in [0.05, 1].
  [[nodiscard]] double max_error() const;

  [[nodiscard]] std::string_view name() const override { return "fit"; }
  [[nodiscard]] std::string_view summary() const override {
    return "closed form, the gradient of a fitted degree-one dissipation function: dissipative and "
           "pole-free by construction, exact pure spin and fast slip (docs/fit.md; standalone header "
           "friction/standalone/fit_law.h)";
  }
  [[nodiscard]] LawPromises promises() const override;

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;
  void do_evaluate_batch(std::span<const ContactInput> in, std::span<FrictionForces> out) const override;
  Pressure pressure_;
};

}  // namespace frictionlab::friction
