#pragma once
// The MuJoCo 2.2 adapter of the engines' side by side (bench/engines/engine.h, docs/engines.md §6).
//
// The model is one MJCF text (mujoco_mjcf below, the only place frictionlab writes a MuJoCo model;
// bench/mujoco's sphere side by side uses it too): a plane (the floor) and one free body whose
// frame is the shape's centre, carrying a sphere geom or a cylinder geom (axis = body z, half
// height = thickness/2), and an <inertial> at Body::com with diaginertia = Body::inertia. Both geoms
// carry the same condim, friction "k torsional rolling", solref and solimp: MuJoCo mixes two geoms
// of equal priority by taking the MAXIMUM of each friction coefficient and the mean of solref and
// solimp (src/engine/engine_collision_driver.c, mj_collideGeoms: "friction: max"), so equal values
// give exactly these.
//
// MuJoCo's friction is (docs: XML reference, geom/@friction, @condim; Computation, "Contact"):
//   condim 1: frictionless; 3: sliding only (no spin friction at all); 4: sliding + torsional;
//   6: + rolling. The torsional coefficient mu3 is a LENGTH: the spin torque is at most mu3 N (the
//   cone's bound), so Engine::torsional_unit() is "m". Every coefficient below mjMINMU = 1e-5 is
//   raised to it (engine_collision_driver.c, "clamp friction to mjMINMU"): a 0 cannot be had.
//
// The contact is soft: the constraint force follows a reference acceleration set by
// solref = (time constant, damping ratio) and solimp (impedance); MuJoCo raises the time constant
// to 2 timestep unless the refsafe flag is disabled (src/engine/engine_core_constraint.c, "integrator
// safety: impose ref[0]>=2*timestep"); Run::notes says when that happened.
//
// Two consequences of the soft friction a user must know (measured with this adapter, MuJoCo 2.2.2):
// * every friction row gets the reference acceleration -B J v with B = 2 / (dmax timeconst)
//   (engine_core_constraint.c, mj_makeImpedance and mj_referenceConstraint; a pyramid edge's row
//   is J_n +- mu J_t): a slip or spin u pushes the body off the plane by about B mu u. Past g the
//   body hops (a sphere sliding at 2 m/s with k = 0.2, or spinning at 20 1/s with torsional
//   0.005 m: N = 0 in most samples); the mean normal force, and so the mean friction, stay m g.
// * the friction is viscous below a crossover slip: a sphere spinning in place with torsional
//   1.2e-4 m decays linearly down to ~7 1/s (pyramidal) or ~3 1/s (elliptic, impratio 1), then
//   exponentially, and never stops. The elliptic cone with impratio 100, or with noslip_iterations
//   10, gives the linear decay to a stop at the closed-form time; noslip does not help the
//   pyramidal cone's torsional row.

#include <array>
#include <memory>
#include <string>

#include "bench/engines/engine.h"

namespace frictionlab::engines {

/// MuJoCo's own knobs, at MuJoCo 2.2's defaults (XML reference, <option> and <geom>) except condim.
struct MujocoOptions {
  /// Contact dimensionality, 1, 3, 4 or 6. MuJoCo's default is 3, which has NO spin friction; this
  /// study's default is 4 (sliding + torsional), what a user who wants spin friction sets, with
  /// MuJoCo's default friction "1 0.005 0.0001", i.e. torsional 0.005 m (Engine::defaults).
  int condim = 4;
  enum class Cone { pyramidal, elliptic };
  Cone cone = Cone::pyramidal;  ///< MuJoCo's default: pyramidal
  /// (time constant s, damping ratio): MuJoCo's default (0.02, 1). Both > 0 (the standard form).
  std::array<double, 2> solref{0.02, 1.0};
  /// (dmin, dmax, width m, midpoint, power): MuJoCo's default (0.9, 0.95, 0.001, 0.5, 2).
  std::array<double, 5> solimp{0.9, 0.95, 0.001, 0.5, 2.0};
  double impratio = 1.0;  ///< frictional-to-normal impedance ratio, elliptic cone only; MuJoCo's default 1
  enum class Integrator { euler, rk4, implicit };
  Integrator integrator = Integrator::euler;  ///< MuJoCo's default: Euler
  enum class Solver { pgs, cg, newton };
  Solver solver = Solver::newton;  ///< MuJoCo's default: Newton
  int iterations = 100;            ///< MuJoCo's default; Numerics::iterations > 0 overrides it
  double tolerance = 1e-8;         ///< the solver's early-exit tolerance; MuJoCo's default 1e-8
  int noslip_iterations = 0;       ///< MuJoCo's default 0 (no noslip post-pass)

  /// std::invalid_argument naming the field, its value and the rule.
  void validate() const;
};

/// MuJoCo's default time step, s (XML reference, option/@timestep): what Numerics::timestep = 0 gives.
inline constexpr double mujoco_default_timestep = 0.002;

/// The MJCF text of `spec`'s model with `options`, the body placed at its start (its lowest point on
/// the plane at x = y = 0). Validates both (std::invalid_argument naming the field).
[[nodiscard]] std::string mujoco_mjcf(const RunSpec& spec, const MujocoOptions& options = {});

/// The MuJoCo adapter.
[[nodiscard]] std::unique_ptr<Engine> make_mujoco_engine(const MujocoOptions& options = {});

}  // namespace frictionlab::engines
