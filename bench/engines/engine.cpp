#include "bench/engines/engine.h"

#include <cmath>
#include <span>

#include "friction/support/errors.h"

namespace frictionlab::engines {
namespace {

void require(bool ok, const char* key, double value, const char* rule) {
  if (!ok) throw support::invalid_value(key, value, rule);
}

template <std::size_t N>
void require_finite(const std::array<double, N>& values, const char* key, const char* rule) {
  for (const double x : values) {
    if (!std::isfinite(x)) throw support::invalid_value(key, std::span<const double>(values), rule);
  }
}

}  // namespace

void validate(const RunSpec& s, double default_timestep) {
  const Body& b = s.body;
  require(std::isfinite(b.radius) && b.radius > 0.0, "body.radius", b.radius, "must be a finite number > 0 m");
  if (b.shape == Body::Shape::disk) {
    require(std::isfinite(b.thickness) && b.thickness > 0.0, "body.thickness", b.thickness,
            "must be a finite number > 0 m for a disk");
  }
  require(std::isfinite(b.mass) && b.mass > 0.0, "body.mass", b.mass, "must be a finite number > 0 kg");
  const auto& J = b.inertia;
  for (const double x : J) {
    if (!(std::isfinite(x) && x > 0.0)) {
      throw support::invalid_value("body.inertia", std::span<const double>(J),
                                   "each principal moment must be a finite number > 0 kg m^2");
    }
  }
  // A rigid body's principal moments obey the triangle inequality (each at most the sum of the
  // others; a thin plate reaches it): a tensor that breaks it is no body's, and the engines'
  // checks (MuJoCo's compiler, ODE's dMassCheck) refuse it.
  const double slack = 1e-9 * (J[0] + J[1] + J[2]);
  if (J[0] > J[1] + J[2] + slack || J[1] > J[0] + J[2] + slack || J[2] > J[0] + J[1] + slack) {
    throw support::invalid_value("body.inertia", std::span<const double>(J),
                                 "the principal moments must obey the triangle inequality (each <= the sum of the others)");
  }
  require_finite(b.com, "body.com", "must be finite (m, body frame)");
  const double r2 = b.com[0] * b.com[0] + b.com[1] * b.com[1];
  const bool inside = b.shape == Body::Shape::sphere
                          ? std::sqrt(r2 + b.com[2] * b.com[2]) < b.radius
                          : std::sqrt(r2) < b.radius && std::abs(b.com[2]) < 0.5 * b.thickness;
  if (!inside) {
    throw support::invalid_value("body.com", std::span<const double>(b.com), "the centre of mass must lie inside the shape");
  }
  const auto& q = s.start.orientation;
  require_finite(q, "start.orientation", "must be a finite unit quaternion (w, x, y, z)");
  if (std::abs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1.0) > 1e-6) {
    throw support::invalid_value("start.orientation", std::span<const double>(q),
                                 "must be a unit quaternion (w, x, y, z): norm 1 within 1e-6");
  }
  require_finite(s.start.v, "start.v", "must be finite (m/s)");
  require_finite(s.start.omega, "start.omega", "must be finite (1/s)");
  const Friction& f = s.friction;
  require(std::isfinite(f.k) && f.k >= 0.0, "friction.k", f.k, "must be a finite number >= 0");
  require(std::isfinite(f.torsional) && f.torsional >= 0.0, "friction.torsional", f.torsional,
          "must be a finite number >= 0 (in the engine's unit)");
  require(std::isfinite(f.rolling) && f.rolling >= 0.0, "friction.rolling", f.rolling,
          "must be a finite number >= 0 (in the engine's unit)");
  const Numerics& n = s.numerics;
  require(std::isfinite(n.timestep) && n.timestep >= 0.0, "numerics.timestep", n.timestep,
          "must be a finite number > 0 s, or 0 for the engine's default");
  if (n.iterations < 0) {
    throw support::invalid_value("numerics.iterations", static_cast<long long>(n.iterations),
                                 "must be >= 1, or 0 for the engine's default");
  }
  require(std::isfinite(n.g) && n.g >= 0.0, "numerics.g", n.g, "must be a finite number >= 0 m/s^2");
  const double dt = n.timestep > 0.0 ? n.timestep : default_timestep;
  require(std::isfinite(n.settle_time) && n.settle_time >= 0.0 && n.settle_time / dt <= 1e9, "numerics.settle_time",
          n.settle_time, "must be a finite number >= 0 s and at most 1e9 time steps");
  require(std::isfinite(s.output_dt) && s.output_dt > 0.0, "output_dt", s.output_dt, "must be a finite number > 0 s");
  require(std::isfinite(s.t_end) && s.t_end >= 0.0 && s.t_end / dt <= 1e9, "t_end", s.t_end,
          "must be a finite number >= 0 s and at most 1e9 time steps");
}

}  // namespace frictionlab::engines
