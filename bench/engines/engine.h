#pragma once
// One rigid body on a horizontal plane, run in a physics engine: what every engine adapter of the
// side by side (docs/engines.md §6) runs and returns. SI units; world frame z up, the plane z = 0,
// gravity -g e_z. The body is a sphere or a flat disk (a cylinder whose axis is the body's z axis);
// its centre of mass may sit off the shape's centre (the tippe top) and its inertia is given about
// the centre of mass in the body's axes (principal). The engine's contact is its own (soft or
// impulsive, point or several points); what each engine adds or needs is recorded in Run::notes.

#include <array>
#include <string>
#include <vector>

namespace frictionlab::engines {

/// The body's shape, mass and inertia.
struct Body {
  enum class Shape { sphere, disk };
  Shape shape = Shape::sphere;
  double radius = 0.05;     ///< m: the sphere's radius, or the disk's
  double thickness = 0.0;   ///< m: the disk's thickness (a cylinder, axis = body z); unused for a sphere
  double mass = 1.0;        ///< kg
  std::array<double, 3> inertia{4e-4, 4e-4, 4e-4};  ///< kg m^2: principal, about the centre of mass, body x, y, z
  std::array<double, 3> com{};  ///< m: the centre of mass in the body frame, from the shape's centre
};

/// The start, world frame. The shape's lowest point touches the plane (no penetration) unless the
/// engine settles first (Numerics::settle_time).
struct Start {
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  ///< body -> world unit quaternion (w, x, y, z)
  std::array<double, 3> v{};      ///< m/s: velocity of the centre of mass
  std::array<double, 3> omega{};  ///< 1/s: angular velocity
};

/// The contact's friction, in the engine's own terms.
struct Friction {
  double k = 0.2;          ///< Coulomb's sliding coefficient (both directions)
  double torsional = 0.0;  ///< the engine's spin-friction coefficient, in its unit (Engine::torsional_unit)
  double rolling = 0.0;    ///< the engine's rolling-friction coefficient, in its unit (0 = none)
};

/// The engine's numerics; 0 means the engine's default.
struct Numerics {
  double timestep = 0.0;    ///< s
  int iterations = 0;       ///< the contact solver's iterations
  double g = 9.81;          ///< m/s^2
  double settle_time = 0.0; ///< s held at rest (the start's orientation, no velocity) before the start
};

/// What to run.
struct RunSpec {
  Body body;
  Start start;
  Friction friction;
  Numerics numerics;
  double t_end = 1.0;       ///< s after the start
  double output_dt = 1e-3;  ///< s between samples (a multiple of the time step, rounded)
};

/// One sample after the start (t = 0 at the start, after any settling).
struct Sample {
  double t = 0.0;
  std::array<double, 3> com{};    ///< m: centre of mass, world
  std::array<double, 3> v{};      ///< m/s: velocity of the centre of mass, world
  std::array<double, 3> omega{};  ///< 1/s: angular velocity, world
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  ///< body -> world unit quaternion (w, x, y, z)
  double normal_force = 0.0;      ///< N: the sum over the contact points (0 out of contact)
};

/// A run: the samples, and what the engine used.
struct Run {
  std::vector<Sample> samples;
  double timestep = 0.0;  ///< s: the step taken (the default if Numerics::timestep was 0)
  int iterations = 0;     ///< the solver's iterations taken
  std::string notes;      ///< the settings a reader needs (cone, solver, softness, the rolling-friction quirk)
};

/// The rules every engine's run obeys (std::invalid_argument naming the field, its value and the
/// rule): positive sizes, mass and principal moments (with the triangle inequality), the centre of
/// mass inside the shape, a unit start quaternion, finite velocities, friction coefficients >= 0,
/// a time step >= 0 (0: `default_timestep`, s), settle_time, output_dt and t_end within 1e9 steps.
/// An adapter adds its engine's own rules.
void validate(const RunSpec& spec, double default_timestep);

/// An engine behind one interface.
class Engine {
 public:
  virtual ~Engine() = default;
  /// "MuJoCo", "Bullet", "ODE".
  [[nodiscard]] virtual std::string name() const = 0;
  /// The library's version as it reports it ("2.2.2", "3.24", "0.16.2").
  [[nodiscard]] virtual std::string version() const = 0;
  /// The unit of Friction::torsional ("m" for a torque per normal force).
  [[nodiscard]] virtual std::string torsional_unit() const = 0;
  /// The torsional (and rolling) coefficients an engine user gets without setting them.
  [[nodiscard]] virtual Friction defaults(double k) const = 0;
  /// The torsional coefficient that gives the pure-spin torque c k N a of a patch of radius a
  /// (docs/engines.md §4: c = 3π/16 for Hertz pressure), and the rolling coefficient it needs.
  [[nodiscard]] virtual Friction calibrated(double k, double c, double a) const = 0;
  /// Runs `spec`. std::invalid_argument naming the field and the rule on bad input;
  /// std::runtime_error with the engine's message if the engine fails or the state becomes non-finite.
  /// Deterministic: the same spec gives the same samples, bit for bit.
  [[nodiscard]] virtual Run run(const RunSpec& spec) const = 0;
};

}  // namespace frictionlab::engines
