#include "dynamics/ensemble/run_recorder.h"

#include <cassert>

namespace frictionlab::dynamics::ensemble {

RunRecorder::RunRecorder(double weight, double decimation_dt) : weight_(weight), decimation_dt_(decimation_dt) {
  assert(weight > 0.0);
}

SampleAccuracy RunRecorder::sample_accuracy() const {
  return decimation_dt_ > 0.0 ? SampleAccuracy::method_step : SampleAccuracy::interpolated;
}

void RunRecorder::sample(const Sample& s) {
  const ContactState& c = s.contact;
  series_.t.push_back(s.t);
  series_.gamma3.push_back(c.gamma[2]);
  series_.kinetic.push_back(s.kinetic);
  series_.spin.push_back(c.Omega);
  series_.in_contact.push_back(c.in_contact ? 1 : 0);
  const Eigen::Vector3d axis = orientation_quaternion(s.x) * Eigen::Vector3d::UnitZ();  // the pose's
  series_.axis_x.push_back(axis.x());
  series_.axis_y.push_back(axis.y());
  series_.axis_z.push_back(axis.z());
  if (decimation_dt_ <= 0.0) return;

  // Rows: the first sample at or after each multiple of dt, plus the latest sample as a
  // provisional last row (so that the run's final state is always the last row), which the next
  // sample replaces.
  const double values[DecimatedTrajectory::kColumnCount] = {s.t, c.gamma[2], c.Omega, c.U, c.N / weight_, s.kinetic};
  // Samples on a grid sit on the multiples of dt up to rounding: count them as there.
  const double slack = 1e-9 * decimation_dt_;
  const bool due = s.t + slack >= static_cast<double>(next_decimated_) * decimation_dt_;
  auto cols = trajectory_.columns();
  if (provisional_) {
    for (std::size_t i = 0; i < cols.size(); ++i) cols[i]->back() = values[i];
  } else {
    for (std::size_t i = 0; i < cols.size(); ++i) cols[i]->push_back(values[i]);
  }
  provisional_ = !due;
  if (due)
    while (static_cast<double>(next_decimated_) * decimation_dt_ <= s.t + slack) ++next_decimated_;
}

}  // namespace frictionlab::dynamics::ensemble
