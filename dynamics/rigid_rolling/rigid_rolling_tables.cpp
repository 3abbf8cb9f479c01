// Prints the tables of docs/rigid-rolling.md as Markdown: the Kane-Levinson rattleback's slow-spin
// data, its growth rates per spin sense, its reversal times (nonlinear model against the averaged
// estimate), and steady circles of a rounded disk held over ten precession periods.
// Usage: rigid_rolling_tables [--quick]   (--quick: fewer and shorter runs, for a smoke test)

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Eigenvalues>

#include "dynamics/rigid_rolling/ellipsoid_body.h"
#include "dynamics/rigid_rolling/inertia_misalignment.h"
#include "dynamics/rigid_rolling/numerical_jacobian.h"
#include "dynamics/rigid_rolling/rattleback_presets.h"
#include "dynamics/rigid_rolling/rolling_equations.h"
#include "dynamics/rigid_rolling/rolling_integrator.h"
#include "dynamics/rigid_rolling/spin_reversal.h"
#include "dynamics/rigid_rolling/steady_circle.h"
#include "dynamics/rigid_rolling/steady_spin.h"
#include "friction/support/number_format.h"

namespace rr = frictionlab::dynamics::rigid_rolling;
using frictionlab::support::significant;

namespace {

std::string row(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const auto& c : cells) out += " " + c + " |";
  return out;
}

void preset_table(const rr::EllipsoidBody& body) {
  const rr::SteadySpinBody lin = rr::steady_spin_body(body);
  const rr::SlowSpinCoefficients exact = rr::slow_spin_coefficients(lin);
  const rr::SlowSpinCoefficients small = rr::small_misalignment_coefficients(lin);
  std::cout << "### Kane & Levinson rattleback: rest point and slow-spin coefficients\n\n";
  std::cout << row({"quantity", "value"}) << "\n" << row({"---", "---"}) << "\n";
  std::cout << row({"height of G over the contact l (m)", significant(lin.height, 6)}) << "\n";
  std::cout << row({"radii of curvature R1, R2 (m)", significant(lin.radius_1, 6) + ", " + significant(lin.radius_2, 6)}) << "\n";
  std::cout << row({"misalignment angle (rad)", significant(rr::misalignment_angle(lin.inertia), 6)}) << "\n";
  std::cout << row({"pitch, roll frequency at n = 0 (rad/s)",
                    significant(exact.pitch_frequency, 6) + ", " + significant(exact.roll_frequency, 6)})
            << "\n";
  std::cout << row({"alpha pitch, roll (exact modes)", significant(exact.pitch, 6) + ", " + significant(exact.roll, 6)}) << "\n";
  std::cout << row({"alpha pitch, roll (first order in J12)", significant(small.pitch, 6) + ", " + significant(small.roll, 6)})
            << "\n\n";
}

void growth_table(const rr::EllipsoidBody& body, const std::vector<double>& spins) {
  const rr::SteadySpinBody lin = rr::steady_spin_body(body);
  const rr::RigidRollingModel model(rr::rigid_body(body));
  std::cout << "### Growth rates of small oscillations about steady spin\n\n";
  std::cout << row({"n (rad/s)", "growth n > 0 (1/s)", "growth n < 0 (1/s)", "ratio", "frequencies at +n (rad/s)",
                    "max |lambda - lambda_fd| (1/s)"})
            << "\n"
            << row({"---", "---", "---", "---", "---", "---"}) << "\n";
  for (double n : spins) {
    const double up = rr::steady_spin_growth_rate(lin, n);
    const double down = rr::steady_spin_growth_rate(lin, -n);
    const rr::SteadySpinSpectrum ev = rr::steady_spin_eigenvalues(lin, n);
    // The closed form against the finite-difference Jacobian of the nonlinear equations.
    const rr::RollingState steady{Eigen::Vector3d(0.0, 0.0, n), Eigen::Vector3d::UnitZ()};
    const rr::RollingJacobian jac = rr::numerical_jacobian(model, steady);
    Eigen::Matrix4d block;
    const int idx[4] = {0, 1, 3, 4};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) block(i, j) = jac(idx[i], idx[j]);
    Eigen::Vector4cd fd = Eigen::EigenSolver<Eigen::Matrix4d>(block, false).eigenvalues();
    double worst = 0.0;
    for (int i = 0; i < 4; ++i) {
      double nearest = INFINITY;
      for (int j = 0; j < 4; ++j) nearest = std::min(nearest, std::abs(ev(i) - fd(j)));
      worst = std::max(worst, nearest);
    }
    std::cout << row({significant(n, 4), significant(up, 6), significant(down, 6), significant(up / down, 4),
                      significant(ev(3).imag(), 6) + ", " + significant(ev(2).imag(), 6), significant(worst, 2)})
              << "\n";
  }
  std::cout << "\n";
}

void reversal_table(const rr::EllipsoidBody& body, const std::vector<double>& spins, double tilt) {
  const rr::SteadySpinBody lin = rr::steady_spin_body(body);
  const rr::RigidRollingModel model(rr::rigid_body(body));
  std::cout << "### First spin reversal from steady spin n0 disturbed along the growing mode (tilt "
            << significant(tilt, 3) << " rad)\n\n";
  std::cout << row({"n0 (rad/s)", "growth (1/s)", "mode energy (J)", "averaged estimate (s)", "nonlinear model (s)",
                    "model/estimate", "max |E - E0|/E0 to reversal"})
            << "\n"
            << row({"---", "---", "---", "---", "---", "---", "---"}) << "\n";
  for (double n0 : spins) {
    const rr::PerturbedSteadySpin start = rr::perturbed_steady_spin(model, lin, n0, tilt);
    const double estimate = rr::averaged_reversal_time(start.growth_rate, start.spin_energy, start.mode_energy);
    rr::ReversalSearch search;
    search.t_max = 20.0 * estimate;
    const rr::SpinReversal rev = rr::first_spin_reversal(model, start.state, search);
    const double e0 = model.energy(start.state);
    double drift = 0.0;
    if (rev.reversed) {
      rr::RollingIntegrator integrator(model);
      double t = 0.0;
      rr::RollingState x = start.state;
      integrator.integrate(t, x, rev.time, [&](double, const rr::RollingState& s) {
        drift = std::max(drift, std::abs(model.energy(s) - e0) / e0);
        return true;
      });
    }
    std::cout << row({significant(n0, 4), significant(start.growth_rate, 5), significant(start.mode_energy, 4),
                      significant(estimate, 6), rev.reversed ? significant(rev.time, 6) : "none",
                      rev.reversed ? significant(rev.time / estimate, 4) : "-", significant(drift, 2)})
              << "\n";
  }
  std::cout << "\n";
}

void circle_table(int periods) {
  rr::RevolutionBody disk;
  disk.mass = 0.3;
  disk.radius = 0.05;
  disk.rim_radius = 0.005;
  disk.transverse_inertia = disk.mass * disk.radius * disk.radius / 4.0;
  disk.axial_inertia = disk.mass * disk.radius * disk.radius / 2.0;
  const rr::RigidRollingModel model(rr::rigid_body(disk));
  std::cout << "### Steady circles of a rounded disk (m 0.3 kg, R 0.05 m, rim 0.005 m, A = m R^2/4, C = m R^2/2), held "
            << periods << " precession periods\n\n";
  std::cout << row({"tilt (rad)", "contact circle (m)", "Omega (rad/s)", "s (rad/s)", "rolling speed (m/s)",
                    "max |gamma3 - sin tilt|", "max |dn|/|omega|"})
            << "\n"
            << row({"---", "---", "---", "---", "---", "---", "---"}) << "\n";
  const double cases[][2] = {{0.05, 2.0}, {0.1, 0.5}, {0.3, 0.2}, {0.6, 0.05}};
  for (const auto& c : cases) {
    const rr::SteadyCircle circle = rr::steady_circle_for_radius(disk, c[0], c[1]);
    rr::RollingState x = rr::steady_circle_state(circle);
    const double n0 = x.spin();
    const double w = x.omega.norm();
    double tilt_dev = 0.0, spin_dev = 0.0;
    rr::RollingIntegrator integrator(model);
    double t = 0.0;
    integrator.integrate(t, x, periods * 2.0 * std::numbers::pi / circle.precession_rate, [&](double, const rr::RollingState& s) {
      tilt_dev = std::max(tilt_dev, std::abs(s.gamma.z() - std::sin(circle.tilt)));
      spin_dev = std::max(spin_dev, std::abs(s.spin() - n0) / w);
      return true;
    });
    std::cout << row({significant(c[0], 3), significant(c[1], 3), significant(circle.precession_rate, 6),
                      significant(circle.spin_rate, 6), significant(circle.rolling_speed, 5), significant(tilt_dev, 2),
                      significant(spin_dev, 2)})
              << "\n";
  }
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const bool quick = argc > 1 && std::string_view(argv[1]) == "--quick";
    const rr::EllipsoidBody body = rr::kane_levinson_rattleback();
    preset_table(body);
    growth_table(body, quick ? std::vector<double>{0.5, 5.0} : std::vector<double>{0.1, 0.5, 1, 2, 5, 10, 20, 30, 50, 100});
    reversal_table(body, quick ? std::vector<double>{2.0, -2.0}
                               : std::vector<double>{0.5, 1, 2, 5, 10, -0.5, -1, -2, -5, -10},
                   1e-3);
    if (!quick) reversal_table(body, {0.5, 1, 2, -0.5, -1, -2}, 1e-4);
    circle_table(quick ? 2 : 10);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rigid_rolling_tables: error: " << e.what() << "\n";
    return 1;
  }
}
