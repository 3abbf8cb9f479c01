// friction/standalone/fit_law.h as an engine uses it: included alone (its folder is the only
// include path of this program, which links nothing of frictionlab), compiled as C++11 with every
// warning an error. It checks, in plain C++ (GoogleTest needs a newer standard), what holds by
// construction: the limits, the parities and symmetries, dissipation, the bounds, the pure-spin
// moment against pi/2 (E(0) for a circle) and E's arithmetic-geometric mean, at a few thousand
// seeded points. Exit status 0 when all hold; each failure is printed.

#include "fit_law.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace {

int failures = 0;

void check(bool ok, const char* what, double value) {
  if (!ok) {
    ++failures;
    std::printf("FAILED: %s (value %.17g)\n", what, value);
  }
}

}  // namespace

int main() {
  using frictionlab_fit::Forces;
  using frictionlab_fit::Geometry;
  using frictionlab_fit::Pressure;
  const double pi = 3.14159265358979323846;
  const double cp[3] = {3.0 / 8.0, 4.0 / (3.0 * pi), 0.5};
  const Pressure pressures[3] = {Pressure::hertz, Pressure::uniform, Pressure::punch};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int p = 0; p < 3; ++p) {
    // A circle's pure-spin moment is c_p E(0) = c_p pi/2, through the fit of E.
    const Geometry circle = frictionlab_fit::make_geometry(1.0, pressures[p]);
    check(std::fabs(circle.M0 - cp[p] * pi / 2.0) < 1e-14, "circle: M0 = c_p pi/2", circle.M0);
    // E's two routes meet at mu = 0.01 (the fit above, the AGM below).
    const double above = frictionlab_fit::elliptic_e(0.01), below = frictionlab_fit::elliptic_e(0.01 * (1.0 - 1e-15));
    check(std::fabs(above - below) < 1e-13, "E: the fit and the AGM meet at b/a = 0.01", above - below);
    for (int i = 0; i < 3000; ++i) {
      const double mu = std::pow(1e-3, uni(rng));
      const double psi = 2.0 * pi * uni(rng);
      const double s = std::pow(10.0, -4.0 + 8.0 * uni(rng));
      const double a = 0.01 + uni(rng), N = 10.0 * uni(rng), k = uni(rng);
      const double Omega = 0.1 + 10.0 * uni(rng), U = s * a * Omega, kN = k * N;
      const Geometry g = frictionlab_fit::make_geometry(mu, pressures[p]);
      const double c = std::cos(psi), sn = std::sin(psi);
      const Forces f = frictionlab_fit::evaluate(g, U, Omega, a, c, sn, N, k);
      const Forces r = frictionlab_fit::evaluate(g, U, -Omega, a, c, sn, N, k);           // spin reversed
      const Forces half = frictionlab_fit::evaluate(g, U, Omega, a, -c, -sn, N, k);       // psi + pi
      const Forces mirror = frictionlab_fit::evaluate(g, U, Omega, a, c, -sn, N, k);      // -psi
      const Forces spin = frictionlab_fit::evaluate(g, 0.0, Omega, a, c, sn, N, k);       // U = 0
      const Forces slide = frictionlab_fit::evaluate(g, U, 0.0, a, c, sn, N, k);          // Omega = 0
      const double tol = 1e-12;
      check(std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M), "finite", f.F1);
      check(f.F1 * U + f.M * Omega >= -tol * kN * (U + a * Omega), "dissipative", f.F1 * U + f.M * Omega);
      check(f.F1 * f.F1 + f.F2 * f.F2 <= kN * kN * (1.0 + tol), "|F| <= kN", std::hypot(f.F1, f.F2) / kN);
      check(std::fabs(f.M) <= g.M0 * kN * a * (1.0 + tol), "|M| <= c_p E kNa", f.M / (kN * a));
      check(r.F1 == f.F1 && r.F2 == f.F2 && r.M == -f.M, "F even, M odd in Omega", r.M + f.M);
      check(half.F1 == f.F1 && half.F2 == f.F2 && half.M == f.M, "psi + pi changes nothing", half.F2 - f.F2);
      check(mirror.F1 == f.F1 && mirror.F2 == -f.F2 && mirror.M == f.M, "-psi flips F2 only", mirror.F2 + f.F2);
      check(spin.F1 == 0.0 && spin.F2 == 0.0 && std::fabs(spin.M - g.M0 * kN * a) <= 1e-15 * g.M0 * kN * a, "pure spin",
            spin.M);
      check(slide.F1 == kN && slide.F2 == 0.0 && slide.M == 0.0, "pure sliding", slide.F1 - kN);
    }
  }
  const Geometry g = frictionlab_fit::make_geometry(0.5, Pressure::hertz);
  const Forces rest = frictionlab_fit::evaluate(g, 0.0, 0.0, 0.1, 1.0, 0.0, 5.0, 0.5);
  check(rest.F1 == 0.0 && rest.F2 == 0.0 && rest.M == 0.0, "at rest: zero", rest.F1);
  if (failures == 0) std::printf("standalone fit_law.h: every check held\n");
  return failures == 0 ? 0 : 1;
}
