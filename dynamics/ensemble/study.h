#pragma once
// A study: the TOML file that says which runs an ensemble makes (docs/ensembles.md §1 documents
// every key). A base scenario, the laws (the first is the reference every other law is compared
// with), the varied scenario keys with their design, and replicas of each start for the chaos
// floor. Every law runs on the same starts (paired runs).
//
//   name = "egg-map"                              # default: the file's stem
//   scenario = "../scenarios/egg-printed-a.toml"  # relative to the study file
//   laws = ["exact", "pade-reconstructed"]        # the first is the reference; LAW@PATCH runs the
//                                                 # law under contact.patch = PATCH (variant.h)
//   set = ["run.output_dt=0.01"]                  # overrides of every run (the --set syntax)
//   shadow = true                                 # the reference's runs evaluate the compared laws
//                                                 # along their motion (dynamics/core/shadow_laws.h):
//                                                 # true (default) the other laws under the
//                                                 # reference's contact model, false none, or a
//                                                 # list of law specs
//   seed = 1
//   [design]
//   type = "grid"                                 # grid | random | sobol | lhs
//   points = 64                                   # random, sobol, lhs: the number of starts
//   [[vary]]
//   key = "initial.gamma3"                        # a scalar scenario key (dynamics/ensemble/varied_key.h)
//   min = 0.1
//   max = 0.99
//   points = 32                                   # grid: points from min to max (or values = [...])
//   scale = "linear"                              # linear | log
//   [replicas]
//   count = 2                                     # copies of each start; replica 0 is the start itself
//   size = 1e-6                                   # perturbation of the others (dynamics/ensemble/replica.h)
//   [output]
//   trajectory_dt = 0.1                           # s, the decimated trajectories of --hdf5
//
// Reading checks types, ranges and unknown keys (std::invalid_argument "FILE: KEY = VALUE is
// invalid: RULE", the key as written: "vary[1].min"). Whether a varied key and the laws exist in the
// scenario is checked when the ensemble is planned (dynamics/ensemble/ensemble_plan.h).

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/ensemble/design.h"

namespace frictionlab::dynamics::ensemble {

enum class AxisScale { linear, log };

/// One varied key and its range.
struct VariedAxis {
  std::string key;                 ///< a scenario key path or a derived key (varied_key.h)
  double min = 0.0;                ///< in the key's unit
  double max = 0.0;                ///< >= min
  long points = 0;                 ///< grid: number of points from min to max, both included
  std::vector<double> values;      ///< grid: explicit values instead (then min/max are their extremes)
  AxisScale scale = AxisScale::linear;

  /// The axis's value at unit coordinate u in [0, 1]: min + u (max - min), or, on a log scale,
  /// exp(log min + u (log max - log min)); u = 1 gives max exactly.
  [[nodiscard]] double at(double u) const;
  /// The grid values: `values`, or `points` points spaced evenly (in log on a log scale).
  [[nodiscard]] std::vector<double> grid() const;
};

struct Study {
  std::string name;
  std::string description;
  std::filesystem::path file;        ///< the study file as given
  std::filesystem::path scenario;    ///< the base scenario (resolved against the study's folder)
  std::vector<std::string> laws;     ///< LAW or LAW@PATCH (variant.h); laws[0] is the reference
  std::vector<std::string> set;      ///< "key=value" overrides of every run
  /// `shadow`: true (the compared laws; the plan resolves them) unless the file says false or
  /// lists laws (then shadow_laws holds them, possibly empty).
  bool shadow_compared = true;
  std::vector<std::string> shadow_laws;  ///< law specs listed by `shadow = [...]`
  std::uint64_t seed = 1;
  DesignKind design = DesignKind::grid;
  long points = 0;                   ///< random, sobol, lhs: the number of starts
  std::vector<VariedAxis> vary;
  long replicas = 1;                 ///< copies of each start (>= 1); replica 0 is the start itself
  double replica_size = 0.0;         ///< the relative size of the replicas' perturbation
  double trajectory_dt = 0.1;        ///< s, interval of the decimated trajectories (--hdf5)
  std::string text;                  ///< the study file's text
  /// The study as parsed, written back as TOML (comments and layout dropped, keys sorted): what
  /// the study's hash is taken of, so that a reworded comment does not change the study.
  std::string canonical;

  [[nodiscard]] const std::string& reference_law() const { return laws.front(); }
};

/// Reads and checks a study file. A relative `scenario` is taken relative to the file's folder.
[[nodiscard]] Study read_study(const std::filesystem::path& file);
/// The same from text; `source` names it in messages, `folder` anchors a relative scenario path.
[[nodiscard]] Study parse_study(std::string_view text, const std::filesystem::path& source,
                                const std::filesystem::path& folder);

}  // namespace frictionlab::dynamics::ensemble
