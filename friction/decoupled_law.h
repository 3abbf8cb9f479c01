#pragma once
// Decoupled friction: full Coulomb sliding friction plus an independent torsional limit — the law
// of Bullet's, Chrono's and Gazebo's (ODE's) spinning friction, with a given length r_spin or with
// the Hertz-calibrated default.
//
//   F1 = kN if U > 0, 0 if U = 0;   F2 = 0;   M = M0 sign(Omega) (0 if Omega = 0),
//
// where the torque limit is, for `decoupled:r_spin=...`, M0 = N r_spin (r_spin a length, m: the
// engines bound the spinning torque by |tau| <= r_spin N, independently of the sliding force; in
// maximally dissipative sliding the torque sits on that bound, M = N r_spin sign(Omega)), and, by
// default, the exact pure-spin torque of the Hertz patch,
//
//   M0 = (3/8) k N a E(e),  e^2 = 1 - mu^2,  mu = b/a,
//
// with E the complete elliptic integral of the second kind (boost::math::ellint_2, modulus e;
// circle: (3 pi/16) kN a, docs/model.md). The default is the law known before as
// `coulomb-decoupled` (an alias of `decoupled` in the registry); `decoupled:r_spin=0` has no spin friction at all.
//
// Provenance: the classical decoupled model of sliding plus pivoting friction (e.g. Contensou's
// "pivoting" torque with the Hertz pressure). What each engine's parameter means and how it maps
// to r_spin (Bullet's `spinningFriction` combined with the other body's friction, Chrono's
// `SetSpinningFriction`, Gazebo's torsional `coefficient` times (3 pi/16) `patch_radius`):
// docs/engines.md §3.
// The default is exact in the two pure limits (U = 0, or Omega = 0) and ignores the coupling in
// between: it overestimates both F1 and |M| whenever slip and spin coexist (the exact law has
// F1 < kN and |M| < M0 for U > 0, Omega != 0).
// Limits: discontinuous at U = 0 (F1 jumps from 0 to kN) and at Omega = 0 (M jumps by 2 M0); F1
// is even and M odd in Omega, nothing depends on psi. Dissipative: F1 U + M Omega =
// kN U + M0 |Omega| >= 0. A fixed r_spin gives a torque that knows nothing of the patch (no
// `bounded` promise); N r_spin overflows only for r_spin > 1 m and N near the largest double
// (rejected with std::invalid_argument). Every other valid input is evaluated.
// Against `exact` the default is an upper bound; its errors are the whole coupling effect: up to
// kN in F1 (slow slip) and up to M0 in M (fast slip), rms 0.60 kN and 0.33 kNa on the study grid
// (docs/accuracy.md). The r_spin that best matches `exact`, per pressure: docs/engines.md.

#include <optional>
#include <string>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"

namespace frictionlab::friction {

/// Decoupled Coulomb sliding friction plus a torsional limit N r_spin, or the exact Hertz
/// pure-spin torque by default.
class DecoupledLaw final : public FrictionLaw {
 public:
  /// r_spin: the torsional length in metres (finite, >= 0), or none for the exact pure-spin torque
  /// of the Hertz patch. std::invalid_argument naming r_spin otherwise.
  explicit DecoupledLaw(std::optional<double> r_spin = std::nullopt);

  /// What `decoupled:r_spin=...` may set (friction/law_spec.h): r_spin, m, >= 0; none: the exact
  /// Hertz pure-spin torque.
  [[nodiscard]] static std::vector<LawParameter> parameters();

  [[nodiscard]] std::string_view name() const override { return "decoupled"; }
  [[nodiscard]] std::string_view summary() const override { return summary_; }
  [[nodiscard]] LawPromises promises() const override;
  /// The torsional length, m, or none (Hertz pure-spin torque).
  [[nodiscard]] std::optional<double> spin_length() const { return r_spin_; }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override;

  std::optional<double> r_spin_;
  std::string summary_;
};

}  // namespace frictionlab::friction
