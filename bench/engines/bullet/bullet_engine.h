#pragma once
// The Bullet 3.24 adapter of the engines' side by side (engine.h): one rigid body on a static
// plane in a btDiscreteDynamicsWorld, set up as a Bullet user sets it up (bullet_engine.cpp says
// what each setting is and where Bullet's source defines it).
//
// What a reader must know (each with its source in bullet_engine.cpp):
//  * btScalar is float unless the build links Bullet's double build (FRICTIONLAB_BULLET_DOUBLE).
//  * Spinning friction is a torque limit per contact point, combined spinning friction times the
//    point's normal force (unit: m), and it acts ONLY when the combined ROLLING friction is > 0
//    (bulletphysics/bullet3#4188): calibrated() sets a negligible rolling friction to switch it on.
//  * Above |omega| = (pi/4)/step, 47.1 1/s at the default step 1/60 s, the orientation turns by
//    less than |omega| step in a step (btTransformUtil::integrateTransform limits the exponential
//    map's angle; omega itself is kept): a fast top needs a small step.
//  * One friction row per contact point (Bullet's default solver mode), along the point's slip, or
//    along world -y when it slips less than sqrt(SIMD_EPSILON) (3.5e-4 m/s in floats): no static
//    friction along world x in the single build.
//  * A flat cylinder's contact points lie on its rim (its support point), so its sliding friction
//    also resists spin, as a ring's would; at the default step a spinning flat disk sinks ~2 cm.
//  * A body that moves slowly falls asleep (deactivation) unless told not to: the adapter disables
//    deactivation by default (BulletOptions::disable_deactivation).

#include <memory>

#include "bench/engines/engine.h"

namespace frictionlab::engines {

/// Bullet's own knobs, each at the value a Bullet user gets unless said otherwise.
struct BulletOptions {
  /// m: the collision margin of the disk (btCylinderShapeZ); 0 keeps Bullet's. Bullet's default is
  /// 0.04 m (CONVEX_DISTANCE_MARGIN, btCollisionMargin.h), lowered by btCylinderShape's constructor
  /// to 0.1 x the smallest half extent (btConvexInternalShape::setSafeMargin): 5e-4 m for a disk
  /// 1 cm thick. The margin rounds the cylinder's edges with its radius (the outer size is kept), so
  /// the adapter sets a smaller one (not Bullet's default). Must be below the smallest half extent.
  /// The sphere's margin is its radius (btSphereShape) and is left alone.
  double disk_margin = 1e-4;
  /// false (Bullet's default solver mode SOLVER_USE_WARMSTARTING | SOLVER_SIMD): one friction row
  /// per contact point, along the point's slip (or a fixed direction, btPlaneSpace1 of the normal,
  /// when the slip is below sqrt(SIMD_EPSILON), 3.5e-4 m/s in floats, 1.5e-8 in doubles: world -y
  /// for the +z normal, so in floats a body rolling along world x without slip has no friction row
  /// along its motion; see the test
  /// RockingAlongXNeedsTwoFrictionDirections). true adds SOLVER_USE_2_FRICTION_DIRECTIONS: a second
  /// row across the first, each bounded by k N on its own (a pyramid: up to sqrt(2) k N in all).
  bool two_friction_directions = false;
  /// true (Bullet's default, btContactSolverInfo::m_splitImpulse): penetration deeper than 0.04 m
  /// (m_splitImpulsePenetrationThreshold) is corrected by a separate position impulse; shallower, as
  /// without split impulse, by Baumgarte (erp2 = 0.2) in the velocity impulse, which the normal force
  /// therefore includes (btSequentialImpulseConstraintSolver.cpp, setupContactConstraint).
  bool split_impulse = true;
  /// true (NOT Bullet's default): setActivationState(DISABLE_DEACTIVATION). Bullet's default puts a
  /// body to sleep once its speeds stay below 0.8 m/s and 1.0 1/s for 2 s (btRigidBody's sleeping
  /// thresholds, gDeactivationTime): it would freeze a slow spin-down before it ends.
  bool disable_deactivation = true;
};

/// The Bullet engine (name "Bullet", version "3.24" as BT_BULLET_VERSION reports it, torsional
/// unit "m"). std::invalid_argument naming the field if an option is out of range.
[[nodiscard]] std::unique_ptr<Engine> make_bullet_engine(const BulletOptions& options = {});

}  // namespace frictionlab::engines
