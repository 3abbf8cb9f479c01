#pragma once
// What `frictionlab paper` concludes from its runs: the comparison of every law with the
// reference along the trajectory, and the generated report DIR/experiments.md with its
// machine-readable tables DIR/behaviour.csv, DIR/comparison.csv and DIR/narrative.csv.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/paper/experiment_runner.h"
#include "dynamics/paper/narrative_checks.h"
#include "dynamics/paper/trajectory_compare.h"

namespace frictionlab::dynamics::paper {

/// Two runs of one case "differ" once their gamma3 are further apart than this.
inline constexpr double kDivergenceThreshold = 0.05;
/// The cost table gives each law's wall time over this law's for the same case: the performance
/// target of the paper job is `exact` within a factor of this law's time (docs/experiments.md §6).
inline constexpr std::string_view kCostComparisonLaw = "pade-reconstructed";
/// The factor of that target: case a with `exact` within this many times the comparison law's time.
inline constexpr double kCostTarget = 1.5;

/// One run against the reference run of its (egg, case).
struct LawComparison {
  const RunResult* run = nullptr;
  const RunResult* reference = nullptr;
  Divergence raw;     ///< gamma3 as sampled
  Divergence smooth;  ///< gamma3's moving average (the nutation removed)
  double stagnation_difference = kNaN;  ///< s, run - reference, when both reached the stagnation region
  double final_gamma3_difference = kNaN;  ///< run - reference, <gamma3> over the last second
  double final_tilt_difference_deg = kNaN;  ///< |tilt(run) - tilt(reference)| from those means
};

/// Every executed run other than the reference (the baseline included) against the reference
/// run of its group, in the order of `results`. Groups without an executed reference are skipped.
[[nodiscard]] std::vector<LawComparison> compare_runs(const std::vector<RunResult>& results,
                                                      double threshold = kDivergenceThreshold);

/// The verdicts of one egg reading with one law (or the baseline).
struct NarrativeVerdicts {
  std::string egg;
  std::string law;  ///< the run label: a law, or the baseline "exact-tol1e-10"
  std::vector<ClaimCheck> checks;
};

/// check_narrative for each (egg, run label) present, the baseline included: where a verdict
/// differs between the reference and its baseline, the motion decides it by chance.
[[nodiscard]] std::vector<NarrativeVerdicts> judge_narrative(const std::vector<RunResult>& results,
                                                             const NarrativeRules& rules = {});

struct ReportContext {
  std::string command;   ///< the command line
  std::string date;      ///< when the job started (local time)
  std::string machine;   ///< machine_description()
  int jobs = 1;          ///< worker threads
  double wall_time = 0.0;  ///< s, the whole job
  std::vector<std::string> figures;        ///< PNG names in DIR/plots
  std::vector<std::string> figure_errors;  ///< why some are missing
  /// The job was stopped (Ctrl-C, SIGTERM, SIGHUP) before it finished: the report begins with an
  /// INTERRUPTED banner saying what ran and how to finish the job (--resume).
  bool interrupted = false;
  /// The error along the motion (dynamics/paper/along_motion.h): its section, markdown.
  std::string along_motion;
};

/// "Linux 6.1 x86_64, AMD EPYC ... (2 logical cores)".
[[nodiscard]] std::string machine_description();

/// Writes DIR/experiments.md, DIR/behaviour.csv, DIR/comparison.csv and DIR/narrative.csv.
void write_report(const std::filesystem::path& out_dir, const std::vector<RunResult>& results,
                  const std::vector<LawComparison>& comparisons, const std::vector<NarrativeVerdicts>& verdicts,
                  const ReportContext& context);

}  // namespace frictionlab::dynamics::paper
