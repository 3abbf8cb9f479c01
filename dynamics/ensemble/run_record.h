#pragma once
// One row of runs.csv: what an ensemble keeps of a run (docs/ensembles.md §3 lists the columns).
//
//   run, start, replica, law           the run's index and identity (dynamics/ensemble/ensemble_plan.h)
//   <varied keys>                      the start's values, as the study names its keys
//   reason                             the termination reason (dynamics/body/simulation.h), or "failed":
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
//   spin_reversals, t_first_reversal, final_spin_sense   how often the spin about the vertical
//                                      Omega changed its sense, when it first did (s; empty: never),
//                                      and its sense at the end (+1, -1; 0: it died out), with a
//                                      hysteresis of 2 % of the run's largest |Omega|
//                                      (dynamics/paper/spin_reversals.h; the rattleback's signature)
//   t_diverge, diverge_ref, diverge_horizon   the first time gamma3 differs from the run it is
//                                      compared with by more than 0.05 (empty: not up to the
//                                      horizon, the end of the shorter run): a law's run against
//                                      the reference law's on the same replica (diverge_ref = that
//                                      law); the reference law's run on replica 2p + 1 against its
//                                      run on replica 2p (diverge_ref = "replica:2p": the chaos floor)
//   t_part, axis_deg_at_<T>            against the same run: the first time the two bodies' symmetry
//                                      axes (world axes, from the pose) are 1 degree apart (empty:
//                                      not up to the horizon), and the angle between them (degrees)
//                                      at each time T of kAxisAngleTimes (empty past the horizon)
//                                      (dynamics/paper/divergence.h). Samples are interpolated
//                                      (dynamics/ensemble/run_recorder.h): angles below ~1e-4 degree
//                                      are that interpolation's error, not the runs'.
//   shadow_<OUT>[LAW] ...              per shadow law LAW of the study (EnsemblePlan::shadow_laws),
//                                      on the reference law's runs (empty on the others): that
//                                      law's error evaluated at the contact of every state of the
//                                      run (dynamics/core/shadow_laws.h, every contact state,
//                                      weighted by time): F_median, F_p95, F_max of |dF| per kN
//                                      (k·N, the friction bound), M_median, M_max of |dM| per kNa,
//                                      dE (J: what LAW would dissipate along the run minus what the
//                                      run dissipated) and failures (states where LAW failed)
//   message                            why a run stopped early or failed (one line)
//
// A puck study (dynamics/ensemble/run_model.h) has the puck's columns instead of the body's
// features: after rhs_calls, slip_stop_time, spin_stop_time (s; empty: never), terminal_ratio
// (U/(a|Omega|) at the first stop), terminal_ratio_limit (extrapolated; empty: none), path_along,
// path_lateral (m: the end's offset from the start along and across the initial velocity),
// turned (rad: the heading's change), work_slide, work_spin (J), the shadow columns, message — the
// quantities of the puck's summary.json (dynamics/puck/puck_summary_json.h); no divergence columns.
//
// Numbers: shortest round-trip text; missing: empty.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/ensemble/run_model.h"
#include "dynamics/paper/run_features.h"

namespace frictionlab::dynamics::ensemble {

inline constexpr double kNaN = paper::kNaN;

/// The times (s) at which runs.csv keeps the angle between a run's axis and its partner's: a
/// geometric sequence, two a decade, from the first tenth of a second to the longest runs.
inline constexpr std::array<double, 9> kAxisAngleTimes = {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0};

/// The puck's own features (dynamics/puck/puck_run.h).
struct PuckFeatures {
  double slip_stop_time = kNaN;        ///< s
  double spin_stop_time = kNaN;        ///< s
  double terminal_ratio = kNaN;        ///< U/(a|Omega|) at the first of the two stops
  double terminal_ratio_limit = kNaN;  ///< extrapolated from the energy decades (aitken_limit)
  double path_along = kNaN;            ///< m, along the initial velocity
  double path_lateral = kNaN;          ///< m, to its left
  double turned = kNaN;                ///< rad, the heading's change
};

/// One shadow law's errors along a run (the shadow columns; NaN, failures -1: not evaluated).
struct ShadowColumns {
  double F_median = kNaN;  ///< |dF| per kN: median over the run's contact states, by time
  double F_p95 = kNaN;     ///< its 95th percentile
  double F_max = kNaN;     ///< its largest
  double M_median = kNaN;  ///< |dM| per kNa
  double M_max = kNaN;
  double dE = kNaN;        ///< J: the law's dissipation along the run minus the run's
  long failures = -1;      ///< states where the law failed
  [[nodiscard]] bool evaluated() const { return failures >= 0; }
};

/// The names of the shadow columns, in order, without the law ("F_median", ...).
[[nodiscard]] const std::array<const char*, 7>& shadow_column_names();

struct RunRecord {
  RunModel model = RunModel::body;  ///< which columns the row has
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
  long spin_reversals = 0;
  double t_first_reversal = kNaN;
  int final_spin_sense = 0;
  double t_diverge = kNaN;
  std::string diverge_ref;
  double diverge_horizon = kNaN;
  double t_part = kNaN;                ///< s: first time the symmetry axes are 1 degree apart
  std::vector<double> axis_angle_deg;  ///< degrees at kAxisAngleTimes (empty or NaN: not compared)
  std::vector<ShadowColumns> shadow;   ///< per shadow law of the study, in its order (every row)
  std::string message;
  PuckFeatures puck;  ///< a puck run's (model == puck); work_slide, work_spin above

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

/// Where a puck run ended: "failed", "stopped" (before the model's end), "moving" (t_end reached),
/// or, at rest, by the ratio U/(a|Omega|) at the first of the two stops: "together" within a decade
/// of 1 (the other motion was then about as slow: both die out together), "slip-first" below 0.1,
/// "spin-first" above 10 (a ratio still far from 1 when one motion stops: the regimes r -> 0 and
/// r -> infinity of docs/puck.md §3). A run at rest without a ratio (it never both slid and spun) is
/// "rest".
[[nodiscard]] std::string puck_outcome_class(std::string_view reason, double terminal_ratio);

/// The columns of runs.csv for the study's varied `keys`, model and shadow laws.
[[nodiscard]] std::vector<std::string> run_columns(const std::vector<std::string>& keys,
                                                   RunModel model = RunModel::body,
                                                   const std::vector<std::string>& shadow_laws = {});
/// The header line (with its line ending).
[[nodiscard]] std::string runs_header(const std::vector<std::string>& keys, RunModel model = RunModel::body,
                                      const std::vector<std::string>& shadow_laws = {});
/// One row (with its line ending), with the columns of r.model and r.shadow.size() shadow laws.
[[nodiscard]] std::string to_csv_row(const RunRecord& r);
/// A row read back (without its line ending); a wrong number of fields or a bad number is
/// std::invalid_argument.
[[nodiscard]] RunRecord parse_run_row(std::string_view line, std::size_t key_count, RunModel model = RunModel::body,
                                      std::size_t shadow_count = 0);
/// The run index of a row (its first field), without parsing the rest; -1 if it has none.
[[nodiscard]] long run_index_of_row(std::string_view line);

}  // namespace frictionlab::dynamics::ensemble
