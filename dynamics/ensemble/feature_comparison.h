#pragma once
// Each law's distribution of each per-run feature against the reference law's, next to the chaos
// floor (dynamics/ensemble/chaos_floor_rule.h), from the rows of a finished study.
//
// Numeric features are compared over the runs that ended as the model intends (t_end, rest or
// rolling): a run stopped at a law's pole has no time to rest and its "final" tilt is the state at
// the pole. How many runs ended so is reported beside, and the outcome class (which counts
// "stopped" as a class of its own) compares all runs. Divergence times compare the law's runs
// against the reference on the same replica with the floor's: the reference on replica 2p + 1
// against 2p.
//
// A puck study (dynamics/ensemble/run_model.h) compares the puck's features. It has no replicas: the
// puck's motion is not chaotic (the same start gives the same run, bit for bit), so its floor is
// zero, and a law changes a feature when its distribution differs significantly (p < 0.01) by
// more than the feature's resolution.

#include <functional>
#include <string>
#include <vector>

#include "dynamics/ensemble/chaos_floor_rule.h"
#include "dynamics/ensemble/run_record.h"
#include "dynamics/ensemble/sample_statistics.h"

namespace frictionlab::dynamics::ensemble {

/// A numeric per-run feature of runs.csv.
struct FeatureDef {
  std::string name;    ///< the column
  std::string label;   ///< what it is, in words
  std::string unit;    ///< "s", "deg", "J", "" ...
  /// The smallest difference (W1, in the unit) that means anything for the feature: below it a
  /// difference is negligible (chaos_floor_rule.h). A choice, named with its reason in the .cpp.
  double resolution = 0.0;
  std::function<double(const RunRecord&)> value;
};

/// The features the report compares: for the body t_vertical, plateau_tilt_deg, t_rest,
/// final_gamma3, liftoffs, min_n_over_mg, work_slide, work_spin, spin_reversals, t_first_reversal;
/// for the puck slip_stop_time,
/// spin_stop_time, log10 of terminal_ratio, path_along, path_lateral, turned, work_slide, work_spin.
[[nodiscard]] const std::vector<FeatureDef>& compared_features(RunModel model = RunModel::body);

/// The quantiles the report lists (5, 25, 50, 75, 95 %).
inline constexpr double kQuantiles[] = {0.05, 0.25, 0.5, 0.75, 0.95};

struct SampleSummary {
  long runs = 0;      ///< rows of the law
  long normal = 0;    ///< of which ended normally
  long finite = 0;    ///< of which have the feature (e.g. reached the vertical)
  std::vector<double> quantiles;  ///< at kQuantiles (NaN if no value)
};

/// Distances of a law's sample to the reference's, and of the reference's halves (the floor).
struct Distances {
  double w1 = kNaN;
  double ks = kNaN;
  double p = kNaN;
  double floor_w1 = kNaN;
  double floor_ks = kNaN;
  double floor_p = kNaN;
  Verdict verdict = Verdict::not_available;
};

struct FeatureComparison {
  std::string feature;
  std::string law;
  SampleSummary summary;
  Distances distances;  ///< n/a for the reference law itself (but its floor is filled)
};

/// Every compared feature for every law (the reference first), from the study's rows.
[[nodiscard]] std::vector<FeatureComparison> compare_features(const std::vector<RunRecord>& rows,
                                                              const std::vector<std::string>& laws,
                                                              RunModel model = RunModel::body);

/// The outcome classes of a law against the reference's: total variation and chi-square p.
struct ClassComparison {
  std::string law;
  CategoryCounts counts;
  double tv = kNaN;
  double p = kNaN;
  double floor_tv = kNaN;
  double floor_p = kNaN;
  Verdict verdict = Verdict::not_available;
};
[[nodiscard]] std::vector<ClassComparison> compare_classes(const std::vector<RunRecord>& rows,
                                                           const std::vector<std::string>& laws,
                                                           RunModel model = RunModel::body);

/// Divergence times: each law's (against the reference on the same replica), and the floor's.
struct DivergenceSummary {
  std::string law;               ///< a law, or "floor" (the reference's replica pairs)
  long compared = 0;             ///< runs with a comparison
  long parted = 0;               ///< of which parted within the horizon
  std::vector<double> quantiles; ///< of the parting times (kQuantiles)
  double median_horizon = kNaN;  ///< s: the median time the runs were compared over
  double ks = kNaN;              ///< against the floor, with unparted runs at +infinity; NaN when the
                                 ///< median horizon is shorter than the floor's median parting time
                                 ///< (half its median horizon if the floor never parts)
  double p = kNaN;
};
/// `time`: which parting time of the runs, RunRecord::t_diverge (gamma3 apart by 0.05, the
/// default) or RunRecord::t_part (the symmetry axes 1 degree apart).
[[nodiscard]] std::vector<DivergenceSummary> compare_divergence(const std::vector<RunRecord>& rows,
                                                                const std::vector<std::string>& laws,
                                                                double RunRecord::*time = &RunRecord::t_diverge);

/// Whether the model's motion is deterministic, without chaos: its floor is zero (the puck).
[[nodiscard]] inline bool floor_is_zero(RunModel model) { return model == RunModel::puck; }

/// Whether a run ended as the model intends (t_end, rest, rolling).
[[nodiscard]] bool ended_normally(const RunRecord& r);

}  // namespace frictionlab::dynamics::ensemble
