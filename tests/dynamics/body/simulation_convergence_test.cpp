// Convergence of the integration against a closed form (Boost.Odeint's habit: halve the step and
// check the order), and tolerance proportionality of the adaptive runs.
//
// The closed form: a solid sphere (C = 2/5 m R^2) launched sliding at v0 without spin, started at
// its static compression so that N = m g exactly (u.gamma = 0 for a sphere). Friction k m g
// opposes the slip; the centre slows as v(t) = v0 - k g t while the sphere spins up about the
// horizontal axis normal to the motion as omega(t) = alpha t, alpha = 5 k g/(2 R), until rolling
// starts at t_roll = 2 v0/(7 k g) with v = omega R = 5 v0/7. The body has then turned by
// theta(t) = alpha t^2/2 about that axis, so in the body frame
//   v = v(t) (cos theta, 0, sin theta),  omega = (0, alpha t, 0),  gamma = (-sin theta, 0, cos theta).
// The comparison is made at t = 0.9 t_roll: at t_roll itself the right-hand side jumps (Coulomb's
// sign function at U = 0), which no Runge-Kutta step resolves to its order.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/body/simulation.h"
#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace simulation_convergence_test {

struct SlidingSphere {
  double R = 0.05, m = 1.0, k = 0.2, lambda = 1e7, g = 9.81, v0 = 2.0;
  [[nodiscard]] double t_roll() const { return 2.0 * v0 / (7.0 * k * g); }
};

// max(|v - v_cf|, R |omega - omega_cf|, v0 |gamma - gamma_cf|) at t (m/s).
double error_against_closed_form(const SlidingSphere& p, double t, const StateVector& x) {
  const double alpha = 2.5 * p.k * p.g / p.R;
  const double theta = 0.5 * alpha * t * t;
  const double v = p.v0 - p.k * p.g * t;
  const Eigen::Vector3d v_cf(v * std::cos(theta), 0.0, v * std::sin(theta));
  const Eigen::Vector3d w_cf(0.0, alpha * t, 0.0);
  const Eigen::Vector3d g_cf(-std::sin(theta), 0.0, std::cos(theta));
  return std::max({(Eigen::Vector3d(velocity(x)) - v_cf).norm(),
                   p.R * (Eigen::Vector3d(angular_velocity(x)) - w_cf).norm(),
                   p.v0 * (Eigen::Vector3d(vertical(x)) - g_cf).norm()});
}

double run_error(const SlidingSphere& p, const std::string& method, double tol, double fixed_step) {
  const auto law = friction::make_law("exact");
  const PlaneContact plane{p.k, p.lambda, p.g};
  const BodyOnPlane sys(testing::sphere_body(p.R, p.m), plane, *law);
  const StateVector x0 =
      make_state({p.v0, 0.0, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), plane.static_height(p.m * p.g));
  RunOptions o;
  o.t_end = 0.9 * p.t_roll();
  o.output_dt = o.t_end;
  o.integrator.method = method;
  o.integrator.abs_tol = o.integrator.rel_tol = tol;
  if (fixed_step > 0.0) o.integrator.initial_step = o.integrator.max_step = fixed_step;
  const RunSummary s = simulate(sys, x0, o);
  EXPECT_EQ(s.reason, Termination::t_end) << s.message;
  EXPECT_EQ(s.t_final, o.t_end);
  return error_against_closed_form(p, s.t_final, s.x_final);
}

// Fixed steps h = t/n (the tolerance, 1, never cuts a step; run.max_step holds them): the error
// must fall as h^p. GSL's rk2 advances with its third-order solution (Abramowitz & Stegun 25.5.8;
// the second-order one only estimates the error), rk4 is the classical fourth-order method.
// n = 128 ... 512 is in the asymptotic range (measured orders within 0.05 of p) and well inside
// the stability limit of the Hertz vibration (h omega_n = 0.8 at n = 128).
constexpr double kOrderTol = 0.25;

TEST(DynSimulationConvergence, FixedStepsConvergeAtTheOrderOfTheMethod) {
  const SlidingSphere p;
  const double t = 0.9 * p.t_roll();
  for (const auto& [method, order] : {std::pair{"rk2", 3.0}, std::pair{"rk4", 4.0}}) {
    double previous = 0.0;
    for (const int n : {128, 256, 512}) {
      const double e = run_error(p, method, 1.0, t / n);
      if (previous > 0.0) {
        EXPECT_NEAR(std::log2(previous / e), order, kOrderTol) << method << " n = " << n;
      }
      previous = e;
    }
  }
}

// Adaptive steps: rkck and rkf45 advance with the fifth-order solution of their 4(5) pair and
// control the fourth-order error estimate, so h ~ tol^(1/5), the local error of what is advanced
// ~ h^6 ~ tol^(6/5) and the global error ~ (number of steps) tol^(6/5) ~ tol: one decade of error
// per decade of tolerance (tolerance proportionality). The least-squares slope over
// tol = 1e-5 ... 1e-10 must be 1 within kSlopeTol (measured 1.1-1.2), and the error must stay
// within kErrorPerTolerance of the tolerance (in m/s per unit tolerance; measured < 5).
constexpr double kSlopeTol = 0.35;
constexpr double kErrorPerTolerance = 50.0;  // m/s

TEST(DynSimulationConvergence, TighteningTheToleranceShrinksTheErrorProportionally) {
  const SlidingSphere p;
  for (const char* method : {"rkck", "rkf45"}) {
    std::vector<double> lt, le;
    for (double tol = 1e-5; tol >= 0.9e-10; tol /= 10.0) {
      const double e = run_error(p, method, tol, 0.0);
      EXPECT_LT(e, kErrorPerTolerance * tol) << method << " tol " << tol;
      lt.push_back(std::log10(tol));
      le.push_back(std::log10(e));
    }
    const double n = static_cast<double>(lt.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < lt.size(); ++i) {
      sx += lt[i];
      sy += le[i];
      sxx += lt[i] * lt[i];
      sxy += lt[i] * le[i];
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    EXPECT_NEAR(slope, 1.0, kSlopeTol) << method;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
