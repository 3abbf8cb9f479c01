#pragma once
// The paper's account of its experiments (section 2; docs/model.md §6) as a list of checkable
// claims, each judged on measured features with a stated rule and the numbers behind it. The
// rules turn the paper's words into thresholds; they are choices, named here and in
// docs/experiments.md, and never tuned to make a claim hold.

#include <string>
#include <string_view>
#include <vector>

#include "dynamics/paper/experiment_runner.h"

namespace frictionlab::dynamics::paper {

enum class Verdict { holds, partly, fails, not_measurable };

/// "yes", "partly", "no", "n/a".
[[nodiscard]] std::string_view to_string(Verdict v);

struct ClaimCheck {
  std::string id;        ///< "a1", ..., "c5"
  std::string claim;     ///< the paper's statement, in English
  Verdict verdict = Verdict::not_measurable;
  std::string evidence;  ///< the numbers, one short sentence
};

/// How the paper's words are read.
struct NarrativeRules {
  double quick_fraction = 0.1;      ///< "quickly", "briefly": within this fraction of the run's duration
  double much_longer = 2.0;         ///< "much longer": at least this factor
  double same_angle_deg = 5.0;      ///< "the same position": tilts within this many degrees
  double oscillation_factor = 2.0;  ///< "oscillates" (b) vs "smoothly" (a): peak-to-peak larger by this factor
  long series_of_liftoffs = 2;      ///< "a series of lift-offs": at least this many
  /// "an equilibrium position": the final 1-s mean of |gamma3| above the near-vertical threshold
  /// (0.99); between this and it, a body still rolling on its pole counts as "partly".
  double near_pole = 0.95;
};

/// The three cases of one egg reading run with one law (null: not run).
struct CaseRuns {
  const RunResult* a = nullptr;
  const RunResult* b = nullptr;
  const RunResult* c = nullptr;
};

/// Every claim of the cases present (a1-a6, b1-b5, c1-c5), in that order.
[[nodiscard]] std::vector<ClaimCheck> check_narrative(const CaseRuns& runs, const NarrativeRules& rules = {});

}  // namespace frictionlab::dynamics::paper
