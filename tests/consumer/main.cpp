// A user's program built against the installed frictionlab package (tests/consumer/CMakeLists.txt).
// It checks the installed libraries against closed forms (docs/model.md) and exits 1 on a mismatch:
//   * the exact law at pure spin on a circular patch: F1 = F2 = 0, M = (3 pi/16) k N a sign(Omega);
//   * the exact law at pure sliding: F1 = k N, F2 = M = 0;
//   * a law spec: exact:pressure=uniform at pure spin on a circle, M = (2/3) k N a sign(Omega);
//   * a law of the user's own, registered from this program (docs/extending.md) and made by name;
//   * the shipped scenario sphere-sliding.toml: a solid sphere launched sliding without spin starts
//     to roll at t = 2 v0 / (7 k g) with speed 5 v0 / 7 (and omega R = v).
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"

namespace {

namespace fl = frictionlab;

int g_failures = 0;

void check_near(const std::string& what, double got, double expected, double tol) {
  const bool ok = std::abs(got - expected) <= tol;
  std::printf("%s %s = %.17g (expected %.17g, tolerance %.3g)\n", ok ? "ok  " : "FAIL", what.c_str(), got,
              expected, tol);
  if (!ok) ++g_failures;
}

// exact is accurate to 1e-13 k N (forces) and 1e-13 k N a (moment) (friction/exact_law.h).
constexpr double kExactRelTol = 1e-12;

void check_exact_law() {
  const auto law = fl::friction::make_law("exact");
  fl::friction::ContactInput in;
  in.a = in.b = 2e-3;  // m: a circle
  in.psi = 0.3;        // rad: irrelevant on a circle
  in.N = 19.62;        // N
  in.k = 0.1;
  const double kN = in.k * in.N;
  for (const double Omega : {10.0, -10.0}) {
    in.U = 0.0;
    in.Omega = Omega;
    const auto f = law->evaluate(in);
    const std::string at = Omega > 0.0 ? " at pure spin, Omega > 0" : " at pure spin, Omega < 0";
    check_near("F1" + at, f.F1, 0.0, kExactRelTol * kN);
    check_near("F2" + at, f.F2, 0.0, kExactRelTol * kN);
    check_near("M" + at, f.M, std::copysign(3.0 * std::numbers::pi / 16.0 * kN * in.a, Omega),
               kExactRelTol * kN * in.a);
  }
  in.U = 0.5;
  in.Omega = 0.0;
  const auto f = law->evaluate(in);
  check_near("F1 at pure sliding", f.F1, kN, kExactRelTol * kN);
  check_near("F2 at pure sliding", f.F2, 0.0, kExactRelTol * kN);
  check_near("M at pure sliding", f.M, 0.0, kExactRelTol * kN * in.a);
}

// A user's law: no friction at all.
class NoFrictionLaw final : public fl::friction::FrictionLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "consumer-no-friction"; }
  [[nodiscard]] std::string_view summary() const override { return "no friction (consumer example)"; }

 private:
  [[nodiscard]] fl::friction::FrictionForces do_evaluate(const fl::friction::ContactInput&) const override {
    return {};
  }
};

void check_specs_and_user_law() {
  fl::friction::ContactInput in;
  in.a = in.b = 2e-3;  // m: a circle
  in.U = 0.0;
  in.Omega = -10.0;
  in.N = 19.62;
  in.k = 0.1;
  const double kNa = in.k * in.N * in.a;
  const auto uniform = fl::friction::make_law("exact:pressure=uniform");
  check_near("M of exact:pressure=uniform at pure spin", uniform->evaluate(in).M, -2.0 / 3.0 * kNa, 1e-10 * kNa);
  fl::friction::register_law("consumer-no-friction", "no friction (consumer example)",
                             [] { return std::make_unique<NoFrictionLaw>(); });
  check_near("M of the registered user law", fl::friction::make_law("consumer-no-friction")->evaluate(in).M, 0.0, 0.0);
}

// Stick is entered once the slip speed is below the scenario's run.rest_slip_speed U_r = 1e-6 m/s;
// the slip falls at 3.5 k g, so the entry comes up to U_r / (3.5 k g) = 1.5e-7 s early, with v
// still up to k g times that (3e-7 m/s) above 5 v0 / 7. The integrator's error (tolerances 1e-9)
// is far below both.
constexpr double kRollTimeTol = 1e-6;   // s
constexpr double kRollSpeedTol = 1e-6;  // m/s

void check_sliding_sphere() {
  namespace dyn = fl::dynamics;
  const std::filesystem::path file = std::filesystem::path(FRICTIONLAB_SCENARIO_DIR) / "sphere-sliding.toml";
  const dyn::Scenario s = dyn::load_scenario(file);
  const auto law = fl::friction::make_law(s.law);
  const dyn::BodyOnPlane sys(s.body, s.contact, *law);  // the scenario carries its built body
  const dyn::RunSummary r = dyn::simulate(sys, dyn::initial_state(s), s.run);
  const bool rolled = r.reason == dyn::Termination::rolling;
  std::printf("%s %s stopped with reason '%s' (expected 'rolling') %s\n", rolled ? "ok  " : "FAIL",
              file.c_str(), std::string(dyn::to_string(r.reason)).c_str(), r.message.c_str());
  if (!rolled) ++g_failures;

  const double v0 = s.initial.v.norm();
  const double k = s.contact.k;
  const double g = s.contact.g;
  const double R = s.body_spec.radius.value();
  // Rolling starts where the sphere enters stick; the run ends once stick has held for
  // run.stick_hold_time (docs/dynamics.md §5).
  check_near("sphere: t at rolling", r.first_stick_entry, 2.0 * v0 / (7.0 * k * g), kRollTimeTol);
  check_near("sphere: stick held", r.t_final - r.first_stick_entry, r.stick_hold.value, 2e-2);
  check_near("sphere: |v| at rolling", dyn::velocity(r.x_final).norm(), 5.0 * v0 / 7.0, kRollSpeedTol);
  check_near("sphere: |omega| R at rolling", dyn::angular_velocity(r.x_final).norm() * R, 5.0 * v0 / 7.0,
             kRollSpeedTol);
}

}  // namespace

int main() {
  try {
    check_exact_law();
    check_specs_and_user_law();
    check_sliding_sphere();
  } catch (const std::exception& e) {
    std::printf("FAIL %s\n", e.what());
    return 1;
  }
  if (g_failures > 0) {
    std::printf("%d check(s) failed\n", g_failures);
    return 1;
  }
  std::printf("all checks passed\n");
  return 0;
}
