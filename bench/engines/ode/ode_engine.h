#pragma once
// The Open Dynamics Engine (ODE 0.16, Debian libode-dev, double precision) behind engine.h.
//
// ODE has no default time step or solver of its own choosing: the adapter's defaults are those of
// Gazebo classic, through which most users meet ODE (sdformat sdf/1.6/physics.sdf, <physics>
// <max_step_size> and <ode><solver>/<constraints>): QuickStep (projected Gauss-Seidel), 50
// iterations, SOR 1.3, step 1 ms, ERP 0.2, CFM 0, contact surface layer 1 mm, maximum correcting
// velocity 100 m/s, at most 20 contacts per pair. The exact LCP (dWorldStep, Dantzig) is an option.
//
// Friction: one contact joint per contact point, mode dContactApprox1 (without it ODE's `mu` is a
// force limit in newtons, not a coefficient: ode/src/joints/contact.cpp sets lo/hi = -mu/+mu and
// only findex = the normal row makes it a multiple of the normal force), mu = mu2 = k, a friction
// pyramid with edges along world x and y for a horizontal plane (dPlaneSpace). Spin and rolling
// friction: dContactRolling | dContactAxisDep with rhoN = Friction::torsional and rho = rho2 =
// Friction::rolling, each a torque limit of rho * (that point's normal force) with dContactApprox1
// (unit: m). defaults(k): no spin or rolling friction (ODE adds none unless asked; Gazebo's torsional
// friction, from its own ODE fork, is off by default: patch_radius 0). calibrated(k, c, a): rhoN =
// c k a, rho = rho2 = 0: the pure-spin torque of a one-point contact (the sphere) is c k N a.
// Quirks a user must know: a flat disk touches at 4 points on its rim, whose sliding friction
// already gives the spin torque k N a of a ring, and rhoN N comes on top; the friction pyramid's
// edges lie along world x and y (sliding at 45 degrees meets sqrt(2) k N); the contact sinks up to
// the 1 mm surface layer; the normal force of a sample is that of the step that ended there.
// See ode_engine.cpp for the sources of each quirk.

#include <memory>

#include "bench/engines/engine.h"

namespace frictionlab::engines {

/// ODE's own knobs; defaults are Gazebo classic's (sdformat physics.sdf), see above.
struct OdeOptions {
  enum class Solver {
    quick,  ///< dWorldQuickStep: projected Gauss-Seidel (SOR-LCP), `iterations` sweeps (Gazebo's default)
    world,  ///< dWorldStep: the exact LCP (Dantzig pivoting), no iterations
  };
  Solver solver = Solver::quick;
  double timestep = 1e-3;                 ///< s: the default step (Numerics::timestep = 0)
  int iterations = 50;                    ///< QuickStep sweeps by default (Numerics::iterations = 0)
  double sor = 1.3;                       ///< QuickStep over-relaxation w (dWorldSetQuickStepW)
  double erp = 0.2;                       ///< world error reduction parameter (dWorldSetERP)
  double cfm = 0.0;                       ///< world constraint force mixing (dWorldSetCFM)
  double contact_surface_layer = 1e-3;    ///< m: depth allowed before correction (dWorldSetContactSurfaceLayer)
  double contact_max_correcting_vel = 100.0;  ///< m/s: cap of the penetration correction (dWorldSetContactMaxCorrectingVel)
  int max_contacts = 20;                  ///< contact points asked of dCollide per step (Gazebo's max_contacts)
  /// Contact stiffness (N/m) and damping (N s/m) as Gazebo classic turns them into each contact's
  /// soft_erp = h kp / (h kp + kd), soft_cfm = 1 / (h kp + kd) (gazebo/physics/ode/ODEPhysics.cc,
  /// ODEPhysics::Collide); 0 (the default) leaves the contacts on the world ERP and CFM above.
  /// Gazebo's own surface defaults (sdformat surface.sdf: kp 1e12, kd 1 on each of the two
  /// surfaces, combined in series and summed: kp 5e11, kd 2) give soft_erp ~ 1, soft_cfm ~ 2e-9.
  double contact_kp = 0.0;
  double contact_kd = 0.0;
  unsigned long seed = 0;                 ///< dRandSetSeed at each run's start (QuickStep shuffles its rows)
};

/// The ODE engine with `options` (std::invalid_argument naming the option if one is out of range).
[[nodiscard]] std::unique_ptr<Engine> make_ode_engine(const OdeOptions& options = {});

}  // namespace frictionlab::engines
