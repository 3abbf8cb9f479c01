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
// (unit: m). See ode_engine.cpp for the sources of each quirk.

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
  unsigned long seed = 0;                 ///< dRandSetSeed at each run's start (QuickStep shuffles its rows)
};

/// The ODE engine with `options` (std::invalid_argument naming the option if one is out of range).
[[nodiscard]] std::unique_ptr<Engine> make_ode_engine(const OdeOptions& options = {});

}  // namespace frictionlab::engines
