#pragma once
// What every run of every model returns (dynamics/core/run_loop.h): why and when it ended, its last good
// state, and the counts of its integration. A model's summary derives from it and adds its own
// (the body: dynamics/body/simulation.h; the puck: dynamics/puck/puck_run.h).

#include <string>
#include <vector>

#include "dynamics/core/run_options.h"
#include "dynamics/core/threshold.h"

namespace frictionlab::dynamics {

template <class State>
struct RunSummaryOf {
  Termination reason = Termination::t_end;
  std::string message;          ///< why, in one line (empty for t_end)
  std::string rule;             ///< the rule that ended the run, in words (empty if none applies)
  std::vector<Threshold> thresholds;  ///< the thresholds of that rule, as applied
  double t_final = 0.0;         ///< s
  State x_final = State::Zero();  ///< the last good state
  long steps = 0;               ///< accepted steps
  long rejected_steps = 0;      ///< steps GSL retried with a smaller size
  long rhs_calls = 0;           ///< evaluations of the right-hand side by the integrator
  long samples = 0;             ///< samples the observer took
  long sample_rhs_calls = 0;    ///< evaluations of the right-hand side for samples and located events
  long hermite_samples = 0;     ///< samples that fell back on cubic Hermite (dynamics/core/step_sampler.h)
  double wall_time = 0.0;       ///< s
  double initial_energy = 0.0;  ///< J
  double final_energy = 0.0;    ///< J
  State abs_tol = State::Zero();  ///< the absolute tolerance of each component (abs_tol * scale)
};

}  // namespace frictionlab::dynamics
