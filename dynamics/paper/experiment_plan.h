#pragma once
// The grid of the paper's experiments (section 2 of Munitsyna (2013); docs/model.md §6): every
// (egg reading x case x law) run that `frictionlab paper` makes, with its scenario file, its
// overrides and its output directory. Names are checked here, before anything runs
// (std::invalid_argument naming the value and the rule). docs/experiments.md describes the job.

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/body/scenario.h"
#include "friction/registry.h"

namespace frictionlab::dynamics::paper {

/// The two readings of the paper's egg (docs/model.md §6; data/scenarios/<egg>-<case>.toml).
[[nodiscard]] const std::vector<std::string>& known_eggs();
/// The paper's initial conditions (a), (b), (c).
[[nodiscard]] const std::vector<std::string>& known_cases();
/// The laws run by default: the reference first.
[[nodiscard]] const std::vector<std::string>& default_laws();

/// The law every other law is compared with along the trajectory: the registry's reference law.
inline const std::string kReferenceLaw = friction::reference_law_name();
/// Output interval of the paper's runs, s (the scenario files say 1e-3 s). 100 Hz resolves the
/// nutation of gamma3 (at most 20.1 Hz in these runs: dynamics/paper/nutation_frequency.py); the
/// Hertz bounce (~49 Hz) is aliased, so lift-offs and min N come from the integrator's steps.
inline constexpr double kPaperOutputDt = 0.01;
/// The chaos baseline: the reference law rerun with both tolerances multiplied by this factor.
/// How far two runs of the same law drift apart is the floor under any law-vs-law difference.
inline constexpr double kBaselineToleranceFactor = 0.1;

/// What `frictionlab paper` was asked to do.
struct PlanOptions {
  std::filesystem::path out_dir;       ///< DIR: runs/, plots/, experiments.md go here
  std::filesystem::path scenario_dir;  ///< where <egg>-<case>.toml live
  std::vector<std::string> laws = default_laws();
  std::vector<std::string> eggs = known_eggs();
  std::vector<std::string> cases = known_cases();
  std::vector<std::string> overrides;  ///< the user's --set key=value, applied after the paper's own
  bool baseline = true;                ///< also run the reference law with tightened tolerances
  /// The reference run evaluates every other law along its motion (run.shadow, shadow.csv).
  bool shadow = true;

  /// Unknown or repeated names, an empty list, an empty out_dir: std::invalid_argument.
  void validate() const;
};

/// One run of the grid.
struct RunSpec {
  std::string egg;        ///< "egg-printed" | "egg-homogeneous"
  std::string case_id;    ///< "a" | "b" | "c"
  std::string law;        ///< friction-law registry name
  std::string label;      ///< the law, or e.g. "exact-tol1e-10" for the baseline
  bool baseline = false;  ///< the reference law with tightened tolerances
  std::filesystem::path scenario_file;
  std::vector<std::string> overrides;  ///< paper defaults, then the user's, then the baseline's
  std::filesystem::path out_dir;       ///< DIR/runs/<egg>-<case>/<label>
  /// What runs: the file with `overrides` and contact.law = `law`, resolved when planned (the file
  /// is read once per group). Null only in a spec made by hand.
  std::shared_ptr<const Scenario> scenario;

  [[nodiscard]] std::string group() const { return egg + "-" + case_id; }
};

/// "a,b , c" -> {"a", "b", "c"}; an empty item is std::invalid_argument naming `what`.
[[nodiscard]] std::vector<std::string> split_list(std::string_view list, std::string_view what);

/// The scenarios/ of the first shipped data folder (dynamics/io/shipped_data.h: data/ here, the
/// installed data, the source tree's) that has <egg>-a.toml; else the source tree's.
[[nodiscard]] std::filesystem::path default_scenario_dir();

/// Every run, grouped by (egg, case) in the order given, laws in the order given, the baseline
/// last in its group. Reads each scenario file once and resolves every run's scenario (so a bad
/// --set or a missing file is an error before anything runs). The plan sets each run's law:
/// an override of contact.law is an error (choose laws with --laws).
[[nodiscard]] std::vector<RunSpec> plan_runs(const PlanOptions& options);

}  // namespace frictionlab::dynamics::paper
