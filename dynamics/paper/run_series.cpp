#include "dynamics/paper/run_series.h"

#include <cassert>
#include <cmath>
#include <limits>

namespace frictionlab::dynamics::paper {

void RunSeries::reserve(std::size_t n) {
  for (auto* v : {&t, &gamma3, &omega_sq, &force, &moment, &major, &axis_ratio, &n_over_mg, &slip, &spin, &kinetic,
                  &axis_x, &axis_y, &axis_z})
    v->reserve(n);
  in_contact.reserve(n);
}

void RunSeries::clear() {
  for (auto* v : {&t, &gamma3, &omega_sq, &force, &moment, &major, &axis_ratio, &n_over_mg, &slip, &spin, &kinetic,
                  &axis_x, &axis_y, &axis_z})
    v->clear();
  in_contact.clear();
}

void RunSeries::push(double t_s, double gamma3_v, double omega_sq_v, double force_v, double moment_v, double major_v,
                     double axis_ratio_v, double n_over_mg_v, double slip_v, double spin_v, double kinetic_v,
                     bool contact) {
  t.push_back(t_s);
  gamma3.push_back(gamma3_v);
  omega_sq.push_back(omega_sq_v);
  force.push_back(force_v);
  moment.push_back(moment_v);
  major.push_back(major_v);
  axis_ratio.push_back(axis_ratio_v);
  n_over_mg.push_back(n_over_mg_v);
  slip.push_back(slip_v);
  spin.push_back(spin_v);
  kinetic.push_back(kinetic_v);
  in_contact.push_back(contact ? 1 : 0);
}

SeriesRecorder::SeriesRecorder(double weight, std::atomic<double>* progress_t)
    : weight_(weight), progress_t_(progress_t) {
  assert(weight > 0.0);
}

void SeriesRecorder::sample(const Sample& s) {
  const ContactState& c = s.contact;
  const double ratio = c.in_contact && c.a > 0.0 ? c.b / c.a : std::numeric_limits<double>::quiet_NaN();
  series_.push(s.t, c.gamma[2], angular_velocity(s.x).squaredNorm(), std::hypot(c.friction.F1, c.friction.F2),
               std::abs(c.friction.M), c.a, ratio, c.N / weight_, c.U, c.Omega, s.kinetic, c.in_contact);
  const Eigen::Vector3d axis = orientation_quaternion(s.x) * Eigen::Vector3d::UnitZ();
  series_.axis_x.push_back(axis.x());
  series_.axis_y.push_back(axis.y());
  series_.axis_z.push_back(axis.z());
}

void SeriesRecorder::step(double t) {
  if (progress_t_) progress_t_->store(t, std::memory_order_relaxed);
}

}  // namespace frictionlab::dynamics::paper
