#include "bench/mujoco/mujoco_sphere.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/engines/mujoco/mujoco_engine.h"
#include "bench/engines/mujoco/mujoco_world.h"
#include "friction/support/checked_output.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::mujoco_side {
namespace {

void require(bool ok, const char* key, double value, const char* rule) {
  if (!ok) throw support::invalid_value(key, value, rule);
}

}  // namespace

void SphereSpec::validate() const {
  require(std::isfinite(R) && R > 0.0, "R", R, "the radius must be a finite number > 0 m");
  require(std::isfinite(mass) && mass > 0.0, "mass", mass, "must be a finite number > 0 kg");
  require(std::isfinite(A) && A > 0.0, "A", A, "must be a finite number > 0 kg m^2");
  require(std::isfinite(C) && C > 0.0 && C <= 2.0 * A, "C", C, "must be a finite number in (0, 2A] kg m^2");
  require(std::isfinite(g) && g > 0.0, "g", g, "must be a finite number > 0 m/s^2");
  require(std::isfinite(k) && k >= mjMINMU, "k", k, "must be a finite number >= 1e-5 (MuJoCo's mjMINMU)");
  require(std::isfinite(torsional) && torsional >= mjMINMU, "torsional", torsional,
          "must be a finite number >= 1e-5 m (MuJoCo's mjMINMU)");
  for (const double x : v0) require(std::isfinite(x), "v0", x, "must be finite (m/s)");
  for (const double x : omega0) require(std::isfinite(x), "omega0", x, "must be finite (1/s)");
  require(std::isfinite(timestep) && timestep > 0.0, "timestep", timestep, "must be a finite number > 0 s");
  require(std::isfinite(output_dt) && output_dt >= timestep, "output_dt", output_dt, "must be >= timestep");
  require(std::isfinite(t_end) && t_end >= output_dt && t_end / timestep <= 1e9, "t_end", t_end,
          "must be >= output_dt and at most 1e9 time steps");
  require(std::isfinite(solref_timeconst) && solref_timeconst >= 2.0 * timestep, "solref_timeconst",
          solref_timeconst, "must be >= 2 timestep (MuJoCo's stability rule for solref)");
  require(std::isfinite(solref_dampratio) && solref_dampratio > 0.0, "solref_dampratio", solref_dampratio,
          "must be a finite number > 0");
  require(std::isfinite(impratio) && impratio >= 1.0, "impratio", impratio, "must be a finite number >= 1");
  require(std::isfinite(settle_time) && settle_time >= 0.0, "settle_time", settle_time,
          "must be a finite number >= 0 s");
}

namespace {

// The sphere as a run of the engines' MuJoCo adapter (bench/engines/mujoco), which writes and steps
// every MuJoCo model of frictionlab: MuJoCo's friction "k torsional 0" at condim 4, the elliptic
// cone, Newton with 100 iterations and tolerance 1e-12, Euler, solref (timeconst, dampratio),
// MuJoCo's default solimp.
engines::RunSpec run_spec(const SphereSpec& s) {
  engines::RunSpec r;
  r.body.shape = engines::Body::Shape::sphere;
  r.body.radius = s.R;
  r.body.mass = s.mass;
  r.body.inertia = {s.A, s.A, s.C};
  r.start.v = s.v0;
  r.start.omega = s.omega0;  // the sphere starts unrotated: world = body frame
  r.friction = {s.k, s.torsional, 0.0};
  r.numerics.timestep = s.timestep;
  r.numerics.g = s.g;
  r.numerics.settle_time = s.settle_time;
  r.t_end = s.t_end;
  r.output_dt = s.output_dt;
  return r;
}

engines::MujocoOptions mujoco_options(const SphereSpec& s) {
  engines::MujocoOptions o;
  o.condim = 4;
  o.cone = engines::MujocoOptions::Cone::elliptic;
  o.solref = {s.solref_timeconst, s.solref_dampratio};
  o.impratio = s.impratio;
  o.solver = engines::MujocoOptions::Solver::newton;
  o.iterations = 100;
  o.tolerance = 1e-12;
  o.integrator = engines::MujocoOptions::Integrator::euler;
  return o;
}

}  // namespace

std::string mjcf(const SphereSpec& s) {
  s.validate();
  return engines::mujoco_mjcf(run_spec(s), mujoco_options(s));
}

std::string mujoco_version() { return mj_versionString(); }

std::vector<Sample> run_sphere(const SphereSpec& spec, const std::filesystem::path& xml) {
  spec.validate();
  // Settles at rest (the soft contact finds its depth under m g), launches, restarts the clock.
  engines::MujocoWorld world(run_spec(spec), mujoco_options(spec));
  support::write_file_atomically(xml, world.mjcf());  // the model, kept for the reader
  const mjModel* m = &world.model();
  const mjData* d = &world.data();
  const int ball = world.body();

  std::vector<Sample> out;
  for (;;) {
    if (world.step_index() % world.steps_per_sample() == 0) {
      world.evaluate();
      const engines::Sample e = world.sample();  // v, omega at the centre (= centre of mass), world
      Sample s;
      s.t = e.t;
      s.v = e.v;
      s.omega = e.omega;
      s.N = e.normal_force;
      // The material point of the sphere at the contact point: MuJoCo puts the contact midway
      // between the surfaces (depth/2 inside the sphere), and its friction acts there; out of
      // contact, the lowest point (0, 0, -R) from the centre. Slip: v + omega x r, horizontal.
      const mjtNum* centre = d->xpos + 3 * ball;
      double r[3] = {0.0, 0.0, -spec.R};
      if (d->ncon > 0) {
        for (int i = 0; i < 3; ++i) r[i] = d->contact[0].pos[i] - centre[i];
      }
      s.U = std::hypot(s.v[0] + s.omega[1] * r[2] - s.omega[2] * r[1],
                       s.v[1] + s.omega[2] * r[0] - s.omega[0] * r[2]);
      s.Omega = s.omega[2];
      for (int c = 0; c < d->ncon; ++c) {
        mjtNum f[6];
        mj_contactForce(m, d, c, f);
        const mjContact& con = d->contact[c];
        s.Ft = std::hypot(f[1], f[2]);
        s.tau += f[3] * con.frame[2];  // about +z: the contact frame's first axis is the normal
        s.depth = std::max(s.depth, -con.dist);
      }
      for (const double x : {s.U, s.Omega, s.N, s.tau}) {
        if (!std::isfinite(x)) {
          throw std::runtime_error("MuJoCo's state became non-finite at t = " + support::message_number(s.t) + " s");
        }
      }
      out.push_back(s);
    }
    if (world.step_index() >= world.steps()) break;
    world.step();
  }
  return out;
}

}  // namespace frictionlab::mujoco_side
