#pragma once
// A test law, independent of friction/: the local Coulomb law integrated over a circular patch under
// UNIFORM pressure p = N/(pi a^2) (the classical Contensou-Erismann setting), by a 1-D quadrature
// about the instantaneous centre of rotation c (docs/model.md §1): in polar coordinates (s, phi)
// about c the traction has the fixed direction -z x e(phi) along each ray, so with L(phi) the
// ray's length inside the patch (units of a)
//     F = -k p a^2 z x ∫ e(phi) L^2/2 dphi,      M = k p a^3 ∫ [(c.e) L^2/2 + L^3/3] dphi,
// (for c outside the patch each ray contributes between its entry L1 and exit L2). Inside: a
// trapezoid rule over the full circle (the integrand is periodic and smooth for |c| < 1 a);
// outside: Gauss-Legendre over the rays that meet the patch, phi = phi0 + alpha sin(theta).
// Checks of its own (uniform_circle_law_test.cpp): pure spin (2/3) kNa, slow-slip slope kN/(a|Omega|),
// fast slip F1 -> kN, M -> kNa/(4s), F2 = 0.

#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "friction/law.h"

namespace frictionlab::testing {

class UniformCircleTestLaw final : public friction::FrictionLaw {
 public:
  UniformCircleTestLaw() : table_(gsl_integration_glfixed_table_alloc(kGaussPoints), &gsl_integration_glfixed_table_free) {}
  [[nodiscard]] std::string_view name() const override { return "test-uniform-circle"; }
  [[nodiscard]] std::string_view summary() const override { return "uniform pressure, circle, 1-D ICR quadrature (tests)"; }

 private:
  static constexpr int kTrapezoid = 1024;
  static constexpr int kGaussPoints = 400;

  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    const double kN = in.k * in.N;
    const double w = std::abs(in.Omega);
    if (w == 0.0) return {in.U > 0.0 ? kN : 0.0, 0.0, 0.0};
    const double u = in.U / (in.a * w);  // ICR at c = (0, u) in units of a (e1 = x, e2 = y)
    double fx = 0.0, fy = 0.0, m = 0.0;  // ∫ sin L^2/2, ∫ cos L^2/2, ∫ [(c.e) L^2/2 + L^3/3]
    if (u < 1.0) {
      const double h = 2.0 * std::numbers::pi / kTrapezoid;
      for (int i = 0; i < kTrapezoid; ++i) {
        const double phi = h * i, sn = std::sin(phi), cs = std::cos(phi);
        const double ce = u * sn;
        const double L = -ce + std::sqrt(ce * ce + 1.0 - u * u);
        fx += sn * L * L / 2.0 * h;
        fy += cs * L * L / 2.0 * h;
        m += (ce * L * L / 2.0 + L * L * L / 3.0) * h;
      }
    } else {
      const double alpha = std::asin(1.0 / u), phi0 = -std::numbers::pi / 2.0;
      for (std::size_t i = 0; i < kGaussPoints; ++i) {
        double theta = 0.0, weight = 0.0;
        gsl_integration_glfixed_point(-std::numbers::pi / 2.0, std::numbers::pi / 2.0, i, &theta, &weight, table_.get());
        const double phi = phi0 + alpha * std::sin(theta), dphi = alpha * std::cos(theta) * weight;
        const double sn = std::sin(phi), cs = std::cos(phi), ce = u * sn;
        const double D = std::sqrt(std::max(0.0, ce * ce - u * u + 1.0));
        const double L1 = -ce - D, L2 = -ce + D;
        const double sq = (L2 * L2 - L1 * L1) / 2.0, cu = (L2 * L2 * L2 - L1 * L1 * L1) / 3.0;
        fx += sn * sq * dphi;
        fy += cs * sq * dphi;
        m += (ce * sq + cu) * dphi;
      }
    }
    const double p = 1.0 / std::numbers::pi;  // kN p a^2 with p = N/(pi a^2): forces in units of kN
    // F = -z x (fx_vec): F_x = p fx... with z x e = (-sin, cos): F = -kN p (-fx, fy) = kN p (fx, -fy).
    const double Fx = kN * p * fx, Fy = -kN * p * fy;
    return {-Fx, -Fy, (in.Omega > 0.0 ? 1.0 : -1.0) * kN * in.a * p * m};
  }

  std::unique_ptr<gsl_integration_glfixed_table, void (*)(gsl_integration_glfixed_table*)> table_;
};

}  // namespace frictionlab::testing
