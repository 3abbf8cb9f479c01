#pragma once
// One row of runs.csv: what an ensemble keeps of a run (docs/ensembles.md §3 lists the columns).
//
//   run, start, replica, law           the run's index and identity (dynamics/ensemble/ensemble_plan.h)
//   <varied keys>                      the start's values, as the study names its keys
//   reason                             the termination reason (dynamics/simulation.h), or "failed":
//                                      the run could not run (its scenario or its law rejected it)
//   final_class                        where it ended: outcome_class() below
//   t_final, wall_time, steps, rhs_calls   s; s of one core (scenario, integration and features);
//                                      accepted steps; right-hand-side calls (steps and samples)
//   t_vertical, vertical_pole          first |gamma3| > 0.999 (dynamics/paper/run_features.h), and
//                                      the pole (+1, -1; 0: never)
//   plateau_tilt_deg                   the tilt of the plateau after the vertical spin (or the rise)
//   t_rest                             t_final of a run that ended rest or rolling
//   final_gamma3                       the mean of gamma3 over the last second
//   liftoffs, min_n_over_mg            counted and taken at every accepted step
//   work_slide, work_spin              J: the work against sliding and against spinning friction
//   t_diverge, diverge_ref, diverge_horizon   the first time gamma3 differs from the run it is
//                                      compared with by more than 0.05 (empty: not up to the
//                                      horizon, the end of the shorter run): a law's run against
//                                      the reference law's on the same replica (diverge_ref = that
//                                      law); the reference law's run on replica 2p + 1 against its
//                                      run on replica 2p (diverge_ref = "replica:2p": the chaos floor)
//   message                            why a run stopped early or failed (one line)
//
// Numbers: shortest round-trip text; missing: empty.

#include <string>
#include <string_view>
#include <vector>

#include "dynamics/paper/run_features.h"

namespace frictionlab::dynamics::ensemble {

inline constexpr double kNaN = paper::kNaN;

struct RunRecord {
  long run = 0;
  long start = 0;
  long replica = 0;
  std::string law;
  std::vector<double> values;
  std::string reason;
  std::string final_class;
  double t_final = kNaN;
  double wall_time = kNaN;
  long steps = 0;
  long rhs_calls = 0;
  double t_vertical = kNaN;
  int vertical_pole = 0;
  double plateau_tilt_deg = kNaN;
  double t_rest = kNaN;
  double final_gamma3 = kNaN;
  long liftoffs = 0;
  double min_n_over_mg = kNaN;
  double work_slide = kNaN;
  double work_spin = kNaN;
  double t_diverge = kNaN;
  std::string diverge_ref;
  double diverge_horizon = kNaN;
  std::string message;

  /// The run could not run at all (reason "failed").
  [[nodiscard]] bool failed() const { return reason == kFailed; }
  static constexpr std::string_view kFailed = "failed";
};

/// Where a run ended, from its termination reason and its final mean gamma3:
///   "failed"   it could not run;
///   "stopped"  it stopped before the model's end (a law's pole, max-steps, non-finite, ...);
///   "pole+", "pole-"  it ended (t_end, rest or rolling) within acos(near_vertical) = 8.1 deg of the
///              vertical on the pole gamma3 = +1 (the pole at z_lo touches) or -1;
///   "tilted"   it ended elsewhere.
[[nodiscard]] std::string outcome_class(std::string_view reason, double final_gamma3,
                                        const paper::FeatureThresholds& th = {});

/// The columns of runs.csv for the study's varied `keys`.
[[nodiscard]] std::vector<std::string> run_columns(const std::vector<std::string>& keys);
/// The header line (with its line ending).
[[nodiscard]] std::string runs_header(const std::vector<std::string>& keys);
/// One row (with its line ending).
[[nodiscard]] std::string to_csv_row(const RunRecord& r);
/// A row read back (without its line ending); a wrong number of fields or a bad number is
/// std::invalid_argument.
[[nodiscard]] RunRecord parse_run_row(std::string_view line, std::size_t key_count);
/// The run index of a row (its first field), without parsing the rest; -1 if it has none.
[[nodiscard]] long run_index_of_row(std::string_view line);

}  // namespace frictionlab::dynamics::ensemble
