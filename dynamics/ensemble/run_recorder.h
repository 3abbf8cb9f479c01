#pragma once
// What an ensemble keeps of a run while it runs, in memory only: the samples that the features
// (dynamics/paper/run_features.h, spin_reversals.h) need — t, gamma3, Omega, kinetic energy, contact — in a
// paper::RunSeries whose other columns stay empty, the body's symmetry axis in world axes (for
// the distance between two runs, dynamics/paper/divergence.h), and, if asked, a decimated
// trajectory. About 57 bytes per sample: 5.7 MB for 1000 s at output_dt = 0.01 s. No file is written.
//
// Without a decimated trajectory the recorder takes interpolated samples (Observer::sample_accuracy):
// the features read gamma3 only, at thresholds of 1e-3 and more, and the cubic Hermite interpolant
// of a step is within ~1e-6 of it (docs/dynamics.md §4), while a step of the method per sample
// costs ~15 % of the run. A decimated trajectory (U, N, the kinetic energy, which the Hertz
// vibration moves within a step) keeps the method's samples.

#include "dynamics/ensemble/decimated_trajectory.h"
#include "dynamics/body/equations_of_motion.h"  // the body's Sample and Observer
#include "dynamics/core/observer.h"
#include "dynamics/paper/run_series.h"

namespace frictionlab::dynamics::ensemble {

class RunRecorder final : public Observer {
 public:
  /// `weight` = m g (N, > 0); `decimation_dt` (s) > 0 records a decimated trajectory, 0 none.
  RunRecorder(double weight, double decimation_dt);
  void sample(const Sample& s) override;
  /// interpolated without a decimated trajectory, method_step with one.
  [[nodiscard]] SampleAccuracy sample_accuracy() const override;

  [[nodiscard]] paper::RunSeries& series() { return series_; }
  [[nodiscard]] DecimatedTrajectory& trajectory() { return trajectory_; }

 private:
  double weight_;
  double decimation_dt_;
  long next_decimated_ = 0;  // index k of the next multiple k dt to record
  paper::RunSeries series_;
  DecimatedTrajectory trajectory_;
  bool provisional_ = false;  // the last row is the latest sample, not one due on the dt grid
};

}  // namespace frictionlab::dynamics::ensemble
