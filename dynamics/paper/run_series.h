#pragma once
// The sampled quantities of one run that the paper's figures and checks need, kept in memory
// (one vector per quantity, SI units), and the observer that records them from a run.

#include <atomic>
#include <cstddef>
#include <vector>

#include "dynamics/body/equations_of_motion.h"  // the body's Sample and Observer
#include "dynamics/core/observer.h"

namespace frictionlab::dynamics::paper {

/// One run, sampled (dynamics/core/observer.h: t = 0, every output interval, the final time).
struct RunSeries {
  std::vector<double> t;           ///< s
  std::vector<double> gamma3;      ///< cosine of the nutation angle (upward vertical, body axis)
  std::vector<double> omega_sq;    ///< |omega|^2, 1/s^2 (the abscissa of the paper's fig. 2)
  std::vector<double> force;       ///< |F| = sqrt(F1^2 + F2^2), N (friction force)
  std::vector<double> moment;      ///< |M|, N m (friction moment about the normal)
  std::vector<double> major;       ///< major semi-axis a of the patch, m (0 out of contact)
  std::vector<double> axis_ratio;  ///< b/a; NaN out of contact (no patch)
  std::vector<double> n_over_mg;   ///< N/(m g)
  std::vector<double> slip;        ///< U, m/s
  std::vector<double> spin;        ///< Omega = omega.gamma, 1/s
  std::vector<double> kinetic;     ///< kinetic energy, J
  std::vector<unsigned char> in_contact;  ///< 1 when eps < 0
  /// The body's symmetry axis (body e3) in world axes, from the pose's quaternion: where the two
  /// runs' axes point apart is their distance (dynamics/paper/divergence.h). Filled by the recorder;
  /// empty in series built by push().
  std::vector<double> axis_x, axis_y, axis_z;

  [[nodiscard]] std::size_t size() const { return t.size(); }
  [[nodiscard]] bool empty() const { return t.empty(); }
  void reserve(std::size_t n);
  void clear();
  /// Appends one sample (used by the recorder, and by tests to build synthetic runs).
  void push(double t_s, double gamma3_v, double omega_sq_v, double force_v, double moment_v, double major_v,
            double axis_ratio_v, double n_over_mg_v, double slip_v, double spin_v, double kinetic_v, bool contact);
};

/// Records a RunSeries from a run. step() publishes the simulated time for a progress display.
class SeriesRecorder final : public Observer {
 public:
  /// `weight` = m g (N, > 0) normalises N. `progress_t` (may be null) receives t after each step.
  explicit SeriesRecorder(double weight, std::atomic<double>* progress_t = nullptr);
  void sample(const Sample& s) override;
  void step(double t) override;

  [[nodiscard]] RunSeries& series() { return series_; }

 private:
  double weight_;
  std::atomic<double>* progress_t_;
  RunSeries series_;
};

}  // namespace frictionlab::dynamics::paper
