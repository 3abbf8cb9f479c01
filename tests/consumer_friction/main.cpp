// A program that uses only frictionlab's laws (tests/consumer_friction/CMakeLists.txt). It checks
// the installed laws against closed forms (docs/model.md) and exits 1 on a mismatch:
//   * the exact law at pure spin on a circular patch: F1 = F2 = 0, M = (3 pi/16) k N a sign(Omega);
//   * the exact law at pure sliding: F1 = k N, F2 = M = 0;
//   * exact-reference, the GSL law, is not in this program's registry (its library is not linked).
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <stdexcept>

#include "friction/registry.h"

namespace {

int g_failures = 0;

void check(const char* what, double got, double expected) {
  const bool ok = std::abs(got - expected) <= 1e-12 * (1.0 + std::abs(expected));
  std::printf("%s %s = %.17g (expected %.17g)\n", ok ? "ok  " : "FAIL", what, got, expected);
  if (!ok) ++g_failures;
}

}  // namespace

int main() {
  namespace fl = frictionlab::friction;
  try {
    const auto law = fl::make_law("exact");
    fl::ContactInput in;
    in.U = 0.0;
    in.Omega = -3.0;
    in.a = in.b = 0.002;
    in.N = 10.0;
    in.k = 0.3;
    const fl::FrictionForces spin = law->evaluate(in);
    check("pure spin F1", spin.F1, 0.0);
    check("pure spin F2", spin.F2, 0.0);
    check("pure spin M", spin.M, -3.0 * std::numbers::pi / 16.0 * 0.3 * 10.0 * 0.002);
    in.U = 1.0;
    in.Omega = 0.0;
    const fl::FrictionForces slide = law->evaluate(in);
    check("pure sliding F1", slide.F1, 3.0);
    check("pure sliding M", slide.M, 0.0);
    bool refused = false;
    try {
      (void)fl::make_law("exact-reference");
    } catch (const std::invalid_argument&) {
      refused = true;
    }
    std::printf("%s exact-reference is not registered without its library\n", refused ? "ok  " : "FAIL");
    if (!refused) ++g_failures;
  } catch (const std::exception& e) {
    std::printf("FAIL %s\n", e.what());
    return 1;
  }
  return g_failures == 0 ? 0 : 1;
}
