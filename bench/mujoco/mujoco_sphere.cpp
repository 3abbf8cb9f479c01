#include "bench/mujoco/mujoco_sphere.h"

#include <mujoco/mujoco.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "friction/support/checked_output.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::mujoco_side {
namespace {

void require(bool ok, const char* key, double value, const char* rule) {
  if (!ok) throw support::invalid_value(key, value, rule);
}

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

std::string n(double x) { return support::shortest(x); }

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

std::string mjcf(const SphereSpec& s) {
  std::ostringstream x;
  x << "<mujoco model=\"frictionlab-sphere\">\n"
    << "  <!-- written by frictionlab's mujoco_side_by_side (docs/engines.md) -->\n"
    << "  <option timestep=\"" << n(s.timestep) << "\" gravity=\"0 0 " << n(-s.g)
    << "\" cone=\"elliptic\" impratio=\"" << n(s.impratio)
    << "\" solver=\"Newton\" iterations=\"100\" tolerance=\"1e-12\" integrator=\"Euler\"/>\n"
    << "  <default>\n"
    << "    <geom condim=\"4\" friction=\"" << n(s.k) << ' ' << n(s.torsional) << " 0\" solref=\""
    << n(s.solref_timeconst) << ' ' << n(s.solref_dampratio) << "\"/>\n"
    << "  </default>\n"
    << "  <worldbody>\n"
    << "    <geom name=\"floor\" type=\"plane\" size=\"0 0 1\"/>\n"
    << "    <body name=\"ball\" pos=\"0 0 " << n(s.R) << "\">\n"
    << "      <joint name=\"free\" type=\"free\"/>\n"
    << "      <inertial pos=\"0 0 0\" mass=\"" << n(s.mass) << "\" diaginertia=\"" << n(s.A) << ' ' << n(s.A) << ' '
    << n(s.C) << "\"/>\n"
    << "      <geom name=\"ball\" type=\"sphere\" size=\"" << n(s.R) << "\"/>\n"
    << "    </body>\n"
    << "  </worldbody>\n"
    << "</mujoco>\n";
  return x.str();
}

std::string mujoco_version() { return mj_versionString(); }

std::vector<Sample> run_sphere(const SphereSpec& spec, const std::filesystem::path& xml) {
  spec.validate();
  support::write_file_atomically(xml, mjcf(spec));
  char error[1000] = "";
  std::unique_ptr<mjModel, ModelDeleter> m(mj_loadXML(xml.c_str(), nullptr, error, sizeof error));
  if (!m) throw std::runtime_error("MuJoCo could not load " + xml.string() + ": " + error);
  std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m.get()));
  if (!d) throw std::runtime_error("MuJoCo could not allocate its data");
  const int ball = mj_name2id(m.get(), mjOBJ_BODY, "ball");

  // Settle at rest: the soft contact finds its depth under m g.
  for (double t = 0.0; t < spec.settle_time; t += spec.timestep) mj_step(m.get(), d.get());
  // Launch: a free joint's qvel is (linear velocity in the world frame, angular velocity in the
  // body frame); the settled sphere has not turned, but rotate anyway.
  mj_forward(m.get(), d.get());
  const mjtNum* R = d->xmat + 9 * ball;  // body to world, row-major
  for (int i = 0; i < 3; ++i) {
    d->qvel[i] = spec.v0[i];
    d->qvel[3 + i] = R[i] * spec.omega0[0] + R[3 + i] * spec.omega0[1] + R[6 + i] * spec.omega0[2];
  }
  d->time = 0.0;

  std::vector<Sample> out;
  const auto steps = static_cast<long>(std::llround(spec.t_end / spec.timestep));
  const auto every = std::max(1L, static_cast<long>(std::llround(spec.output_dt / spec.timestep)));
  for (long step = 0; step <= steps; ++step) {
    if (step % every == 0) {
      mj_forward(m.get(), d.get());
      mjtNum vel[6];
      mj_objectVelocity(m.get(), d.get(), mjOBJ_BODY, ball, vel, 0);  // (angular, linear), world frame
      Sample s;
      s.t = step * spec.timestep;
      for (int i = 0; i < 3; ++i) {
        s.omega[i] = vel[i];
        s.v[i] = vel[3 + i];
      }
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
        mj_contactForce(m.get(), d.get(), c, f);
        const mjContact& con = d->contact[c];
        s.N += f[0];
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
    if (step < steps) mj_step(m.get(), d.get());
  }
  return out;
}

}  // namespace frictionlab::mujoco_side
