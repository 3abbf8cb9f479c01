#include "bench/engines/mujoco/mujoco_world.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "bench/engines/mujoco/mujoco_model.h"
#include "friction/support/number_format.h"

namespace frictionlab::engines {
namespace {

// mjVFS holds 2000 file names of 1000 characters: too big for the stack.
struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};

// Loads MJCF text from memory: a one-file virtual file system (mj_loadXML reads a file of the VFS
// when one of that name is there, src/xml/xml.cc mjParseXML).
mjModel* load(const std::string& text) {
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const char* name = "frictionlab_engine.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(text.size())) != 0) {
    throw std::runtime_error("MuJoCo could not make its virtual model file");
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name)], text.data(), text.size());
  char error[1000] = "";
  mjModel* m = mj_loadXML(name, vfs.get(), error, sizeof error);
  if (!m) throw std::runtime_error(std::string("MuJoCo could not load the model: ") + error);
  return m;
}

std::string g(double x) { return support::significant(x, 4); }

// MuJoCo's default warning handler prints "WARNING: ..." to standard output and appends it to
// MUJOCO_LOG.TXT in the current folder (engine_util_errmem.c, mju_warning). The world reads the
// warnings from mjData after each step and throws (check_warnings), so the handler only has to keep
// quiet: installed once, for the process (mju_user_warning is a global of the library).
void quiet_warning(const char* /*message*/) {}
void install_quiet_warning_handler() {
  static const bool installed = [] {
    mju_user_warning = quiet_warning;
    return true;
  }();
  (void)installed;
}

const char* cone_text(MujocoOptions::Cone c) {
  return c == MujocoOptions::Cone::elliptic ? "elliptic cone" : "pyramidal cone";
}
const char* solver_text(MujocoOptions::Solver s) {
  switch (s) {
    case MujocoOptions::Solver::pgs: return "PGS";
    case MujocoOptions::Solver::cg: return "CG";
    default: return "Newton";
  }
}
const char* integrator_text(MujocoOptions::Integrator i) {
  switch (i) {
    case MujocoOptions::Integrator::rk4: return "RK4";
    case MujocoOptions::Integrator::implicit: return "implicit";
    default: return "Euler";
  }
}

}  // namespace

MujocoWorld::MujocoWorld(const RunSpec& spec, const MujocoOptions& options)
    : spec_(spec), options_(options), mjcf_(mujoco_mjcf(spec, options)) {
  install_quiet_warning_handler();
  model_ = load(mjcf_);
  data_ = mj_makeData(model_);
  if (!data_) {
    mj_deleteModel(model_);
    throw std::runtime_error("MuJoCo could not allocate its data");
  }
  body_ = mj_name2id(model_, mjOBJ_BODY, "body");
  const double dt = timestep();
  steps_ = std::llround(spec.t_end / dt);
  every_ = std::max(1L, static_cast<long>(std::llround(spec.output_dt / dt)));

  try {
    // Settle with zero velocity (mj_makeData starts at qpos0, the model's start pose, qvel = 0).
    const long settle = spec.numerics.settle_time > 0.0
                            ? std::max(1L, static_cast<long>(std::llround(spec.numerics.settle_time / dt)))
                            : 0L;
    for (long i = 0; i < settle; ++i) step();

    // Launch. A free joint's qvel is (velocity of the body frame's origin, world; angular velocity,
    // body frame) (XML reference, joint/@type "free"; the Jacobian of engine_core_smooth.c). The
    // origin is the shape's centre; the centre of mass is at R com from it.
    const mjtNum* qpos = data_->qpos;  // (x, y, z, qw, qx, qy, qz)
    mjtNum q[4] = {qpos[3], qpos[4], qpos[5], qpos[6]};
    mju_normalize4(q);
    mjtNum R[9];
    mju_quat2Mat(R, q);  // body -> world, row-major
    mjtNum r[3], w_body[3], wxr[3];
    const mjtNum com[3] = {spec.body.com[0], spec.body.com[1], spec.body.com[2]};
    const mjtNum w[3] = {spec.start.omega[0], spec.start.omega[1], spec.start.omega[2]};
    mju_rotVecMat(r, com, R);
    mju_rotVecMatT(w_body, w, R);
    mju_cross(wxr, w, r);
    for (int i = 0; i < 3; ++i) {
      data_->qvel[i] = spec.start.v[i] - wxr[i];
      data_->qvel[3 + i] = w_body[i];
    }
    data_->time = 0.0;
    index_ = 0;
    launched_ = true;
  } catch (...) {
    mj_deleteData(data_);
    mj_deleteModel(model_);
    throw;
  }
}

MujocoWorld::~MujocoWorld() {
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

double MujocoWorld::timestep() const { return model_->opt.timestep; }
int MujocoWorld::iterations() const { return model_->opt.iterations; }
double MujocoWorld::time() const { return static_cast<double>(index_) * timestep(); }

void MujocoWorld::check_warnings(const char* when) const {
  // MuJoCo does not fail: it warns, and on a bad number resets the data to qpos0 and goes on.
  for (const int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC, mjWARN_CONTACTFULL, mjWARN_CNSTRFULL}) {
    if (data_->warning[w].number > 0) {
      std::ostringstream msg;
      msg << "MuJoCo " << when << " at t = " << support::message_number(time()) << " s: "
          << mju_warningText(w, data_->warning[w].lastinfo);
      throw std::runtime_error(msg.str());
    }
  }
}

void MujocoWorld::step() {
  mj_step(model_, data_);
  ++index_;
  check_warnings(launched_ ? "warned" : "warned while settling");
}

void MujocoWorld::evaluate() {
  std::vector<mjtNum> warm(data_->qacc_warmstart, data_->qacc_warmstart + model_->nv);
  mj_forward(model_, data_);
  std::copy(warm.begin(), warm.end(), data_->qacc_warmstart);
  check_warnings("warned");
}

Sample MujocoWorld::sample() const {
  Sample s;
  s.t = time();
  mjtNum vel[6];
  mj_objectVelocity(model_, data_, mjOBJ_BODY, body_, vel, 0);  // (angular, linear) at the centre of mass, world
  for (int i = 0; i < 3; ++i) {
    s.omega[i] = vel[i];
    s.v[i] = vel[3 + i];
    s.com[i] = data_->xipos[3 * body_ + i];
  }
  for (int i = 0; i < 4; ++i) s.orientation[i] = data_->xquat[4 * body_ + i];
  // Every contact is the body's with the plane (there is nothing else); mj_contactForce gives the
  // force in the contact frame, normal first (also for the pyramidal cone: engine_support.c).
  for (int c = 0; c < data_->ncon; ++c) {
    mjtNum f[6];
    mj_contactForce(model_, data_, c, f);
    s.normal_force += f[0];
  }
  bool finite = std::isfinite(s.normal_force);
  for (int i = 0; i < 3; ++i) finite = finite && std::isfinite(s.com[i] + s.v[i] + s.omega[i]);
  if (!finite) {
    throw std::runtime_error("MuJoCo's state became non-finite at t = " + support::message_number(s.t) + " s");
  }
  return s;
}

std::string MujocoWorld::notes() const {
  const double dt = timestep();
  const auto& o = options_;
  const auto& f = spec_.friction;
  std::ostringstream x;
  x << "MuJoCo " << mj_versionString() << ": dt " << g(dt) << " s"
    << (spec_.numerics.timestep > 0.0 ? "" : " (default)")
    << ", " << integrator_text(o.integrator) << ", " << solver_text(o.solver) << " solver, " << iterations()
    << " iterations, tolerance " << g(o.tolerance) << ", " << cone_text(o.cone) << ", condim " << o.condim
    << ", friction (k, torsional m, rolling m) = (" << g(f.k) << ", " << g(f.torsional) << ", " << g(f.rolling)
    << ") on both geoms (MuJoCo mixes by max)";
  // What MuJoCo changes silently, and what it does not use.
  const auto floor = [&](const char* what, double value, bool used) {
    if (used && value < mjMINMU) x << ", " << what << ' ' << g(value) << " raised to mjMINMU = 1e-05";
    if (!used) x << ", " << what << " unused at condim " << o.condim;
  };
  floor("k", f.k, o.condim >= 3);
  floor("torsional", f.torsional, o.condim >= 4);
  floor("rolling", f.rolling, o.condim >= 6);
  x << ", soft contact solref (" << g(o.solref[0]) << ", " << g(o.solref[1]) << ")";
  if (o.solref[0] < 2.0 * dt) x << " with the time constant raised to 2 dt = " << g(2.0 * dt) << " s (refsafe)";
  x << ", solimp (" << g(o.solimp[0]) << ", " << g(o.solimp[1]) << ", " << g(o.solimp[2]) << ", "
    << g(o.solimp[3]) << ", " << g(o.solimp[4]) << ")";
  if (o.cone == MujocoOptions::Cone::elliptic) x << ", impratio " << g(o.impratio);
  if (o.noslip_iterations > 0) x << ", noslip " << o.noslip_iterations << " iterations";
  if (spec_.body.shape == Body::Shape::disk) {
    x << ", disk = cylinder: mjc_PlaneCylinder puts 3 contact points on the rim 120 deg apart when it lies flat"
         " (1 to 4 when tilted), each with its own sliding and torsional friction";
  }
  // engine_core_constraint.c: each pyramid edge (and the elliptic cone's friction rows) gets the
  // reference acceleration -B J v, B = 2 / (dmax timeconst): a slip (or spin) u pushes the body
  // off the plane by about B mu u, and it hops while that exceeds g.
  x << ", quirk: slip u pushes the body up by ~B mu u, B = 2/(dmax timeconst) = "
    << g(2.0 / (o.solimp[1] * std::max(o.solref[0], 2.0 * dt))) << " 1/s (it hops while > g; mean N stays m g)";
  if (spec_.numerics.settle_time > 0.0) x << ", settled " << g(spec_.numerics.settle_time) << " s at rest";
  return x.str();
}

}  // namespace frictionlab::engines
