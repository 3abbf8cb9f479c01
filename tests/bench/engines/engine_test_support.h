#pragma once
// What the engine adapters' tests (tests/bench/engines/<engine>/) share: the solid sphere of the
// problems, the slip of its lowest point, the body's axis, and a least-squares slope of a sampled
// quantity (the rate of a spin-down).

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "bench/engines/engine.h"

namespace frictionlab::engines::testing {

/// A homogeneous solid sphere, its centre of mass at its centre: I = 2/5 m R^2 about every axis.
inline Body solid_sphere(double R = 0.05, double m = 1.0) {
  Body b;
  b.shape = Body::Shape::sphere;
  b.radius = R;
  b.mass = m;
  const double I = 0.4 * m * R * R;
  b.inertia = {I, I, I};
  return b;
}

/// The slip speed of a sphere's lowest point (centre of mass at its centre): |v + omega x (-R e_z)|.
inline double lowest_point_slip(const Sample& s, double R) {
  return std::hypot(s.v[0] - R * s.omega[1], s.v[1] + R * s.omega[0]);
}

/// The body's z axis in the world, from the body -> world quaternion (w, x, y, z).
inline std::array<double, 3> body_z(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
}

/// The least-squares slope of y(t) over the samples with t in [t0, t1].
inline double slope(const std::vector<Sample>& samples, double t0, double t1,
                    const std::function<double(const Sample&)>& y) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (const Sample& s : samples) {
    if (s.t < t0 || s.t > t1) continue;
    const double v = y(s);
    n += 1;
    st += s.t;
    sy += v;
    stt += s.t * s.t;
    sty += s.t * v;
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

}  // namespace frictionlab::engines::testing
