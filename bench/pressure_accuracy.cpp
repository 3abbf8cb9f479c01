// The accuracy of `exact` for each pressure model, measured against `exact-reference` with the same
// pressure (an independent 2-D GSL quadrature, itself accurate to 1e-10) on a seeded random set:
// mu log-uniform in [0.01, 1], psi uniform in (-pi, pi), both signs of Omega, and the ICR
// s log-uniform in [1e-3, 1e3] (half the points) or within 1e-3 .. 0.3 of the rim, inside or out
// (the other half: c~ = s (sin psi, cos psi / mu) with |c~| = 1 +- r), where the integrands are
// hardest. Prints the largest |exact - reference| per kN (F1, F2) and kNa (M), and where.
//
//   build/bench/pressure_accuracy [points per pressure, default 200] [seed, default 1]
//
// A program, not a test: ~0.1 s per point (the reference).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>

#include "friction/registry.h"
#include "friction/support/number_format.h"
#include "friction/reference_laws.h"

int main(int argc, char** argv) {
  namespace fl = frictionlab::friction;
  namespace sup = frictionlab::support;
  fl::register_reference_laws();
  const int n = argc > 1 ? std::atoi(argv[1]) : 200;
  const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 1u;
  const double pi = std::numbers::pi;
  for (const std::string pressure : {"hertz", "uniform", "punch"}) {
    const auto law = fl::make_law("exact:pressure=" + pressure);
    const auto reference = fl::make_law("exact-reference:pressure=" + pressure);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    double worst[3] = {0.0, 0.0, 0.0};
    std::string where[3];
    for (int i = 0; i < n; ++i) {
      const double mu = std::pow(10.0, -2.0 * uni(rng));
      const double psi = pi * (2.0 * uni(rng) - 1.0);
      double s = std::pow(10.0, -3.0 + 6.0 * uni(rng));
      if (i % 2 == 1) {
        const double r = std::pow(10.0, -3.0 + 2.5 * uni(rng));
        const double rho = uni(rng) < 0.5 ? 1.0 - r : 1.0 + r;
        s = rho / std::hypot(std::sin(psi), std::cos(psi) / mu);
      }
      const double omega = i % 4 < 2 ? 1.0 : -1.0;
      const fl::ContactInput in{s, omega, 1.0, mu, psi, 1.0, 1.0};
      const fl::FrictionForces f = law->evaluate(in);
      const fl::FrictionForces g = reference->evaluate(in);
      const double e[3] = {std::abs(f.F1 - g.F1), std::abs(f.F2 - g.F2), std::abs(f.M - g.M)};
      for (int c = 0; c < 3; ++c) {
        if (!(e[c] <= worst[c])) {
          worst[c] = e[c];
          where[c] = "s=" + sup::significant(s, 6) + " mu=" + sup::significant(mu, 6) +
                     " psi=" + sup::significant(psi, 6) + " Omega=" + (omega > 0 ? "+1" : "-1");
        }
      }
    }
    std::printf("exact:pressure=%s vs exact-reference, %d points (seed %u): max |err| F1 %s (%s), F2 %s (%s), M %s (%s)\n",
                pressure.c_str(), n, seed, sup::significant(worst[0], 2).c_str(), where[0].c_str(),
                sup::significant(worst[1], 2).c_str(), where[1].c_str(), sup::significant(worst[2], 2).c_str(),
                where[2].c_str());
  }
  return 0;
}
