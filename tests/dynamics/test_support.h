#pragma once
// Helpers shared by the dynamics tests: small test laws with known behaviour and common bodies
// (EXPECT_EIGEN_NEAR, from tests/support/eigen_near.h, compares Eigen objects).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <atomic>
#include <limits>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dynamics/body/body.h"
#include "dynamics/body/state.h"
#include "tests/support/eigen_near.h"
#include "friction/law.h"

namespace frictionlab::testing {

/// The brief's decoupled Coulomb law for a circular patch: F1 = kN when U > 0 (0 at U = 0),
/// F2 = 0, M = (3 pi/16) k N a sign(Omega). Ignores b and psi. Counts its calls.
class CoulombCircleTestLaw final : public friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-coulomb-circle"; }
  [[nodiscard]] std::string_view summary() const override { return "decoupled Coulomb, circle (tests)"; }
  mutable std::atomic<long> calls{0};

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    ++calls;
    const double kN = in.k * in.N;
    const double sgn = in.Omega > 0.0 ? 1.0 : (in.Omega < 0.0 ? -1.0 : 0.0);
    return {in.U > 0.0 ? kN : 0.0, 0.0, 3.0 * std::numbers::pi / 16.0 * kN * in.a * sgn};
  }
};

/// A smooth, coupled, dissipative law (the "ellipsoidal" law of Moller, Leine and Glocker,
/// docs/model.md) with an extra F2 = kN U Omega a / (U^2 + (a Omega)^2 + a^2) so that every
/// component of the friction is exercised: F1 = kN U / sqrt(U^2 + Rb^2 Omega^2), M = kN Rb^2 Omega
/// / sqrt(...), Rb = (3 pi/16) sqrt(a b). F2 does no work (it is normal to the slip), so the law is
/// dissipative. Zero at U = Omega = 0.
class SmoothTestLaw final : public friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-smooth"; }
  [[nodiscard]] std::string_view summary() const override { return "smooth coupled law (tests)"; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    const double kN = in.k * in.N;
    const double Rb = 3.0 * std::numbers::pi / 16.0 * std::sqrt(in.a * in.b);
    const double den = std::sqrt(in.U * in.U + Rb * Rb * in.Omega * in.Omega);
    if (den == 0.0) return {};
    const double aw = in.a * in.Omega;
    return {kN * in.U / den, kN * in.U * aw / (in.U * in.U + aw * aw + in.a * in.a), kN * Rb * Rb * in.Omega / den};
  }
};

/// Fails the test if it is ever called (no friction must be evaluated out of contact).
class ForbiddenLaw final : public friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-forbidden"; }
  [[nodiscard]] std::string_view summary() const override { return "must not be called (tests)"; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    ADD_FAILURE() << "friction law called with N = " << in.N;
    return {};
  }
};

/// Returns a non-finite F2 once the slip speed drops below `pole_U` (a stand-in for a law's pole).
class PoleTestLaw final : public friction::FrictionLaw {
 public:
  explicit PoleTestLaw(double pole_U) : pole_U_(pole_U) {}
  [[nodiscard]] std::string_view name() const override { return "test-pole"; }
  [[nodiscard]] std::string_view summary() const override { return "non-finite below a slip speed (tests)"; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    const double kN = in.k * in.N;
    return {kN, in.U < pole_U_ ? std::numeric_limits<double>::infinity() : 0.0, 0.0};
  }
  double pole_U_;
};

/// Throws once the spin exceeds `limit` (a law rejecting its input mid-run).
class ThrowingTestLaw final : public friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-throwing"; }
  [[nodiscard]] std::string_view summary() const override { return "throws mid-run (tests)"; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    if (std::abs(in.Omega) < 5.0) throw std::invalid_argument("test law: Omega below 5 1/s is not accepted");
    return {0.0, 0.0, 0.01 * in.N * in.a * (in.Omega > 0 ? 1.0 : -1.0)};
  }
};

/// The decoupled Coulomb forces of CoulombCircleTestLaw, and a declared singular set where the slip
/// ratio s = U/(a |Omega|) passes s_pole: the F2 "denominator" is s - s_pole (through_zero = true,
/// a pole) or 1/(s - s_pole) (false: it changes sign through infinity, which is no pole). The forces
/// stay finite across it, so nothing but the watch of the denominators can notice the crossing.
class DeclaredPoleTestLaw final : public friction::FrictionLaw {
 public:
  DeclaredPoleTestLaw(double s_pole, bool through_zero) : s_pole_(s_pole), through_zero_(through_zero) {}
  [[nodiscard]] std::string_view name() const override { return "test-declared-pole"; }
  [[nodiscard]] std::string_view summary() const override { return "finite forces, declared pole (tests)"; }
  [[nodiscard]] bool has_poles() const override { return true; }
  [[nodiscard]] friction::PoleDenominators pole_denominators(const friction::ContactInput& in) const override {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double d = in.U / (in.a * std::abs(in.Omega)) - s_pole_;
    return {nan, through_zero_ ? d : 1.0 / d, nan};
  }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    const double kN = in.k * in.N;
    const double sgn = in.Omega > 0.0 ? 1.0 : (in.Omega < 0.0 ? -1.0 : 0.0);
    return {in.U > 0.0 ? kN : 0.0, 0.0, 3.0 * std::numbers::pi / 16.0 * kN * in.a * sgn};
  }
  double s_pole_;
  bool through_zero_;
};

/// A homogeneous sphere (m, R) with its centre of mass at the centre.
inline dynamics::Body sphere_body(double radius, double mass) {
  dynamics::BodySpec spec;
  spec.preset = "sphere";
  spec.radius = radius;
  spec.mass = mass;
  return dynamics::make_body(spec);
}

/// A homogeneous disk with a toroidal rim (docs/convex-bodies.md §5): centre circle R, rim radius
/// rho (m), mass (kg).
inline dynamics::Body toroidal_disk_body(double radius, double rim_radius, double mass) {
  dynamics::BodySpec spec;
  spec.shape = "toroidal-disk";
  spec.shape_parameters["radius"] = {radius};
  spec.shape_parameters["rim_radius"] = {rim_radius};
  spec.mass = mass;
  return dynamics::make_body(spec);
}

/// One of the paper's eggs (docs/model.md), m = 2 kg.
inline dynamics::Body egg_body(const std::string& preset) {
  dynamics::BodySpec spec;
  spec.preset = preset;
  spec.mass = 2.0;
  return dynamics::make_body(spec);
}

/// The paper's case a (docs/model.md): gamma3 = 0.97, gamma2 = 0, omega = (0, 0, 100) 1/s, v = 0,
/// eps0 = -0.3e-4 m.
inline dynamics::StateVector paper_case_a() {
  return dynamics::make_state(Eigen::Vector3d::Zero(), {0.0, 0.0, 100.0},
                              {std::sqrt(1.0 - 0.97 * 0.97), 0.0, 0.97}, -0.3e-4);
}

}  // namespace frictionlab::testing
