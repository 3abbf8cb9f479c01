#include "dynamics/rigid_rolling/spin_reversal.h"

#include <cmath>
#include <complex>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace {

constexpr int kMaxRefinements = 200;

}  // namespace

double averaged_reversal_time(double growth_rate, double spin_energy, double mode_energy) {
  if (!(std::isfinite(growth_rate) && growth_rate > 0.0))
    throw support::invalid_value("growth_rate", growth_rate, "it must be finite and > 0 1/s (a growing mode)");
  if (!(std::isfinite(spin_energy) && spin_energy > 0.0))
    throw support::invalid_value("spin_energy", spin_energy, "it must be finite and > 0 J");
  if (!(std::isfinite(mode_energy) && mode_energy > 0.0))
    throw support::invalid_value("mode_energy", mode_energy, "it must be finite and > 0 J");
  const double q = std::sqrt(spin_energy / (spin_energy + mode_energy));
  return q * std::atanh(q) / growth_rate;
}

PerturbedSteadySpin perturbed_steady_spin(const RigidRollingModel& model, const SteadySpinBody& linearised, double spin,
                                          double tilt) {
  if (!(std::isfinite(tilt) && tilt > 0.0)) throw support::invalid_value("tilt", tilt, "it must be finite and > 0 rad");
  if (!std::isfinite(spin)) throw support::invalid_value("spin", spin, "it must be finite (1/s)");
  const SteadySpinModes modes = steady_spin_modes(linearised, spin, true);
  int k = 0;
  modes.values.real().maxCoeff(&k);
  Eigen::Vector4cd v = modes.vectors.col(k);
  const int big = std::abs(v(2)) >= std::abs(v(3)) ? 2 : 3;
  v *= std::polar(1.0, -std::arg(v(big))) * (tilt / std::abs(v(big)));
  const Eigen::Vector4d z = v.real();
  PerturbedSteadySpin out;
  out.state.omega = Eigen::Vector3d(z(0), z(1), spin);
  out.state.gamma = Eigen::Vector3d(z(2), z(3), 1.0).normalized();
  out.growth_rate = modes.values(k).real();
  out.spin_energy = 0.5 * linearised.inertia(2, 2) * spin * spin;
  const RollingState steady{Eigen::Vector3d(0.0, 0.0, spin), Eigen::Vector3d::UnitZ()};
  out.mode_energy = model.energy(out.state) - model.energy(steady);
  return out;
}

SpinReversal first_spin_reversal(const RigidRollingModel& model, const RollingState& start, const ReversalSearch& search) {
  if (!(std::isfinite(search.t_max) && search.t_max > 0.0))
    throw support::invalid_value("t_max", search.t_max, "it must be finite and > 0 s");
  if (!(std::isfinite(search.time_tolerance) && search.time_tolerance > 0.0))
    throw support::invalid_value("time_tolerance", search.time_tolerance, "it must be finite and > 0 s");
  const double sense = start.spin() > 0.0 ? 1.0 : (start.spin() < 0.0 ? -1.0 : 0.0);
  if (sense == 0.0) throw support::invalid_value("initial spin", start.spin(), "it must be nonzero (omega . gamma)");

  RollingIntegrator integrator(model, search.integrator);
  double t = 0.0;
  RollingState x = start;
  double t_before = 0.0;
  RollingState x_before = start;
  bool crossed = false;
  integrator.integrate(t, x, search.t_max, [&](double t_now, const RollingState& x_now) {
    if (sense * x_now.spin() <= 0.0) {
      crossed = true;
      return false;
    }
    t_before = t_now;
    x_before = x_now;
    return true;
  });
  SpinReversal out;
  out.steps = integrator.steps();
  if (!crossed) {
    out.state = x;
    return out;
  }
  // Regula falsi with the Illinois modification on f(t) = sense * spin(x(t)), f(a) > 0 >= f(b);
  // x(t) by integrating from the bracketing step's start (t_before, x_before).
  double a = t_before, b = t, fa = sense * x_before.spin(), fb = sense * x.spin();
  RollingState xb = x;
  int side = 0;
  // Illinois converges superlinearly; the cap only guards against a tolerance below the spacing of doubles.
  for (int iteration = 0; iteration < kMaxRefinements && b - a > search.time_tolerance && fb != 0.0; ++iteration) {
    double c = (a * fb - b * fa) / (fb - fa);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const RollingState xc = integrator.state_at(t_before, x_before, c);
    const double fc = sense * xc.spin();
    if (fc > 0.0) {
      a = c;
      fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = c;
      fb = fc;
      xb = xc;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  out.reversed = true;
  out.time = b;
  out.state = xb;
  return out;
}

}  // namespace frictionlab::dynamics::rigid_rolling
