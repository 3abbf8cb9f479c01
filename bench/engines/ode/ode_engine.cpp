// The ODE adapter (ode_engine.h). Sources cited are ODE 0.16's (github:thomasmarsh/ODE, the
// upstream history; ode/src/joints/contact.cpp has not changed since 0.16) and Gazebo's sdformat.
#include "bench/engines/ode/ode_engine.h"

#include <ode/ode.h>
#include <ode/version.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

#ifndef dDOUBLE
#error "the ODE adapter expects ODE built in double precision (Debian's libode-dev: dDOUBLE)"
#endif

namespace frictionlab::engines {
namespace {

using Vec3 = std::array<double, 3>;

// ---------------------------------------------------------------------------------------------
// ODE's process-wide state.

// ODE reports its errors and failed internal assertions (e.g. a quaternion gone non-finite) through
// handlers that by default print and abort() the process (ode/src/error.cpp). Ours throw instead:
// Engine::run promises a std::runtime_error with the engine's message. ODE is C++ inside (built
// with exceptions) and every object of a run is owned by RAII below, but unwinding out of a step
// leaves ODE's shared stepping job list half used (dCloseODE then fails its own assertion
// "m_job_list == NULL"), so after an ODE error the library is not trusted again in this process:
// later runs throw at once, and dCloseODE is skipped at exit.
std::atomic<bool> ode_failed{false};

[[noreturn]] void throw_ode_error(int errnum, const char* message, va_list arguments) {
  std::array<char, 1024> text{};
  std::vsnprintf(text.data(), text.size(), message, arguments);
  ode_failed = true;
  throw std::runtime_error("ODE error " + std::to_string(errnum) + ": " + support::one_line(text.data()));
}

// dInitODE2 once per process, dCloseODE at exit: a function-local static is initialised once,
// thread-safely (C++11), and destroyed at exit.
struct OdeLibrary {
  OdeLibrary() {
    if (dInitODE2(0) == 0) throw std::runtime_error("ODE: dInitODE2 failed");
    dSetErrorHandler(&throw_ode_error);
    dSetDebugHandler(&throw_ode_error);
  }
  ~OdeLibrary() {
    if (!ode_failed) dCloseODE();
  }
  OdeLibrary(const OdeLibrary&) = delete;
  OdeLibrary& operator=(const OdeLibrary&) = delete;
};

// Runs are serialised: QuickStep shuffles its constraint rows with ODE's one global random number
// generator (ode/src/quickstep.cpp, REORDERING_METHOD__RANDOMLY, dRandInt; ode/src/misc.cpp keeps
// one `seed` per process), so two runs in parallel threads would draw from each other's sequence
// and lose their determinism. The same lock covers the collision library's per-thread data.
std::mutex& ode_mutex() {
  static std::mutex mutex;
  return mutex;
}

void ensure_ode_ready_for_this_thread() {
  static OdeLibrary library;
  // Collision (dCollide) needs ODE's per-thread data in each thread that calls it (odeinit.h);
  // with the default init flags it is released by dCloseODE.
  thread_local bool allocated = false;
  if (!allocated) {
    if (dAllocateODEDataForThread(dAllocateMaskAll) == 0) throw std::runtime_error("ODE: dAllocateODEDataForThread failed");
    allocated = true;
  }
  if (ode_failed) throw std::runtime_error("ODE: an earlier run failed inside ODE in this process; its state is no longer trusted");
}

// RAII owners of the ODE objects of one run.
struct World {
  dWorldID id = dWorldCreate();
  World() = default;
  ~World() { dWorldDestroy(id); }
  World(const World&) = delete;
  World& operator=(const World&) = delete;
};
struct Geom {
  dGeomID id;
  explicit Geom(dGeomID g) : id(g) {}
  ~Geom() { dGeomDestroy(id); }
  Geom(const Geom&) = delete;
  Geom& operator=(const Geom&) = delete;
};
struct JointGroup {
  dJointGroupID id = dJointGroupCreate(0);
  JointGroup() = default;
  ~JointGroup() { dJointGroupDestroy(id); }
  JointGroup(const JointGroup&) = delete;
  JointGroup& operator=(const JointGroup&) = delete;
};

// ---------------------------------------------------------------------------------------------
// Validation.

void require_positive(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) throw support::invalid_value(key, value, "it must be finite and > 0");
}
void require_non_negative(const char* key, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) throw support::invalid_value(key, value, "it must be finite and >= 0");
}

void validate_options(const OdeOptions& o) {
  require_positive("ode.timestep", o.timestep);
  if (o.iterations < 1) throw support::invalid_value("ode.iterations", static_cast<long long>(o.iterations), "it must be >= 1");
  if (!(std::isfinite(o.sor) && o.sor > 0.0 && o.sor < 2.0)) throw support::invalid_value("ode.sor", o.sor, "it must lie in (0, 2)");
  if (!(std::isfinite(o.erp) && o.erp >= 0.0 && o.erp <= 1.0)) throw support::invalid_value("ode.erp", o.erp, "it must lie in [0, 1]");
  require_non_negative("ode.cfm", o.cfm);
  require_non_negative("ode.contact_surface_layer", o.contact_surface_layer);
  require_positive("ode.contact_max_correcting_vel", o.contact_max_correcting_vel);
  // dCollide takes the count in the low 16 bits of its flags (collision.h, NUMC_MASK).
  require_non_negative("ode.contact_kp", o.contact_kp);
  require_non_negative("ode.contact_kd", o.contact_kd);
  if (o.max_contacts < 1 || o.max_contacts > 0xffff) {
    throw support::invalid_value("ode.max_contacts", static_cast<long long>(o.max_contacts), "it must lie in [1, 65535]");
  }
}

void validate_spec(const RunSpec& s, double default_timestep) {
  engines::validate(s, default_timestep);  // the rules of every engine (bench/engines/engine.h)
  require_positive("t_end", s.t_end);
}

// Steps in `duration` at step h, rounded to the nearest (the interface's "a multiple of the time
// step, rounded"); too many steps is refused rather than run for hours.
long long steps_in(const char* key, double duration, double h) {
  const double n = std::round(duration / h);
  if (n > 1e9) throw support::invalid_value(key, duration, "it must be at most 1e9 time steps (" + support::shortest(h) + " s)");
  return static_cast<long long>(n);
}

// ---------------------------------------------------------------------------------------------
// The contact.

// ODE's surface for Friction `f`. Cited: ode/src/joints/contact.cpp (dxJointContact::getInfo1/2).
dSurfaceParameters surface_of(const Friction& f, const OdeOptions& o, double h) {
  dSurfaceParameters s{};
  // dContactApprox1 (= Approx1_1 | Approx1_2 | Approx1_N) sets findex = the normal row for the two
  // friction rows and the three rolling rows: their bounds become +-mu * lambda_normal (a
  // coefficient) instead of +-mu (a force in N, ODE's default "box" friction).
  s.mode = dContactApprox1;
  s.mu = f.k;
  if (f.torsional > 0.0 || f.rolling > 0.0) {
    // dContactAxisDep (= dContactMu2) makes rho, rho2, rhoN separate; without it rho is used for
    // all three axes, i.e. rolling friction = spin friction.
    s.mode |= dContactRolling | dContactAxisDep;
    s.mu2 = f.k;
    // A quirk of getInfo1: with dContactAxisDep a coefficient rho == 0 still counts a constraint
    // row (only rho < 0 is dropped), while getInfo2 fills no row for it: the solver then gets an
    // all-zero row, whose diagonal is 0 with CFM 0 (a 0/0 in QuickStep). A negative coefficient
    // is clamped to 0 and counts no row, so "none" is passed as -1.
    s.rho = f.rolling > 0.0 ? f.rolling : -1.0;
    s.rho2 = s.rho;
    s.rhoN = f.torsional > 0.0 ? f.torsional : -1.0;
  }
  if (o.contact_kp > 0.0) {  // Gazebo's spring-damper contact (OdeOptions::contact_kp)
    s.mode |= dContactSoftERP | dContactSoftCFM;
    s.soft_erp = h * o.contact_kp / (h * o.contact_kp + o.contact_kd);
    s.soft_cfm = 1.0 / (h * o.contact_kp + o.contact_kd);
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// Geometry of the start.

// Rotates v by the unit quaternion q = (w, x, y, z).
Vec3 rotate(const std::array<double, 4>& q, const Vec3& v) {
  const double w = q[0];
  const Vec3 u{q[1], q[2], q[3]};
  const Vec3 t{2.0 * (u[1] * v[2] - u[2] * v[1]), 2.0 * (u[2] * v[0] - u[0] * v[2]), 2.0 * (u[0] * v[1] - u[1] * v[0])};
  return {v[0] + w * t[0] + (u[1] * t[2] - u[2] * t[1]), v[1] + w * t[1] + (u[2] * t[0] - u[0] * t[2]),
          v[2] + w * t[2] + (u[0] * t[1] - u[1] * t[0])};
}

// Height of the shape's centre above its lowest point for the orientation q.
double centre_height(const Body& b, const std::array<double, 4>& q) {
  if (b.shape == Body::Shape::sphere) return b.radius;
  const double nz = rotate(q, Vec3{0.0, 0.0, 1.0})[2];  // the cylinder's axis, world z component
  return b.radius * std::sqrt(std::max(0.0, 1.0 - nz * nz)) + 0.5 * b.thickness * std::abs(nz);
}

// ---------------------------------------------------------------------------------------------
// The engine.

class OdeEngine final : public Engine {
 public:
  explicit OdeEngine(const OdeOptions& options) : options_(options) { validate_options(options_); }

  [[nodiscard]] std::string name() const override { return "ODE"; }
  [[nodiscard]] std::string version() const override { return dODE_VERSION; }
  [[nodiscard]] std::string torsional_unit() const override { return "m"; }

  // Upstream ODE applies no spin or rolling friction unless dContactRolling is set. Gazebo's own
  // torsional friction (its ODE fork) is off by default too: sdformat sdf/1.6/surface.sdf has
  // <torsional><coefficient> 1 with <use_patch_radius> true and <patch_radius> 0, a zero patch and
  // so a zero torque.
  [[nodiscard]] Friction defaults(double k) const override { return Friction{k, 0.0, 0.0}; }

  // With dContactApprox1 each contact point's spin torque is bounded by rhoN times its normal force
  // (contact.cpp: lo/hi = -+rhoN, findex = the normal row), so over the points the bound is rhoN N:
  // rhoN = c k a gives the pure-spin torque c k N a. No rolling friction is needed for it to act.
  [[nodiscard]] Friction calibrated(double k, double c, double a) const override { return Friction{k, c * k * a, 0.0}; }

  [[nodiscard]] Run run(const RunSpec& spec) const override {
    validate_spec(spec, options_.timestep);
    const std::lock_guard<std::mutex> lock(ode_mutex());
    ensure_ode_ready_for_this_thread();
    return simulate(spec);
  }

 private:
  [[nodiscard]] Run simulate(const RunSpec& spec) const;

  OdeOptions options_;
};

Run OdeEngine::simulate(const RunSpec& spec) const {
  const Body& body_spec = spec.body;
  const double h = spec.numerics.timestep > 0.0 ? spec.numerics.timestep : options_.timestep;
  const int iterations = spec.numerics.iterations > 0 ? spec.numerics.iterations : options_.iterations;
  const bool quick = options_.solver == OdeOptions::Solver::quick;
  const long long per_sample = steps_in("output_dt", spec.output_dt, h);
  if (per_sample < 1) throw support::invalid_value("output_dt", spec.output_dt, "it must be at least half the time step (" + support::shortest(h) + " s)");
  const long long settle_steps = steps_in("numerics.settle_time", spec.numerics.settle_time, h);
  const long long end_steps = steps_in("t_end", spec.t_end, h);
  const long long samples = end_steps / per_sample;  // the last sample at or before t_end

  // Everything is created afresh for each run, and the random generator reseeded, so that a run
  // does not depend on what ran before it in the process.
  dRandSetSeed(options_.seed);
  World world;
  dWorldSetGravity(world.id, 0.0, 0.0, -spec.numerics.g);
  dWorldSetERP(world.id, options_.erp);
  dWorldSetCFM(world.id, options_.cfm);
  dWorldSetContactSurfaceLayer(world.id, options_.contact_surface_layer);
  dWorldSetContactMaxCorrectingVel(world.id, options_.contact_max_correcting_vel);
  dWorldSetQuickStepNumIterations(world.id, iterations);
  dWorldSetQuickStepW(world.id, options_.sor);

  // The body: ODE's body position is its centre of mass (dBodySetMass asserts a centred mass), so
  // the mass is centred at the body origin and the geom is offset to -com in the body frame.
  const dBodyID body = dBodyCreate(world.id);  // destroyed with the world
  dMass mass;
  dMassSetZero(&mass);
  dMassSetParameters(&mass, body_spec.mass, 0.0, 0.0, 0.0, body_spec.inertia[0], body_spec.inertia[1], body_spec.inertia[2], 0.0,
                     0.0, 0.0);
  dBodySetMass(body, &mass);
  Geom shape(body_spec.shape == Body::Shape::sphere ? dCreateSphere(nullptr, body_spec.radius)
                                                    : dCreateCylinder(nullptr, body_spec.radius, body_spec.thickness));
  dGeomSetBody(shape.id, body);
  dGeomSetOffsetPosition(shape.id, -body_spec.com[0], -body_spec.com[1], -body_spec.com[2]);
  Geom plane(dCreatePlane(nullptr, 0.0, 0.0, 1.0, 0.0));  // z = 0, static (no body)

  const auto& q = spec.start.orientation;
  const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const std::array<double, 4> unit_q{q[0] / qn, q[1] / qn, q[2] / qn, q[3] / qn};
  const Vec3 com_offset = rotate(unit_q, body_spec.com);
  const double z_centre = centre_height(body_spec, unit_q);
  dQuaternion dq{unit_q[0], unit_q[1], unit_q[2], unit_q[3]};
  dBodySetQuaternion(body, dq);
  dBodySetPosition(body, com_offset[0], com_offset[1], z_centre + com_offset[2]);

  const dSurfaceParameters surface = surface_of(spec.friction, options_, h);
  JointGroup contacts;
  const auto max_contacts = static_cast<std::size_t>(options_.max_contacts);
  std::vector<dContact> contact(max_contacts);
  std::vector<dJointFeedback> feedback(max_contacts);
  std::vector<dJointID> joints;
  joints.reserve(max_contacts);
  double normal_force = 0.0;  // of the last step taken

  const auto step = [&] {
    dJointGroupEmpty(contacts.id);
    joints.clear();
    const int n = dCollide(shape.id, plane.id, options_.max_contacts, &contact[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      contact[i].surface = surface;
      const dJointID j = dJointCreateContact(world.id, contacts.id, &contact[i]);
      dJointAttach(j, body, nullptr);  // body 1 = the body: the contact normal points into it (contact.h)
      dJointSetFeedback(j, &feedback[i]);
      joints.push_back(j);
    }
    if (quick) {
      dWorldQuickStep(world.id, h);
    } else {
      dWorldStep(world.id, h);
    }
    // The force of each joint on body 1, world frame; its component along the contact normal.
    normal_force = 0.0;
    for (std::size_t i = 0; i < joints.size(); ++i) {
      const dReal* nrm = contact[i].geom.normal;
      normal_force += feedback[i].f1[0] * nrm[0] + feedback[i].f1[1] * nrm[1] + feedback[i].f1[2] * nrm[2];
    }
  };

  // Settling: held at rest (zero velocity) for settle_time, then the start's velocities on the
  // settled pose.
  for (long long i = 0; i < settle_steps; ++i) step();
  dBodySetLinearVel(body, spec.start.v[0], spec.start.v[1], spec.start.v[2]);
  dBodySetAngularVel(body, spec.start.omega[0], spec.start.omega[1], spec.start.omega[2]);

  Run run;
  run.timestep = h;
  run.iterations = quick ? iterations : 0;
  run.samples.reserve(static_cast<std::size_t>(samples) + 1);
  const auto sample = [&](long long index) {
    Sample s;
    s.t = static_cast<double>(index * per_sample) * h;
    const dReal* p = dBodyGetPosition(body);
    const dReal* v = dBodyGetLinearVel(body);
    const dReal* w = dBodyGetAngularVel(body);
    const dReal* qq = dBodyGetQuaternion(body);
    s.com = {p[0], p[1], p[2]};
    s.v = {v[0], v[1], v[2]};
    s.omega = {w[0], w[1], w[2]};
    s.orientation = {qq[0], qq[1], qq[2], qq[3]};
    s.normal_force = normal_force;
    for (const double x : {p[0], p[1], p[2], v[0], v[1], v[2], w[0], w[1], w[2], qq[0], qq[1], qq[2], qq[3], normal_force}) {
      if (!std::isfinite(x)) throw std::runtime_error("ODE: the state became non-finite at t = " + support::shortest(s.t) + " s");
    }
    run.samples.push_back(s);
  };
  sample(0);
  for (long long k = 1; k <= samples; ++k) {
    for (long long i = 0; i < per_sample; ++i) step();
    sample(k);
  }

  const std::string solver = quick ? "QuickStep (PGS) " + std::to_string(iterations) + " iterations, SOR " + support::shortest(options_.sor)
                                   : std::string("dWorldStep (exact LCP, Dantzig)");
  const Friction& f = spec.friction;
  const std::string softness =
      options_.contact_kp > 0.0
          ? "contacts soft_erp " + support::shortest(surface.soft_erp) + ", soft_cfm " + support::shortest(surface.soft_cfm) +
                " (Gazebo's kp " + support::shortest(options_.contact_kp) + " N/m, kd " + support::shortest(options_.contact_kd) + " N s/m)"
          : "ERP " + support::shortest(options_.erp) + ", CFM " + support::shortest(options_.cfm);
  const std::string spin =
      f.torsional > 0.0 || f.rolling > 0.0
          ? "dContactRolling|AxisDep: rhoN = " + support::shortest(f.torsional) + " m, rho = rho2 = " + support::shortest(f.rolling) +
                " m (torque limits rho N_i per point, which add up over the points)"
          : std::string("no rolling or spin friction rows (ODE's default)");
  run.notes = "ODE " + std::string(dODE_VERSION) + " (double); step " + support::shortest(h) + " s; " + solver + "; " + softness +
              ", surface layer " + support::shortest(options_.contact_surface_layer) + " m, max correcting velocity " +
              support::shortest(options_.contact_max_correcting_vel) +
              " m/s (Gazebo classic's defaults); a contact joint per point (sphere-plane 1; cylinder-plane 4 on the rim when flat, "
              "1-2 when tilted); dContactApprox1: friction pyramid mu = mu2 = " +
              support::shortest(f.k) + " with edges along world x and y; " + spin +
              "; normal_force: the contact feedback of the step that ended at the sample (at t = 0: the last settling step's, 0 "
              "without settling); QuickStep's row shuffling seeded with dRandSetSeed(" +
              std::to_string(options_.seed) + ") at each run";
  return run;
}

}  // namespace

std::unique_ptr<Engine> make_ode_engine(const OdeOptions& options) { return std::make_unique<OdeEngine>(options); }

}  // namespace frictionlab::engines
