// The MuJoCo model of a RunSpec (MJCF text) and the checks of its input.

#include "bench/engines/mujoco/mujoco_model.h"

#include <mujoco/mujoco.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "bench/engines/mujoco/mujoco_engine.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::engines {
namespace {

using Vec3 = std::array<double, 3>;

void require(bool ok, const char* key, double value, const char* rule) {
  if (!ok) throw support::invalid_value(key, value, rule);
}

std::string n(double x) { return support::shortest(x); }

// The unit quaternion of the start (validated: its norm is 1 within 1e-6), normalised exactly.
std::array<double, 4> unit(const std::array<double, 4>& q) {
  const double s = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / s, q[1] / s, q[2] / s, q[3] / s};
}

// The body z axis in the world: the third column of the rotation matrix of q (body -> world).
Vec3 body_z_axis(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)};
}

// The shape's centre (the body frame's origin) such that its lowest point is at the world origin.
// A sphere: straight above it at R. A cylinder of radius R and half height h, axis a: its lowest
// point is c - h sign(a_z) a - R u, with u the unit vector normal to a pointing most upward
// (e_z - a_z a normalised); lying flat (u undefined) the centre of the lower face.
Vec3 start_centre(const Body& body, const std::array<double, 4>& q) {
  if (body.shape == Body::Shape::sphere) return {0.0, 0.0, body.radius};
  const Vec3 a = body_z_axis(q);
  const double h = 0.5 * body.thickness;
  const double s = a[2] >= 0.0 ? 1.0 : -1.0;
  Vec3 c{h * s * a[0], h * s * a[1], h * s * a[2]};
  const Vec3 up{-a[2] * a[0], -a[2] * a[1], 1.0 - a[2] * a[2]};
  const double len = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  if (len > 1e-12) {
    for (int i = 0; i < 3; ++i) c[i] += body.radius * up[i] / len;
  }
  c[0] = c[0] == 0.0 ? 0.0 : c[0];  // no negative zeros in the model text
  c[1] = c[1] == 0.0 ? 0.0 : c[1];
  return c;
}

const char* cone_name(MujocoOptions::Cone c) {
  return c == MujocoOptions::Cone::elliptic ? "elliptic" : "pyramidal";
}
const char* integrator_name(MujocoOptions::Integrator i) {
  switch (i) {
    case MujocoOptions::Integrator::rk4: return "RK4";
    case MujocoOptions::Integrator::implicit: return "implicit";
    default: return "Euler";
  }
}
const char* solver_name(MujocoOptions::Solver s) {
  switch (s) {
    case MujocoOptions::Solver::pgs: return "PGS";
    case MujocoOptions::Solver::cg: return "CG";
    default: return "Newton";
  }
}

}  // namespace

void MujocoOptions::validate() const {
  if (condim != 1 && condim != 3 && condim != 4 && condim != 6) {
    throw support::invalid_value("mujoco.condim", static_cast<long long>(condim),
                                 "MuJoCo's condim must be 1, 3, 4 or 6 (XML reference, geom/@condim)");
  }
  require(std::isfinite(solref[0]) && solref[0] > 0.0, "mujoco.solref[0]", solref[0],
          "the time constant must be a finite number > 0 s (the standard form)");
  require(std::isfinite(solref[1]) && solref[1] > 0.0, "mujoco.solref[1]", solref[1],
          "the damping ratio must be a finite number > 0");
  require(std::isfinite(solimp[0]) && solimp[0] > 0.0 && solimp[0] < 1.0, "mujoco.solimp[0]", solimp[0],
          "dmin must be in (0, 1)");
  require(std::isfinite(solimp[1]) && solimp[1] >= solimp[0] && solimp[1] < 1.0, "mujoco.solimp[1]", solimp[1],
          "dmax must be in [dmin, 1)");
  require(std::isfinite(solimp[2]) && solimp[2] >= 0.0, "mujoco.solimp[2]", solimp[2],
          "the width must be a finite number >= 0 m");
  require(std::isfinite(solimp[3]) && solimp[3] > 0.0 && solimp[3] < 1.0, "mujoco.solimp[3]", solimp[3],
          "the midpoint must be in (0, 1)");
  require(std::isfinite(solimp[4]) && solimp[4] >= 1.0, "mujoco.solimp[4]", solimp[4],
          "the power must be a finite number >= 1");
  require(std::isfinite(impratio) && impratio > 0.0, "mujoco.impratio", impratio, "must be a finite number > 0");
  if (iterations < 1) {
    throw support::invalid_value("mujoco.iterations", static_cast<long long>(iterations), "must be >= 1");
  }
  require(std::isfinite(tolerance) && tolerance >= 0.0, "mujoco.tolerance", tolerance,
          "must be a finite number >= 0");
  if (noslip_iterations < 0) {
    throw support::invalid_value("mujoco.noslip_iterations", static_cast<long long>(noslip_iterations),
                                 "must be >= 0");
  }
}

namespace mujoco_detail {

void validate(const RunSpec& s) {
  engines::validate(s, mujoco_default_timestep);  // the rules of every engine (bench/engines/engine.h)
  require(s.numerics.g > 0.0, "numerics.g", s.numerics.g, "must be a finite number > 0 m/s^2");
}

double timestep(const RunSpec& spec) {
  return spec.numerics.timestep > 0.0 ? spec.numerics.timestep : mujoco_default_timestep;
}

int iterations(const RunSpec& spec, const MujocoOptions& options) {
  return spec.numerics.iterations > 0 ? spec.numerics.iterations : options.iterations;
}

}  // namespace mujoco_detail

std::string mujoco_mjcf(const RunSpec& s, const MujocoOptions& o) {
  mujoco_detail::validate(s);
  o.validate();
  const auto q = unit(s.start.orientation);
  const Vec3 c = start_centre(s.body, q);
  const auto& J = s.body.inertia;
  const auto& f = s.friction;
  std::ostringstream x;
  x << "<mujoco model=\"frictionlab-engine\">\n"
    << "  <!-- written by frictionlab's MuJoCo adapter (bench/engines/mujoco/mujoco_model.cpp) -->\n"
    << "  <option timestep=\"" << n(mujoco_detail::timestep(s)) << "\" gravity=\"0 0 " << n(-s.numerics.g)
    << "\" integrator=\"" << integrator_name(o.integrator) << "\" cone=\"" << cone_name(o.cone) << "\" impratio=\""
    << n(o.impratio) << "\" solver=\"" << solver_name(o.solver) << "\" iterations=\""
    << mujoco_detail::iterations(s, o) << "\" tolerance=\"" << n(o.tolerance) << "\" noslip_iterations=\""
    << o.noslip_iterations << "\"/>\n"
    // Both geoms carry the same contact parameters (MuJoCo mixes them: max of friction, mean of
    // solref and solimp, max of condim).
    << "  <default>\n"
    << "    <geom condim=\"" << o.condim << "\" friction=\"" << n(f.k) << ' ' << n(f.torsional) << ' '
    << n(f.rolling) << "\" solref=\"" << n(o.solref[0]) << ' ' << n(o.solref[1]) << "\" solimp=\""
    << n(o.solimp[0]) << ' ' << n(o.solimp[1]) << ' ' << n(o.solimp[2]) << ' ' << n(o.solimp[3]) << ' '
    << n(o.solimp[4]) << "\"/>\n"
    << "  </default>\n"
    << "  <worldbody>\n"
    << "    <geom name=\"floor\" type=\"plane\" size=\"0 0 1\"/>\n"
    << "    <body name=\"body\" pos=\"" << n(c[0]) << ' ' << n(c[1]) << ' ' << n(c[2]) << "\" quat=\"" << n(q[0])
    << ' ' << n(q[1]) << ' ' << n(q[2]) << ' ' << n(q[3]) << "\">\n"
    << "      <joint name=\"free\" type=\"free\"/>\n"
    << "      <inertial pos=\"" << n(s.body.com[0]) << ' ' << n(s.body.com[1]) << ' ' << n(s.body.com[2])
    << "\" mass=\"" << n(s.body.mass) << "\" diaginertia=\"" << n(J[0]) << ' ' << n(J[1]) << ' ' << n(J[2])
    << "\"/>\n";
  if (s.body.shape == Body::Shape::sphere) {
    x << "      <geom name=\"shape\" type=\"sphere\" size=\"" << n(s.body.radius) << "\"/>\n";
  } else {
    x << "      <geom name=\"shape\" type=\"cylinder\" size=\"" << n(s.body.radius) << ' '
      << n(0.5 * s.body.thickness) << "\"/>\n";
  }
  x << "    </body>\n"
    << "  </worldbody>\n"
    << "</mujoco>\n";
  return x.str();
}

}  // namespace frictionlab::engines
