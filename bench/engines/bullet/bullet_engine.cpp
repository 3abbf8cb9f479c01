#include "bench/engines/bullet/bullet_engine.h"

// Bullet 3.24's sources quoted below are those of the tag 3.24 of github.com/bulletphysics/bullet3
// (Debian's libbullet-dev 3.24+dfsg-2 is built from them); the headers are /usr/include/bullet.
#include <btBulletDynamicsCommon.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::engines {
namespace {

// Bullet's fixed step: btDiscreteDynamicsWorld::stepSimulation(timeStep, maxSubSteps = 1,
// fixedTimeStep = 1/60.f) (btDiscreteDynamicsWorld.h).
constexpr double kDefaultTimestep = 1.0 / 60.0;
// btContactSolverInfo's constructor: m_numIterations = 10 (btContactSolverInfo.h).
constexpr int kDefaultIterations = 10;
// btManifoldResult::calculateCombined{Friction,RollingFriction,SpinningFriction} clamp the
// combined coefficients to [-10, 10] (MAX_FRICTION, btManifoldResult.cpp lines 31-65).
constexpr double kMaxCombinedFriction = 10.0;
// The rolling friction calibrated() sets only to switch spinning friction on: the solver adds the
// spinning (and rolling) rows of a contact point only `if ((cp.m_combinedRollingFriction > 0.f) &&
// (rollingFriction > 0))` (btSequentialImpulseConstraintSolver.cpp line 1058, convertContact;
// bulletphysics/bullet3#4188). Any positive value passes that test; the smallest positive normal
// float does, in both builds, and its rolling torque limit (1.2e-38 N m per newton of normal force)
// is far below anything a float state can register.
constexpr double kSpinEnablingRolling = static_cast<double>(std::numeric_limits<float>::min());
// btTransformUtil::integrateTransform (btTransformUtil.h, called by btRigidBody::
// predictIntegratedTransform from btDiscreteDynamicsWorld::integrateTransformsInternal) limits the
// angle of the exponential map to ANGULAR_MOTION_THRESHOLD = 0.5 * SIMD_HALF_PI per step, but keeps
// the whole omega in the quaternion's vector part and normalises: above (pi/4)/step the orientation
// turns by 2 atan(|omega| step / (pi/4) tan(pi/8)) < |omega| step, while omega is kept.
// (btRigidBody::integrateVelocities, which would clamp omega at (pi/2)/step, is not called by
// btDiscreteDynamicsWorld in 3.24.)
constexpr double kQuarterPi = 0.78539816339744830962;

void require(bool ok, const char* key, double value, const char* rule) {
  if (!ok) throw support::invalid_value(key, value, rule);
}

std::string n(double x) { return support::shortest(x); }
// Four significant digits, for the notes' derived numbers.
std::string g4(double x) { return support::significant(x, 4); }

btVector3 to_bt(const std::array<double, 3>& v) {
  return {static_cast<btScalar>(v[0]), static_cast<btScalar>(v[1]), static_cast<btScalar>(v[2])};
}
std::array<double, 3> from_bt(const btVector3& v) {
  return {static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z())};
}

void validate(const RunSpec& s, const BulletOptions& options) {
  engines::validate(s, kDefaultTimestep);  // the rules of every engine (bench/engines/engine.h)
  const Body& b = s.body;
  if (b.shape == Body::Shape::disk) {
    // The cylinder's inner (implicit) half extents are the outer ones less the margin.
    require(options.disk_margin < std::min(b.radius, b.thickness / 2), "BulletOptions::disk_margin",
            options.disk_margin, "must be below the disk's smallest half extent (radius, thickness/2)");
  }
  const Friction& f = s.friction;
  require(f.k <= kMaxCombinedFriction, "friction.k", f.k, "must be a finite number in [0, 10] (Bullet clamps combined friction at 10)");
  require(f.torsional <= kMaxCombinedFriction, "friction.torsional", f.torsional,
          "must be a finite number in [0, 10] m (Bullet clamps it at 10)");
  require(f.rolling <= kMaxCombinedFriction, "friction.rolling", f.rolling,
          "must be a finite number in [0, 10] m (Bullet clamps it at 10)");
  // stepSimulation(t, 0) takes no step at all if btFuzzyZero(t), |t| < SIMD_EPSILON.
  const Numerics& nu = s.numerics;
  require(nu.timestep == 0.0 || static_cast<btScalar>(nu.timestep) > SIMD_EPSILON, "numerics.timestep", nu.timestep,
          "must be 0 (Bullet's 1/60 s) or a finite number above SIMD_EPSILON s (Bullet skips shorter steps)");
}

// One world with the plane and the body, owned here, torn down in the order Bullet needs (bodies
// out of the world before the world, the world before its parts).
class Scene {
 public:
  Scene(const RunSpec& spec, const BulletOptions& options, btScalar step);
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
  ~Scene() {
    world_->removeRigidBody(body_.get());
    world_->removeRigidBody(ground_.get());
  }

  // maxSubSteps = 0 is Bullet's variable-step mode: exactly one internal step of step_ per call,
  // no interpolation (btDiscreteDynamicsWorld.cpp lines 399-415); for step_ = 1/60.f it is the step
  // that stepSimulation(1/60.f) with its default arguments takes.
  void step() { world_->stepSimulation(step_, 0); }
  btRigidBody& body() { return *body_; }
  [[nodiscard]] double normal_force() const;
  [[nodiscard]] bool compound() const { return compound_ != nullptr; }
  [[nodiscard]] double disk_margin() const { return convex_ ? static_cast<double>(convex_->getMargin()) : 0.0; }

 private:
  btScalar step_;
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  btStaticPlaneShape plane_{btVector3(0, 0, 1), 0};
  std::unique_ptr<btRigidBody> ground_;
  std::unique_ptr<btConvexInternalShape> convex_;
  std::unique_ptr<btCompoundShape> compound_;
  std::unique_ptr<btRigidBody> body_;
};

Scene::Scene(const RunSpec& spec, const BulletOptions& options, btScalar step) : step_(step) {
  world_ = std::make_unique<btDiscreteDynamicsWorld>(&dispatcher_, &broadphase_, &solver_, &configuration_);
  world_->setGravity(btVector3(0, 0, static_cast<btScalar>(-spec.numerics.g)));
  btContactSolverInfo& info = world_->getSolverInfo();
  info.m_numIterations = spec.numerics.iterations > 0 ? spec.numerics.iterations : kDefaultIterations;
  info.m_splitImpulse = options.split_impulse ? 1 : 0;
  if (options.two_friction_directions) info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;

  // The plane: a static body (mass 0). Friction 1 and spinning/rolling 0, so that the combined
  // coefficients are the body's own: combined friction = f0 f1 (btManifoldResult.cpp lines 56-65),
  // combined spinning = s0 f1 + s1 f0 and rolling = r0 f1 + r1 f0 (lines 31-53).
  ground_ = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &plane_));
  ground_->setFriction(1);
  ground_->setRollingFriction(0);
  ground_->setSpinningFriction(0);

  const Body& b = spec.body;
  if (b.shape == Body::Shape::sphere) {
    convex_ = std::make_unique<btSphereShape>(static_cast<btScalar>(b.radius));  // margin = radius
  } else {
    const auto r = static_cast<btScalar>(b.radius);
    convex_ = std::make_unique<btCylinderShapeZ>(btVector3(r, r, static_cast<btScalar>(b.thickness / 2)));
    // btCylinderShape::setMargin keeps the outer size (btCylinderShape.h); 0 keeps Bullet's margin.
    if (options.disk_margin > 0.0) convex_->setMargin(static_cast<btScalar>(options.disk_margin));
  }
  // Bullet's body frame is the centre of mass: a centre of mass off the shape's centre is a compound
  // with the shape at -com (the usual Bullet way, btCompoundShape).
  btCollisionShape* shape = convex_.get();
  const btVector3 com = to_bt(b.com);
  if (!com.isZero()) {
    compound_ = std::make_unique<btCompoundShape>();
    compound_->addChildShape(btTransform(btQuaternion::getIdentity(), -com), convex_.get());
    shape = compound_.get();
  }

  // The pose: the shape's lowest point (Bullet's own support point, margin included, the point its
  // convex-plane collision uses) on the plane at x = y = 0.
  const auto& q = spec.start.orientation;
  const btQuaternion rotation(static_cast<btScalar>(q[1]), static_cast<btScalar>(q[2]), static_cast<btScalar>(q[3]),
                              static_cast<btScalar>(q[0]));
  const btMatrix3x3 basis(rotation);
  const btVector3 lowest_in_shape = convex_->localGetSupportingVertex(basis.transpose() * btVector3(0, 0, -1));
  const btVector3 shape_centre = -(basis * lowest_in_shape);
  btRigidBody::btRigidBodyConstructionInfo info_body(static_cast<btScalar>(b.mass), nullptr, shape, to_bt(b.inertia));
  info_body.m_startWorldTransform = btTransform(rotation, shape_centre + basis * com);
  info_body.m_friction = static_cast<btScalar>(spec.friction.k);
  info_body.m_rollingFriction = static_cast<btScalar>(spec.friction.rolling);
  info_body.m_spinningFriction = static_cast<btScalar>(spec.friction.torsional);
  body_ = std::make_unique<btRigidBody>(info_body);
  if (options.disable_deactivation) body_->setActivationState(DISABLE_DEACTIVATION);

  world_->addRigidBody(ground_.get());
  world_->addRigidBody(body_.get());
}

// The normal force of the last step: the normal impulses the solver applied at the body's contact
// points with the plane (btManifoldPoint::m_appliedImpulse, written back by
// btSequentialImpulseConstraintSolver::writeBackContacts), over the step.
double Scene::normal_force() const {
  double impulse = 0.0;
  const int manifolds = dispatcher_.getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    const btPersistentManifold* m = dispatcher_.getManifoldByIndexInternal(i);
    const bool ours = (m->getBody0() == body_.get() && m->getBody1() == ground_.get()) ||
                      (m->getBody0() == ground_.get() && m->getBody1() == body_.get());
    if (!ours) continue;
    for (int j = 0; j < m->getNumContacts(); ++j) impulse += static_cast<double>(m->getContactPoint(j).getAppliedImpulse());
  }
  return impulse / static_cast<double>(step_);
}

Sample sample_of(double t, btRigidBody& body, double normal_force) {
  Sample s;
  s.t = t;
  s.com = from_bt(body.getCenterOfMassPosition());
  s.v = from_bt(body.getLinearVelocity());
  s.omega = from_bt(body.getAngularVelocity());
  const btQuaternion q = body.getOrientation();
  s.orientation = {static_cast<double>(q.w()), static_cast<double>(q.x()), static_cast<double>(q.y()),
                   static_cast<double>(q.z())};
  s.normal_force = normal_force;
  return s;
}

void require_finite_state(const Sample& s) {
  bool ok = std::isfinite(s.normal_force);
  for (const double x : s.com) ok = ok && std::isfinite(x);
  for (const double x : s.v) ok = ok && std::isfinite(x);
  for (const double x : s.omega) ok = ok && std::isfinite(x);
  for (const double x : s.orientation) ok = ok && std::isfinite(x);
  if (!ok) throw std::runtime_error("Bullet: the body's state became non-finite at t = " + n(s.t) + " s");
}

std::string notes(const RunSpec& spec, const BulletOptions& options, const Scene& scene, double step,
                  int iterations) {
  const double omega_limit = kQuarterPi / step;
  const double no_slip = std::sqrt(static_cast<double>(SIMD_EPSILON));
  const auto& w = spec.start.omega;
  const double omega0 = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  std::string s = "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100);
  s += btIsDoublePrecision() ? " (double build, btScalar = double)" : " (single precision, btScalar = float)";
  s += "; btDiscreteDynamicsWorld, btSequentialImpulseConstraintSolver, btDefaultCollisionConfiguration, "
       "btDbvtBroadphase; step " + n(step) + " s, one internal step per stepSimulation(step, 0)";
  s += "; " + std::to_string(iterations) + " solver iterations, warm starting 0.85, cfm 0, restitution 0";
  s += options.two_friction_directions ? ", two friction directions per point"
                                       : ", one friction direction per point (along its slip; below " + g4(no_slip) +
                                             " m/s of slip a fixed one, btPlaneSpace1 of the normal: world -y, so no "
                                             "static friction along x)";
  s += options.split_impulse ? ", penetration corrected by Baumgarte (erp2 0.2, in the velocity impulse), by split "
                               "impulse beyond 0.04 m"
                             : ", no split impulse (Baumgarte erp2 0.2)";
  s += "; contact processing threshold BT_LARGE_FLOAT (every manifold point solved, also those apart by less than "
       "the breaking threshold, 0.02 x the shape's bounding radius)";
  s += "; plane btStaticPlaneShape friction 1, spinning and rolling 0: combined friction = k (product), "
       "combined spinning and rolling = the body's (s0 f1 + s1 f0; all clamped at 10)";
  if (spec.body.shape == Body::Shape::sphere) {
    s += "; body btSphereShape (margin = radius)";
  } else {
    s += "; body btCylinderShapeZ, margin " + n(scene.disk_margin()) +
         " m (Bullet's: 0.04 m or 0.1 x the smallest half extent if less); one new contact point per step, at the "
         "rim even when flat (the cylinder's support point), up to 4 kept while they stay within the breaking "
         "threshold, so sliding friction on the rim also resists spin";
  }
  if (scene.compound()) s += " in a btCompoundShape at -com";
  s += "; spinning friction: torque <= torsional x N per point, also <= torsional / step (the impulse is capped "
       "at the coefficient's number)";
  if (spec.friction.torsional > 0.0 && spec.friction.rolling <= 0.0) {
    s += ", and OFF here: Bullet adds it only with rolling friction > 0 (bullet3#4188)";
  } else if (spec.friction.torsional > 0.0) {
    s += ", on (rolling friction " + n(spec.friction.rolling) + " m > 0 switches it on, bullet3#4188)";
  }
  s += "; the orientation turns by less than |omega| step above |omega| = (pi/4)/step = " + g4(omega_limit) +
       " 1/s (the exponential map's angle is limited)";
  if (omega0 > omega_limit) s += " (the start's " + n(omega0) + " 1/s is above it)";
  s += "; gyroscopic term implicit (BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY); ";
  s += options.disable_deactivation ? "deactivation disabled (Bullet's sleeping would freeze a slow spin-down)"
                                    : "deactivation on (Bullet's default: asleep below 0.8 m/s and 1 1/s for 2 s)";
  return s;
}

class BulletEngine final : public Engine {
 public:
  explicit BulletEngine(const BulletOptions& options) : options_(options) {
    require(std::isfinite(options.disk_margin) && options.disk_margin >= 0.0, "BulletOptions::disk_margin",
            options.disk_margin, "must be a finite number >= 0 m (0: Bullet's own)");
  }

  [[nodiscard]] std::string name() const override { return "Bullet"; }
  [[nodiscard]] std::string version() const override {
    return std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100);
  }
  [[nodiscard]] std::string torsional_unit() const override { return "m"; }

  // btCollisionObject's constructor: m_friction 0.5, m_rollingFriction 0, m_spinningFriction 0
  // (btCollisionObject.cpp lines 36-39): a Bullet user who sets only the friction gets no spinning
  // and no rolling friction.
  [[nodiscard]] Friction defaults(double k) const override {
    require(std::isfinite(k) && k >= 0.0, "k", k, "must be a finite number >= 0");
    return {k, 0.0, 0.0};
  }

  // The solver's torsional row at a contact point is bounded by combined spinning friction x the
  // point's normal impulse (btSequentialImpulseConstraintSolver.cpp lines 1676-1687): a torque
  // torsional x N. The pure-spin torque c k N a thus needs torsional = c k a (m), and rolling > 0.
  [[nodiscard]] Friction calibrated(double k, double c, double a) const override {
    require(std::isfinite(k) && k >= 0.0, "k", k, "must be a finite number >= 0");
    require(std::isfinite(c) && c >= 0.0, "c", c, "must be a finite number >= 0");
    require(std::isfinite(a) && a >= 0.0, "a", a, "must be a finite number >= 0 m");
    return {k, c * k * a, kSpinEnablingRolling};
  }

  [[nodiscard]] Run run(const RunSpec& spec) const override {
    validate(spec, options_);
    const auto step = static_cast<btScalar>(spec.numerics.timestep > 0.0 ? spec.numerics.timestep : kDefaultTimestep);
    const double dt = static_cast<double>(step);  // the step Bullet takes (a float in the single build)
    Scene scene(spec, options_, step);
    Run run;
    run.timestep = dt;
    run.iterations = spec.numerics.iterations > 0 ? spec.numerics.iterations : kDefaultIterations;
    run.notes = notes(spec, options_, scene, dt, run.iterations);

    // Settling: held at the start's pose with no velocity, then launched from the settled pose.
    const long long settle_steps = std::llround(spec.numerics.settle_time / dt);
    for (long long i = 0; i < settle_steps; ++i) scene.step();
    btRigidBody& body = scene.body();
    body.setLinearVelocity(to_bt(spec.start.v));
    body.setAngularVelocity(to_bt(spec.start.omega));
    if (!options_.disable_deactivation) body.activate(true);  // wakes a body that fell asleep while settling

    const long long every = std::max(1LL, std::llround(spec.output_dt / dt));
    const double interval = static_cast<double>(every) * dt;
    // t_end counts as on a sample within a relative 1e-6: the float step 1/60.f = 0.016666668 s is
    // 4e-8 (relative) off 1/60 s, so t_end = 1 s is 2.4e-6 of an interval past sample 60.
    const auto samples = static_cast<long long>(std::floor(spec.t_end / interval * (1.0 + 1e-6))) + 1;
    run.samples.reserve(static_cast<std::size_t>(samples));
    run.samples.push_back(sample_of(0.0, body, settle_steps > 0 ? scene.normal_force() : 0.0));
    for (long long i = 1; i < samples; ++i) {
      for (long long j = 0; j < every; ++j) scene.step();
      run.samples.push_back(sample_of(static_cast<double>(i) * interval, body, scene.normal_force()));
      require_finite_state(run.samples.back());
    }
    return run;
  }

 private:
  BulletOptions options_;
};

}  // namespace

std::unique_ptr<Engine> make_bullet_engine(const BulletOptions& options) {
  return std::make_unique<BulletEngine>(options);
}

}  // namespace frictionlab::engines
