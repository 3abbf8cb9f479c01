#include "bench/engines/problems.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/state.h"
#include "dynamics/puck/puck_scenario.h"
#include "dynamics/puck/terminal_ratio.h"
#include "friction/registry.h"

namespace frictionlab::engines {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::array<double, 3> arr(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

// The pure-spin moment per kNa of `law` on a circle: M/(k N a) at U = 0 (3 pi/16 for Hertz
// pressure, 2/3 for uniform), from the law itself.
double pure_spin_coefficient(const std::string& law_spec) {
  const auto law = friction::make_law(law_spec);
  const friction::FrictionForces f = law->evaluate({0.0, 1.0, 1.0, 1.0, friction::PatchAngle(), 1.0, 1.0});
  return f.M;
}

// A body scenario (a sphere of revolution) as the engines' sphere: the shape frame is the body
// frame, the start's orientation turns the scenario's vertical gamma up (heading 0), velocities go
// to the world frame. Also the static patch radius of frictionlab's contact at the start.
Problem sphere_problem(const std::filesystem::path& file) {
  const dynamics::Scenario s = dynamics::load_scenario(file);
  if (s.body_spec.preset != "sphere" || !s.body_spec.radius) {
    throw std::invalid_argument("body.preset = '" + s.body_spec.preset + "' in " + file.string() +
                                " is invalid here: the engines' problems need a `sphere` body");
  }
  const Eigen::Matrix3d& J = s.body.inertia;
  if (!J.isDiagonal(0.0)) {
    throw std::invalid_argument("body.inertia in " + file.string() +
                                " is invalid here: the engines need principal axes along the shape's");
  }
  Problem p;
  p.scenario = file;
  p.law = s.law;
  p.spec.body.shape = Body::Shape::sphere;
  p.spec.body.radius = *s.body_spec.radius;
  p.spec.body.mass = s.body.mass;
  p.spec.body.inertia = {J(0, 0), J(1, 1), J(2, 2)};
  p.spec.body.com = arr(s.body.centre_of_mass);
  const Eigen::Vector4d q = dynamics::orientation_from(s.initial.gamma.normalized(), 0.0);
  p.spec.start.orientation = {q[0], q[1], q[2], q[3]};
  const Eigen::Quaterniond R(q[0], q[1], q[2], q[3]);
  p.spec.start.v = arr(R * s.initial.v);
  p.spec.start.omega = arr(R * s.initial.omega);
  p.spec.friction.k = s.contact.k;
  p.spec.numerics.g = s.contact.g;
  p.spec.t_end = s.run.t_end;
  p.spec.output_dt = s.run.output_dt;
  const auto law = friction::make_law(s.law);
  const dynamics::BodyOnPlane sys(s.body, s.contact, *law);
  p.patch_radius = sys.contact_state(dynamics::initial_state(s)).a;
  p.spin_c = pure_spin_coefficient(s.law);
  return p;
}

}  // namespace

double spin_down_time(double omega0, double R, double k, double g, double a) {
  return 32.0 * omega0 * R * R / (15.0 * std::numbers::pi * k * g * a);
}

double slide_to_roll_time(double v0, double k, double g) { return 2.0 * v0 / (7.0 * k * g); }

std::vector<Problem> make_problems(const std::filesystem::path& scenarios) {
  std::vector<Problem> out;

  Problem spin = sphere_problem(scenarios / "sphere-spinning.toml");
  spin.id = "spin-down";
  spin.title = "spin-down of a sphere";
  spin.quantity = "time for the spin to fall to 1 % (s)";
  const double omega0 = spin.spec.start.omega[2];
  spin.answer = 0.99 * spin_down_time(omega0, spin.spec.body.radius, spin.spec.friction.k, spin.spec.numerics.g,
                                      spin.patch_radius);
  spin.answer_source = "0.99 T, T = 32 ω0 R²/(15π k g a) (closed form)";
  out.push_back(std::move(spin));

  {
    const dynamics::puck::PuckScenario s = dynamics::puck::load_puck_scenario(scenarios / "puck-disk.toml");
    if (s.puck.b != s.puck.a) {
      throw std::invalid_argument("puck.b in puck-disk.toml is invalid here: the engines' disk needs a circle");
    }
    Problem p;
    p.id = "puck";
    p.title = "sliding and spinning disk";
    p.scenario = scenarios / "puck-disk.toml";
    p.law = s.law;
    p.spec.body.shape = Body::Shape::disk;
    p.spec.body.radius = s.puck.a;
    // A thin disk: a tenth of its radius (the puck model has no thickness; the motion on the plane
    // depends only on m and I, and the transverse moment below keeps it a solid cylinder's).
    p.spec.body.thickness = 0.1 * s.puck.a;
    p.spec.body.mass = s.puck.mass;
    const double h = p.spec.body.thickness;
    const double A = s.puck.mass * (3.0 * s.puck.a * s.puck.a + h * h) / 12.0;
    p.spec.body.inertia = {A, A, s.puck.inertia};
    const double c = std::cos(0.5 * s.initial.heading), sn = std::sin(0.5 * s.initial.heading);
    p.spec.start.orientation = {c, 0.0, 0.0, sn};
    p.spec.start.v = {s.initial.v[0], s.initial.v[1], 0.0};
    p.spec.start.omega = {0.0, 0.0, s.initial.omega};
    p.spec.friction.k = s.k;
    p.spec.numerics.g = s.g;
    p.spec.t_end = std::min(s.run.t_end, 1.0);
    p.spec.output_dt = std::min(s.run.output_dt, 1e-3);
    p.patch_radius = s.puck.a;
    p.spin_c = pure_spin_coefficient(s.law);
    p.quantity = "v/(a ω) at 1e-3 of the kinetic energy";
    const auto law = friction::make_law(s.law);
    const auto analysis = dynamics::puck::analyse_terminal_ratio(*law, s.puck.inertia_ratio());
    if (analysis.attracting.size() != 1) {
      throw std::runtime_error("the puck's law has " + std::to_string(analysis.attracting.size()) +
                               " attracting terminal ratios, not one: the problem has no single answer");
    }
    p.answer = analysis.attracting.front();
    p.answer_source = "the terminal ratio r* of " + s.law + " (zero of G(r), dynamics/puck/terminal_ratio.h)";
    out.push_back(std::move(p));
  }

  Problem top = sphere_problem(scenarios / "tippe-top.toml");
  top.id = "tippe-top";
  top.title = "tippe top";
  top.quantity = "inversion time, γ3 < -0.9 (s)";
  top.answer = kNaN;
  top.answer_source = "frictionlab, exact law (no closed form)";
  out.push_back(std::move(top));

  Problem roll = sphere_problem(scenarios / "sphere-sliding.toml");
  roll.id = "slide-to-roll";
  roll.title = "sliding sphere to rolling";
  roll.quantity = "v/v0 at the end";
  roll.answer = 5.0 / 7.0;
  roll.answer_source = "5/7 from t = 2 v0/(7 k g) (closed form)";
  out.push_back(std::move(roll));
  return out;
}

}  // namespace frictionlab::engines
