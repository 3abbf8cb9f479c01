// What an ensemble keeps of a run (dynamics/ensemble/run_recorder.h).

#include "dynamics/ensemble/run_recorder.h"

#include <gtest/gtest.h>

namespace frictionlab::dynamics::ensemble {
namespace run_recorder_test {

void feed(RunRecorder& r, double t, double gamma3) {
  const StateVector x = StateVector::Zero();
  ContactState c;
  c.gamma = Eigen::Vector3d(0, 0, gamma3);
  c.in_contact = true;
  c.N = 9.81;
  c.U = 0.5;
  c.Omega = 3.0;
  r.sample(Sample{t, x, c, 1.0, 0.25});
}

TEST(EnsembleRunRecorder, KeepsWhatTheFeaturesNeedAndNothingElse) {
  RunRecorder r(9.81, 0.0);
  for (int i = 0; i <= 10; ++i) feed(r, 0.01 * i, 0.5);
  EXPECT_EQ(r.series().size(), 11u);
  EXPECT_EQ(r.series().gamma3.size(), 11u);
  EXPECT_EQ(r.series().kinetic.size(), 11u);
  EXPECT_EQ(r.series().in_contact.size(), 11u);
  EXPECT_TRUE(r.series().force.empty()) << "columns the features do not read are not kept";
  EXPECT_TRUE(r.trajectory().empty());
}

TEST(EnsembleRunRecorder, TakesInterpolatedSamplesUnlessItKeepsATrajectory) {
  // The features read gamma3, which the step's interpolant gives to ~1e-6; a decimated trajectory
  // also keeps U, N and the kinetic energy, which the Hertz vibration moves within a step.
  EXPECT_EQ(RunRecorder(9.81, 0.0).sample_accuracy(), SampleAccuracy::interpolated);
  EXPECT_EQ(RunRecorder(9.81, 0.1).sample_accuracy(), SampleAccuracy::method_step);
}

TEST(EnsembleRunRecorder, DecimatesToTheFirstSampleOfEachIntervalAndTheLast) {
  RunRecorder r(9.81, 0.1);
  for (int i = 0; i <= 34; ++i) feed(r, 0.01 * i, 0.01 * i);  // t = 0 ... 0.34
  const auto& d = r.trajectory();
  ASSERT_EQ(d.size(), 5u);  // 0, 0.1, 0.2, 0.3 and the last, 0.34
  EXPECT_EQ(d.t[0], 0.0);
  EXPECT_NEAR(d.t[1], 0.1, 1e-12);
  EXPECT_NEAR(d.t[3], 0.3, 1e-12);
  EXPECT_EQ(d.t[4], 0.34);
  EXPECT_EQ(d.gamma3[4], 0.34 * 1.0);
  EXPECT_EQ(d.n_over_mg[0], 1.0);
  EXPECT_EQ(d.spin[0], 3.0);
  EXPECT_EQ(d.slip[0], 0.5);
  EXPECT_EQ(d.kinetic[0], 0.25);
  feed(r, 0.40, 0.4);  // due: replaces the provisional last row
  EXPECT_EQ(d.size(), 5u);
  EXPECT_EQ(d.t[4], 0.40);
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
