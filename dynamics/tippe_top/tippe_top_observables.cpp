#include "dynamics/tippe_top/tippe_top_observables.h"

#include <cmath>

namespace frictionlab::dynamics::tippe_top {
namespace {

// The time where the segment (t0, g0)-(t1, g1) crosses `level` downwards (g0 >= level > g1).
double crossing(double t0, double g0, double t1, double g1, double level) {
  return t0 + (t1 - t0) * (g0 - level) / (g0 - g1);
}

}  // namespace

double gamma3(const StateVector& x) {
  const auto g = vertical(x);
  return g[2] / g.norm();
}

double jellett_quantity(const Body& body, const StateVector& x, const ContactState& c) {
  const auto w = angular_velocity(x);
  const Eigen::Vector3d L = body.axisymmetric ? Eigen::Vector3d(body.axisymmetric->A * w[0], body.axisymmetric->A * w[1],
                                                                 body.axisymmetric->C * w[2])
                                               : Eigen::Vector3d(body.inertia * w);
  return L.dot(c.point.r);
}

double jellett_rate(const ContactState& c) {
  if (!c.in_contact) return 0.0;
  return -c.friction.M * c.gamma.dot(c.point.r);
}

void InversionWatch::add(double t, double g) {
  if (first_) {
    first_ = false;
    started_upright_ = g > kUprightGamma3;
    if (g < 0.0) horizontal_ = t;
  } else {
    if (std::isnan(horizontal_) && g < 0.0) horizontal_ = crossing(t_prev_, g_prev_, t, g, 0.0);
    if (started_upright_ && std::isnan(inverted_) && g < kInvertedGamma3)
      inverted_ = crossing(t_prev_, g_prev_, t, g, kInvertedGamma3);
  }
  if (g < min_) {
    min_ = g;
    min_t_ = t;
  }
  t_prev_ = t;
  g_prev_ = g;
}

}  // namespace frictionlab::dynamics::tippe_top
